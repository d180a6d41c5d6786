// Equivalent conicity by the EN 15302 integral method; see conicity.hpp.
#include "geometry/conicity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "core/roots.hpp"
#include "core/units.hpp"

namespace mh {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kMaxIterations = 200;
}  // namespace

double en15302_window(double t) { return std::min(0.05, 0.5 * t); }

EquivalentConicity::EquivalentConicity(std::vector<double> y, std::vector<double> dr, const ConicityOptions& opt)
    : y_(std::move(y)), dr_(std::move(dr)), y0_(kNaN), opt_(opt) {
  if (y_.size() < 3 || y_.size() != dr_.size()) throw std::invalid_argument("EquivalentConicity: need >= 3 points (y, delta_r)");
  for (std::size_t k = 1; k < y_.size(); ++k)
    if (!(y_[k] > y_[k - 1])) throw std::invalid_argument("EquivalentConicity: y must increase strictly");
  for (double v : dr_)
    if (!std::isfinite(v)) throw std::invalid_argument("EquivalentConicity: delta_r must be finite");
  per_step_ = static_cast<double>(y_.size() - 1) / (y_.back() - y_.front());
  // S at the table points (trapezoids: exact for Δr linear between points), S(0) = 0 after the
  // shift below (only differences of S enter I).
  S_.assign(y_.size(), 0.0);
  for (std::size_t k = 1; k < y_.size(); ++k) S_[k] = S_[k - 1] + 0.5 * (dr_[k] + dr_[k - 1]) * (y_[k] - y_[k - 1]);
  if (y_.front() <= 0 && y_.back() >= 0) {
    const double s0 = S(0.0);
    for (double& s : S_) s -= s0;
  }
  // Equilibrium: the sign changes of Δr from − (or 0) to +; the minimum of S nearest y = 0.
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k < y_.size(); ++k) {
    if (!(dr_[k - 1] <= 0 && dr_[k] > 0)) continue;
    const double yc = dr_[k - 1] == 0 ? y_[k - 1] : y_[k - 1] + (y_[k] - y_[k - 1]) * (-dr_[k - 1]) / (dr_[k] - dr_[k - 1]);
    if (std::fabs(yc) < std::fabs(best)) best = yc;
  }
  if (std::isfinite(best)) y0_ = best;
}

std::size_t EquivalentConicity::interval(double y) const {
  // From the index the mean spacing gives, to the last point at or below y: the interval that
  // std::upper_bound would find, without its binary search (the integrand asks for it often).
  const std::size_t n = y_.size();
  if (std::isnan(y)) return n - 2;  // as upper_bound: no point is above NaN
  const double t = (y - y_.front()) * per_step_;
  std::size_t k = !(t > 0) ? 0 : t >= static_cast<double>(n - 1) ? n - 1 : static_cast<std::size_t>(t);
  while (k > 0 && !(y_[k] <= y)) --k;
  while (k + 1 < n && y_[k + 1] <= y) ++k;
  const std::size_t upper = y_[k] <= y ? k + 1 : 0;  // the first point above y
  return std::clamp<std::size_t>(upper, 1, n - 1) - 1;  // y in [y_k, y_k+1]
}

double EquivalentConicity::S(double y) const { return S_in(y, interval(y)); }

double EquivalentConicity::S_in(double y, std::size_t k) const {
  const double h = y_[k + 1] - y_[k], t = y - y_[k];
  const double slope = (dr_[k + 1] - dr_[k]) / h;
  return S_[k] + dr_[k] * t + 0.5 * slope * t * t;
}

double EquivalentConicity::S_between(double a, double b) const {
  const std::size_t k = interval(a), kb = interval(b);
  if (kb == k) {
    // ∫_a^b of the linear Δr: (b − a) times Δr at the midpoint.
    const double slope = (dr_[k + 1] - dr_[k]) / (y_[k + 1] - y_[k]);
    return (b - a) * (dr_[k] + slope * (0.5 * (a + b) - y_[k]));
  }
  return S_in(b, kb) - S_in(a, k);
}

ConicityResult EquivalentConicity::at(double A) const {
  ConicityResult r;
  r.amplitude = A;
  r.tan_gamma_e = r.y1 = r.y2 = r.I = kNaN;
  if (std::isnan(y0_)) {
    r.status = "no_centre";
    return r;
  }
  // y2 ∈ [y0, y0 + 2ŷ] (then y1 = y2 − 2ŷ ∈ [y0 − 2ŷ, y0]), inside the table.
  const double l = std::max(y0_, y_.front() + 2 * A), h = std::min(y0_ + 2 * A, y_.back());
  if (!(l <= h)) {
    r.status = "out_of_range";
    return r;
  }
  auto F = [&](double y2) { return S(y2) - S(y2 - 2 * A); };
  const double Fl = F(l), Fh = F(h);
  double y2;
  if (Fl == 0) y2 = l;
  else if (Fh == 0) y2 = h;
  else if (Fl < 0 && Fh > 0) {
    RootTolerance tol;
    tol.abs = opt_.turning_point_tolerance;
    tol.rel = 0;
    tol.max_iterations = kMaxIterations;
    const RootResult s = bracketed_root(F, l, h, Fl, Fh, tol);
    y2 = 0.5 * (s.lo + s.hi);
  } else {
    r.status = "out_of_range";
    return r;
  }
  const double y1 = y2 - 2 * A, m = 0.5 * (y1 + y2);
  r.y1 = y1;
  r.y2 = y2;
  // I = ∫ ŷ cos θ / √(S(y2) − S(m + ŷ sin θ)) dθ over [−π/2, π/2], table interval by table
  // interval: between two rows S is one quadratic, so the integrand is analytic on each piece
  // (its kinks, where the slope of Δr jumps, are the pieces' ends) and Gauss–Kronrod converges on
  // it at once; over the whole range the kinks of a rough measured Δr made the adaptive rule
  // bisect down to them. Each piece meets the relative goal, so I does.
  const std::size_t k1 = interval(y1), k2 = interval(y2);
  const double S2 = S_in(y2, k2), S1 = S_in(y1, k1);
  const double half = units::pi / 2;
  auto slope_of = [&](std::size_t k) { return (dr_[k + 1] - dr_[k]) / (y_[k + 1] - y_[k]); };
  double I = 0;
  // The piece of interval k between θa < θb.
  auto piece = [&](std::size_t k, double ta, double tb) {
    if (!(tb > ta)) return;
    const double sl = slope_of(k);
    auto g = [&](double th) {
      // S(y2) − S(y), with S(y1) = S(y2) (the turning points' definition): from the nearer
      // turning point, so that the difference does not cancel next to it; within the turning
      // point's own interval ∫ of the linear Δr is (b − a) times Δr at the midpoint.
      const double y = std::clamp(m + A * std::sin(th), y1, y2);
      double d;
      if (y >= m) d = k == k2 ? (y2 - y) * (dr_[k] + sl * (0.5 * (y + y2) - y_[k])) : S2 - S_in(y, k);
      else d = k == k1 ? -(y - y1) * (dr_[k] + sl * (0.5 * (y1 + y) - y_[k])) : S1 - S_in(y, k);
      if (!(d > 0)) return 0.0;  // only at θ = ±π/2 to rounding, where the limit is finite and the weight 0
      return A * std::cos(th) / std::sqrt(d);
    };
    // On x ∈ [−1, 1], θ = c + h x: Boost's error test compares the error of the rule on [−1, 1]
    // with the goal times the estimate on [θa, θb], which asks h times the goal of a piece of
    // half-width h; mapped, each piece is held to the relative goal itself.
    const double c = 0.5 * (ta + tb), h = 0.5 * (tb - ta);
    auto gx = [&](double x) { return h * g(c + h * x); };
    I += boost::math::quadrature::gauss_kronrod<double, 15>::integrate(gx, -1.0, 1.0, opt_.quadrature_depth,
                                                                       opt_.quadrature_tolerance);
  };
  double ta = -half;
  for (std::size_t k = k1; k < k2; ++k) {
    // The row y_{k+1} ∈ (y1, y2) ends interval k's piece.
    const double tb = std::asin(std::clamp((y_[k + 1] - m) / A, -1.0, 1.0));
    piece(k, ta, tb);
    ta = std::max(ta, tb);
  }
  piece(k2, ta, half);
  r.I = I;
  r.tan_gamma_e = units::pi * units::pi / (I * I);
  return r;
}

}  // namespace mh
