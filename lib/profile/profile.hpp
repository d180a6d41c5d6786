#pragma once
// A wheel or rail profile in the canonical frame (method.md §1):
//   y lateral, positive towards the FIELD side; z vertical, positive UP; SI (metres) inside.
//   Wheels: y = 0 at the taping line, the flange at negative y, z = −(increase of rolling radius),
//           so the flange tip is the lowest point.
//   Rails:  the origin of the file is kept; the gauge corner is at negative y, the head top is
//           the highest point.
#include <string>
#include <utility>
#include <vector>

namespace mh {

enum class ProfileKind { Unknown, Wheel, Rail };

const char* to_string(ProfileKind k);

/// What the clean-up of a measured profile did (read.hpp ProfileCleanup; `profile info`).
struct CleanupReport {
  std::string mode;                 ///< "envelope", "strict" or "off"; empty for generated profiles
  std::size_t duplicates = 0;       ///< exact duplicates of the previous point removed
  std::size_t jitter = 0;           ///< points dropped as measurement jitter (≤ 0.05 mm back in y)
  std::size_t folds = 0;            ///< folds/loops removed by taking the outer envelope
  std::size_t fold_points = 0;      ///< points dropped by the envelope
  std::size_t crossings = 0;        ///< crossing points added where a loop crosses itself
  double y_from_mm = 0, y_to_mm = 0;  ///< y range (canonical frame, file y before the taping-line shift) of the folds
  double largest_fold_mm = 0;       ///< largest backward step in y of a removed fold
  /// Rails: the gauge face turns under the head inside the depth that can touch; the profile
  /// starts at the widest point (rail_landmarks takes the gauge point there, EN 13848-1).
  bool gauge_undercut = false;
};

struct Profile {
  ProfileKind kind = ProfileKind::Unknown;
  std::vector<double> y;   ///< [m] lateral, towards the field side, strictly increasing after cleaning
  std::vector<double> z;   ///< [m] vertical, up
  std::string source;      ///< file path or "standard:S1002" etc.
  std::string format;      ///< "simpack", "miniprof", "table", "vampire", "standard"
  std::string checksum;    ///< SHA-256 of the source file's bytes (hex), empty for generated profiles
  std::vector<std::string> warnings;  ///< what cleaning did (e.g. "removed 3 duplicated points")
  CleanupReport cleanup;   ///< what the clean-up did (files only)
  /// Wheels whose file origin is not the taping line: how the reader put y = 0 there (the file
  /// y it chose and why: the file origin is the flange back, or the innermost point is taken as
  /// the flange back; EN 13715, 70 mm). Empty when y is as in the file.
  std::string taping_line;
  /// Measures found in the file's header (MiniProf "Sd/Sh/qR" line, ...), as written there.
  std::vector<std::pair<std::string, std::string>> file_measures;
  /// [m] Step of the coordinates as printed in the file: 10^-d mm for the most decimals d seen
  /// (times the reader's and the user's scale); 0 for generated profiles and sampled MiniProf
  /// drawing elements. The curvature fit compares its residual with the rounding error this
  /// step explains (curve.hpp, profiles.md "Measured or exact").
  double print_step = 0;
  /// [m] The printed step of each point (its finer coordinate's 10^-d mm; 0: unknown, e.g. a
  /// sampled drawing element), empty when not known at all (generated profiles). Where it
  /// varies along a file (a stitched measurement printed partly to 17 digits and partly to 4)
  /// the noise is classed region by region (profile/print_regions.hpp). Code that adds,
  /// removes or reorders points keeps it in step, or clears it.
  std::vector<double> point_step;
  /// [m] Rails: the gauge face below the first point where a function z(y) cannot hold it, as
  /// the 60E1/54E1/60E2 flank that a 1:20 cant makes vertical (profiles.md "Inclination"): its
  /// points from the one next to (y[0], z[0]) downwards to its foot, each face_y equal to y[0]
  /// (vertical). Empty for most profiles. y/z stay the function z(y) that the curvature fit and
  /// the multi-Hertzian search use; the grid methods' normal gap sees the rail continued by the
  /// face (geometry/gap.hpp), and the writers put it before the first point (write.hpp).
  std::vector<double> face_y, face_z;

  std::size_t size() const { return y.size(); }
};

/// Rail inclination (cant) applied by the tool. `AsIs`: the profile is already canted or vertical
/// and is used as read. Never applied twice: the case file must say which (profiles.md).
/// Any ratio 1:N (N ≥ 5: 1:20, 1:30, 1:40 ...) or an angle in degrees ("2.5deg", 0 … 11.3°).
struct Inclination {
  enum class Mode { AsIs, None, Ratio, Angle };
  Mode mode = Mode::AsIs;
  double value = 0;  ///< Ratio: N of 1:N; Angle: degrees
  static const Inclination AsIs, None, In40, In20;
  bool operator==(const Inclination& o) const { return mode == o.mode && value == o.value; }
  bool operator!=(const Inclination& o) const { return !(*this == o); }
};
inline const Inclination Inclination::AsIs{Inclination::Mode::AsIs, 0};
inline const Inclination Inclination::None{Inclination::Mode::None, 0};
inline const Inclination Inclination::In40{Inclination::Mode::Ratio, 40};
inline const Inclination Inclination::In20{Inclination::Mode::Ratio, 20};

/// Parse "as-is", "none", "1:N" (N ≥ 5, e.g. "1:40", "1:30", "1:20") or "<angle>deg" (0 ≤ angle ≤
/// 11.3, e.g. "2.5deg"). Throws std::invalid_argument on anything else.
Inclination parse_inclination(const std::string& s);
/// "as-is", "none", "1:40", "2.5deg" (parse_inclination gives it back).
std::string to_string(const Inclination& i);
/// Cant angle [rad]: atan(1/N), the angle, or 0.
double inclination_angle(const Inclination& i);

/// Rotate a rail profile about its origin by `angle` [rad] towards the track centre (the gauge
/// side, negative y): counter-clockwise in the (y field, z up) plane, so that the crown's tangent
/// gets the slope +tan(angle) (profiles.md "Inclination"). Expects y increasing; flank points
/// that become vertical or overhanging are clipped (with a warning), so y stays increasing. A
/// vertical gauge face (face_y, face_z) is turned with the points, among them: no face is left.
void rotate_towards_track_centre(Profile& p, double angle);

}  // namespace mh

namespace mh {

/// Landmarks used for positioning (method.md §7) and `profile info`.
struct RailLandmarks {
  double y_top = 0, z_top = 0;      ///< [m] highest point of the head
  double y_gauge = 0, z_gauge = 0;  ///< [m] gauge point: gauge side (negative y), `below` under the top
  bool has_gauge = false;
  /// The gauge face turns under above `below` (CleanupReport::gauge_undercut): the gauge point
  /// is the widest point, where the smallest distance within 0 … `below` lies (EN 13848-1).
  bool gauge_at_widest = false;
};
/// Gauge point `below` [m] under the highest point (standard 14 mm), searched from the top
/// towards the gauge side (negative y); the first crossing, linearly interpolated.
RailLandmarks rail_landmarks(const Profile& rail, double below = 0.014);

struct WheelLandmarks {
  double y_tip = 0, z_tip = 0;  ///< [m] flange tip: the lowest point (canonical frame, z up)
};
WheelLandmarks wheel_landmarks(const Profile& wheel);

/// Wheel measures after EN 15313 (docs/profiles.md §9), from the profile in the canonical
/// frame (taping line at y = 0, flange at negative y, z = −increase of radius), all [m]:
///  Sh flange height: from the tread at the taping line (z at y = 0) to the flange tip (lowest z);
///  Sd flange thickness: from the flange back, which the canonical frame puts 70 mm from the
///     taping line (y = −70 mm, EN 13715; the taping-line rule of read.hpp), to the flange face
///     at 10 mm from the taping-line level towards the tip (z = z(0) − 10 mm);
///  qR flange slope: lateral distance between that Sd point and the flange face point 2 mm
///     from the tip (z = z_tip + 2 mm).
/// The flange-face points are the first crossings from the tip towards the tread, linearly
/// interpolated. S1002 new (32.5 mm flange): Sh 28, Sd 32.5, qR 10.8 mm.
struct WheelMeasures {
  double Sh = 0, Sd = 0, qR = 0;
  bool valid = false;   ///< false when the profile does not reach y = 0 or the levels (why says it)
  std::string why;
};
WheelMeasures wheel_measures(const Profile& wheel);

}  // namespace mh
