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
