#include "contact/multi_hertz/multi_hertz.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "core/numfmt.hpp"
#include "core/roots.hpp"
#include "core/units.hpp"

namespace mh {


namespace {

struct Cand {
  int ellipse;
  CandidateGeom g;
  double A, B, cg, sg;  // cos γ, sin γ
  bool hertzian;
  EllipseLaw law;
};

std::uint64_t bits(double v) {
  std::uint64_t u;
  std::memcpy(&u, &v, sizeof u);
  return u;
}

// The law of an ellipse depends only on (A, B, material, exact): the same for every Q at one t_Y,
// and the sweep runs Q inside t_Y. One slot per potential ellipse remembers the last law built;
// a hit needs A and B bit-identical, so results are bit-identical with and without the cache.
struct LawSlot {
  bool used = false;
  std::uint64_t A = 0, B = 0;
  bool hertzian = false;
  EllipseLaw law;
};
struct LawCache {
  std::uint64_t E = 0, nu = 0, E_rail = 0, nu_rail = 0, p_lim = 0, yield = 0;
  bool exact = false, yield_law = false;
  LawMaterial lm;  // law_material() of the material of the key: checked once, not per law
  std::vector<LawSlot> slots;
  // Forget every slot when the material or the coefficient path changed.
  void key(const Material& m, bool ex, std::size_t ne) {
    const bool same = bits(m.E) == E && bits(m.nu) == nu && bits(m.E_rail) == E_rail &&
                      bits(m.nu_rail) == nu_rail && bits(m.p_lim) == p_lim && ex == exact &&
                      m.yield_law == yield_law && bits(m.yield_min()) == yield;
    if (!same) {
      lm = law_material(m);  // first: an invalid material throws with the key unchanged
      E = bits(m.E); nu = bits(m.nu); E_rail = bits(m.E_rail); nu_rail = bits(m.nu_rail); p_lim = bits(m.p_lim);
      yield_law = m.yield_law; yield = bits(m.yield_min());
      exact = ex;
      slots.clear();
    }
    if (slots.size() < ne) slots.resize(ne);
  }
};

}  // namespace

bool candidate_sums(const CandidateGeom& g, double* A, double* B) {
  // Roller rig: + 1/(2 R_ryy) in A; a straight rail adds nothing.
  const CurvatureSums s = curvature_sums(g.R_wyy(), g.r_roller > 0 ? g.k_ryy() : 0.0, g.k_wxx, g.k_rxx);
  *A = s.A;
  *B = s.B;
  // A Hertz ellipse when both sums are positive and finite and λ = A/B is within the range of the
  // Hertz coefficients (hertz.hpp): beyond it the contact is nearly conformal, not an ellipse. Any
  // other failure to build a law (an invalid material) is a bug of the caller and propagates as
  // an exception: an internal error, never "non-Hertzian".
  if (!(s.B > 0 && s.A > 0 && std::isfinite(s.A) && std::isfinite(s.B))) return false;
  const double lambda = s.A / s.B;
  return lambda >= kLambdaMinExact && lambda <= kLambdaMaxExact;
}

void add_loaded_candidate(const ContactGeometry& G, int ellipse, const CandidateGeom& g, double A, double B,
                          const EllipseLaw* law, double h, double cg, double sg, const MultiHertzOptions& opt,
                          CaseResult& r) {
  // A loaded candidate off the end of a profile (method.md §3.7): its geometry is the end's,
  // extrapolated; never silent.
  if (g.off_profile) r.warnings.emplace_back(WarningClass::OffProfile, ContactKind::Ellipse, ellipse);
  if (!law) {
    r.warnings.emplace_back(WarningClass::NonHertzianExcluded, ContactKind::Ellipse, ellipse);
    return;
  }
  r.loaded.emplace_back();
  LoadedEllipse& L = r.loaded.back();
  L.ellipse = ellipse;
  L.g = g;
  L.cos_gamma = cg;
  L.sin_gamma = sg;
  L.A = A;
  L.B = B;
  L.c = law->c;
  L.h_y = law->h_y;
  L.s = ellipse_state(*law, h);
  L.validity = hertz_validity(G, g, L.s.b, opt.validity);
  // The contact point on each profile: for plots and checks.
  if (G.rail_curve) L.z_r = G.rail_curve->z(g.y_r);
  if (G.wheel_curve) L.z_w = G.wheel_curve->z(g.y_w);
  if (!L.validity.valid)
    r.warnings.push_back(L.validity.warning(ellipse, opt.validity));
  r.Fz += L.s.N * cg;
  r.Fy += L.s.N * sg;
  // Case summary shared with the grid methods (case_result.hpp).
  r.pmax = std::max(r.pmax, L.s.p_max);
  r.area += units::pi * L.s.a * L.s.b;
  r.approach = std::max(r.approach, L.s.approach / cg + g.gap);
}

void candidate_ellipses(const ContactGeometry& G, const Material& mat, double tY, const MultiHertzOptions& opt,
                        std::vector<CandidateEllipse>& out) {
  const std::size_t ne = G.n_ellipses();
  std::vector<CandidateGeom> geo(ne);
  int main = 0;
  G.candidates_at(tY, opt.roll, geo.data(), &main);
  out.assign(ne, CandidateEllipse{});
  for (std::size_t e = 0; e < ne; ++e) {
    CandidateEllipse& c = out[e];
    c.ellipse = static_cast<int>(e) + 1;
    c.g = geo[e];
    c.hertzian = candidate_sums(c.g, &c.A, &c.B);
    if (c.hertzian) c.c = make_ellipse_law(c.A, c.B, mat, opt.exact_coefficients).c;
    if (G.rail_curve) c.z_r = G.rail_curve->z(c.g.y_r);
    if (G.wheel_curve) c.z_w = G.wheel_curve->z(c.g.y_w);
  }
}

CaseResult solve_multi_hertz(const ContactGeometry& G, const Material& mat, double tY, double Q,
                             const MultiHertzOptions& opt) {
  CaseResult r;
  solve_multi_hertz(G, mat, tY, Q, opt, r);
  return r;
}

void solve_multi_hertz(const ContactGeometry& G, const Material& mat, double tY, double Q,
                       const MultiHertzOptions& opt, CaseResult& r) {
  reset_case_result(r);  // as a fresh CaseResult, keeping the vectors' capacity
  if (!(Q > 0) || !std::isfinite(Q)) {
    r.status = CaseStatus::NoContact;
    r.message = "Q must be > 0";
    return;
  }
  if (!G.covers(tY)) {
    r.status = CaseStatus::OutOfRange;
    r.message = "t_Y = " + format_number(tY * 1e3) + " mm outside the geometry table [" +
                format_number(G.tY.front() * 1e3) + ", " + format_number(G.tY.back() * 1e3) + "] mm";
    return;
  }
  const std::size_t ne = G.n_ellipses();
  thread_local std::vector<CandidateGeom> geo;
  thread_local std::vector<Cand> cs;
  thread_local LawCache cache;
  cache.key(mat, opt.exact_coefficients, ne);
  geo.resize(ne);
  cs.clear();
  int main = 0;
  G.candidates_at(tY, opt.roll, geo.data(), &main);
  // Flange climb (method.md §3.7): the main contact at this t_Y has passed the wheel's steepest
  // flange point. Geometric, the same for every method: the grid methods copy it from this
  // solution, their start (contact/grid/patch_driver.hpp).
  const bool climb = ne > 0 && geo[static_cast<std::size_t>(main)].flange_climb;
  auto flag_climb = [&] {
    if (climb) r.warnings.emplace_back(WarningClass::FlangeClimb, ContactKind::Ellipse, main + 1);
  };
  for (std::size_t e = 0; e < ne; ++e) {
    Cand c;
    c.ellipse = static_cast<int>(e) + 1;
    c.g = geo[e];
    c.hertzian = candidate_sums(c.g, &c.A, &c.B);
    c.cg = std::cos(c.g.gamma);
    c.sg = std::sin(c.g.gamma);
    if (c.hertzian) {
      LawSlot& slot = cache.slots[e];
      if (slot.used && slot.A == bits(c.A) && slot.B == bits(c.B)) {
        c.hertzian = slot.hertzian;
        c.law = slot.law;
      } else {
        c.law = make_ellipse_law(c.A, c.B, cache.lm, opt.exact_coefficients);
        slot.used = true;
        slot.A = bits(c.A);
        slot.B = bits(c.B);
        slot.hertzian = c.hertzian;
        slot.law = c.law;
      }
    }
    cs.push_back(c);
  }
  // Σ N_i cos γ_i and its derivative in δz (eqs. 10–11).
  auto total = [&](double dz, double* dF) {
    double F = 0, D = 0;
    for (const Cand& c : cs) {
      if (!c.hertzian) continue;
      const double h = (dz - c.g.gap) * c.cg;
      if (h <= 0) continue;
      double dN;
      F += c.law.force(h, &dN) * c.cg;
      D += dN * c.cg * c.cg;
    }
    if (dF) *dF = D;
    return F;
  };
  // Start: the Hertzian candidate with the smallest gap (the main strip, if Hertzian) carrying Q
  // alone, in closed form; it bounds δz from above since the others only add force.
  const Cand* first = nullptr;
  for (const Cand& c : cs)
    if (c.hertzian && (!first || c.g.gap < first->g.gap)) first = &c;
  if (!first) {
    // The wheel does touch the rail, conformally: this method has no answer, and an answer of
    // zero force (no_contact) would be taken as a wheel in the air by a vehicle-dynamics code.
    r.status = CaseStatus::NotConverged;
    r.message = "no Hertzian candidate: every potential ellipse has B <= 0 (a conformal contact) at this t_Y: the "
                "multi-Hertzian method cannot solve it, no force computed; solve it with method auto, strips or "
                "half-space";
    flag_climb();
    return;
  }
  // Eq. 10 by Newton's method in δz, kept inside the bracket [lo, hi] (core/roots.hpp): F is
  // increasing and piecewise smooth (a candidate enters with zero force and zero slope).
  const double lo = first->g.gap;  // F(lo) = 0 < Q (only candidates with smaller gap could load: none)
  const double hi = first->g.gap + first->law.h0_for_force(Q / first->cg) / first->cg;
  RootTolerance tol;
  tol.rel = DBL_EPSILON;
  tol.max_iterations = opt.max_iterations + 1;  // the start at hi, then up to max_iterations steps
  tol.f_abs = opt.rtol * Q;
  const RootResult root = newton_root(
      [&](double z) {
        double dF = 0;
        const double F = total(z, &dF);
        return std::pair<double, double>(F - Q, dF);
      },
      hi, lo, hi, tol);
  const double dz = root.x;
  r.iterations = root.iterations - 1;  // Newton steps after the start at hi
  r.dz = dz;
  r.residual = root.f / Q;
  if (std::fabs(root.f) > tol.f_abs && std::fabs(r.residual) > 4 * std::numeric_limits<double>::epsilon()) {
    r.status = CaseStatus::NotConverged;
    r.message = "equilibrium not reached in " + std::to_string(r.iterations) + " iterations (relative residual " +
                format_number(r.residual) + ")";
  }
  for (const Cand& c : cs) {
    const double h = (dz - c.g.gap) * c.cg;
    if (h <= 0) continue;
    add_loaded_candidate(G, c.ellipse, c.g, c.A, c.B, c.hertzian ? &c.law : nullptr, h, c.cg, c.sg, opt, r);
  }
  r.n_contacts = static_cast<int>(r.loaded.size());
  flag_climb();
}

}  // namespace mh
