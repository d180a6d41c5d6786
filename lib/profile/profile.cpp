#include "profile/profile.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace mh {

const char* to_string(ProfileKind k) {
  switch (k) {
    case ProfileKind::Wheel: return "wheel";
    case ProfileKind::Rail: return "rail";
    default: return "unknown";
  }
}

Inclination parse_inclination(const std::string& s) {
  if (s == "as-is") return Inclination::AsIs;
  if (s == "none") return Inclination::None;
  if (s == "1:40") return Inclination::In40;
  if (s == "1:20") return Inclination::In20;
  throw std::invalid_argument("inclination must be one of \"as-is\", \"none\", \"1:40\", \"1:20\"");
}

const char* to_string(Inclination i) {
  switch (i) {
    case Inclination::AsIs: return "as-is";
    case Inclination::None: return "none";
    case Inclination::In40: return "1:40";
    case Inclination::In20: return "1:20";
  }
  return "?";
}

double inclination_angle(Inclination i) {
  switch (i) {
    case Inclination::In40: return std::atan(1.0 / 40.0);
    case Inclination::In20: return std::atan(1.0 / 20.0);
    default: return 0.0;
  }
}

void rotate_towards_track_centre(Profile& p, double angle) {
  if (angle == 0.0 || p.size() == 0) return;
  const double c = std::cos(angle), s = std::sin(angle);
  std::vector<double> y(p.size()), z(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    y[i] = c * p.y[i] - s * p.z[i];
    z[i] = s * p.y[i] + c * p.z[i];
  }
  // A steep flank can become vertical or overhanging: keep, from the highest point outwards,
  // the points whose y keeps moving away from it; the rest (far below the head) is clipped.
  std::size_t top = 0;
  for (std::size_t i = 1; i < z.size(); ++i)
    if (z[i] > z[top]) top = i;
  std::size_t a = top, b = top;
  while (a > 0 && y[a - 1] < y[a]) --a;
  while (b + 1 < y.size() && y[b + 1] > y[b]) ++b;
  const std::size_t clipped = a + (y.size() - 1 - b);
  p.y.assign(y.begin() + static_cast<std::ptrdiff_t>(a), y.begin() + static_cast<std::ptrdiff_t>(b + 1));
  p.z.assign(z.begin() + static_cast<std::ptrdiff_t>(a), z.begin() + static_cast<std::ptrdiff_t>(b + 1));
  if (clipped)
    p.warnings.push_back("inclination: clipped " + std::to_string(clipped) +
                         " flank points that became vertical or overhanging");
}

}  // namespace mh

namespace mh {

RailLandmarks rail_landmarks(const Profile& rail, double below) {
  RailLandmarks L;
  if (rail.size() == 0) return L;
  std::size_t itop = 0;
  for (std::size_t i = 1; i < rail.size(); ++i)
    if (rail.z[i] > rail.z[itop]) itop = i;
  L.y_top = rail.y[itop];
  L.z_top = rail.z[itop];
  const double zg = L.z_top - below;
  for (std::size_t i = itop; i > 0; --i) {
    if (rail.z[i - 1] <= zg && rail.z[i] > zg) {
      const double t = (zg - rail.z[i - 1]) / (rail.z[i] - rail.z[i - 1]);
      L.y_gauge = rail.y[i - 1] + t * (rail.y[i] - rail.y[i - 1]);
      L.z_gauge = zg;
      L.has_gauge = true;
      break;
    }
  }
  return L;
}

WheelLandmarks wheel_landmarks(const Profile& wheel) {
  WheelLandmarks L;
  if (wheel.size() == 0) return L;
  std::size_t imin = 0;
  for (std::size_t i = 1; i < wheel.size(); ++i)
    if (wheel.z[i] < wheel.z[imin]) imin = i;
  L.y_tip = wheel.y[imin];
  L.z_tip = wheel.z[imin];
  return L;
}

}  // namespace mh
