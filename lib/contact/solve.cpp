#include "contact/solve.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "contact/ellipse/hertz_validity.hpp"
#include "contact/judge/judge.hpp"
#include "contact/half_space/tangential_patch.hpp"
#include "contact/tangential/tangential_solve.hpp"
#include "geometry/gap.hpp"

namespace mh {

namespace {

// The half-space options of a solve: with friction the patch grids' pressures are kept, the
// tangential step solves on them (solve_tangential_patches).
HalfSpaceOptions half_space_options(const MethodOptions& opt) {
  HalfSpaceOptions o = opt.half_space;
  o.keep_pressure = o.keep_pressure || opt.tangential.enabled();
  return o;
}

// The tangential problem of a solved row (docs/tangential.md): creepages of every contact,
// FASTSIM per ellipse, the exact solution per half-space patch, the case sums.
void tangential_step(CaseResult& r, const Material& mat, double tY, const MethodOptions& opt) {
  solve_tangential(r, mat, tY, opt.tangential);
  solve_tangential_patches(r, mat, opt.tangential.mu);
}

// "auto" (docs/method.md §9): the multi-Hertzian answer is kept when it can be trusted — it
// converged and every loaded ellipse passes the Hertz validity test, with no non-Hertzian
// candidate excluded; otherwise the case is solved by the strip method. The `method` column says
// which one solved it, and a case handed over carries the warning auto:strips:<reason>.
CaseResult solve_auto(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt) {
  CaseResult mhr = solve_multi_hertz(G, mat, tY, Q, opt.multi_hertzian);
  if (mhr.status == CaseStatus::OutOfRange) return mhr;
  // The judge's tests on the multi-Hertzian answer (judge.hpp): the Hertz validity of each
  // ellipse, an excluded non-Hertzian candidate, interacting ellipses, a corner of the gap inside
  // a patch (hertz_validity.hpp, gap_kink: the edge-gap test measures the profiles' sampled
  // curvature at the patch edges, which on a measured flange misses it, and the pressure there is
  // singular; docs/methods.md, auto). The first failure, in that order, is the reason given.
  add_validity_warnings(mhr, G, mat, tY, opt);
  bool hand_on = true;
  Warning why = Warning::auto_to(Method::Strips, AutoReason::Status);
  auto first = [&](WarningClass c) {
    return std::find_if(mhr.warnings.begin(), mhr.warnings.end(), [c](const Warning& w) { return w.cls == c; });
  };
  if (mhr.status != CaseStatus::Ok) {
    why.status = mhr.status;
  } else if (auto w = first(WarningClass::NonHertzian); w != mhr.warnings.end()) {
    why.contact = w->contact;
    // The gap-corner test runs only on rows that passed the others: its warning is alone.
    if (w->n == 1 && w->m[0].q == Quantity::GapKink) {
      why.reason = AutoReason::GapKink;
      why.add(Quantity::GapKink, w->m[0].value, w->m[0].rel, w->m[0].limit);
    } else {
      why.reason = AutoReason::NotHertzian;
    }
  } else if (first(WarningClass::NonHertzianExcluded) != mhr.warnings.end()) {
    why.reason = AutoReason::CandidateExcluded;
  } else if (auto i = first(WarningClass::Interacting); i != mhr.warnings.end()) {
    // Contacts close enough to interact elastically: each ellipse is solved on its own, while the
    // strip method couples them (the gauge-shoulder case of §9; judge.hpp).
    why.reason = AutoReason::Interact;
    why.contact = i->contact;
    why.contact2 = i->contact2;
  } else {
    hand_on = false;
  }
  if (!hand_on) {
    tangential_step(mhr, mat, tY, opt);  // before Y/Q: Y includes the creep forces
    add_vehicle_state_warnings(mhr, G);
    decide_status(mhr);
    return mhr;
  }
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
  if (sr.status == CaseStatus::Ok && strip_failed.empty()) return sr;  // judged by solve_contact
  Warning to_hs = Warning::auto_to(Method::HalfSpace, AutoReason::StripsNotConverged);
  if (sr.status == CaseStatus::Ok) {
    to_hs.reason = AutoReason::StripsFailed;
    to_hs.failed = strip_failed.front();
  }
  CaseResult hr = solve_half_space(G, mat, tY, Q, half_space_options(opt), start);
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
    case Method::HalfSpace: r = solve_half_space(G, mat, tY, Q, half_space_options(opt)); break;
    case Method::Strips: r = solve_strip_method(G, mat, tY, Q, opt.strips); break;
    case Method::MultiHertzian:
    default: r = solve_multi_hertz(G, mat, tY, Q, opt.multi_hertzian); break;
  }
  // Whether the row can be trusted, by one judge for every method (judge.hpp, docs/status.md).
  // auto's multi-Hertzian rows were judged already (their tests decided whether to keep them);
  // the grid rows it hands back are judged here like any other.
  if (opt.method != Method::Auto || r.method != Method::MultiHertzian) {
    tangential_step(r, mat, tY, opt);
    judge_case(r, G, mat, tY, opt);
  }
  return r;
}

void solve_contact(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt,
                   CaseResult& out) {
  solve_contact(G, mat, tY, Q, opt, out, nullptr);
}

void solve_contact(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt,
                   CaseResult& out, GridWorkspace* ws) {
  switch (opt.method) {
    case Method::MultiHertzian: solve_multi_hertz(G, mat, tY, Q, opt.multi_hertzian, out); break;
    case Method::HalfSpace:
      if (!ws) {
        out = solve_contact(G, mat, tY, Q, opt);
        return;
      }
      solve_half_space(G, mat, tY, Q, half_space_options(opt), ws->half_space, out);
      break;
    case Method::Strips:
      if (!ws) {
        out = solve_contact(G, mat, tY, Q, opt);
        return;
      }
      solve_strip_method(G, mat, tY, Q, opt.strips, ws->strips, out);
      break;
    default: out = solve_contact(G, mat, tY, Q, opt); return;
  }
  tangential_step(out, mat, tY, opt);
  judge_case(out, G, mat, tY, opt);  // as above
}

}  // namespace mh
