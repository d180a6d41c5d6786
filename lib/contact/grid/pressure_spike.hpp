#pragma once
// A peak pressure that stands on a single element of a grid solution: the element carrying the
// patch's largest pressure against the largest of its eight neighbours. A smooth (Hertz-like)
// pressure has a ratio near 1 at its peak; a ratio far above it means the gap has a corner or a
// spike there (a kink in a measured profile, the end of a profile), where the elastic pressure
// is singular and the peak grows as the element shrinks: the peak is then a property of the grid,
// not of the contact. The grid methods report it as the warning
// `pressure_spike:patch=K:y_rail_mm=...:p_MPa=...:neighbours_MPa=...` (docs/half_space.md).
#include <cstddef>
#include <vector>

namespace mh {

struct PressureSpike {
  bool found = false;     ///< the peak exceeds kSpikeFactor times every neighbour
  int i = -1, j = -1;     ///< element of the peak (x index, s index)
  double p = 0;           ///< [Pa] the peak
  double neighbours = 0;  ///< [Pa] the largest pressure of its eight neighbours (0: none loaded)
};

/// The peak counts as a spike above this ratio to its largest neighbour.
constexpr double kSpikeFactor = 3.0;

/// Pressures p[i + nx j] (i along x, j along s) of one patch grid.
PressureSpike find_pressure_spike(const std::vector<double>& p, int nx, int ns);

}  // namespace mh
