#pragma once
// The rolled wheel of the grid methods' gap (method.md §3.8, eq. 3.8.1; WheelRailGap with a roll):
// the wheel profile rotated by δ about its origin (the taping line point), the same rotation as
// ContactGeometry::candidates_at(t, δ), resampled as a curve z(y) of the pair's frame.

#include <cmath>

#include "profile/curve.hpp"

namespace mh {

/// The pair's t_Y [m] of one wheel of a rigid wheelset displaced by y and rolled against its rail
/// by δ [rad] (method.md §3.8): the axle centre, at (−a, H) from the wheel profile's origin (a the
/// taping line's distance from the wheelset centre, H = z0 + R0), stays where the unrolled
/// wheelset has it, so the origin moves by a (cos δ − 1) + H sin δ along the pair's y.
/// `sigma_y` is σ y (σ = +1 left, −1 right). The one placement of the wheelset call and of a
/// wheelset table's lookup.
inline double rolled_wheel_tY(double sigma_y, double delta, double a, double H) {
  return sigma_y + (delta == 0 ? 0.0 : a * (std::cos(delta) - 1) + H * std::sin(delta));
}

/// The wheel curve W rotated by δ [rad] about its origin: each node (y, z) of W goes to
/// (y cos δ − z sin δ, y sin δ + z cos δ) (positive δ raises the field side, y > 0, as
/// candidates_at(t, δ)); the rotated curve is resampled on W's grid step from its first rotated
/// node, each node's source point found on W by TOMS 748 to 1e-15 m, with slope tan(θ + δ)
/// (tan θ = W's slope there) and W's curvature (a rotation keeps it). Only the part of W where the
/// rotated curve is a graph over y (1 − z' tan δ > 0.05) around the origin is kept.
/// Precondition: |δ| < 0.5 rad.
ProfileCurve rolled_wheel_curve(const ProfileCurve& W, double roll);
/// The same into `out` (not W), its vectors keeping their capacity: no allocation once grown.
void rolled_wheel_curve(const ProfileCurve& W, double roll, ProfileCurve& out);

}  // namespace mh
