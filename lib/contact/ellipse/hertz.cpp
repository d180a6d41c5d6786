// Hertz coefficients m, n, ρ of λ = A/B (method.md §2): the exact path from complete elliptic
// integrals in Carlson form (Boost.Math), and the fast tabulated path.
#include "contact/ellipse/hertz.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>

#include "core/numfmt.hpp"
#include "core/roots.hpp"
#include "core/units.hpp"

namespace mh {


namespace {

using units::pi;

/// Options of the exact solve for g (documented defaults).
struct ExactSolveOptions {
  int max_iterations = 200;              ///< TOMS 748 iterations in ln g (it converges in ~10–20)
  double rel_tolerance = 4 * DBL_EPSILON;  ///< on ln g, relative
  double abs_tolerance = 1e-300;         ///< on ln g, absolute (ln g → 0 as λ → 1)
};

/// Carlson integrals R_F(0, y, 1) = K and R_D(0, y, 1) for y = g² = 1 − e² (complementary
/// parameter): K = R_F, K − E = (e²/3) R_D (DLMF 19.25.1). No modulus round trip.
struct Carlson {
  double RF, RD;
};
Carlson carlson(double y) {
  return {boost::math::ellint_rf(0.0, y, 1.0), boost::math::ellint_rd(0.0, y, 1.0)};
}

/// B/A as a function of g (A ≤ B): (E/g² − K)/(K − E) = (3 R_F/R_D − 1)/g² (the factor e² of
/// E − g²K = e² (R_F − R_D/3) and of K − E cancels analytically). Decreasing from ∞ (g → 0) to 1.
double ratio_of_g(double g) {
  const Carlson c = carlson(g * g);
  return (3.0 * c.RF / c.RD - 1.0) / (g * g);
}

/// ln(B/A)(g) − ln(B/A)_target in t = ln g: decreasing, smooth, with its root at the g of λ.
double root_fn(double t, double log_target) { return std::log(ratio_of_g(std::exp(t))) - log_target; }

/// m, n, ρ for λ ≤ 1 (a is the major axis, m ≥ n).
HertzCoefficients coefficients_le1(double lambda) {
  const ExactSolveOptions opt;
  HertzCoefficients c;
  c.lambda = lambda;
  if (lambda == 1.0) return c;  // circle: exactly 1, 1, 1
  const double log_target = -std::log(lambda);
  auto f = [&](double t) { return root_fn(t, log_target); };
  // Bracket: f(0) = −ln(1/λ) < 0; f decreases with t; step the lower end down until f > 0
  // (B/A ≈ 1/(g² (ln(4/g) − 1)) for small g, so g ≈ √λ is within a few decades).
  double hi = 0.0, f_hi = f(hi);
  if (!(f_hi < 0)) return c;  // λ within rounding of 1
  double lo = 0.5 * std::log(lambda), f_lo = f(lo);
  for (int k = 0; f_lo <= 0; ++k) {
    if (k > 60) throw std::runtime_error("hertz_coefficients_exact: no bracket for lambda = " + format_number(lambda));
    hi = lo;
    f_hi = f_lo;
    lo -= 2.0;
    f_lo = f(lo);
  }
  const RootResult root = bracketed_root(f, lo, hi, f_lo, f_hi, {opt.abs_tolerance, opt.rel_tolerance, opt.max_iterations});
  if (!root.converged)
    throw std::runtime_error("hertz_coefficients_exact: no convergence for lambda = " + format_number(lambda));
  const double t = root.x;
  const double g = std::exp(t);
  if (!(g < 1.0)) return c;
  const double y = g * g;
  const Carlson k = carlson(y);
  const double E = k.RF - (1.0 - y) / 3.0 * k.RD;  // E(e) = R_F − (e²/3) R_D
  c.m = std::cbrt(2.0 * E / (pi * y));            // m³ = 2E/(π g²)
  c.n = c.m * g;                                   // g = b/a = n/m
  c.rho = 2.0 * k.RF / (pi * c.m);                 // ρ = 2K/(π m), m the major coefficient
  return c;
}

HertzCoefficients swapped(const HertzCoefficients& s, double lambda) {
  // λ > 1: m(λ) = n(1/λ), n(λ) = m(1/λ), ρ(λ) = ρ(1/λ) (method.md §2).
  HertzCoefficients c;
  c.lambda = lambda;
  c.m = s.n;
  c.n = s.m;
  c.rho = s.rho;
  return c;
}

void check_lambda(double lambda, double lo, double hi) {
  if (!std::isfinite(lambda) || !(lambda >= lo && lambda <= hi))
    throw std::invalid_argument("lambda = A/B = " + format_number(lambda) + " is outside the supported range [" +
                                format_number(lo) + ", " + format_number(hi) +
                                "] of the Hertz coefficients (extreme ellipticity: not a Hertzian ellipse)");
}

// ---- Fast path ------------------------------------------------------------------------------
// Natural cubic splines of ln m, ln n, ln ρ against x = ln λ on a uniform grid over
// [ln 1e-5, 0.5]. Used on [ln 1e-4, 0] only: the extra decade below and the half unit above
// λ = 1 keep the natural end conditions (wrong second derivatives) away from the used range,
// where their influence has decayed by 0.27 per node (the grid crosses λ = 1 smoothly: the
// coefficients are analytic there, the table values for x > 0 come from the swap).
constexpr double kTableXmin = -11.512925464970229;  // ln 1e-5
constexpr double kTableXmax = 0.5;
constexpr int kTableIntervals = 480;                // step ≈ 0.025 in ln λ
constexpr double kTableStep = (kTableXmax - kTableXmin) / kTableIntervals;

struct SplineTable {
  // Per node: value and second derivative of ln m, ln n, ln ρ.
  std::vector<std::array<double, 3>> y, y2;
  SplineTable() {
    const int n = kTableIntervals + 1;
    y.resize(n);
    y2.assign(n, {0.0, 0.0, 0.0});
    for (int i = 0; i < n; ++i) {
      const double x = (i == n - 1) ? kTableXmax : kTableXmin + kTableStep * i;
      const double lambda = std::exp(x);
      const HertzCoefficients c = lambda <= 1.0 ? coefficients_le1(lambda)
                                                : swapped(coefficients_le1(1.0 / lambda), lambda);
      y[i] = {std::log(c.m), std::log(c.n), std::log(c.rho)};
    }
    // Natural spline on a uniform grid: y2[i-1] + 4 y2[i] + y2[i+1] = 6 (y[i+1] − 2y[i] + y[i-1])/h²,
    // y2[0] = y2[n-1] = 0. Thomas algorithm.
    const double h2 = kTableStep * kTableStep;
    for (int q = 0; q < 3; ++q) {
      std::vector<double> cp(n, 0.0), dp(n, 0.0);
      for (int i = 1; i < n - 1; ++i) {
        const double rhs = 6.0 * (y[i + 1][q] - 2.0 * y[i][q] + y[i - 1][q]) / h2;
        const double denom = 4.0 - cp[i - 1];
        cp[i] = 1.0 / denom;
        dp[i] = (rhs - dp[i - 1]) / denom;
      }
      for (int i = n - 2; i >= 1; --i) y2[i][q] = dp[i] - cp[i] * y2[i + 1][q];
    }
  }
};

const SplineTable& table() {
  static const SplineTable t;  // built once, thread-safe (C++11 static initialisation)
  return t;
}

/// Fast m, n, ρ for x = ln λ in [ln 1e-4, 0].
HertzCoefficients fast_le1(double lambda, double x) {
  const SplineTable& T = table();
  const double s = (x - kTableXmin) / kTableStep;
  std::size_t i = static_cast<std::size_t>(s);
  if (i >= static_cast<std::size_t>(kTableIntervals)) i = kTableIntervals - 1;
  const double t = s - static_cast<double>(i), u = 1.0 - t;
  const double h2_6 = kTableStep * kTableStep / 6.0;
  const double cu = (u * u * u - u) * h2_6, ct = (t * t * t - t) * h2_6;
  double r[3];
  for (int q = 0; q < 3; ++q)
    r[q] = u * T.y[i][q] + t * T.y[i + 1][q] + cu * T.y2[i][q] + ct * T.y2[i + 1][q];
  HertzCoefficients c;
  c.lambda = lambda;
  c.m = std::exp(r[0]);
  c.n = std::exp(r[1]);
  c.rho = std::exp(r[2]);
  return c;
}

}  // namespace

HertzCoefficients hertz_coefficients_exact(double lambda) {
  check_lambda(lambda, kLambdaMinExact, kLambdaMaxExact);
  if (lambda <= 1.0) return coefficients_le1(lambda);
  return swapped(coefficients_le1(1.0 / lambda), lambda);
}

HertzCoefficients hertz_coefficients(double lambda) {
  check_lambda(lambda, kLambdaMinExact, kLambdaMaxExact);
  if (lambda < kLambdaMinFast || lambda > kLambdaMaxFast) return hertz_coefficients_exact(lambda);
  if (lambda == 1.0) return HertzCoefficients{};
  if (lambda < 1.0) return fast_le1(lambda, std::log(lambda));
  return swapped(fast_le1(1.0 / lambda, -std::log(lambda)), lambda);
}

HertzShape hertz_shape(double A, double B) {
  const double lambda = std::min(std::max(A / B, kLambdaMinExact), kLambdaMaxExact);
  const HertzCoefficients c = hertz_coefficients(lambda);
  const double s = 1.0 / std::sqrt(c.rho * (A + B));
  return {c.m * s, c.n * s};
}

double hertz_C(double N, double A, double B, double E_star) {
  return std::cbrt(1.5 * N / E_star / (A + B));  // (eqs. 2–3)
}

}  // namespace mh
