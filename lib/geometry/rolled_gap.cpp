#include "geometry/rolled_gap.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/roots.hpp"

namespace mh {

ProfileCurve rolled_wheel_curve(const ProfileCurve& W, double roll) {
  ProfileCurve out = W;
  rolled_wheel_curve(W, roll, out);
  return out;
}

void rolled_wheel_curve(const ProfileCurve& W, double roll, ProfileCurve& out) {
  const double c = std::cos(roll), sn = std::sin(roll), tn = std::tan(roll);
  const std::size_t n = W.nodes();
  // The rotated lateral coordinate of W's point at y, increasing in y where 1 − z' tan δ > 0.
  auto Y = [&](double y) { return y * c - W.z(y) * sn; };
  auto graph = [&](std::size_t i) {
    double d;
    W.z(W.node_y(i), &d);
    return 1 - d * tn > 0.05;
  };
  // The run of nodes around the origin (the node nearest y = 0) where the rotated curve is a graph.
  std::size_t i0 = static_cast<std::size_t>(std::clamp(std::lround(-W.node_y(0) / (W.node_y(1) - W.node_y(0))), 0L,
                                                       static_cast<long>(n - 1)));
  std::size_t lo = i0, hi = i0;
  while (lo > 0 && graph(lo - 1)) --lo;
  while (hi + 1 < n && graph(hi + 1)) ++hi;
  const double h = W.node_y(1) - W.node_y(0);
  const double y_first = Y(W.node_y(lo)), y_last = Y(W.node_y(hi));
  const std::size_t m = static_cast<std::size_t>(std::floor((y_last - y_first) / h + 1e-9)) + 1;
  // Room for the nodes of any roll up to kRollRoom (and this one): the rotated span is at most
  // (n − 1) h + |sin δ| (z span), so a curve kept for one roll takes another's in place.
  constexpr double kRollRoom = 0.05;  // [rad], MultiHertzOptions::roll's bound
  const std::size_t room = std::max(
      m, n + static_cast<std::size_t>(std::ceil(std::max(std::fabs(sn), std::sin(kRollRoom)) * W.node_z_span() / h)) + 2);
  thread_local std::vector<double> z, dz, k;  // the nodes, kept for the next call
  for (auto* v : {&z, &dz, &k}) v->reserve(room);
  z.assign(m, 0.0);
  dz.assign(m, 0.0);
  k.assign(m, 0.0);
  std::size_t i = lo;  // source interval [node i, node i + 1] holding the target
  for (std::size_t j = 0; j < m; ++j) {
    const double yt = y_first + h * static_cast<double>(j);
    while (i + 1 < hi && Y(W.node_y(i + 1)) < yt) ++i;
    const double a = W.node_y(i), b = W.node_y(std::min(i + 1, hi));
    const double fa = Y(a) - yt, fb = Y(b) - yt;
    double y = fa >= 0 ? a : fb <= 0 ? b : a;
    if (fa < 0 && fb > 0) {
      RootTolerance tol;
      tol.abs = 1e-15;
      tol.rel = 0;
      y = bracketed_root([&](double v) { return Y(v) - yt; }, a, b, fa, fb, tol).x;
    }
    double d;
    const double zw = W.z(y, &d);
    z[j] = y * sn + zw * c;
    dz[j] = (d + tn) / (1 - d * tn);  // tan(θ + δ)
    k[j] = W.kappa(y);
  }
  out.assign_nodes(y_first, h, z, dz, k, W, room);
}

}  // namespace mh
