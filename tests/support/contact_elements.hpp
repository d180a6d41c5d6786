#pragma once
// CONTACT's loaded elements, as its subsurface reference scripts write them (one row per element:
// its centre, its pressure and its traction on body 1, the body of CONTACT's stresses), placed on
// the regular grid of a GridLoad. Shared by the tests that load CONTACT's own patches.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "contact/rcf/grid_subsurface.hpp"
#include "support/data_csv.hpp"

namespace mh::test {

/// The elements of `e` (columns x_mm, `y_col`, pn_MPa, px_MPa, `qy_col`) on a grid of dx × dy [m]
/// whose first element centre is the smallest x and y of the rows.
inline GridLoad grid_load_from_elements(const CsvTable& e, double dx, double dy, double nu, const char* y_col,
                                        const char* qy_col) {
  constexpr double kMPa = 1e6, kMm = 1e-3;
  GridLoad G;
  G.dx = dx, G.dy = dy, G.nu = nu;
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  for (std::size_t k = 0; k < e.rows.size(); ++k) {
    const double x = csv_num(e, k, "x_mm") * kMm, y = csv_num(e, k, y_col) * kMm;
    xmin = std::min(xmin, x), xmax = std::max(xmax, x), ymin = std::min(ymin, y), ymax = std::max(ymax, y);
  }
  G.x0 = xmin, G.y0 = ymin;
  G.nx = static_cast<int>(std::lround((xmax - xmin) / G.dx)) + 1;
  G.ny = static_cast<int>(std::lround((ymax - ymin) / G.dy)) + 1;
  const std::size_t n = static_cast<std::size_t>(G.nx * G.ny);
  G.p.assign(n, 0.0), G.qx.assign(n, 0.0), G.qy.assign(n, 0.0);
  for (std::size_t k = 0; k < e.rows.size(); ++k) {
    const long i = std::lround((csv_num(e, k, "x_mm") * kMm - G.x0) / G.dx);
    const long j = std::lround((csv_num(e, k, y_col) * kMm - G.y0) / G.dy);
    const std::size_t m = static_cast<std::size_t>(i + G.nx * j);
    G.p[m] = csv_num(e, k, "pn_MPa") * kMPa;
    G.qx[m] = csv_num(e, k, "px_MPa") * kMPa, G.qy[m] = csv_num(e, k, qy_col) * kMPa;
  }
  return G;
}

}  // namespace mh::test
