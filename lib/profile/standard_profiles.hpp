#pragma once
// Standard wheel and rail profiles generated from their definitions (profiles.md):
//   "S1002" wheel, EN 13715, piecewise sections A–H;
//   "60E1"  rail,  EN 13674-1 (UIC 60) head: R300, R80, R13, 1:20 flank;
//   "54E1"  rail,  EN 13674-1 (UIC 54) head: R300, R80, R13, 1:20 flank;
//   "60E2"  rail,  EN 13674-1:2017 head: R200, R70, R16, R8, 1:20 flank;
//   "49E1"  rail,  EN 13674-1:2017 head: R300, R80, R13, 1:17.2 flank
//           (60E2 and 49E1: EN 13674-1:2017, transcribed from one public source, rohrbecka/EN13674);
//   "EN15302-wheel-A", "EN15302-rail-A": the EN 15302:2021 reference wheel A and rail A
//           (appendix I, as transcribed in rohrbecka/EN15302; rail A is defined canted 1:20 and
//           takes no further inclination) for the equivalent-conicity reference tables.
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

/// The names make_standard_profile accepts: "S1002", "60E1", "54E1", "60E2", "49E1",
/// "EN15302-wheel-A", "EN15302-rail-A".
const std::vector<std::string>& standard_profile_names();

/// Is `name` a wheel ("S1002", "EN15302-wheel-A") or a rail? Throws InputError for unknown names.
ProfileKind standard_profile_kind(const std::string& name);

/// Generate a standard profile.
///   name: one of standard_profile_names() (InputError listing the valid names otherwise);
///   incl: rails: None (vertical, also for AsIs), In40 or In20, applied about the crown top with
///         rotate_towards_track_centre (profile.hpp); wheels and the already canted EN15302-rail-A:
///         None or AsIs only (InputError otherwise: never applied twice);
///   step: [m] largest distance between nodes along the profile (default 0.1 mm; allowed
///         1 µm … 5 mm, InputError otherwise).
/// At 1:20 the gauge-side 1:20 flank becomes exactly vertical and is not a function z(y): the
/// generated rail then ends at the last arc's (R13, 60E2: R8) flank tangency point on the gauge
/// side (vertical tangent there), and `warnings` says so. The field-side flank is kept in every
/// case. (49E1's 1:17.2 flank stays 0.47° short of vertical at 1:20 and is kept.)
Profile make_standard_profile(const std::string& name, Inclination incl = Inclination::None,
                              double step = 0.1e-3);

/// y [m] of the junctions between sections (S1002 A–H) or arcs/flanks (rails), ascending,
/// before inclination; the ends of the profile are not included. These are nodes of every
/// generated profile.
std::vector<double> standard_profile_breakpoints(const std::string& name);

/// y range [m] of the definition (before inclination): S1002 −70 … +60 mm; EN15302-wheel-A
/// −70 … +65 mm; rails to 20 mm below the crown top on both flanks; EN15302-rail-A
/// −32.634 … 39.2705 mm (its published range).
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

/// A rail head built from its definition (rails-en13674.md "Construction"; docs/profiles.md):
/// upright, origin at the crown top, a chain of circular arcs, each tangent to the previous one
/// (internal tangency: the new centre lies on the previous radius through the junction, at
/// R_k − R_{k+1} from the previous centre). Arc 0 is centred on (0, −R[0]); arc k ends at
/// |y| = y_junction[k]; the last arc ends where its tangent reaches the flank, inclined
/// 1 : flank_n to the vertical, which the profiles continue down to `depth` below the crown top.
/// Lower, the fillet rounds the head's corner where the flank meets the under-head line
/// (1 : underhead_n to the horizontal, rising outwards, through (0, underhead_z0)): the
/// construction derives it (60E1: from 35.3 mm below the top), the profiles leave it out, as a
/// wheel cannot reach it (docs/profiles.md, "Rail 60E1"). Lengths [m].
struct RailHeadDefinition {
  std::vector<double> R;           ///< [m] radii from the crown outwards (60E1: 300, 80, 13 mm)
  std::vector<double> y_junction;  ///< [m] |y| of the junction of arc k and k+1 (60E1: 10.228, 26.0265 mm)
  double flank_n = 20.0;           ///< flank inclination 1 : flank_n to the vertical (1:20; 49E1 1:17.2)
  double depth = 0.020;            ///< [m] the profiles' flank ends this far below the crown top (20 mm)
  double fillet_R = 3e-3;          ///< [m] radius of the fillet at the head's lower corner (R3; 49E1 R2)
  double underhead_n = 2.75;       ///< under-head line 1 : underhead_n to the horizontal (1:2.75; 49E1 1:3)
  double underhead_z0 = -51e-3;    ///< [m] its height at y = 0 (60E1, 60E2 −51; 54E1 −49.4; 49E1 −51.5 mm)
};

/// One arc of the construction, field side (the gauge side is its mirror y → −y). Lengths [m].
struct RailArc {
  double R = 0;             ///< [m] radius
  double yc = 0, zc = 0;    ///< [m] centre
  double y0 = 0, z0 = 0;    ///< [m] start (the crown top or the previous junction)
  double y1 = 0, z1 = 0;    ///< [m] end (the next junction or the flank tangency point)
};

/// The derived construction, field side. Lengths [m].
struct RailHeadConstruction {
  std::vector<RailArc> arcs;     ///< from the crown outwards (60E1: centres (0, −300), (7.5005, −80.1279), (23.0160, −14.9491) mm)
  double yt = 0, zt = 0;         ///< [m] last arc/flank tangency point (60E1: about 36.000, −14.300 mm)
  double y_end = 0, z_end = 0;   ///< [m] end of the profiles' flank, `depth` below the crown top
  /// The fillet, from its tangency point with the flank (y0, z0; 60E1: 37.049, −35.275 mm) to the
  /// head's widest point (y1, z1: the vertical tangent, level with the centre); below that it
  /// turns under the head to the under-head line (60E1: centre (34.052, −35.425) mm).
  RailArc fillet;
  double y_under = 0, z_under = 0;  ///< [m] the fillet's tangency point with the under-head line
};

/// The definitions of "60E1", "54E1", "60E2", "49E1" (InputError for other names).
RailHeadDefinition rail_head_definition(const std::string& name);
/// Centres, junction points, the tangency points and the fillet from the definition.
RailHeadConstruction construct_rail_head(const RailHeadDefinition& d);

}  // namespace mh
