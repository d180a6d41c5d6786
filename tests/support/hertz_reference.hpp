#pragma once
// The closed-form Hertz contact of two elastic bodies, written once for the tests and independent
// of the library (lib/contact/ellipse/hertz.*): every test that checks a solver against Hertz
// takes its reference values from here. SI throughout (curvatures 1/m, forces N, pressures Pa,
// lengths m).
//
// Source: K. L. Johnson, Contact Mechanics, Cambridge University Press, 1985, §3.6 (eqs. 3.69–3.71,
// the ellipsoidal pressure p0 √(1 − x²/a² − y²/b²) on a half-space) and §4.2 (Hertz). Complete
// elliptic integrals from Boost.Math (boost::math::ellint_1 and ellint_d, modulus convention).
// Accuracy: the axis ratio g = b/a is bisected to the last bit and K − E is never formed; what is
// lost is in the modulus e = √(1 − g²), which carries 1 − e² = g² only to about 1e-16/g². Measured
// against the library's Carlson form of hertz.cpp at 64f391c (it works from g² directly): relative
// differences of a, b, p0, δ at most 2e-15 for 0.1 ≤ A/B ≤ 10, 1e-14 at A/B = 1e∓2, 3e-14 at
// 1e∓3, 6e-13 at 1e∓4, 6e-11 at 1e∓6. Defined for 1e-6 ≤ A/B ≤ 1e6.
//
// Notation: Johnson's composite modulus E*_J = 1 / ((1−ν₁²)/E₁ + (1−ν₂²)/E₂). The library's
// Material::E_star() is the paper's E/(1−ν²), twice E*_J for identical bodies (options.hpp).

namespace mh::testing {

/// [Pa] Johnson's composite modulus of two bodies, 1 / ((1−ν₁²)/E₁ + (1−ν₂²)/E₂) (Johnson §4.2,
/// eq. 4.22). E₁, E₂ [Pa], ν₁, ν₂ [-].
double johnson_modulus(double E_1, double nu_1, double E_2, double nu_2);

/// The Hertz contact of the gap A x² + B y² under the normal load N.
struct HertzReference {
  double a = 0;       ///< [m] semi-axis along x (the direction of the curvature sum A)
  double b = 0;       ///< [m] semi-axis along y (the direction of B)
  double p0 = 0;      ///< [Pa] peak pressure, 3N / (2π a b)
  double p_mean = 0;  ///< [Pa] mean pressure, N / (π a b)
  double delta = 0;   ///< [m] approach of distant points of the two bodies (Johnson's δ)
};

/// For A ≤ B the major semi-axis is a (along x); with g = b/a ≤ 1, e² = 1 − g², K = K(e) and
/// D = D(e) = (K − E)/e²:
///     B/A = (K − D) / (g² D)         (Johnson eq. 3.69 with E = K − e² D; solved for g)
///     a³ = 3 N D / (2π E*_J A),  b = g a,  p0 = 3N/(2π a b),  δ = p0 b K / E*_J  (eqs. 3.69–3.71).
/// A = B is the sphere: a = b = (3 N R / (4 E*_J))^(1/3), R = 1/(2A), δ = a²/R (eqs. 4.22–4.23).
/// For A > B the roles of x and y swap. A, B > 0 [1/m] with 1e-6 ≤ A/B ≤ 1e6, N ≥ 0 [N],
/// E_star_J > 0 [Pa] (Johnson's, see johnson_modulus); throws std::invalid_argument otherwise.
HertzReference hertz_reference(double A, double B, double N, double E_star_J);

}  // namespace mh::testing
