#pragma once
// Equivalent conicity tan γe from the rolling-radius difference Δr(y), by the integral method of
// EN 15302 (the linearised wheelset's kinematic wavelength, Klingel; docs/wheelset.md
// "Equivalent conicity"):
//   S(y) = ∫₀^y Δr(y') dy',
//   I(ŷ) = ∫_{y1}^{y2} dy / √(S(y2) − S(y)),   tan γe = π² / I²,
// where the turning points y1 < y2 of the oscillation of amplitude ŷ = (y2 − y1)/2 have
// S(y1) = S(y2) (for a symmetric pair y1 = −ŷ, y2 = ŷ). Derivation: a wheelset obeying Klingel's
// law y'' = −Δr(y)/(2 b r0) conserves (y')²/2 + S(y)/(2 b r0); its wavelength is
// 2 √(b r0) I(ŷ), the linear wheelset's 2π √(b r0 / tan γ): equal when tan γ = π²/I².
//
// Δr is a table (y_k, Δr_k), linear between its points, so S is exactly piecewise quadratic.
// The end singularities of the integrand (1/√ at both turning points) are removed by
// y = m + ŷ sin θ (m = (y1 + y2)/2), which leaves a bounded integrand on θ ∈ [−π/2, π/2];
// it is integrated by Gauss–Kronrod (Boost.Math) on spans of the table split at rows only (S is
// one quadratic between two rows, the integrand analytic there): a span is accepted when its two
// halves agree with it, else split down to one interval, which the adaptive rule finishes;
// S(y2) − S(y) from the nearer turning point and from the local quadratic where both points
// share a table interval (no cancellation next to y2). The turning
// points come from TOMS 748 (Boost.Math) on S(y2) − S(y2 − 2ŷ) = 0, y2 ∈ [y0, y0 + 2ŷ], with
// y0 the minimum of S (where Δr changes sign from − to +, the one nearest y = 0).
#include <string>
#include <vector>

namespace mh {

/// Options with their documented defaults.
struct ConicityOptions {
  double quadrature_tolerance = 1e-7;   ///< relative error goal of I on each span, so of I (default 1e-7: tan γe to 2e-7 relative)
  unsigned quadrature_depth = 15;       ///< largest bisection depth of the adaptive quadrature on one table interval (default 15)
  /// [m] turning points located to this (default 1e-12 m; tan γe moves by < 1e-9).
  double turning_point_tolerance = 1e-12;
};

struct ConicityResult {
  double amplitude = 0;     ///< [m] ŷ as asked
  double tan_gamma_e = 0;   ///< tan γe (NaN unless status "ok")
  double y1 = 0, y2 = 0;    ///< [m] turning points
  double I = 0;             ///< I(ŷ) (dimensionless)
  /// "ok"; "out_of_range": the turning points lie outside the Δr table; "no_centre": Δr does not
  /// change sign from − to + in the table (no equilibrium position); "no_oscillation": S rises
  /// above S(y2) between the turning points (y1, y2 given), so the wheelset cannot swing between
  /// them: no tan γe at this amplitude.
  std::string status = "ok";
};

/// EN 15302 tolerance window of tan γe: ± min(0.05, 0.5 tan γe).
double en15302_window(double tan_gamma_e);

class EquivalentConicity {
 public:
  /// y [m] strictly increasing (at least 3 points), Δr [m] at those y. Throws std::invalid_argument otherwise.
  EquivalentConicity(std::vector<double> y, std::vector<double> delta_r, const ConicityOptions& opt = {});

  /// tan γe at amplitude ŷ [m] (> 0).
  ConicityResult at(double amplitude) const;

  /// S(y) [m²] (y inside the table).
  double S(double y) const;
  /// [m] the equilibrium position: the minimum of S (NaN when Δr never changes sign − to +).
  double centre() const { return y0_; }

 private:
  std::vector<double> y_, dr_, S_;
  double y0_;
  ConicityOptions opt_;
  double per_step_ = 0;  // [1/m] (n − 1)/(y_n − y_1): the index guess of interval()
  /// k with y in [y_k, y_k+1], clamped to the table's first and last interval.
  std::size_t interval(double y) const;
  /// S(y) with y in table interval k.
  double S_in(double y, std::size_t k) const;
  /// S(b) − S(a), a ≤ b, from the local quadratic when both lie in one interval.
  double S_between(double a, double b) const;
};

}  // namespace mh
