#include "contact/solve.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "contact/ellipse/hertz_validity.hpp"
#include "contact/judge/judge.hpp"
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
  bool hand_on = true;
  Warning why = Warning::auto_to(Method::Strips, AutoReason::Status);
  if (mhr.status != CaseStatus::Ok) {
    why.status = mhr.status;
  } else if (auto L = std::find_if(mhr.loaded.begin(), mhr.loaded.end(), [](const LoadedEllipse& e) { return !e.validity.valid; });
             L != mhr.loaded.end()) {
    why.reason = AutoReason::NotHertzian;
    why.contact = L->ellipse;
  } else if (has_class(mhr.warnings, WarningClass::NonHertzianExcluded)) {
    why.reason = AutoReason::CandidateExcluded;
  } else if (const EllipseInteraction e = interacting_ellipses(mhr, opt.strips.d_comb); e.found) {
    // Contacts close enough to interact elastically: each ellipse is solved on its own, while the
    // strip method couples them (the gauge-shoulder case of §9; judge.hpp).
    why.reason = AutoReason::Interact;
    why.contact = e.first;
    why.contact2 = e.second;
  } else {
    hand_on = false;
    // A corner of the gap the grid methods solve on, inside a patch (hertz_validity.hpp, gap_kink):
    // the test above measures the profiles' sampled curvature at the patch edges, which on a
    // measured flange misses it, and the pressure there is singular (docs/methods.md, auto).
    if (!mhr.loaded.empty()) {
      const WheelRailGap gap(G, tY);
      for (const auto& L : mhr.loaded) {
        const GapKink k = gap_kink(gap, L.g, L.B, L.s.b, L.s.p0, 0.5 * mat.E_star(), mhr.approach, opt.multi_hertzian.validity);
        if (!k.valid) {
          hand_on = true;
          why.reason = AutoReason::GapKink;
          why.contact = L.ellipse;
          k.add_to(why, opt.multi_hertzian.validity);
          break;
        }
      }
    }
  }
  if (!hand_on) return mhr;
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
  sr.warnings.insert(sr.warnings.begin(), why);
  // A strip answer is kept when it passes its physical checks (contact/grid/grid_checks.hpp: no
  // warning of a validity class). Otherwise (not converged, e.g. a load inside a jump of its
  // N(δ), docs/strips.md, or a strip_outlier, a hole, ...) the exact half-space method, slower
  // but robust, solves the case, and its answer is taken only if it passes the same checks; else
  // the strip row stays, with its status and warnings.
  const std::vector<WarningClass> strip_failed = validity_failures(sr.warnings);
  if (sr.status == CaseStatus::Ok && strip_failed.empty()) return sr;
  Warning to_hs = Warning::auto_to(Method::HalfSpace, AutoReason::StripsNotConverged);
  if (sr.status == CaseStatus::Ok) {
    to_hs.reason = AutoReason::StripsFailed;
    to_hs.failed = strip_failed.front();
  }
  CaseResult hr = solve_half_space(G, mat, tY, Q, opt.half_space, start);
  const std::vector<WarningClass> hs_failed = validity_failures(hr.warnings);
  if (hr.status != CaseStatus::Ok || !hs_failed.empty()) {
    Warning rejected = Warning::auto_to(Method::HalfSpace, AutoReason::HalfSpaceRejected);
    rejected.status = hr.status;
    if (!hs_failed.empty()) {
      rejected.has_failed = true;
      rejected.failed = hs_failed.front();
    }
    sr.warnings.push_back(rejected);
    return sr;
  }
  hr.warnings.insert(hr.warnings.begin(), to_hs);
  hr.warnings.insert(hr.warnings.begin(), why);
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
