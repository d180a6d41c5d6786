#include "contact/grid/pressure_spike.hpp"

#include <algorithm>

namespace mh {

PressureSpike find_pressure_spike(const std::vector<double>& p, int nx, int ns) {
  PressureSpike s;
  for (int j = 0; j < ns; ++j)
    for (int i = 0; i < nx; ++i) {
      const double v = p[static_cast<std::size_t>(i + nx * j)];
      if (v > s.p) { s.p = v; s.i = i; s.j = j; }
    }
  if (s.i < 0) return s;
  for (int dj = -1; dj <= 1; ++dj)
    for (int di = -1; di <= 1; ++di) {
      const int i = s.i + di, j = s.j + dj;
      if ((di == 0 && dj == 0) || i < 0 || j < 0 || i >= nx || j >= ns) continue;
      s.neighbours = std::max(s.neighbours, p[static_cast<std::size_t>(i + nx * j)]);
    }
  s.found = s.p > kSpikeFactor * s.neighbours;
  return s;
}

}  // namespace mh
