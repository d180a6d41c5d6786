#pragma once
// One Hertzian ellipse: the Hertz coefficients m, n, ρ of λ = A/B (paper eqs. 1–4; method.md §2)
// and the material. SI throughout (lengths m, curvatures 1/m, forces N, pressures Pa).
//
// The force law of an ellipse built on these coefficients is in ellipse_law.hpp.
#include <cmath>
#include <string>
#include "contact/options.hpp"
#include "core/units.hpp"

namespace mh {


/// Hertz coefficients of λ = A/B (method.md §2): semi-axes a = m C (along x), b = n C (along y),
/// true approach δ = ρ C² (A+B), with C = [(3/2) N (1−ν²)/E / (A+B)]^(1/3) (eqs. 2–3).
struct HertzCoefficients {
  double lambda = 1;  ///< [-] A/B
  double m = 1;       ///< [-] a / C (eq. 2)
  double n = 1;       ///< [-] b / C (eq. 3)
  double rho = 1;     ///< [-] δ / (C² (A+B)); symmetric: ρ(λ) = ρ(1/λ)
};

/// Supported range of λ for hertz_coefficients_exact() (aspect ratio b/a from ~3e-6 to ~3e5);
/// outside it std::invalid_argument. Far beyond any Hertzian wheel–rail contact.
constexpr double kLambdaMinExact = 1e-10;
constexpr double kLambdaMaxExact = 1e10;
/// Range where the fast path interpolates its table (its accuracy is measured over this range by
/// tests/unit/contact/test_hertz.cpp); outside it hertz_coefficients() falls back to the exact path.
constexpr double kLambdaMinFast = 1e-4;
constexpr double kLambdaMaxFast = 1e4;

/// Exact coefficients from complete elliptic integrals (Boost.Math). For A ≤ B (λ ≤ 1; a is the major
/// semi-axis) let g = b/a ≤ 1 and e² = 1 − g² (e the modulus, K = K(e), E = E(e)):
///     B/A = (E/g² − K)/(K − E),   m = (2E/(π g²))^(1/3),   n = m g,   ρ = 2K/(π m)
/// (Johnson, Contact Mechanics, 1985, §4.2, rewritten with C). g is solved for with a
/// bracketed TOMS 748 iteration in ln g (core/roots.hpp). K and E are evaluated in Carlson form from g² directly,
/// K = R_F(0, g², 1), K − E = (e²/3) R_D(0, g², 1), so that B/A = (3 R_F/R_D − 1)/g² has no
/// cancellation near λ = 1 nor near g → 0 (the modulus e = √(1−g²) would lose digits there).
/// For λ > 1 the roles of the axes swap: m(λ) = n(1/λ), n(λ) = m(1/λ), and ρ(λ) = ρ(1/λ), i.e.
/// ρ = 2K/(π · major coefficient): the approach does not depend on which axis is called x.
/// Exactly m = n = ρ = 1 at λ = 1. Throws std::invalid_argument for λ not finite or outside
/// [kLambdaMinExact, kLambdaMaxExact], std::runtime_error if the solve for g fails (never seen).
HertzCoefficients hertz_coefficients_exact(double lambda);

/// Fast path: natural cubic spline of ln m, ln n, ln ρ against ln λ on a uniform table over
/// λ ∈ [1e-5, e^0.5] built once (thread-safe) from the exact path, used for λ ∈ [1e-4, 1] and,
/// through the exact swap symmetry above, for λ ∈ (1, 1e4]. Outside [kLambdaMinFast,
/// kLambdaMaxFast] it falls back to hertz_coefficients_exact() (no clamping). Worst relative error
/// of m, n, ρ against the exact path over 1e-4 … 1e4, measured by tests/unit/contact/test_hertz.cpp: see
/// kFastPathMaxRelError. About 50 ns a call, no allocation.
HertzCoefficients hertz_coefficients(double lambda);

/// The bound asserted by the fast-path test (the measured worst error is printed by the test).
constexpr double kFastPathMaxRelError = 2e-10;  // measured 4.7e-11 (at λ = 1.013)

/// The curvature sums of eq. 1 [1/m]: A = 1/(2 R_wyy) + k_ryy/2 along x (the rolling direction;
/// k_ryy = 1/R_ryy is the roller's curvature on a roller rig, 0 for a straight rail) and
/// B = (k_wxx + k_rxx)/2 across (the profiles' curvatures, 1/R_wxx and 1/R_rxx). R_wyy [m] is the
/// wheel's rolling radius at the contact point.
struct CurvatureSums {
  double A = 0;  ///< [1/m]
  double B = 0;  ///< [1/m]
};
inline CurvatureSums curvature_sums(double R_wyy, double k_ryy, double k_wxx, double k_rxx) {
  return {1.0 / (2.0 * R_wyy) + 0.5 * k_ryy, 0.5 * (k_wxx + k_rxx)};  // (eq. 1)
}

/// The shape of the Hertz contact of the gap h = A x² + B y² (A, B > 0) at approach δ, per √δ:
/// a = ka √δ along x, b = kb √δ along y. From δ = ρ C² (A+B), a = m C, b = n C (eqs. 2–4):
/// ka = m / √(ρ (A+B)), kb = n / √(ρ (A+B)); independent of the elastic constants (Johnson,
/// Contact Mechanics, §4.2). λ = A/B outside [kLambdaMinExact, kLambdaMaxExact] is clamped to
/// that range (an ellipse more than 3e5 times longer than wide: the strip solver's extent
/// estimates ask for such shapes on strips whose lateral curvature is nearly zero).
struct HertzShape {
  double ka = 0;  ///< [m^(1/2)] a / √δ
  double kb = 0;  ///< [m^(1/2)] b / √δ
};
HertzShape hertz_shape(double A, double B);

/// C = [(3/2) N (1−ν²)/E / (A+B)]^(1/3) [m] of eqs. 2–3, with E_star = E/(1−ν²) [Pa], N [N],
/// A, B [1/m].
double hertz_C(double N, double A, double B, double E_star);

}  // namespace mh

