#pragma once
// Standard wheel and rail profiles generated from their definitions (profiles.md):
//   "S1002" wheel, EN 13715, piecewise sections A–H;
//   "60E1"  rail,  EN 13674-1 (UIC 60) head: R300, R80, R13, 1:20 flank;
//   "54E1"  rail,  EN 13674-1 (UIC 54) head: R300, R80, R13, 1:20 flank.
// Results are mh::Profile objects in the canonical frame of profile.hpp (y to the field side,
// z up, metres):
//   wheel: y = S (lateral coordinate from the taping line, flange at negative y), z = −F(S);
//   rail:  origin at the crown top (before inclination), symmetric head, gauge side at negative y.
//
// Nodes: every section (S1002 A–H, or each arc / flank of a rail) is divided into equal pieces no
// longer than `step` measured along the profile (arcs: equal angles; lines: equal y steps;
// polynomials: equal lengths along the curve), so steep flanks are as densely sampled as the
// tread, and every breakpoint is a node exactly (the curvature code sees the jumps). So are the
// landmarks: the S1002 taping line (S = 0) and flange tip (S = −55, F = 28), and the rail crown
// top (0, 0).
//
// S1002 continuity: the published sections meet only to about 1e−4 mm (worst at S = −35:
// 1.2e−4 mm; 3.7e−5 mm at S = −26; ≤ 7e−8 mm elsewhere). The definition is kept as published;
// at a breakpoint the node takes the value of the section that owns it, which is the section on
// its right (the table's ranges are closed on the left, "−35 ≤ S < −26"), and A owns S = 60.
#include <string>
#include <utility>
#include <vector>

#include "profile/profile.hpp"

namespace mh {

/// The names make_standard_profile accepts: "S1002", "60E1", "54E1".
const std::vector<std::string>& standard_profile_names();

/// Is `name` a wheel ("S1002") or a rail ("60E1", "54E1")? Throws InputError for unknown names.
ProfileKind standard_profile_kind(const std::string& name);

/// Generate a standard profile.
///   name: "S1002", "60E1" or "54E1" (InputError listing the valid names otherwise);
///   incl: rails: None (vertical, also for AsIs), In40 or In20, applied about the crown top with
///         rotate_towards_track_centre (profile.hpp); wheels: None or AsIs only (InputError for
///         1:40 / 1:20: a wheel has no inclination);
///   step: [m] largest distance between nodes along the profile (default 0.1 mm; allowed
///         1 µm … 5 mm, InputError otherwise).
/// At 1:20 the gauge-side 1:20 flank becomes exactly vertical and is not a function z(y): the
/// generated rail then ends at the R13/flank tangency point on the gauge side (vertical tangent
/// there), and `warnings` says so. The field-side flank is kept in every case.
Profile make_standard_profile(const std::string& name, Inclination incl = Inclination::None,
                              double step = 0.1e-3);

/// y [m] of the junctions between sections (S1002 A–H) or arcs/flanks (rails), ascending,
/// before inclination; the ends of the profile are not included. These are nodes of every
/// generated profile.
std::vector<double> standard_profile_breakpoints(const std::string& name);

/// y range [m] of the definition (before inclination): S1002 −70 … +60 mm; rails to 20 mm below
/// the crown top on both flanks.
std::pair<double, double> standard_profile_range(const std::string& name);

/// The definition's height z(y) [m] in the canonical frame (before inclination) and, if `dz` is
/// given, its slope dz/dy. y [m] must lie in standard_profile_range (InputError otherwise).
/// At a breakpoint, the section on the right (side = +1, the owner in the S1002 table) or on the
/// left (side = −1) is evaluated.
double standard_profile_z(const std::string& name, double y, double* dz = nullptr, int side = +1);

/// The definition's radius of curvature [m] at y [m] (before inclination), with the paper's sign
/// (method.md §1): positive when the centre of curvature is inside the material. Rails: R300,
/// R80, R13 arcs give +0.300, +0.080, +0.013; the flanks +infinity. S1002: circle sections give
/// their radius (D: −0.013, throat; F: +0.020; G: +0.012, flange tip; H: +0.0205), the straight
/// sections A and E +infinity, and the polynomial sections B and C the analytic curvature of the
/// polynomial, R = (1 + z'²)^(3/2) / z'' with the wheel's sign (1/R_wxx = +kappa, profile/curve.hpp).
/// At a breakpoint: the section on the right (side = +1) or on the left (side = −1).
double standard_profile_radius(const std::string& name, double y, int side = +1);

/// A rail head built from its definition (profiles.md "Rail 60E1"): arcs R1 (centre (0, −R1),
/// through the crown top) out to |y| = y12, R2 out to |y| = y23, each tangent to the previous one
/// (internal tangency: the centre lies on the previous arc's normal at the junction), then R3 until
/// its tangent is the flank, inclined 1 : flank_n to the vertical, which runs down to `depth`
/// below the crown top. All lengths [m].
struct RailHeadDefinition {
  double R1 = 0.300;         ///< [m] crown radius
  double R2 = 0.080;         ///< [m] second radius
  double R3 = 0.013;         ///< [m] gauge corner radius
  double y12 = 0;            ///< [m] |y| of the R1/R2 junction (60E1: 10.228 mm, 54E1: 10.012 mm)
  double y23 = 0;            ///< [m] |y| of the R2/R3 junction (60E1: 26.0265 mm, 54E1: 24.8635 mm)
  double flank_n = 20.0;     ///< flank inclination 1 : flank_n to the vertical (1:20)
  double depth = 0.020;      ///< [m] the flank ends this far below the crown top (default 20 mm)
};

/// The derived construction, field side (the gauge side is its mirror y → −y). Lengths [m].
struct RailHeadConstruction {
  double z12 = 0;                ///< [m] height of the R1/R2 junction (at y12)
  double yc2 = 0, zc2 = 0;       ///< [m] centre of R2 (60E1: 7.5005, −80.1279 mm)
  double z23 = 0;                ///< [m] height of the R2/R3 junction (at y23)
  double yc3 = 0, zc3 = 0;       ///< [m] centre of R3 (60E1: 23.0160, −14.9492 mm)
  double yt = 0, zt = 0;         ///< [m] R3/flank tangency point (60E1: about 36.000, −14.300 mm)
  double y_end = 0, z_end = 0;   ///< [m] end of the flank, `depth` below the crown top
};

/// The definitions of "60E1" and "54E1" (InputError for other names).
RailHeadDefinition rail_head_definition(const std::string& name);
/// Centres and tangency points from the definition.
RailHeadConstruction construct_rail_head(const RailHeadDefinition& d);

}  // namespace mh
