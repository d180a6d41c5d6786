#pragma once
// A Hertzian pressure on a grid of boundary elements, for the tangential tests: p0 √(1 − x²/a² −
// y²/b²) at the element centres of an nx × ny grid covering the ellipse enlarged by `scale`
// (1: the ellipse exactly; CONTACT's module-3 decks use 1.1).
#include <cmath>
#include <cstddef>
#include <vector>

struct HertzGrid {
  int nx, ny;
  double dx, dy, x0, y0, N = 0;  ///< [m] element sizes, centre of element (0, 0); [N] Σ p dA
  std::vector<double> p;         ///< [Pa], index ix + nx·iy
  HertzGrid(double a, double b, double p0, int nx_, int ny_, double scale = 1)
      : nx(nx_), ny(ny_), dx(2 * scale * a / nx_), dy(2 * scale * b / ny_), x0(-scale * a + dx / 2),
        y0(-scale * b + dy / 2), p(static_cast<std::size_t>(nx_ * ny_), 0.0) {
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double x = x0 + i * dx, y = y0 + j * dy, q = 1 - x * x / (a * a) - y * y / (b * b);
        if (q > 0) p[static_cast<std::size_t>(i + nx * j)] = p0 * std::sqrt(q);
        N += p[static_cast<std::size_t>(i + nx * j)] * dx * dy;
      }
  }
};
