#include "support/hertz_reference.hpp"

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_d.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace mh::testing {

namespace {
constexpr double kPi = 3.14159265358979323846;

// K(e) and D(e) = (K − E)/e² of modulus e = √(1 − g²). D is evaluated directly (boost::math::ellint_d),
// so B/A = (K − D)/(g² D) has no cancellation near the circle (e → 0), where K − E would lose
// e² of its digits. Near the slender limit the modulus itself carries the error (1 − e² = g² is
// known to about 1e-16/g²): the accuracy stated in the header.
void K_D(double g, double* K, double* D) {
  const double e = std::sqrt((1 - g) * (1 + g));
  *K = boost::math::ellint_1(e);
  *D = boost::math::ellint_d(e);
}

// B/A as a function of the axis ratio g = b/a ∈ (0, 1] (A ≤ B): strictly decreasing from +∞ to 1.
double curvature_ratio(double g) {
  double K, D;
  K_D(g, &K, &D);
  return (K - D) / (g * g * D);
}
}  // namespace

double johnson_modulus(double E_1, double nu_1, double E_2, double nu_2) {
  return 1.0 / ((1 - nu_1 * nu_1) / E_1 + (1 - nu_2 * nu_2) / E_2);
}

HertzReference hertz_reference(double A, double B, double N, double E_star_J) {
  if (!(A > 0) || !(B > 0) || !std::isfinite(A) || !std::isfinite(B) || !(N >= 0) || !std::isfinite(N) ||
      !(E_star_J > 0) || !std::isfinite(E_star_J) || !(A / B >= 1e-6 && A / B <= 1e6))
    throw std::invalid_argument("hertz_reference: need A, B > 0 with 1e-6 <= A/B <= 1e6, N >= 0, E*_J > 0 (A = " +
                                std::to_string(A) +
                                ", B = " + std::to_string(B) + ", N = " + std::to_string(N) + ")");
  if (A > B) {  // the major axis along y: solve with the axes swapped
    const HertzReference s = hertz_reference(B, A, N, E_star_J);
    HertzReference r = s;
    r.a = s.b;
    r.b = s.a;
    return r;
  }
  // Axis ratio g from B/A = (K − D)/(g² D): bisection in ln g to the last bit (the ratio falls
  // monotonically from +∞ at g → 0 to 1 at g = 1).
  const double target = B / A;
  double g = 1;
  if (target > 1) {
    double lo = std::log(1e-7), hi = 0;  // ratio(1e-7) ≈ 6e12 > any target allowed
    for (int i = 0; i < 200 && hi - lo > 0; ++i) {
      const double mid = 0.5 * (lo + hi);
      if (mid == lo || mid == hi) break;
      (curvature_ratio(std::exp(mid)) > target ? lo : hi) = mid;
    }
    g = std::exp(0.5 * (lo + hi));
  }
  double K, D;
  K_D(g, &K, &D);
  HertzReference r;
  r.a = std::cbrt(3 * N * D / (2 * kPi * E_star_J * A));
  r.b = g * r.a;
  if (N == 0) return r;
  r.p0 = 3 * N / (2 * kPi * r.a * r.b);
  r.p_mean = N / (kPi * r.a * r.b);
  r.delta = r.p0 * r.b * K / E_star_J;
  return r;
}

}  // namespace mh::testing
