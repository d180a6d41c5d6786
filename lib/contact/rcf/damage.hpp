#pragma once
// Damage and wear of one contact from its frictional energy Tγ (docs/methods.md "Damage and wear
// functions"): the rail RCF damage function of the Whole Life Rail Model (Burstow) and the Sheffield
// (USFD) wear function of an R8T wheel on a UIC60 900A rail (Lewis & Dwyer-Joyce). Both are
// empirical fits with their published constants as documented defaults; every constant is an
// option. Light header (the case-file reader includes it), no state.
//
// Tγ here is the contact's Fx ξ + Fy η [N = J/m] (TangentialResult::Tgamma, forces on the rail,
// ≥ 0 without spin), the quantity the two functions were calibrated on (a vehicle-dynamics
// program's Tγ of the creep forces and creepages); the spin term Mz φ is reported apart and does
// not enter them.
#include <cmath>
#include <string>

namespace mh {

/// The RCF damage function of the Whole Life Rail Model: damage per axle passage (Miner sum, crack
/// initiation at 1) against Tγ: zero below Tgamma_threshold, linear up to damage_peak at
/// Tgamma_peak, linear down to zero at Tgamma_zero (wear removes the initiating cracks), zero
/// above. Burstow, "Whole Life Rail Model application and development for RSSB — continued
/// development of an RCF damage parameter", AEA Technology Rail report AEATR-ES-2004-880 (2004),
/// for RSSB; defaults 15, 65 J/m, 1e-5, 175 J/m as the secondary literature cites that report (the
/// report itself was not available to this project: hence inputs).
/// A variant in public code starts at 20 J/m (2.22e-7 Tγ − 4.44e-6; its falling branch
/// −9.09e-8 Tγ + 1.59e-5 is the same line): set Tgamma_threshold_N = 20 for it.
struct BurstowOptions {
  double Tgamma_threshold_N = 15;   ///< [J/m] no damage below
  double Tgamma_peak_N = 65;        ///< [J/m] damage peak
  double damage_peak = 1e-5;        ///< [-] damage per axle at the peak
  double Tgamma_zero_N = 175;       ///< [J/m] damage zero again (wear dominates) from here on
  /// Empty when 0 ≤ threshold < peak < zero and damage_peak > 0; else which rule is broken.
  std::string invalid() const {
    if (!(Tgamma_threshold_N >= 0 && Tgamma_threshold_N < Tgamma_peak_N && Tgamma_peak_N < Tgamma_zero_N))
      return "needs 0 <= Tgamma_threshold_N < Tgamma_peak_N < Tgamma_zero_N";
    if (!(damage_peak > 0 && std::isfinite(damage_peak))) return "needs damage_peak > 0";
    return {};
  }
};

/// [-] Damage per axle passage at Tγ [N = J/m]; NaN for a NaN Tγ. Negative Tγ (a spin-dominated
/// contact) is below the threshold: 0.
inline double burstow_damage(double Tgamma, const BurstowOptions& o = {}) {
  if (std::isnan(Tgamma)) return NAN;
  if (Tgamma <= o.Tgamma_threshold_N || Tgamma >= o.Tgamma_zero_N) return 0.0;
  if (Tgamma <= o.Tgamma_peak_N)
    return o.damage_peak * (Tgamma - o.Tgamma_threshold_N) / (o.Tgamma_peak_N - o.Tgamma_threshold_N);
  return o.damage_peak * (o.Tgamma_zero_N - Tgamma) / (o.Tgamma_zero_N - o.Tgamma_peak_N);
}

/// The USFD wear function: wear rate w [µg per metre rolled per mm² of contact] against Tγ/A
/// [N/mm²], from twin-disc tests of R8T wheel steel against UIC60 900A rail steel (Lewis &
/// Dwyer-Joyce, "Wear mechanisms and transitions in railway wheel steels", Proc. IMechE Part J 218
/// (2004) 467–478; used for profile evolution in Braghin, Lewis, Dwyer-Joyce & Bruni, "A
/// mathematical model to predict railway wheel profile evolution due to wear", Wear 261 (2006)
/// 1253–1264):
///   mild       w = K1 Tγ/A                 for Tγ/A < x1     (K1 = 5.3, x1 = 10.4)
///   severe     w = K2                      for x1 ≤ Tγ/A ≤ x2 (K2 = 55.0, x2 = 77.2)
///   catastrophic w = K2 + K3 (Tγ/A − x2)    for Tγ/A > x2     (K3 = 61.9)
/// Convention at the second break (the published intercept): the catastrophic line is quoted as
/// 61.9 Tγ/A − 4778.7, which is −0.02 at 77.2, not 55.0: the wear rate would drop from 55 to 0 at
/// the break and regain 55 only at 78.1 N/mm². Here the quoted slope K3 starts from the severe
/// value at x2 (intercept 55.0 − 61.9 × 77.2 = −4723.7), so the function is continuous and never
/// decreasing; above 78.1 N/mm² it is 54.98 µg/(m·mm²) above the quoted line (a shift of
/// 0.9 N/mm² in Tγ/A). At the first break the quoted constants give 55.12 → 55.0 (kept as quoted).
struct UsfdWearOptions {
  double K1 = 5.3;     ///< [µg/(m·mm²) per N/mm²] mild regime slope
  double x1 = 10.4;    ///< [N/mm²] mild → severe
  double K2 = 55.0;    ///< [µg/(m·mm²)] severe regime plateau
  double x2 = 77.2;    ///< [N/mm²] severe → catastrophic
  double K3 = 61.9;    ///< [µg/(m·mm²) per N/mm²] catastrophic regime slope
  std::string invalid() const {
    if (!(K1 > 0 && K2 > 0 && K3 > 0)) return "needs K1, K2, K3 > 0";
    if (!(x1 > 0 && x1 < x2)) return "needs 0 < x1 < x2";
    return {};
  }
};

/// [µg/(m·mm²)] USFD wear rate at Tγ/A given in N/mm² (the published units); NaN for NaN.
/// Negative Tγ/A (spin-dominated contact): the mild line, floored at 0.
inline double usfd_wear_rate_ug_per_m_mm2(double Tgamma_over_A_N_per_mm2, const UsfdWearOptions& o = {}) {
  const double x = Tgamma_over_A_N_per_mm2;
  if (std::isnan(x)) return NAN;
  if (x < o.x1) return o.K1 * std::fmax(x, 0.0);
  if (x <= o.x2) return o.K2;
  return o.K2 + o.K3 * (x - o.x2);
}

/// The wear of one contact: the rate from Tγ [N] over its contact area A [m²], and the mass worn
/// per metre rolled, rate × A. SI: kg/m³ (1 µg/(m·mm²) = 1e-3 kg/m³) and kg/m. NaN unless A > 0.
struct Wear {
  double rate = NAN;        ///< [kg/m³] mass per metre rolled per unit contact area
  double per_metre = NAN;   ///< [kg/m] mass per metre rolled
};
inline Wear usfd_wear(double Tgamma, double A, const UsfdWearOptions& o = {}) {
  Wear w;
  if (!(A > 0) || std::isnan(Tgamma)) return w;
  const double x = (Tgamma / A) * 1e-6;                    // [N/mm²] from [N/m²]
  w.rate = usfd_wear_rate_ug_per_m_mm2(x, o) * 1e-3;      // [kg/m³] from [µg/(m·mm²)]
  w.per_metre = w.rate * A;
  return w;
}

}  // namespace mh
