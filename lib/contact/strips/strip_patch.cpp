// Semi-Hertzian strip solver with elastic coupling; see strips.hpp. This file is the driver:
// input checks, approach given, and load control (the approach from the force balance,
// docs/method.md §9 "Algorithm" item 5). The strip extents are in strip_extents.cpp, the
// influence of one strip in strip_influence.cpp, the coupled solve at fixed approach (active set,
// plastic cap, result assembly) in strip_collocation.cpp.
//
// Sources:
//  - Johnson, Contact Mechanics (1985) §4.2 (Hertz contact of the equivalent sphere: the
//    starting approach).
#include "contact/strips/strip_patch.hpp"

#include "contact/strips/strip_collocation.hpp"
#include "contact/strips/strip_end_gap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include "core/numfmt.hpp"
#include "core/units.hpp"

namespace mh {

namespace {

constexpr double kPi = units::pi;
using strips_detail::Solver;

bool check_input(const StripGeometry& geo, double H, double p_lim, const StripOptions& opt, std::string* why) {
  std::ostringstream os;
  if (!opt.valid(why)) return false;
  const std::size_t n = geo.s.size();
  if (n == 0 || geo.g.size() != n || geo.A.size() != n || geo.xc.size() != n) {
    os << "geometry: s, g, A, xc must be non-empty and of equal size (sizes " << geo.s.size() << ", "
       << geo.g.size() << ", " << geo.A.size() << ", " << geo.xc.size() << ")";
    *why = os.str();
    return false;
  }
  if (!(geo.ds > 0.0) || !std::isfinite(geo.ds)) {
    os << "geometry.ds = " << geo.ds << ": must be positive and finite";
    *why = os.str();
    return false;
  }
  // Spacing tolerance: relative deviation of s_{i+1} - s_i from ds.
  constexpr double kSpacingRtol = 1e-6;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(geo.s[i]) || !std::isfinite(geo.g[i]) || !std::isfinite(geo.xc[i]) || !(geo.A[i] > 0.0) ||
        !std::isfinite(geo.A[i])) {
      os << "geometry row " << i << ": s, g, xc must be finite and A > 0 (A = " << geo.A[i] << ")";
      *why = os.str();
      return false;
    }
    if (i > 0 && std::fabs(geo.s[i] - geo.s[i - 1] - geo.ds) > kSpacingRtol * geo.ds) {
      os << "geometry.s[" << i << "] - s[" << i - 1 << "] = " << geo.s[i] - geo.s[i - 1]
         << ": must equal ds = " << geo.ds;
      *why = os.str();
      return false;
    }
  }
  if (!(H > 0.0) || !std::isfinite(H)) {
    os << "H = " << H << ": must be positive and finite";
    *why = os.str();
    return false;
  }
  if (!(p_lim > 0.0)) {
    os << "p_lim = " << p_lim << ": must be positive (INFINITY for elastic)";
    *why = os.str();
    return false;
  }
  return true;
}

}  // namespace

std::vector<int> loaded_strips(const StripResult& r) {
  std::vector<int> v;
  loaded_strips(r, v);
  return v;
}

void loaded_strips(const StripResult& r, std::vector<int>& out) {
  out.clear();
  for (const StripState& st : r.strips) out.push_back(st.index);
}

std::vector<StripState> map_strips(const std::vector<StripState>& old, double ds_old,
                                   const std::vector<double>& s_old, const std::vector<double>& s_new) {
  std::vector<StripState> out;
  map_strips(old, ds_old, s_old, s_new, out);
  return out;
}

void map_strips(const std::vector<StripState>& old, double ds_old, const std::vector<double>& s_old,
                const std::vector<double>& s_new, std::vector<StripState>& out) {
  out.clear();
  if (old.empty()) return;
  for (std::size_t j = 0; j < s_old.size() && j < s_new.size(); ++j) {
    const double so = s_old[j];
    auto hi = std::lower_bound(old.begin(), old.end(), so, [](const StripState& a, double v) { return a.s < v; });
    StripState st;
    if (hi == old.begin() || hi == old.end()) {
      const StripState& e = hi == old.begin() ? old.front() : old.back();
      if (!(std::fabs(so - e.s) < ds_old)) continue;
      st = e;
    } else {
      const StripState& a = *(hi - 1);
      const StripState& b = *hi;
      if (b.index != a.index + 1) {  // a gap between bands (two strips wide at least): its tails
        if (so - a.s < ds_old) st = a;
        else if (b.s - so < ds_old) st = b;
        else continue;
      } else {
        const double w = (so - a.s) / (b.s - a.s);
        st = w < 0.5 ? a : b;
        st.a = (1 - w) * a.a + w * b.a;
        st.a_elastic = (1 - w) * a.a_elastic + w * b.a_elastic;
        st.q = (1 - w) * a.q + w * b.q;
        st.plastic = a.plastic && b.plastic;
      }
    }
    st.index = static_cast<int>(j);
    st.s = s_new[j];
    out.push_back(st);
  }
}


StripSolver::StripSolver(const StripGeometry& geo, double H, double p_lim, const StripOptions& opt) {
  reset(geo, H, p_lim, opt);
}

void StripSolver::reset(const StripGeometry& geo, double H, double p_lim, const StripOptions& opt) {
  p_lim_ = p_lim;
  why_.clear();
  if (!check_input(geo, H, p_lim, opt, &why_)) {
    valid_ = false;
    return;
  }
  valid_ = true;
  if (s_ && &s_->geo == &geo) s_->reinit(H, opt);  // the same geometry object, new contents: its memory kept
  else s_ = std::make_unique<Solver>(geo, H, opt);
}

StripSolver::~StripSolver() = default;

namespace {

/// The estimate `r`'s check against the end-gap condition, and the refinement it calls for
/// (StripOptions::end_gap_tol), decided once per patch through `warm`; `r` becomes the refined
/// solution.
void checked(const Solver& S, StripResult& r, bool load_given, double target, double p_lim, StripWarmStart* warm) {
  if (r.status != StripStatus::Ok) return;
  if (warm && warm->end_gap >= 0) {  // decided at this patch's first solve
    r.end_gap_error = warm->end_gap_error;
    if (warm->end_gap == 0) return;
  } else {
    // The error is that of the elastic strips; a capped strip's length follows from its load and
    // its overlap (§9 item 6), and it keeps that length through the refinement.
    r.end_gap_error = end_gap_error(S, r, p_lim);
    const bool refine = r.end_gap_error > S.opt.end_gap_tol;
    if (warm) {
      warm->end_gap = refine ? 1 : 0;
      warm->end_gap_error = r.end_gap_error;
    }
    if (!refine) return;
  }
  const int before = r.iterations;
  const double err = r.end_gap_error;
  StripResult& f = S.scratch.refined;
  refine_extents(S, load_given, target, p_lim, r, f);
  f.iterations += before;
  f.end_gap_error = err;
  f.refined = true;
  r = f;
}

void remember(const StripResult& r, StripWarmStart* warm) {
  if (!warm) return;
  loaded_strips(r, warm->loaded);
  if (r.refined && r.status == StripStatus::Ok) warm->previous = r;
}

}  // namespace

StripResult StripSolver::at_approach(double delta, StripWarmStart* warm) const {
  StripResult r;
  at_approach(delta, warm, r);
  return r;
}

void StripSolver::at_approach(double delta, StripWarmStart* warm, StripResult& r) const {
  if (!valid_ || !std::isfinite(delta)) {
    strips_detail::clear_result(r);
    r.status = StripStatus::InvalidInput;
    r.message = !valid_ ? why_ : "delta must be finite";
    return;
  }
  if (warm && warm->end_gap == 1 && !warm->previous.strips.empty()) {
    refine_extents(*s_, false, delta, p_lim_, warm->previous, r);  // from the last refined extents
    r.refined = true;
    r.end_gap_error = warm->end_gap_error;
  } else {
    s_->evaluate(delta, p_lim_, warm ? &warm->loaded : nullptr, r);
    checked(*s_, r, false, delta, p_lim_, warm);
  }
  remember(r, warm);
}

StripResult solve_strips_approach(const StripGeometry& geo, double H, double delta, double p_lim,
                                  const StripOptions& opt, const std::vector<int>* warm) {
  StripWarmStart w;
  if (warm) w.loaded = *warm;
  return StripSolver(geo, H, p_lim, opt).at_approach(delta, &w);
}

StripResult solve_strips_load(const StripGeometry& geo, double H, double Nt, double p_lim,
                              const StripOptions& opt, const std::vector<int>* warm) {
  StripWarmStart w;
  if (warm) w.loaded = *warm;
  return StripSolver(geo, H, p_lim, opt).at_load(Nt, &w);
}

StripResult StripSolver::at_load(double Nt, StripWarmStart* warm, double delta_start) const {
  StripResult r;
  at_load(Nt, warm, delta_start, r);
  return r;
}

void StripSolver::at_load(double Nt, StripWarmStart* warm, double delta_start, StripResult& r) const {
  if (!valid_ || !(Nt > 0.0) || !std::isfinite(Nt)) {
    strips_detail::clear_result(r);
    r.status = StripStatus::InvalidInput;
    r.message = !valid_ ? why_ : "N must be positive and finite";
    return;
  }
  if (warm && warm->end_gap == 1 && !warm->previous.strips.empty()) {
    StripResult& start = s_->end_gap.start;
    start = warm->previous;
    if (delta_start > s_->gmin && std::isfinite(delta_start)) start.delta = delta_start;
    refine_extents(*s_, true, Nt, p_lim_, start, r);
    r.refined = true;
    r.end_gap_error = warm->end_gap_error;
  } else {
    estimate_at_load(Nt, warm ? &warm->loaded : nullptr, delta_start, r);
    checked(*s_, r, true, Nt, p_lim_, warm);
  }
  remember(r, warm);
}

void StripSolver::estimate_at_load(double Nt, const std::vector<int>* warm_start, double delta_start,
                                   StripResult& out) const {
  const Solver& S = *s_;
  const StripGeometry& geo = S.geo;
  const double H = S.H, p_lim = p_lim_;
  const StripOptions& opt = S.opt;
  // Start: Hertz with the equivalent sphere at the deepest row (Johnson §4.2,
  // R_e = 1/(2 sqrt(A B)), E* = 1/(pi H)): delta = (9 N^2 / (16 R_e E*^2))^(1/3).
  const int i0 = S.imin;
  const double B0 = S.Bloc[i0] > 0.0 ? S.Bloc[i0] : geo.A[i0];
  const double Re = 1.0 / (2.0 * std::sqrt(geo.A[i0] * B0));
  const double Es = 1.0 / (kPi * H);
  double d = S.gmin + std::cbrt(9.0 * Nt * Nt / (16.0 * Re * Es * Es));
  if (delta_start > S.gmin && std::isfinite(delta_start)) d = delta_start;

  // Safeguarded secant on psi(delta) = N^(2/3) - Nt^(2/3), nearly linear in
  // delta for Hertz-like patches (N ~ (delta - gmin)^(3/2)). The bracket
  // starts at [gmin (N = 0), +inf).
  const double psi_t = std::cbrt(Nt * Nt);
  double lo = S.gmin, hi = std::numeric_limits<double>::infinity();
  double d_prev = S.gmin, psi_prev = -psi_t;
  StripResult& best = S.scratch.best;
  strips_detail::clear_result(best);
  best.status = StripStatus::NotConverged;
  std::vector<int>& warm = S.scratch.warm;  // each approach starts its active set from the previous one's
  if (warm_start) warm = *warm_start;
  else warm.clear();
  StripResult& r = out;
  for (int it = 1; it <= opt.max_iterations; ++it) {
    S.evaluate(d, p_lim, &warm, r);
    loaded_strips(r, warm);
    r.iterations = it;
    const double N = (r.status == StripStatus::Ok || r.status == StripStatus::NotConverged) ? r.N : 0.0;
    if (r.status == StripStatus::NotConverged) {
      r.message = "inner solve: " + r.message;
      return;
    }
    const double psi = std::cbrt(N * N) - psi_t;
    if (std::fabs(N - Nt) <= opt.load_rtol * Nt) return;
    if (it == 1 || std::fabs(N - Nt) < std::fabs(best.N - Nt)) best = r;  // closest so far
    if (N < Nt) lo = std::max(lo, d); else hi = std::min(hi, d);
    // Bracket collapsed to adjacent doubles: N(delta) jumps across the target
    // (e.g. the plastic set changes its capping order there).
    if (std::isfinite(hi) && hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * hi) {
      best.status = StripStatus::NotConverged;
      assign_format(best.message, "N(delta) jumps across the target at delta = %g m (closest N = %g N); returned the closest iterate",
                    hi, best.N);
      best.failure = Warning(WarningClass::NotConvergedLoad)
                         .add(Quantity::Residual, (best.N - Nt) / Nt, '>', opt.load_rtol)
                         .add(Quantity::Iterations, it);
      best.iterations = it;
      out = best;
      return;
    }
    double next = std::numeric_limits<double>::quiet_NaN();
    if (psi != psi_prev) next = d - psi * (d - d_prev) / (psi - psi_prev);
    if (!(next > lo && next < hi)) {
      next = std::isfinite(hi) ? 0.5 * (lo + hi) : S.gmin + 2.0 * (d - S.gmin);
    }
    d_prev = d;
    psi_prev = psi;
    d = next;
  }
  best.status = StripStatus::NotConverged;
  best.message = "load not reached within max_iterations; returned the closest iterate";
  best.failure = Warning(WarningClass::NotConvergedLoad)
                     .add(Quantity::Residual, (best.N - Nt) / Nt, '>', opt.load_rtol)
                     .add(Quantity::Iterations, opt.max_iterations);
  best.iterations = opt.max_iterations;
  out = best;
}

}  // namespace mh
