#pragma once
// A wheel or rail profile in the canonical frame (method.md §1):
//   y lateral, positive towards the FIELD side; z vertical, positive UP; SI (metres) inside.
//   Wheels: y = 0 at the taping line, the flange at negative y, z = −(increase of rolling radius),
//           so the flange tip is the lowest point.
//   Rails:  the origin of the file is kept; the gauge corner is at negative y, the head top is
//           the highest point.
#include <string>
#include <vector>

namespace mh {

enum class ProfileKind { Unknown, Wheel, Rail };

const char* to_string(ProfileKind k);

struct Profile {
  ProfileKind kind = ProfileKind::Unknown;
  std::vector<double> y;   ///< [m] lateral, towards the field side, strictly increasing after cleaning
  std::vector<double> z;   ///< [m] vertical, up
  std::string source;      ///< file path or "standard:S1002" etc.
  std::string format;      ///< "simpack", "miniprof", "table", "vampire", "standard"
  std::string checksum;    ///< SHA-256 of the source file's bytes (hex), empty for generated profiles
  std::vector<std::string> warnings;  ///< what cleaning did (e.g. "removed 3 duplicated points")

  std::size_t size() const { return y.size(); }
};

/// Rail inclination (cant) applied by the tool. `AsIs`: the profile is already canted or vertical
/// and is used as read. Never applied twice: the case file must say which (profiles.md).
enum class Inclination { AsIs, None, In40, In20 };

/// Parse "as-is", "none", "1:40", "1:20". Throws std::invalid_argument on anything else.
Inclination parse_inclination(const std::string& s);
const char* to_string(Inclination i);
/// Cant angle [rad]: atan(1/40), atan(1/20), or 0.
double inclination_angle(Inclination i);

/// Rotate a rail profile about its origin by `angle` [rad] towards the track centre (the gauge
/// side, negative y): counter-clockwise in the (y field, z up) plane, so that the crown's tangent
/// gets the slope +tan(angle) (profiles.md "Inclination"). Expects y increasing; flank points
/// that become vertical or overhanging are clipped (with a warning), so y stays increasing.
void rotate_towards_track_centre(Profile& p, double angle);

}  // namespace mh

namespace mh {

/// Landmarks used for positioning (method.md §7) and `profile info`.
struct RailLandmarks {
  double y_top = 0, z_top = 0;      ///< [m] highest point of the head
  double y_gauge = 0, z_gauge = 0;  ///< [m] gauge point: gauge side (negative y), `below` under the top
  bool has_gauge = false;
};
/// Gauge point `below` [m] under the highest point (standard 14 mm), searched from the top
/// towards the gauge side (negative y); the first crossing, linearly interpolated.
RailLandmarks rail_landmarks(const Profile& rail, double below = 0.014);

struct WheelLandmarks {
  double y_tip = 0, z_tip = 0;  ///< [m] flange tip: the lowest point (canonical frame, z up)
};
WheelLandmarks wheel_landmarks(const Profile& wheel);

}  // namespace mh
