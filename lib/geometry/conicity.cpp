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
/// A maximum of S between the turning points higher than S(y2) by more than this fraction of the
/// well's depth S(y2) − S(y0) is real, not rounding (S is exact to ~1e-16 of its values).
constexpr double kNoOscillation = 1e-9;
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
  // I = ∫ ŷ cos θ / √(S(y2) − S(m + ŷ sin θ)) dθ over [−π/2, π/2], split at table rows only:
  // between two rows S is one quadratic and the integrand analytic; its kinks (where the slope of
  // Δr jumps) lie at the rows. A span of table intervals integrated by Gauss–Kronrod (15 points)
  // is accepted when the sum over its two halves (split at its middle row) agrees with it to the
  // relative goal and each half's own Kronrod–Gauss estimate meets it; else each half is a span
  // again, down to one table interval, which the adaptive rule finishes. (The Kronrod–Gauss
  // difference alone, on nodes that straddle kinks, can miss the goal by a factor 50: two
  // placements of the nodes against the kinks cannot agree by chance.) A smooth Δr is done in a
  // few spans; a rough measured one is not bisected in θ down to its kinks as over the whole
  // range at once. Each span meets the relative goal, so I does.
  const std::size_t k1 = interval(y1), k2 = interval(y2);
  const double S2 = S_in(y2, k2), S1 = S_in(y1, k1);
  // S(y2) − S(y) for y in table interval k, with S(y1) = S(y2) (the turning points' definition):
  // from the nearer turning point, so that the difference does not cancel next to it; within the
  // turning point's own interval ∫ of the linear Δr is (b − a) times Δr at the midpoint.
  auto below_turning = [&](double y, std::size_t k) {
    const double sl = (dr_[k + 1] - dr_[k]) / (y_[k + 1] - y_[k]);
    if (y >= m) return k == k2 ? (y2 - y) * (dr_[k] + sl * (0.5 * (y + y2) - y_[k])) : S2 - S_in(y, k);
    return k == k1 ? -(y - y1) * (dr_[k] + sl * (0.5 * (y1 + y) - y_[k])) : S1 - S_in(y, k);
  };
  // The wheelset swings between y1 and y2 only if S stays below S(y2) between them (the integrand
  // is real): S' = Δr, so S's maxima lie where Δr, linear on each interval, falls through zero.
  // A maximum above the turning level by more than the rounding (kNoOscillation of the well's
  // depth S(y2) − S(y0)) stops the wheelset short of y1 or y2: no oscillation of amplitude ŷ.
  {
    const double depth = S2 - S(y0_);
    for (std::size_t k = k1; k <= k2; ++k) {
      if (!(dr_[k] > 0 && dr_[k + 1] <= 0)) continue;
      const double y = y_[k] + dr_[k] / (dr_[k] - dr_[k + 1]) * (y_[k + 1] - y_[k]);
      if (!(y > y1 && y < y2)) continue;
      if (below_turning(y, k) < -kNoOscillation * depth) {
        r.status = "no_oscillation";
        return r;
      }
    }
  }
  const double half = units::pi / 2, tol = opt_.quadrature_tolerance;
  using GK = boost::math::quadrature::gauss_kronrod<double, 15>;
  // Gauss–Kronrod over θ ∈ [θa, θb], which spans table intervals ka … kb (err: |Kronrod − Gauss|),
  // or with the adaptive rule when it is one table interval.
  auto rule = [&](std::size_t ka, std::size_t kb, double ta, double tb, double* err) -> double {
    if (err) *err = 0;
    if (!(tb > ta)) return 0.0;
    auto g = [&](double th) {
      const double y = std::clamp(m + A * std::sin(th), y1, y2);
      const std::size_t k = ka == kb ? ka : std::clamp(interval(y), ka, kb);
      const double d = below_turning(y, k);
      if (!(d > 0)) return 0.0;  // only at θ = ±π/2 to rounding, where the limit is finite and the weight 0
      return A * std::cos(th) / std::sqrt(d);
    };
    // On x ∈ [−1, 1], θ = c + h x: Boost's error test compares the error of the rule on [−1, 1]
    // with the goal times the estimate on [θa, θb], which would ask h times the goal of a span of
    // half-width h; mapped, each span is held to the relative goal itself.
    const double c = 0.5 * (ta + tb), h = 0.5 * (tb - ta);
    auto gx = [&](double x) { return h * g(c + h * x); };
    return GK::integrate(gx, -1.0, 1.0, ka == kb ? opt_.quadrature_depth : 0u, tol, err);
  };
  auto theta_row = [&](std::size_t j) { return std::asin(std::clamp((y_[j] - m) / A, -1.0, 1.0)); };
  // ∫ over the span ka … kb, θ ∈ [θa, θb], whose rule gave `whole`.
  auto span = [&](auto& self, std::size_t ka, std::size_t kb, double ta, double tb, double whole) -> double {
    if (ka == kb) return rule(ka, kb, ta, tb, nullptr);
    const std::size_t km = ka + (kb - ka + 1) / 2;  // the row between intervals km − 1 and km
    const double tm = std::clamp(theta_row(km), ta, tb);
    double eL = 0, eR = 0;
    const double L = rule(ka, km - 1, ta, tm, &eL), R = rule(km, kb, tm, tb, &eR);
    if (std::fabs(L + R - whole) <= tol * std::fabs(L + R) && eL <= tol * std::fabs(L) && eR <= tol * std::fabs(R))
      return L + R;
    return self(self, ka, km - 1, ta, tm, L) + self(self, km, kb, tm, tb, R);
  };
  const double I = span(span, k1, k2, -half, half, rule(k1, k2, -half, half, nullptr));
  r.I = I;
  r.tan_gamma_e = units::pi * units::pi / (I * I);
  return r;
}

}  // namespace mh
