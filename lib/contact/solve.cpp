#include "contact/solve.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "contact/ellipse/hertz_validity.hpp"
#include "geometry/gap.hpp"

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
  // strip method couples them (the gauge-shoulder case of §9; case_result.hpp).
  if (reason.empty())
    if (const EllipseInteraction e = interacting_ellipses(mhr, opt.strips.d_comb); e.found)
      reason = "ellipses " + std::to_string(e.first) + " and " + std::to_string(e.second) + " interact";
  // A corner of the gap the grid methods solve on, inside a patch (hertz_validity.hpp, gap_kink):
  // the test above measures the profiles' sampled curvature at the patch edges, which on a
  // measured flange misses it, and the pressure there is singular (docs/methods.md, auto).
  if (reason.empty() && !mhr.loaded.empty()) {
    const WheelRailGap gap(G, tY);
    for (const auto& L : mhr.loaded) {
      const GapKink k = gap_kink(gap, L.g, L.B, L.s.b, L.s.p0, 0.5 * mat.E_star(), mhr.approach, opt.multi_hertzian.validity);
      if (!k.valid) {
        reason = "ellipse " + std::to_string(L.ellipse) + " " + k.describe(opt.multi_hertzian.validity);
        break;
      }
    }
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
  // A strip answer is kept when it passes its physical checks (contact/grid/grid_checks.hpp: no
  // warning of a validity class). Otherwise (not converged, e.g. a load inside a jump of its
  // N(δ), docs/strips.md, or a strip_outlier, a hole, ...) the exact half-space method, slower
  // but robust, solves the case, and its answer is taken only if it passes the same checks; else
  // the strip row stays, with its status and warnings.
  if (sr.status == CaseStatus::Ok && validity_failures(sr.warnings).empty()) return sr;
  const std::string why = sr.status == CaseStatus::Ok ? "strips failed " + validity_failures(sr.warnings).front()
                                                      : "strips not converged";
  CaseResult hr = solve_half_space(G, mat, tY, Q, opt.half_space, start);
  if (hr.status != CaseStatus::Ok || !validity_failures(hr.warnings).empty()) {
    sr.warnings.push_back("auto:half-space:rejected:" + std::string(to_string(hr.status)) +
                          (validity_failures(hr.warnings).empty() ? "" : ":" + validity_failures(hr.warnings).front()));
    return sr;
  }
  hr.warnings.insert(hr.warnings.begin(), "auto:half-space:" + why);
  hr.warnings.insert(hr.warnings.begin(), "auto:strips:" + reason);
  return hr;
}

}  // namespace

CaseResult solve_contact(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt) {
  CaseResult r;
  switch (opt.method) {
    case Method::Auto: r = solve_auto(G, mat, tY, Q, opt); break;
    case Method::HalfSpace: r = solve_half_space(G, mat, tY, Q, opt.half_space); break;
    case Method::Strips: r = solve_strip_method(G, mat, tY, Q, opt.strips); break;
    case Method::MultiHertzian:
    default: r = solve_multi_hertz(G, mat, tY, Q, opt.multi_hertzian); break;
  }
  // Whether the row can be trusted, by one rule for every method (docs/status.md): auto's rows
  // handed to a grid method are judged by that method's checks, the multi-Hertzian rows it keeps
  // passed the Hertz and interaction tests already.
  judge_validity(r, opt.strips.d_comb);
  return r;
}

void solve_contact(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt,
                   CaseResult& out) {
  if (opt.method != Method::MultiHertzian) {
    out = solve_contact(G, mat, tY, Q, opt);
    return;
  }
  solve_multi_hertz(G, mat, tY, Q, opt.multi_hertzian, out);
  judge_validity(out, opt.strips.d_comb);  // as above
}

}  // namespace mh
