#pragma once
// The pair-level plausibility check of a wheel placed by gauge positioning (docs/case-file.md,
// docs/profiles.md "Placement check"): before any case is solved, the main contact at t_Y = 0
// must lie on the tread of both profiles. A wheel whose taping line was not found (a measured
// file whose origin is its flange back), a mirrored profile or wrong track data put the flange
// tip or the rim on the rail crown: every case would be solved, confidently and wrongly.
#include <string>

#include "geometry/contact_geometry.hpp"

namespace mh {

/// Limits of the placement check. A contact on the tread of both profiles at t_Y = 0 has a small
/// contact angle (S1002 on 60E1 at 1:40: 1.4 deg; the flange root starts near 10 deg) and a
/// rolling radius near the nominal one (the S1002 tread from the flange root to the field-side
/// end lies within 2.7 mm of the taping line's radius; the flange tip 28 mm, a rim 60 mm beyond).
struct PlacementLimits {
  static constexpr double kMaxContactAngle_deg = 10.0;   ///< |γ| of the main contact at t_Y = 0
  static constexpr double kMaxRadiusDeviation_mm = 5.0;  ///< |r_roll − nominal radius| there
};

/// The main contact at t_Y = 0 and whether it lies on the tread of both profiles. The rules, in
/// order: the wheel profile holds its origin y = 0 (the taping line, where the nominal radius
/// is); |γ| ≤ kMaxContactAngle_deg; |r_roll − R0| ≤ kMaxRadiusDeviation_mm; the contact lies
/// inside both profiles' measured ranges (not off_profile).
struct PlacementCheck {
  bool found = false;        ///< the profiles overlap at t_Y = 0
  CandidateGeom main;        ///< the main contact there (valid when found)
  double nominal_radius = 0; ///< [m]
  bool ok = false;
  std::string why;           ///< which rule failed, with the numbers (empty when ok)
  std::string numbers;       ///< "contact at rail y ... mm, wheel y ... mm, angle ... deg, rolling radius ... mm (nominal ...)"
};

/// Evaluate the check on a geometry whose profiles, strips and offset are set (build_geometry
/// calls it before the t_Y grid is built). Never throws.
PlacementCheck check_placement(const ContactGeometry& G);

}  // namespace mh
