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

/// Exact coefficients from complete elliptic integrals (GSL). For A ≤ B (λ ≤ 1; a is the major
/// semi-axis) let g = b/a ≤ 1 and e² = 1 − g² (e the modulus, K = K(e), E = E(e)):
///     B/A = (E/g² − K)/(K − E),   m = (2E/(π g²))^(1/3),   n = m g,   ρ = 2K/(π m)
/// (Johnson, Contact Mechanics, 1985, §4.2, rewritten with C). g is solved for with a
/// bracketed Brent iteration in ln g. K and E are evaluated in Carlson form from g² directly,
/// K = R_F(0, g², 1), K − E = (e²/3) R_D(0, g², 1), so that B/A = (3 R_F/R_D − 1)/g² has no
/// cancellation near λ = 1 nor near g → 0 (the modulus e = √(1−g²) would lose digits there).
/// For λ > 1 the roles of the axes swap: m(λ) = n(1/λ), n(λ) = m(1/λ), and ρ(λ) = ρ(1/λ), i.e.
/// ρ = 2K/(π · major coefficient): the approach does not depend on which axis is called x.
/// Exactly m = n = ρ = 1 at λ = 1. Throws std::invalid_argument for λ not finite or outside
/// [kLambdaMinExact, kLambdaMaxExact], std::runtime_error if GSL reports an error.
HertzCoefficients hertz_coefficients_exact(double lambda);

/// Fast path: natural cubic spline of ln m, ln n, ln ρ against ln λ on a uniform table over
/// λ ∈ [1e-5, e^0.5] built once (thread-safe) from the exact path, used for λ ∈ [1e-4, 1] and,
/// through the exact swap symmetry above, for λ ∈ (1, 1e4]. Outside [kLambdaMinFast,
/// kLambdaMaxFast] it falls back to hertz_coefficients_exact() (no clamping). Worst relative error
/// of m, n, ρ against the exact path over 1e-4 … 1e4, measured by tests/unit/contact/test_hertz.cpp: see
/// kFastPathMaxRelError. About 50 ns a call, no allocation.
HertzCoefficients hertz_coefficients(double lambda);

/// The bound asserted by the fast-path test (the measured worst error is printed by the test).
constexpr double kFastPathMaxRelError = 1e-6;

/// C = [(3/2) N (1−ν²)/E / (A+B)]^(1/3) [m] of eqs. 2–3, with E_star = E/(1−ν²) [Pa], N [N],
/// A, B [1/m].
double hertz_C(double N, double A, double B, double E_star);

}  // namespace mh

