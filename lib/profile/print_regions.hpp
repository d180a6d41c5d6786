#pragma once
// Regions of a profile file printed to different precision (profiles.md §7 "Measured or exact,
// region by region"): a stitched measurement may carry part of its points to 17 digits (a design
// section, a converted scan) and the rest to 4 decimals (the gauge's own output). The noise is
// then decided per region (curve.hpp), and the boundaries come from what the file says of
// itself, the printed step of each point (Profile::point_step), not from the fit's residual
// (which cannot tell noise from a window's misfit at a tight feature).
#include <cstddef>
#include <vector>

#include "profile/profile.hpp"

namespace mh {

struct PrintRegion {
  std::size_t first = 0, last = 0;  ///< point indices, inclusive
  double step = 0;                  ///< [m] the finest printed step seen around its points (0: unknown)
};

struct PrintRegionOptions {
  /// A point's precision is the finest step printed within this many points each side (default
  /// 5: a writer that drops trailing zeros prints a coarser step on about one token in ten, and
  /// all 22 tokens of a window coarse together on one in 10^22).
  int window = 5;
  /// ... among the neighbours at most this factor finer than the point's own step (default 1e4:
  /// up to four dropped zeros), so that another printing's precision does not spread into it.
  double dropped_zeros = 1e4;
  /// [m] Steps below this are one class, full precision (default 1e-9 m, 6 decimals in mm:
  /// a file printed to 17 significant digits has steps from 1e-14 to 1e-18 mm by magnitude).
  double full_precision = 1e-9;
  /// Neighbouring precisions that differ by less than this factor are one region (default 10:
  /// 17 digits against 4 decimals differ by 10^11, two writers' 5 and 7 decimals by 100).
  double factor = 10.0;
  /// A region of fewer points than this is merged into its longer neighbour (default 20: a
  /// region must hold enough curvature fits for its own median residual).
  int min_points = 20;
};

/// The regions of p (in point order) where the printed precision differs by at least
/// opt.factor; one region spanning the profile when it does not or the steps are not known.
std::vector<PrintRegion> print_regions(const Profile& p, const PrintRegionOptions& opt = {});

}  // namespace mh
