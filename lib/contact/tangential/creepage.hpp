#pragma once
// Creepages of one wheel–rail contact from the wheelset's motion (docs/method.md §10).
//
// Frame: the pair's frame of method.md §1 (x along the rolling direction, y towards the field side
// of the rail considered, z up) — for a LEFT wheel the track frame itself; for a right wheel its
// mirror image, so the same formulas serve both wheels with every lateral and yaw quantity given
// in the pair's frame (docs/tangential.md: converting from the track frame).
// The contact frame is the pair's frame tilted by the contact angle γ about x: ŝ = (0, cos γ,
// sin γ) in the contact plane towards the field side, n = x̂ × ŝ = (0, −sin γ, cos γ) out of the
// rail into the wheel (Kalker's z, into body 1, the wheel); φ and Mz are about n.
#include "contact/tangential/tangential_types.hpp"

namespace mh {

/// The wheelset's motion of one case, in the pair's frame (SI).
struct Kinematics {
  double V = 0;            ///< [m/s] forward speed (> 0)
  double yaw = 0;          ///< [rad] yaw angle ψ, positive turning x towards the field side (+y)
  double lateral_velocity = 0;  ///< [m/s] ẏ of the wheelset, positive towards the field side
  double yaw_rate = 0;     ///< [rad/s] ψ̇, same sense as ψ
  /// [rad/s] the wheel's rotation rate Ω about its axle (positive: rolling forward); NaN: rolling
  /// at the nominal radius, Ω = V / r0.
  double pitch_rate = NAN;
  /// [rad] the wheel's roll δ against the rail (pair frame, MultiHertzOptions::roll): the axle
  /// turned by δ about x turns the spin's share of Ω to sin(γ − δ). Default 0.
  double roll = 0;
};

/// Where the contact sits on the wheelset (from the contact geometry).
struct ContactKinematicPoint {
  double r_roll = 0;   ///< [m] wheel rolling radius at the contact
  double gamma = 0;    ///< [rad] contact angle (method.md §1)
  /// [m] lateral distance of the contact from the wheelset's centre plane, positive towards the
  /// field side (half the flange-back distance + flange-back offset + y_w: method.md §10).
  double l = 0;
};

/// ξ, η, φ of one contact (docs/method.md §10):
///   ξ = 1 − Ω r / V − ψ̇ l / V,   η = (ẏ / V − ψ) / cos γ,   φ = (ψ̇ cos γ − Ω sin γ) / V,
/// linearised in ψ; Ω = V / r0 unless the pitch rate is given. r0 [m]: the nominal radius.
Creepages creepages_from_kinematics(const Kinematics& k, const ContactKinematicPoint& p, double r0);

}  // namespace mh
