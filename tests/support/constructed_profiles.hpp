#pragma once
// Constructed profiles with real features at 2–5 mm, for the smoothing-for-contact tests
// (profiles.md §7): a rail whose gauge corner is a tight arc, and a hollow-worn S1002 wheel,
// each either exact (dense, no noise) or "measured": sampled every `step` along the profile,
// with reproducible uniform scatter of ±`noise` normal to the profile, printed to `print`.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/roots.hpp"
#include "profile/profile.hpp"
#include "profile/standard_profiles.hpp"

namespace mh::testing {

// splitmix64: the same stream on every platform (std::*_distribution is not).
inline double uniform_pm1(std::uint64_t& x) {
  std::uint64_t z = (x += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

/// Scatter normal to the local chord (±noise, uniform, seed), rounding of y and z to `print`
/// (0: none), points that no longer increase in y dropped (as the reader's clean-up does).
inline void measure(Profile& p, double noise, double print, std::uint64_t seed) {
  const std::size_t n = p.size();
  std::vector<double> y = p.y, z = p.z;
  for (std::size_t i = 0; i < n && noise > 0; ++i) {
    const std::size_t a = i > 0 ? i - 1 : i, b = i + 1 < n ? i + 1 : i;
    const double ty = p.y[b] - p.y[a], tz = p.z[b] - p.z[a], t = std::hypot(ty, tz);
    const double e = noise * uniform_pm1(seed);
    y[i] += -tz / t * e;
    z[i] += ty / t * e;
  }
  p.y.clear();
  p.z.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const double yi = print > 0 ? std::round(y[i] / print) * print : y[i];
    const double zi = print > 0 ? std::round(z[i] / print) * print : z[i];
    if (!p.y.empty() && !(yi > p.y.back())) continue;
    p.y.push_back(yi);
    p.z.push_back(zi);
  }
  p.print_step = print;
}

/// Points every `step` (at most) along a chain of pieces: arcs (centre, radius, angles) and lines.
struct Piece {
  bool arc = false;
  double y0, z0, y1, z1;  // ends
  double yc = 0, zc = 0, R = 0;
};
inline void sample(const std::vector<Piece>& chain, double step, Profile& p) {
  for (const Piece& c : chain) {
    double len, a0 = 0, a1 = 0;
    if (c.arc) {
      a0 = std::atan2(c.z0 - c.zc, c.y0 - c.yc);
      a1 = std::atan2(c.z1 - c.zc, c.y1 - c.yc);
      if (a1 - a0 > 3.14159265358979323846) a1 -= 2 * 3.14159265358979323846;
      if (a0 - a1 > 3.14159265358979323846) a1 += 2 * 3.14159265358979323846;
      len = std::fabs(a1 - a0) * c.R;
    } else {
      len = std::hypot(c.y1 - c.y0, c.z1 - c.z0);
    }
    const int m = std::max(1, static_cast<int>(std::ceil(len / step - 1e-9)));
    for (int k = p.y.empty() ? 0 : 1; k <= m; ++k) {
      const double t = static_cast<double>(k) / m;
      if (c.arc) {
        const double a = a0 + t * (a1 - a0);
        p.y.push_back(c.yc + c.R * std::cos(a));
        p.z.push_back(c.zc + c.R * std::sin(a));
      } else {
        p.y.push_back(c.y0 + t * (c.y1 - c.y0));
        p.z.push_back(c.z0 + t * (c.z1 - c.z0));
      }
    }
  }
}

/// A rail head of definition d (construct_rail_head: gauge flank end → crown → field flank end),
/// sampled every `step` along the profile, measured (measure()) and canted by `cant` [rad].
inline Profile rail_from_definition(const RailHeadDefinition& d, double step, double noise, double print, double cant,
                                    std::uint64_t seed, const std::string& source) {
  const RailHeadConstruction c = construct_rail_head(d);
  std::vector<Piece> field;
  for (const RailArc& a : c.arcs) field.push_back({true, a.y0, a.z0, a.y1, a.z1, a.yc, a.zc, a.R});
  field.push_back({false, c.yt, c.zt, c.y_end, c.z_end});
  std::vector<Piece> chain;  // gauge flank end → crown → field flank end
  for (auto it = field.rbegin(); it != field.rend(); ++it)
    chain.push_back({it->arc, -it->y1, it->z1, -it->y0, it->z0, -it->yc, it->zc, it->R});
  for (const Piece& f : field) chain.push_back(f);
  Profile p;
  p.kind = ProfileKind::Rail;
  p.format = "constructed";
  p.source = source;
  sample(chain, step, p);
  measure(p, noise, print, seed);
  if (cant != 0) rotate_towards_track_centre(p, cant);
  return p;
}

/// A 60E1 head whose gauge corner (the R13 arc) is an arc of radius `Rc` (3–5 mm: a sharp
/// corner), R300/R80 as 60E1 (rail_head_definition, construct_rail_head), the 1:20 flanks to
/// 20 mm below the top, sampled every `step` along the profile, measured as above, then canted
/// by `cant` [rad] (as a case file's inclination would, after the measurement).
inline Profile worn_corner_rail(double Rc, double step, double noise, double print, double cant, std::uint64_t seed = 7) {
  // The R80 arc extended until the corner arc of radius Rc meets 60E1's own flank line (the same
  // flank end 20 mm below the top, so the gauge point and the wheel's placement stay those of 60E1).
  RailHeadDefinition d = rail_head_definition("60E1");
  const double y_end = construct_rail_head(d).y_end;
  d.R.back() = Rc;
  auto flank_miss = [&](double yj) {
    RailHeadDefinition e = d;
    e.y_junction.back() = yj;
    return construct_rail_head(e).y_end - y_end;
  };
  const double lo = d.y_junction.back(), hi = lo + 8e-3;
  RootTolerance tol;
  tol.abs = 1e-12;
  d.y_junction.back() = bracketed_root(flank_miss, lo, hi, flank_miss(lo), flank_miss(hi), tol).x;
  return rail_from_definition(d, step, noise, print, cant, seed,
                              "60E1 with an R" + std::to_string(Rc * 1e3).substr(0, 3) + " gauge corner");
}

/// A 60E1 head whose crown arc (R300) has radius `R_crown` (80 … 600 mm), the other arcs and the
/// junction |y| = 10.228 mm as 60E1; measured and canted as worn_corner_rail. The calibration
/// rails of the length's curvature bound (profiles.md §7 "Crown"), not those of the seeds table.
inline Profile crown_rail(double R_crown, double step, double noise, double print, double cant, std::uint64_t seed = 7) {
  RailHeadDefinition d = rail_head_definition("60E1");
  d.R.front() = R_crown;
  return rail_from_definition(d, step, noise, print, cant, seed,
                              "60E1 with an R" + std::to_string(static_cast<int>(R_crown * 1e3 + 0.5)) + " crown");
}

/// The hollow-worn S1002: the tread worn `depth` deep (radius reduced) between y = y1 and y2 [m]
/// on the wheel's taping-line frame, with shoulders that take `b` (quintic smoothstep: the
/// shoulder's smallest radius is b²/(5.77 depth), 3.1 mm for b 3 mm, depth 0.5 mm), leaving a
/// false flange on the field side. Sampled every `step` along the profile and measured as above.
inline Profile hollow_wheel(double step, double noise, double print, double depth = 0.5e-3, double y1 = -15e-3,
                            double y2 = 12e-3, double b = 3e-3, std::uint64_t seed = 11) {
  Profile p = make_standard_profile("S1002", Inclination::None, step);
  auto smoothstep = [](double t) { t = std::clamp(t, 0.0, 1.0); return t * t * t * (10 - 15 * t + 6 * t * t); };
  for (std::size_t i = 0; i < p.size(); ++i)
    p.z[i] += depth * smoothstep((p.y[i] - (y1 - b)) / b) * smoothstep((y2 + b - p.y[i]) / b);
  p.source = "S1002 hollow-worn";
  p.format = "constructed";
  measure(p, noise, print, seed);
  return p;
}

}  // namespace mh::testing
