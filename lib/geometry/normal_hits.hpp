#pragma once
// Where a patch plane's normal line meets the rail and the wheel (geometry/gap.cpp): shared by the
// normal gap (gap.cpp) and the gap-corner bounds (gap_bounds.cpp). Internal to lib/geometry.
#include "geometry/gap.hpp"

namespace mh::detail {

/// The plane point at s and where its normal meets the rail (h_r) and the wheel (h_w) [m]
/// (normal_gap); on_face: the normal meets the rail's vertical gauge face.
struct NormalHits {
  double qy = 0, h_r = 0, h_w = 0;
  bool on_face = false;
};

/// The normal line from plane P at (x, s) with the wheel at approach dz. c, sn: cos γ and sin γ of
/// the plane; hr0, hw0: the Newton starts of h_r and h_w (a neighbouring sample's, whose hits lie
/// within the sample spacing's curvature term of these).
NormalHits normal_hits(const WheelRailGap& gap, const PatchPlane& P, double c, double sn, double x, double s, double dz,
                       double hr0 = 0, double hw0 = 0);

}  // namespace mh::detail
