#pragma once
// The project's one home for root finding in one variable: every solver that looks for a root
// calls these, never a loop of its own. The first three wrap Boost.Math (header-only, Boost licence):
//  - bracketed_root: TOMS 748 (Alefeld, Potra & Shi, ACM TOMS 21 (1995) 327–344;
//    boost::math::tools::toms748_solve), for a continuous f with a sign change in [lo, hi];
//  - newton_root: Newton–Raphson kept inside a bracket, with bisection where a step would leave it
//    (boost::math::tools::newton_raphson_iterate), for a monotone f whose derivative is at hand;
//  - bisected_root: plain bisection (boost::math::tools::bisect), where the root of interest is
//    the one bisection finds among several in the bracket (it keeps the same one whatever f's
//    shape between them), or where f may be discontinuous;
//  - newton_polish: a few plain Newton steps from an explicit approximation of the root, for an
//    increasing convex f (the closed-form inverses of the force laws).
// All stop on whichever comes first: the bracket (or step) below abs + rel·|x|, or |f| ≤ f_abs.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include <boost/math/policies/policy.hpp>
#include <boost/math/tools/roots.hpp>
#include <boost/math/tools/toms748_solve.hpp>

namespace mh {

/// When a root is found (documented defaults).
struct RootTolerance {
  double abs = 0;                  ///< on x, absolute (default 0)
  double rel = 4 * DBL_EPSILON;    ///< on x, relative to the smaller end of the bracket (default 4 ε)
  int max_iterations = 100;        ///< iterations (default 100)
  double f_abs = 0;                ///< |f| at or below this is a root (default 0: only an exact zero)
};

struct RootResult {
  double x = NAN;        ///< the root: of the points evaluated, the one with the smallest |f|
  double f = NAN;        ///< f(x)
  int iterations = 0;    ///< evaluations of f (beyond the two bracket ends given)
  bool converged = false;  ///< a tolerance of RootTolerance was met within max_iterations
  /// The last bracket [lo, hi] (bracketed_root, bisected_root): its midpoint is the root where a
  /// caller wants the bracket's centre rather than the best point evaluated.
  double lo = NAN, hi = NAN;
};

namespace roots_detail {
// No error is thrown through the solvers: a bracket without a sign change gives the better end,
// not converged; too many iterations give the best point, not converged.
using Policy = boost::math::policies::policy<boost::math::policies::domain_error<boost::math::policies::ignore_error>,
                                            boost::math::policies::evaluation_error<boost::math::policies::ignore_error>>;
}  // namespace roots_detail

/// A root of f in [lo, hi], with f_lo = f(lo) and f_hi = f(hi) of opposite signs (or one zero).
template <class F>
RootResult bracketed_root(F&& f, double lo, double hi, double f_lo, double f_hi, const RootTolerance& tol = {}) {
  RootResult r;
  auto keep = [&r](double x, double fx) {
    if (!(std::fabs(fx) >= std::fabs(r.f))) { r.x = x; r.f = fx; }
  };
  keep(lo, f_lo);
  keep(hi, f_hi);
  if (std::fabs(r.f) <= tol.f_abs) { r.converged = true; r.lo = r.hi = r.x; return r; }
  auto g = [&](double x) {
    const double fx = f(x);
    ++r.iterations;
    keep(x, fx);
    return fx;
  };
  auto done = [&](double a, double b) {
    return std::fabs(r.f) <= tol.f_abs || std::fabs(b - a) <= tol.abs + tol.rel * std::min(std::fabs(a), std::fabs(b));
  };
  std::uintmax_t n = static_cast<std::uintmax_t>(std::max(tol.max_iterations, 1));
  const std::pair<double, double> ab = boost::math::tools::toms748_solve(g, lo, hi, f_lo, f_hi, done, n, roots_detail::Policy());
  r.converged = done(ab.first, ab.second) || r.f == 0;
  r.lo = ab.first;
  r.hi = ab.second;
  return r;
}

/// A root of f in [lo, hi] (f(lo), f(hi) of opposite signs) by bisection, to a bracket narrower
/// than tol.abs + tol.rel·min(|lo|, |hi|) or tol.max_iterations halvings; x is the bracket's
/// midpoint (f is not evaluated there).
template <class F>
RootResult bisected_root(F&& f, double lo, double hi, const RootTolerance& tol = {}) {
  RootResult r;
  auto done = [&](double a, double b) { return std::fabs(b - a) <= tol.abs + tol.rel * std::min(std::fabs(a), std::fabs(b)); };
  auto g = [&](double x) {
    ++r.iterations;
    return f(x);
  };
  std::uintmax_t n = static_cast<std::uintmax_t>(std::max(tol.max_iterations, 1)) + 3;  // + Boost's 3 at the ends
  const std::pair<double, double> ab = boost::math::tools::bisect(g, lo, hi, done, n, roots_detail::Policy());
  r.x = 0.5 * (ab.first + ab.second);
  r.converged = done(ab.first, ab.second);
  r.lo = ab.first;
  r.hi = ab.second;
  return r;
}

/// A root of f in [lo, hi] by Newton's method from `guess`, for f monotone in [lo, hi] with a
/// root inside; f_df(x) returns {f(x), f'(x)}. Steps that would leave the bracket bisect it.
/// x is the best point evaluated (smallest |f|).
template <class F>
RootResult newton_root(F&& f_df, double guess, double lo, double hi, const RootTolerance& tol = {}) {
  RootResult r;
  auto g = [&](double x) {
    const std::pair<double, double> v = f_df(x);
    ++r.iterations;
    if (!(std::fabs(v.first) >= std::fabs(r.f))) { r.x = x; r.f = v.first; }
    // A root to f_abs: report a zero so that the iteration stops here (Boost stops on f = 0).
    if (std::fabs(v.first) <= tol.f_abs) return std::pair<double, double>(0.0, v.second);
    return v;
  };
  // Digits of x asked of Boost: from the relative tolerance (at most double's 53).
  const int digits = std::min(std::numeric_limits<double>::digits,
                              static_cast<int>(std::ceil(-std::log2(std::max(tol.rel, DBL_EPSILON)))) + 1);
  std::uintmax_t n = static_cast<std::uintmax_t>(std::max(tol.max_iterations, 1));
  // Boost returns one step beyond its last evaluation; the result is the best point evaluated,
  // so that x and f belong together (a caller builds its solution at x).
  (void)boost::math::tools::newton_raphson_iterate(g, guess, lo, hi, digits, n);
  r.converged = std::fabs(r.f) <= tol.f_abs || n < static_cast<std::uintmax_t>(tol.max_iterations);
  return r;
}

/// Newton's method from a guess already close to a simple root (an explicit approximation of it),
/// for f increasing and convex on [lo, hi] with the root inside; f_df(x) returns {f(x), f'(x)}.
/// For such an f every step after the first lands at or above the root and descends to it, so
/// clamping the iterates to [lo, hi] is the only safeguard needed. Converged when a step is at
/// most tol.abs + tol.rel·|x| (x is then the iterate after that step, f the value before it) or
/// |f| ≤ tol.f_abs (x the point evaluated); otherwise it stops after tol.max_iterations
/// evaluations, or where f' ≤ 0, not converged. Without
/// newton_root's set-up (Boost's digit count, bracket bookkeeping): for closed-form inverses
/// whose guess is so good that one or two steps reach machine precision.
template <class F>
RootResult newton_polish(F&& f_df, double guess, double lo, double hi, const RootTolerance& tol = {}) {
  RootResult r;
  double x = std::min(std::max(guess, lo), hi);
  while (r.iterations < tol.max_iterations) {
    const std::pair<double, double> v = f_df(x);
    ++r.iterations;
    r.f = v.first;
    if (std::fabs(v.first) <= tol.f_abs) {
      r.converged = true;
      break;
    }
    if (!(v.second > 0)) break;  // not increasing here: not the function this is for
    const double step = v.first / v.second;
    const double next = std::min(std::max(x - step, lo), hi);
    const bool small = std::fabs(step) <= tol.abs + tol.rel * std::fabs(next);  // unclamped: a root beyond lo or hi is not one
    x = next;
    if (small) {
      r.converged = true;
      break;
    }
  }
  r.x = x;
  return r;
}

}  // namespace mh
