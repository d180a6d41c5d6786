#include "contact/solve.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace mh {

namespace {

// "auto" (docs/method.md §9): the multi-Hertzian answer is kept when it can be trusted — it
// converged and every loaded ellipse passes the Hertz validity test, with no non-Hertzian
// candidate excluded; otherwise the case is solved by the strip method. The `method` column says
// which one solved it, and a case handed over carries the warning auto:strips:<reason>.
CaseResult solve_auto(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt) {
  CaseResult mhr = solve_case(G, mat, tY, Q, opt.multi_hertzian);
  if (mhr.status == CaseStatus::OutOfRange) return mhr;
  std::string reason;
  if (mhr.status != CaseStatus::Ok) reason = to_string(mhr.status);
  for (const auto& L : mhr.loaded)
    if (reason.empty() && !L.validity.valid) reason = "ellipse " + std::to_string(L.ellipse) + " not Hertzian";
  for (const auto& w : mhr.warnings)
    if (reason.empty() && w.rfind("non_hertzian_excluded", 0) == 0) reason = "non-Hertzian candidate excluded";
  // Contacts close enough to interact elastically: each ellipse is solved on its own, while the
  // strip method couples them (the gauge-shoulder case of §9). Close: the lateral gap between the
  // patches' edges on the rail is below d_comb, the distance at which the grid methods make the
  // regions one patch.
  for (std::size_t i = 0; i < mhr.loaded.size() && reason.empty(); ++i)
    for (std::size_t j = i + 1; j < mhr.loaded.size() && reason.empty(); ++j) {
      const LoadedEllipse &A = mhr.loaded[i], &B = mhr.loaded[j];
      const double edge_gap = std::fabs(A.g.y_r - B.g.y_r) - A.s.b * std::cos(A.g.gamma) - B.s.b * std::cos(B.g.gamma);
      if (edge_gap < opt.strips.d_comb)
        reason = "ellipses " + std::to_string(A.ellipse) + " and " + std::to_string(B.ellipse) + " interact";
    }
  if (reason.empty()) return mhr;
  CaseResult sr = solve_strip_method(G, mat, tY, Q, opt.strips);
  sr.warnings.insert(sr.warnings.begin(), "auto:strips:" + reason);
  if (sr.status != CaseStatus::NotConverged) return sr;
  // The strip method did not converge either (e.g. a load inside a jump of its N(δ),
  // docs/strips.md): the exact half-space method, slower but robust, solves the case; the
  // warnings say both steps.
  CaseResult hr = solve_half_space(G, mat, tY, Q, opt.half_space);
  if (hr.status != CaseStatus::Ok) return sr;
  hr.warnings.insert(hr.warnings.begin(), "auto:half-space:strips not converged");
  hr.warnings.insert(hr.warnings.begin(), "auto:strips:" + reason);
  return hr;
}

}  // namespace

namespace {
CaseResult solve_by_method(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt) {
  switch (opt.method) {
    case Method::Auto: return solve_auto(G, mat, tY, Q, opt);
    case Method::HalfSpace: return solve_half_space(G, mat, tY, Q, opt.half_space);
    case Method::Strips: return solve_strip_method(G, mat, tY, Q, opt.strips);
    case Method::MultiHertzian:
    default: return solve_case(G, mat, tY, Q, opt.multi_hertzian);
  }
}
}  // namespace

CaseResult solve_method(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt) {
  CaseResult r = solve_by_method(G, mat, tY, Q, opt);
  // Flange climb (method.md §3.7): the main contact at this t_Y has passed the wheel's steepest
  // flange point, whatever the method; the case says so.
  if (r.status != CaseStatus::OutOfRange && G.covers(tY) && G.n_ellipses() > 0) {
    std::vector<CandidateGeom> c(G.n_ellipses());
    int main = 0;
    G.candidates_at(tY, c.data(), &main);
    if (c[static_cast<std::size_t>(main)].flange_climb) r.warnings.push_back("flange_climb:ellipse=" + std::to_string(main + 1));
  }
  // Off the end of a profile (method.md §3.7), grid methods: a patch whose contact reaches the
  // end of either profile stands on extrapolated geometry. (The multi-Hertzian solver flags its
  // loaded candidates itself.)
  if (G.wheel_curve && G.rail_curve && !G.strip_y.empty())
    for (const PatchResult& P : r.patches) {
      const double c = std::cos(P.gamma);
      if (G.off_profile(tY, P.y_r + P.s_lo * c) || G.off_profile(tY, P.y_r + P.s_hi * c))
        r.warnings.push_back("off_profile:patch=" + std::to_string(P.patch));
    }
  return r;
}

}  // namespace mh
