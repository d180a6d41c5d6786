// Tractions per element and FASTSIM's traction at a point (traction_grid.hpp).
#include "contact/tangential/traction_grid.hpp"

#include <algorithm>
#include <cmath>

namespace mh {

TractionSample fastsim_traction_at(const EllipseTraction& t, double a, double b, double mu, double x, double y) {
  TractionSample out;
  const FastsimGrid& g = t.cells;
  const double q = 1 - (x * x) / (a * a) - (y * y) / (b * b);
  if (!(q > 0) || g.nx < 1 || g.ny < 1 || !(mu > 0)) return out;
  const bool ell = t.bound == TractionBound::Elliptical;
  // The strip that holds y (strips of width 2b/ny from y = −b, fastsim.cpp).
  const int j = std::clamp(static_cast<int>(std::floor((y + b) / (2 * b) * g.ny)), 0, g.ny - 1);
  const std::size_t row = static_cast<std::size_t>(j) * static_cast<std::size_t>(g.nx);
  // Cell centres x_k = a_j − (k + ½) h from the leading edge: t_k = (x_0 − x) / h is x's place.
  const double h = g.nx > 1 ? g.x[row] - g.x[row + 1] : 2 * g.x[row];
  const double tk = h > 0 ? (g.x[row] - x) / h : 0.0;
  auto used = [&](int k, double& ux, double& uy) {
    const std::size_t i = row + static_cast<std::size_t>(k);
    const double bnd = mu * g.pn[i];
    ux = bnd > 0 ? g.px[i] / bnd : 0.0;
    uy = bnd > 0 ? g.py[i] / bnd : 0.0;
  };
  double ux = 0, uy = 0;
  int near = 0;
  if (tk <= 0) {
    used(0, ux, uy);
  } else if (tk >= g.nx - 1) {
    near = g.nx - 1;
    used(near, ux, uy);
  } else {
    const int k0 = static_cast<int>(std::floor(tk));
    const double w = tk - k0;
    double ax = 0, ay = 0, bx = 0, by = 0;
    used(k0, ax, ay);
    used(k0 + 1, bx, by);
    ux = (1 - w) * ax + w * bx;
    uy = (1 - w) * ay + w * by;
    near = w < 0.5 ? k0 : k0 + 1;
  }
  out.slip = g.slip[row + static_cast<std::size_t>(near)] != 0;
  const double u = std::hypot(ux, uy);
  if (out.slip && u > 0) {
    ux /= u;
    uy /= u;
  }
  // The bound's pressure at the point: the cells' P times the bound's shape (fastsim.cpp: the
  // shape factorises, so P = pn / shape at any cell).
  const std::size_t c = row + static_cast<std::size_t>(near);
  const double qc = 1 - (g.x[c] * g.x[c]) / (a * a) - (g.y[c] * g.y[c]) / (b * b);
  const double shape_c = ell ? std::sqrt(qc) : qc, shape = ell ? std::sqrt(q) : q;
  const double pn = shape_c > 0 ? g.pn[c] / shape_c * shape : 0.0;
  out.px = mu * pn * ux;
  out.py = mu * pn * uy;
  return out;
}

}  // namespace mh
