#pragma once
// One Hertzian ellipse: the Hertz coefficients m, n, ρ of λ = A/B (paper eqs. 1–4; method.md §2)
// and the material. SI throughout (lengths m, curvatures 1/m, forces N, pressures Pa).
//
// The force law of an ellipse built on these coefficients is in ellipse_law.hpp.
#include <cmath>
#include <string>
#include "core/units.hpp"

namespace mh {

/// Identical elastic materials for wheel and rail, plus the limit pressure of the plastic law.
struct Material {
  double E = 210e9;          ///< [Pa] Young's modulus of the wheel, and of the rail unless E_rail is set (default 210 GPa, steel)
  double nu = 0.28;          ///< [-] Poisson's ratio of the wheel, and of the rail unless nu_rail is set, in (0, 0.5) (default 0.28)
  double E_rail = NAN;       ///< [Pa] the rail's Young's modulus when it differs (NaN: same as E)
  double nu_rail = NAN;      ///< [-] the rail's Poisson's ratio when it differs (NaN: same as nu)
  double p_lim = INFINITY;   ///< [Pa] limit pressure of the plastic law (method.md §5); INFINITY = elastic
  double Er() const { return std::isnan(E_rail) ? E : E_rail; }
  double nur() const { return std::isnan(nu_rail) ? nu : nu_rail; }
  /// [Pa] the paper's E/(1−ν²) of eqs. 2–3, 8 for identical bodies; for two materials the value
  /// that gives the same pair compliance: 2 / ((1−ν_w²)/E_w + (1−ν_r²)/E_r). Johnson's composite
  /// modulus of the pair is half of it: E*_J = 1 / ((1−ν_w²)/E_w + (1−ν_r²)/E_r).
  double E_star() const {
    if (std::isnan(E_rail) && std::isnan(nu_rail)) return E / (1 - nu * nu);  // identical bodies
    return 2.0 / ((1 - nu * nu) / E + (1 - nur() * nur()) / Er());
  }
  /// [1/Pa] combined compliance of the half-space solvers (docs/method.md §8):
  /// (1−ν_w²)/(π E_w) + (1−ν_r²)/(π E_r) = 2 / (π E_star).
  double compliance() const { return 2.0 / (units::pi * E_star()); }
  /// Ceres-style check: true when valid; otherwise false and *why names the field, the value and
  /// the rule (E > 0 and finite, 0 < ν < 0.5, p_lim > 0 or INFINITY; the same for the rail's).
  bool valid(std::string* why = nullptr) const;
};

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
/// tests/test_hertz.cpp); outside it hertz_coefficients() falls back to the exact path.
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
/// of m, n, ρ against the exact path over 1e-4 … 1e4, measured by tests/test_hertz.cpp: see
/// kFastPathMaxRelError. About 50 ns a call, no allocation.
HertzCoefficients hertz_coefficients(double lambda);

/// The bound asserted by the fast-path test (the measured worst error is printed by the test).
constexpr double kFastPathMaxRelError = 1e-6;

/// C = [(3/2) N (1−ν²)/E / (A+B)]^(1/3) [m] of eqs. 2–3, with E_star = E/(1−ν²) [Pa], N [N],
/// A, B [1/m].
double hertz_C(double N, double A, double B, double E_star);

}  // namespace mh

