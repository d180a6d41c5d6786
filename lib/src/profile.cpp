#include "mhcontact/profile.hpp"

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
  if (angle == 0.0) return;
  const double c = std::cos(angle), s = std::sin(angle);
  std::vector<std::pair<double, double>> pts(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    pts[i] = {c * p.y[i] - s * p.z[i], s * p.y[i] + c * p.z[i]};
  std::stable_sort(pts.begin(), pts.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t i = 0; i < pts.size(); ++i) {
    p.y[i] = pts[i].first;
    p.z[i] = pts[i].second;
  }
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
