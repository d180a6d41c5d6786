#pragma once
// The pair-level plausibility check of a wheel placed by gauge positioning (docs/case-file.md,
// docs/profiles.md "Placement check"): before any case is solved, the placement itself is judged
// (the taping line, the flange against the rail's gauge point), not the contact it produces. The
// misplacements it was made for are tens of millimetres: a wheel whose taping line was not found
// (a measured file whose origin is its flange back or its flange tip), a mirrored profile, wrong
// track data put the flange on the rail head or far inside the track, and every case would be
// solved, confidently and wrongly. A correctly placed wheel whose centred contact lies on its
// flange root (a thick worn flange, a tight gauge) is a placement, not a misplacement.
#include <string>

#include "geometry/contact_geometry.hpp"

namespace mh {

/// Limits of the placement check. The flange clearance is measured at t_Y = 0, the wheel standing
/// on the rail, at the height of the rail's gauge point (gauge_height below its top): the lateral
/// distance from the rail's gauge point to the wheel's flange flank facing it, positive when the
/// flange is inside the track. S1002 on 60E1 at 1:40, standard track: 6.6 mm; a thick flange
/// (Sd 36.4 mm): 2.7 mm. The largest a placed wheelset shows: a thin flange (Sd 22 mm, EN 15313:
/// +10.5 mm) in a widened gauge (1470 mm: +17.5 mm per rail), about 35 mm.
struct PlacementLimits {
  static constexpr double kMaxFlangeClearance_mm = 40.0;  ///< flange clearance above this: the
                                                           ///< wheel stands tens of mm inside the track
};

/// The placement at t_Y = 0 and whether it is plausible. The rules, in order (docs/profiles.md):
///  1. the wheel profile holds its origin y = 0 (the taping line, where the nominal radius is);
///  2. its flange (a lowest point at least flange_min_height below the taping line) lies on the
///     gauge side (y < 0): a flange on the field side is a mirrored profile;
///  3. a wheel with a flange has the flange inside the track: its tip reaches below the rail's
///     gauge point, and the flange clearance there is at most kMaxFlangeClearance_mm;
///  4. the main contact at t_Y = 0 lies inside both profiles' measured ranges (not off_profile).
/// The contact angle and rolling radius at t_Y = 0 are reported, not judged.
struct PlacementCheck {
  bool found = false;        ///< the profiles overlap at t_Y = 0
  CandidateGeom main;        ///< the main contact there (valid when found)
  double nominal_radius = 0; ///< [m]
  double lateral_offset = 0; ///< [m] rail y of the wheel's origin at t_Y = 0 (ContactGeometry::y_offset):
                             ///< the track.lateral_offset_mm of explicit positioning that reproduces it
  bool flange_measured = false;  ///< the flange reaches the gauge point's height (clearance below)
  double flange_clearance = 0;   ///< [m] rule 3's clearance (when flange_measured)
  bool ok = false;
  std::string why;           ///< which rule failed, with the numbers (empty when ok)
  std::string numbers;       ///< "contact at rail y ... mm, ..., flange clearance ... mm at the gauge point"
  /// The explicit placement that reproduces this one, to copy into a case file:
  /// "\"positioning\": \"explicit\", \"lateral_offset_mm\": -3.4".
  std::string explicit_placement() const;
};

/// Evaluate the check on a geometry whose profiles, strips, offset and rail gauge point are set
/// (build_geometry calls it before the t_Y grid is built); rail_gauge_z [m] is the height of the
/// rail's gauge point (RailLandmarks::z_gauge), flange_min_height GeometryOptions'. Never throws.
PlacementCheck check_placement(const ContactGeometry& G, double rail_gauge_z,
                               double flange_min_height = GeometryOptions{}.flange_min_height);

}  // namespace mh
