#pragma once
// The refinement of a wheel–rail separation's minimum between strips, shared by the upright main
// point (ContactGeometry::locate_main) and the rolled one (rolled_candidates.cpp): the roots of the
// separation's slope d(y) going from negative to positive over `sub` sub-intervals of [a, b] are
// its local minima; each is found to `tol` and the lowest separation g wins.

#include "core/roots.hpp"

namespace mh {

/// How a minimum is refined: sub-intervals scanned for sign changes of the slope, the root's
/// tolerance [m], and the root finder (bisection keeps the root bisection finds of several in a
/// sub-interval, whatever the slope's shape; else TOMS 748).
struct GapMinimumScan {
  int sub = 24;
  double tol = 1e-13;
  bool bisect = true;
};

/// The lowest local minimum of g on [a, b] (a <= b) from the sign changes of its slope d, against
/// the starting best (best_y, best_g), which it updates.
template <class D, class G>
void lowest_gap_minimum(D&& d, G&& g, double a, double b, const GapMinimumScan& scan, double& best_y, double& best_g) {
  if (!(a < b)) return;
  double y0 = a, d0 = d(a);
  for (int i = 1; i <= scan.sub; ++i) {
    const double y1 = a + (b - a) * i / scan.sub, d1 = d(y1);
    if (d0 < 0 && d1 >= 0) {
      RootTolerance tol;
      tol.abs = scan.tol;
      tol.rel = 0;
      tol.max_iterations = 60;
      const double ym = scan.bisect ? bisected_root(d, y0, y1, tol).x : bracketed_root(d, y0, y1, d0, d1, tol).x;
      const double gm = g(ym);
      if (gm < best_g) best_g = gm, best_y = ym;
    }
    y0 = y1;
    d0 = d1;
  }
}

}  // namespace mh
