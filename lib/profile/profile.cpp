#include "profile/profile.hpp"

#include "core/units.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <cctype>
#include <cstdlib>
#include <stdexcept>

#include "core/numfmt.hpp"

namespace mh {

const char* to_string(ProfileKind k) {
  switch (k) {
    case ProfileKind::Wheel: return "wheel";
    case ProfileKind::Rail: return "rail";
    default: return "unknown";
  }
}

Inclination parse_inclination(const std::string& s) {
  const std::string rule =
      "inclination must be \"as-is\", \"none\", a ratio \"1:N\" with N >= 5 (e.g. \"1:40\", \"1:30\", "
      "\"1:20\") or an angle in degrees (e.g. \"2.5deg\", at most 11.3deg)";
  if (s == "as-is") return Inclination::AsIs;
  if (s == "none") return Inclination::None;
  auto number = [&](const std::string& t) {
    if (t.empty() || std::isspace(static_cast<unsigned char>(t[0]))) throw std::invalid_argument(rule + ", not \"" + s + "\"");
    char* e = nullptr;
    const double v = std::strtod(t.c_str(), &e);
    if (e == t.c_str() || *e != '\0' || !std::isfinite(v)) throw std::invalid_argument(rule + ", not \"" + s + "\"");
    return v;
  };
  if (s.rfind("1:", 0) == 0) {
    const double n = number(s.substr(2));
    if (!(n >= 5)) throw std::invalid_argument(rule + ", not \"" + s + "\" (N must be at least 5)");
    return Inclination{Inclination::Mode::Ratio, n};
  }
  const auto d = s.size() >= 3 ? s.size() - 3 : std::string::npos;
  if (d != std::string::npos && s.compare(d, 3, "deg") == 0) {
    const double a = number(s.substr(0, d));
    if (!(a >= 0 && a <= 11.31)) throw std::invalid_argument(rule + ", not \"" + s + "\" (angle out of range)");
    return Inclination{Inclination::Mode::Angle, a};
  }
  throw std::invalid_argument(rule + ", not \"" + s + "\"");
}

std::string to_string(const Inclination& i) {
  switch (i.mode) {
    case Inclination::Mode::AsIs: return "as-is";
    case Inclination::Mode::None: return "none";
    case Inclination::Mode::Ratio: return "1:" + format_number(i.value);
    case Inclination::Mode::Angle: return format_number(i.value) + "deg";
  }
  return "?";
}

double inclination_angle(const Inclination& i) {
  switch (i.mode) {
    case Inclination::Mode::Ratio: return std::atan(1.0 / i.value);
    case Inclination::Mode::Angle: return i.value * units::pi / 180.0;
    default: return 0.0;
  }
}

void rotate_towards_track_centre(Profile& p, double angle) {
  if (angle == 0.0 || p.size() == 0) return;
  if (p.point_step.size() != p.size()) p.point_step.clear();
  if (!p.face_y.empty()) {
    // A vertical gauge face turned is no longer vertical: it goes back among the points (foot
    // first), and the rule below keeps what stays a function z(y).
    if (!p.point_step.empty()) p.point_step.insert(p.point_step.begin(), p.face_y.size(), p.point_step.front());
    p.y.insert(p.y.begin(), p.face_y.rbegin(), p.face_y.rend());
    p.z.insert(p.z.begin(), p.face_z.rbegin(), p.face_z.rend());
    p.face_y.clear();
    p.face_z.clear();
  }
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
  if (!p.point_step.empty())
    p.point_step.assign(p.point_step.begin() + static_cast<std::ptrdiff_t>(a),
                        p.point_step.begin() + static_cast<std::ptrdiff_t>(b + 1));
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
  if (!L.has_gauge && rail.cleanup.gauge_undercut && rail.z[0] > zg && rail.z[0] < L.z_top) {
    L.y_gauge = rail.y[0];
    L.z_gauge = rail.z[0];
    L.has_gauge = true;
    L.gauge_at_widest = true;
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

namespace mh {

WheelMeasures wheel_measures(const Profile& w) {
  WheelMeasures M;
  const std::size_t n = w.size();
  if (n < 2) { M.why = "too few points"; return M; }
  if (!(w.y.front() <= 0 && w.y.back() >= 0)) { M.why = "the profile does not reach the taping line y = 0"; return M; }
  std::size_t itip = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (w.z[i] < w.z[itip]) itip = i;
  std::size_t j = 1;
  while (j + 1 < n && w.y[j] < 0) ++j;
  const double z0 = w.z[j - 1] + (w.z[j] - w.z[j - 1]) * (0 - w.y[j - 1]) / (w.y[j] - w.y[j - 1]);
  const double ztip = w.z[itip];
  if (!(w.y[itip] < 0)) { M.why = "the flange tip is not at negative y"; return M; }
  // First crossing of level zl on the flange face, from the tip towards the tread.
  auto face = [&](double zl, double& y) {
    for (std::size_t i = itip + 1; i < n && w.y[i] <= 0; ++i)
      if (w.z[i - 1] <= zl && w.z[i] >= zl) {
        const double dz = w.z[i] - w.z[i - 1];
        y = dz > 0 ? w.y[i - 1] + (w.y[i] - w.y[i - 1]) * (zl - w.z[i - 1]) / dz : w.y[i];
        return true;
      }
    return false;
  };
  double yd = 0, yq = 0;
  const double zd = z0 - 0.010, zq = ztip + 0.002;
  if (!(ztip < zd) || !face(zd, yd)) { M.why = "the flange is not 10 mm high"; return M; }
  if (!face(zq, yq)) { M.why = "no flange face 2 mm above the tip"; return M; }
  M.Sh = z0 - ztip;
  M.Sd = yd + 0.070;  // the flange back 70 mm from the taping line (EN 13715; ProfileCheckLimits)
  M.qR = yd - yq;
  M.valid = true;
  return M;
}

}  // namespace mh
