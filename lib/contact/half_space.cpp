#include "contact/half_space.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "contact/influence.hpp"
#include "contact/multi_hertz.hpp"
#include "core/numfmt.hpp"
#include "geometry/gap.hpp"

namespace mh {

bool HalfSpaceOptions::valid(std::string* why) const {
  auto fail = [&](const std::string& s) { if (why) *why = s; return false; };
  if (!(dx >= 0.01e-3 && dx <= 2e-3)) return fail("dx_mm = " + format_number(dx * 1e3) + ": must be in [0.01, 2] mm");
  if (!(ds >= 0.01e-3 && ds <= 2e-3)) return fail("ds_mm = " + format_number(ds * 1e3) + ": must be in [0.01, 2] mm");
  if (!(d_comb >= 0 && d_comb <= 100e-3)) return fail("d_comb_mm = " + format_number(d_comb * 1e3) + ": must be in [0, 100] mm");
  if (!(margin >= 1.0 && margin <= 4.0)) return fail("margin = " + format_number(margin) + ": must be in [1, 4]");
  if (!(force_rtol > 0 && force_rtol < 1e-2)) return fail("force_rtol = " + format_number(force_rtol) + ": must be in (0, 0.01)");
  if (max_outer < 1 || max_outer > 1000) return fail("max_outer = " + std::to_string(max_outer) + ": must be in [1, 1000]");
  if (max_rebuilds < 0 || max_rebuilds > 20) return fail("max_rebuilds = " + std::to_string(max_rebuilds) + ": must be in [0, 20]");
  return cg.valid(why);
}

namespace {

constexpr double kRegionStep = 0.02e-3;  // [m] sampling of g(y) for the interpenetration regions
constexpr long kMaxElements = 4'000'000; // one patch grid larger than this is refused (memory)

// One patch: its plane, grid, undeformed normal gap, influence operator and pressure.
struct Patch {
  double y_a = 0, y_b = 0;  // rail-y extent of its interpenetration region(s)
  PatchPlane P;
  int nx = 0, ns = 0;
  double x0 = 0, s0 = 0;     // centre of element (0, 0)
  std::vector<double> h;     // [m] undeformed normal gap at first contact
  std::vector<double> p;     // [Pa]
  std::unique_ptr<InfluenceGrid> C;
  double h_min = 0;
  NormalCGResult last;
  int iterations = 0;
};

// Patches of the interpenetration at vertical approach dz_grid (their grids), with the plane of
// each from the interpenetration at dz_ref (the approach of the solution, or its estimate):
// regions closer than d_comb merge into one patch.
std::vector<Patch> form_patches(const WheelRailGap& gap, double dz_ref, double dz_grid,
                                const HalfSpaceOptions& opt, std::string* why) {
  std::vector<Patch> out;
  auto regions = gap.interpenetration(dz_grid, kRegionStep);
  std::vector<std::pair<double, double>> merged;
  for (const auto& r : regions) {
    if (!merged.empty() && r.first - merged.back().second < opt.d_comb) merged.back().second = r.second;
    else merged.push_back(r);
  }
  for (const auto& m : merged) {
    Patch k;
    k.y_a = m.first;
    k.y_b = m.second;
    // Reference point and plane (CONTACT's "interpenetration centre of gravity"): the mean of the
    // rail point (y, z_r) and of the rail's inclination angle over the interpenetration at dz_ref,
    // weighted by the squared interpenetration e(x, y)² = (dz − g(y) − x²/2r)². Across x a row
    // weighs ∫ e² dx = (16/15) e0² √(2 r e0), e0 = dz − g(y). A region that does not interpenetrate
    // at dz_ref (it only touches at the larger dz_grid) is weighted at dz_grid.
    double xmax = 0;
    const int n = std::max(4, static_cast<int>((k.y_b - k.y_a) / kRegionStep));
    for (double dz : {dz_ref, dz_grid}) {
      double w = 0, wy = 0, wz = 0, wa = 0;
      for (int i = 0; i <= n; ++i) {
        const double y = k.y_a + (k.y_b - k.y_a) * i / n;
        const double r = gap.rolling_radius(y);
        const double e0 = std::max(dz - gap.g(y), 0.0);
        if (dz == dz_grid) xmax = std::max(xmax, std::sqrt(2 * r * e0));  // g + x²/2r < dz
        if (!(e0 > 0)) continue;
        const double wr = e0 * e0 * std::sqrt(2 * r * e0);
        double slope = 0;
        const double z = gap.z_rail(y, &slope);
        w += wr; wy += wr * y; wz += wr * z; wa += wr * std::atan(slope);
      }
      if (w > 0 && k.P.y_ref == 0 && k.P.z_ref == 0 && k.P.gamma == 0) {
        k.P.y_ref = wy / w;
        k.P.z_ref = wz / w;
        k.P.gamma = wa / w;
      }
    }
    const double c = std::cos(k.P.gamma);
    // Grid: x symmetric about 0 (no yaw), s over the region's extent in the plane, 3 elements of room.
    const double sa = (k.y_a - k.P.y_ref) / c - 3 * opt.ds, sb = (k.y_b - k.P.y_ref) / c + 3 * opt.ds;
    k.nx = 2 * static_cast<int>(std::ceil((xmax + 3 * opt.dx) / opt.dx));
    k.ns = std::max(1, static_cast<int>(std::ceil((sb - sa) / opt.ds)));
    if (static_cast<long>(k.nx) * k.ns > kMaxElements) {
      *why = "a contact patch would need " + std::to_string(static_cast<long>(k.nx) * k.ns) +
             " elements (more than " + std::to_string(kMaxElements) + "): use larger dx_mm/ds_mm";
      return {};
    }
    k.x0 = -(k.nx / 2 - 0.5) * opt.dx;
    k.s0 = 0.5 * (sa + sb) - (k.ns - 1) * 0.5 * opt.ds;
    k.h.assign(static_cast<std::size_t>(k.nx) * k.ns, 0.0);
    k.h_min = std::numeric_limits<double>::infinity();
    for (int j = 0; j < k.ns; ++j) {
      const double s = k.s0 + j * opt.ds;
      for (int i = k.nx / 2; i < k.nx; ++i) {  // h is even in x: compute x > 0, mirror
        const double x = k.x0 + i * opt.dx;
        // The gap with the wheel at dz_ref, shifted back by the normal approach dz_ref cos γ, so that
        // δ = dz cos γ reproduces it exactly at dz = dz_ref (and to first order nearby).
        const double v = normal_gap(gap, k.P, x, s, dz_ref) + dz_ref * c;
        k.h[static_cast<std::size_t>(i + k.nx * j)] = v;
        k.h[static_cast<std::size_t>(k.nx - 1 - i + k.nx * j)] = v;
        k.h_min = std::min(k.h_min, v);
      }
    }
    k.p.assign(k.h.size(), 0.0);
    out.push_back(std::move(k));
  }
  return out;
}

// Does any element on the grid's edge carry pressure? (Then the grid is too small.)
bool touches_edge(const Patch& k) {
  for (int i = 0; i < k.nx; ++i)
    if (k.p[static_cast<std::size_t>(i)] > 0 || k.p[static_cast<std::size_t>(i + k.nx * (k.ns - 1))] > 0) return true;
  for (int j = 0; j < k.ns; ++j)
    if (k.p[static_cast<std::size_t>(k.nx * j)] > 0 || k.p[static_cast<std::size_t>(k.nx - 1 + k.nx * j)] > 0) return true;
  return false;
}

}  // namespace

CaseResult solve_half_space(const ContactGeometry& G, const Material& mat, double tY, double Q,
                            const HalfSpaceOptions& opt) {
  CaseResult r;
  r.method = Method::HalfSpace;
  r.dz = NAN;
  if (!(Q > 0) || !std::isfinite(Q)) {
    r.status = CaseStatus::NoContact;
    r.message = "Q must be > 0";
    return r;
  }
  if (!G.covers(tY) || !G.wheel_curve || !G.rail_curve) {
    r.status = CaseStatus::OutOfRange;
    r.message = "t_Y = " + format_number(tY * 1e3) + " mm outside the geometry table [" +
                format_number(G.tY.front() * 1e3) + ", " + format_number(G.tY.back() * 1e3) + "] mm";
    return r;
  }
  if (std::isfinite(mat.p_lim)) {
    // Plastic model: when the elastic solution stays below the cap it is the solution of the
    // capped problem too (it satisfies every condition, and the solution is unique), exactly.
    Material elastic = mat;
    elastic.p_lim = INFINITY;
    CaseResult el = solve_half_space(G, elastic, tY, Q, opt);
    if (el.status != CaseStatus::Ok || el.pmax <= mat.p_lim) return el;
  }
  const WheelRailGap gap(G, tY);
  const double H = mat.compliance();
  const double p_lim = mat.p_lim;

  // First estimate of the vertical approach: the multi-Hertzian one (below a microsecond), or a
  // Hertz-like 0.05 mm when it has none.
  double dz_est = 0.05e-3;
  {
    const CaseResult mhr = solve_case(G, mat, tY, Q);
    if (mhr.status == CaseStatus::Ok && mhr.approach > 0 && std::isfinite(mhr.approach)) dz_est = mhr.approach;
  }

  std::vector<Patch> patches;
  double dz = dz_est, dz_ref = dz_est;
  int outer = 0;
  bool solved = false;
  for (int pass = 0; pass <= opt.max_rebuilds && !solved; ++pass) {
    r.status = CaseStatus::Ok;
    r.message.clear();
    std::string why;
    patches = form_patches(gap, dz_ref, opt.margin * dz_ref, opt, &why);
    if (patches.empty()) {
      r.status = CaseStatus::NotConverged;
      r.message = why.empty() ? "no interpenetration region found" : why;
      return r;
    }
    for (auto& k : patches) k.C = std::make_unique<InfluenceGrid>(k.nx, k.ns, opt.dx, opt.ds, H);

    bool cg_failed = false;
    // F(δz) = Σ_k N_k cos γ_k with δ_k = δz cos γ_k (eqs. 10–11 on the grids).
    auto force = [&](double z) {
      double F = 0;
      for (auto& k : patches) {
        const double c = std::cos(k.P.gamma);
        k.last = solve_normal_approach(*k.C, k.h.data(), z * c, p_lim, k.p.data(), opt.cg);
        k.iterations += k.last.iterations;
        if (k.last.status == GridStatus::NotConverged) cg_failed = true;
        F += k.last.N * c;
      }
      return F;
    };
    if (patches.size() == 1) {
      // One patch: load control in the patch (Polonsky–Keer), N = Q / cos γ.
      Patch& k = patches[0];
      const double c = std::cos(k.P.gamma);
      k.last = solve_normal_load(*k.C, k.h.data(), Q / c, p_lim, k.p.data(), opt.cg);
      k.iterations += k.last.iterations;
      if (k.last.status != GridStatus::Ok) cg_failed = true;
      dz = k.last.delta / c;
      ++outer;
    } else {
      // Several patches: a safeguarded secant (Illinois) on δz, bracketed from the estimate.
      double lo = 0, Flo = -Q, hi = dz_ref, Fhi = force(hi) - Q;
      ++outer;
      while (Fhi < 0 && outer < opt.max_outer) {
        lo = hi; Flo = Fhi;
        hi *= 1.5;
        Fhi = force(hi) - Q;
        ++outer;
      }
      int side = 0;
      dz = hi;
      double Fz = Fhi;
      while (std::fabs(Fz) > opt.force_rtol * Q && outer < opt.max_outer) {
        double z = (lo * Fhi - hi * Flo) / (Fhi - Flo);
        if (!(z > lo && z < hi)) z = 0.5 * (lo + hi);
        Fz = force(z) - Q;
        ++outer;
        dz = z;
        if (Fz > 0) { hi = z; Fhi = Fz; if (side == 1) Flo *= 0.5; side = 1; }
        else { lo = z; Flo = Fz; if (side == -1) Fhi *= 0.5; side = -1; }
        if (hi - lo < 1e-15) break;
      }
      if (std::fabs(Fz) > opt.force_rtol * Q) {
        r.status = CaseStatus::NotConverged;
        r.message = "force balance not reached in " + std::to_string(outer) + " iterations on the approach";
      }
      // The last evaluation was at dz: the pressures on the grids belong to it.
    }
    if (cg_failed) {
      r.status = CaseStatus::NotConverged;
      r.message = "the half-space solver did not converge on a patch grid";
    }
    bool edge = false;
    for (const auto& k : patches) edge = edge || touches_edge(k);
    // Rebuild when the contact outgrew the grid, or when the planes were placed for an approach
    // more than ref_rtol away from the solution's (the reference point follows the approach).
    if (edge || dz > opt.margin * dz_ref || std::fabs(dz - dz_ref) > opt.ref_rtol * dz) {
      dz_ref = edge ? std::max(dz, dz_ref) * 1.3 : dz;
      continue;
    }
    solved = true;
  }

  if (!solved) {
    r.status = CaseStatus::NotConverged;
    r.message = "the contact patches did not settle (grid edge or reference point) after " + std::to_string(opt.max_rebuilds) + " rebuilds";
  }
  // Results per patch and for the case.
  r.approach = dz;
  r.iterations = outer;
  int index = 0;
  for (auto& k : patches) {
    PatchResult pr;
    pr.patch = ++index;
    pr.y_r = k.P.y_ref;
    pr.z_r = gap.z_rail(k.P.y_ref);  // the reference point on the rail profile (as CONTACT reports it)
    pr.y_w = gap.y_wheel(k.P.y_ref);
    pr.gamma = k.P.gamma;
    pr.iterations = k.iterations;
    const double da = opt.dx * opt.ds;
    int i0 = k.nx, i1 = -1, j0 = k.ns, j1 = -1;
    double sp = 0, spx = 0, sps = 0;
    for (int j = 0; j < k.ns; ++j)
      for (int i = 0; i < k.nx; ++i) {
        const double p = k.p[static_cast<std::size_t>(i + k.nx * j)];
        if (!(p > 0)) continue;
        ++pr.n_elements;
        pr.pmax = std::max(pr.pmax, p);
        if (std::isfinite(p_lim) && p >= p_lim) { pr.plastic_area += da; pr.capped_load += p * da; }
        sp += p; spx += p * (k.x0 + i * opt.dx); sps += p * (k.s0 + j * opt.ds);
        i0 = std::min(i0, i); i1 = std::max(i1, i); j0 = std::min(j0, j); j1 = std::max(j1, j);
      }
    pr.N = sp * da;
    pr.area = pr.n_elements * da;
    if (pr.n_elements > 0) {
      pr.length_x = (i1 - i0 + 1) * opt.dx;
      pr.width_s = (j1 - j0 + 1) * opt.ds;
      pr.x_centroid = spx / sp;
      pr.s_centroid = sps / sp;
    }
    pr.approach = dz * std::cos(k.P.gamma) - k.h_min;
    if (pr.N <= 0) continue;  // a potential patch that carries nothing is not reported
    if (opt.keep_pressure) {
      pr.nx = k.nx; pr.ns = k.ns; pr.dx = opt.dx; pr.ds = opt.ds; pr.x0 = k.x0; pr.s0 = k.s0;
      pr.p = k.p;
    }
    r.Fz += pr.N * std::cos(pr.gamma);
    r.Fy += pr.N * std::sin(pr.gamma);
    r.pmax = std::max(r.pmax, pr.pmax);
    r.area += pr.area;
    r.patches.push_back(std::move(pr));
  }
  index = 0;
  for (auto& pr : r.patches) pr.patch = ++index;
  r.n_contacts = static_cast<int>(r.patches.size());
  r.residual = (r.Fz - Q) / Q;
  if (r.status == CaseStatus::Ok && std::fabs(r.residual) > 10 * opt.force_rtol && patches.size() > 1) {
    r.status = CaseStatus::NotConverged;
    r.message = "force balance residual " + format_number(r.residual);
  }
  return r;
}

}  // namespace mh
