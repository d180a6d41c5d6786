#include "contact/multi_hertz/approach_given.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>

#include "core/numfmt.hpp"
#include "core/units.hpp"

namespace mh {

double normal_stiffness(const LoadedEllipse& L) {
  if (!(L.s.h0 > 0)) return 0;
  if (L.s.plastic) return L.s.N / (L.s.h0 - L.h_y / 3.0);  // method.md §5: N = k_p (h0 − h_y/3)
  return 1.5 * L.s.N / L.s.h0;                              // eq. 8: N = k_e h0^(3/2)
}

void solve_multi_hertz_approach(const ContactGeometry& G, const Material& mat, double tY, double dz,
                                const MultiHertzOptions& opt, ApproachWorkspace& ws, CaseResult& r) {
  r.status = CaseStatus::Ok;
  r.method = Method::MultiHertzian;
  r.message.clear();
  r.warnings.clear();
  r.loaded.clear();
  r.patches.clear();
  r.dz = dz;
  r.approach = 0;
  r.iterations = 0;
  r.residual = 0;
  r.Fz = r.Fy = r.pmax = r.area = 0;
  r.n_contacts = 0;
  if (!std::isfinite(dz)) {
    r.status = CaseStatus::NoContact;
    r.message = "the approach dz must be finite";
    return;
  }
  if (!G.covers(tY)) {  // the wording of solve_multi_hertz
    r.status = CaseStatus::OutOfRange;
    r.message = "t_Y = " + format_number(tY * 1e3) + " mm outside the geometry table [" +
                format_number(G.tY.front() * 1e3) + ", " + format_number(G.tY.back() * 1e3) + "] mm";
    return;
  }
  const std::size_t ne = G.n_ellipses();
  ws.geo.resize(ne);
  int main = 0;
  G.candidates_at(tY, ws.geo.data(), &main);
  for (std::size_t e = 0; e < ne; ++e) {
    const CandidateGeom& g = ws.geo[e];
    const double h = (dz - g.gap) * std::cos(g.gamma);  // (eq. 11)
    if (!(h > 0)) continue;
    const int idx = static_cast<int>(e) + 1;
    // A loaded candidate off the end of a profile (method.md §3.7): never silent.
    if (g.off_profile) r.warnings.push_back("off_profile:ellipse=" + std::to_string(idx));
    // A and B, the Hertzian test and the law exactly as solve_multi_hertz builds them
    // (candidate_ellipses shares that code: same bits).
    double A = 0, B = 0;
    bool hertzian = false;
    EllipseLaw law;
    {
      // eq. 1, as multi_hertz.cpp's curvature_sums
      A = 1.0 / (2.0 * g.R_wyy());
      if (g.r_roller > 0) A += 0.5 * g.k_ryy();
      B = 0.5 * (g.k_wxx + g.k_rxx);
      hertzian = B > 0 && A > 0 && std::isfinite(A) && std::isfinite(B);
      if (hertzian) {
        try {
          law = make_ellipse_law(A, B, mat, opt.exact_coefficients);
        } catch (const std::exception&) {
          hertzian = false;  // λ beyond the Hertz range: nearly conformal, no ellipse
        }
      }
    }
    if (!hertzian) {
      r.warnings.push_back("non_hertzian_excluded:ellipse=" + std::to_string(idx));
      continue;
    }
    const double cg = std::cos(g.gamma), sg = std::sin(g.gamma);
    LoadedEllipse L;
    L.ellipse = idx;
    L.g = g;
    L.A = A;
    L.B = B;
    L.c = law.c;
    L.h_y = law.h_y;
    L.s = ellipse_state(law, h);
    L.validity = hertz_validity(G, g, L.s.b, opt.validity);
    if (G.rail_curve) L.z_r = G.rail_curve->z(g.y_r);
    if (G.wheel_curve) L.z_w = G.wheel_curve->z(g.y_w);
    if (!L.validity.valid)
      r.warnings.push_back("non_hertzian:ellipse=" + std::to_string(idx) + ":" + L.validity.describe(opt.validity));
    r.Fz += L.s.N * cg;
    r.Fy += L.s.N * sg;
    r.pmax = std::max(r.pmax, L.s.p_max);
    r.area += units::pi * L.s.a * L.s.b;
    r.approach = std::max(r.approach, L.s.approach / cg + g.gap);
    r.loaded.push_back(L);
  }
  r.n_contacts = static_cast<int>(r.loaded.size());
  if (r.loaded.empty()) {
    r.status = CaseStatus::NoContact;
    r.message = "no contact: the approach dz = " + format_number(dz * 1e3) + " mm loads no Hertzian candidate";
  }
  if (ne > 0 && ws.geo[static_cast<std::size_t>(main)].flange_climb)
    r.warnings.push_back("flange_climb:ellipse=" + std::to_string(main + 1));
}

}  // namespace mh
