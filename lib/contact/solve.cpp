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
  CaseResult mhr = solve_multi_hertz(G, mat, tY, Q, opt.multi_hertzian);
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
  // The grid methods start from the elastic multi-Hertzian solution: mhr itself when the model
  // is elastic, else one elastic solve shared by strips and the half-space fallback.
  CaseResult elastic_mh;
  const CaseResult* start = &mhr;
  if (std::isfinite(mat.p_lim)) {
    Material elastic = mat;
    elastic.p_lim = INFINITY;
    elastic_mh = solve_multi_hertz(G, elastic, tY, Q);
    start = &elastic_mh;
  }
  CaseResult sr = solve_strip_method(G, mat, tY, Q, opt.strips, start);
  sr.warnings.insert(sr.warnings.begin(), "auto:strips:" + reason);
  if (sr.status != CaseStatus::NotConverged) return sr;
  // The strip method did not converge either (e.g. a load inside a jump of its N(δ),
  // docs/strips.md): the exact half-space method, slower but robust, solves the case; the
  // warnings say both steps.
  CaseResult hr = solve_half_space(G, mat, tY, Q, opt.half_space, start);
  if (hr.status != CaseStatus::Ok) return sr;
  hr.warnings.insert(hr.warnings.begin(), "auto:half-space:strips not converged");
  hr.warnings.insert(hr.warnings.begin(), "auto:strips:" + reason);
  return hr;
}

}  // namespace

CaseResult solve_contact(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt) {
  switch (opt.method) {
    case Method::Auto: return solve_auto(G, mat, tY, Q, opt);
    case Method::HalfSpace: return solve_half_space(G, mat, tY, Q, opt.half_space);
    case Method::Strips: return solve_strip_method(G, mat, tY, Q, opt.strips);
    case Method::MultiHertzian:
    default: return solve_multi_hertz(G, mat, tY, Q, opt.multi_hertzian);
  }
}

}  // namespace mh
