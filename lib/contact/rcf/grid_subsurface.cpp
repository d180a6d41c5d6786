// Stresses below a grid patch (grid_subsurface.hpp).
#include "contact/rcf/grid_subsurface.hpp"

#include <algorithm>
#include <cmath>

#include "contact/strips/strip_influence.hpp"  // gauss_legendre, the library's one Gauss–Legendre rule

namespace mh {

namespace {

constexpr double kPiG = 3.14159265358979323846;

struct Rules {
  std::vector<std::vector<double>> x, w;  // rule n at index n, on [−1, 1]
  const std::vector<double>& xs(int n) { grow(n); return x[static_cast<std::size_t>(n)]; }
  const std::vector<double>& ws(int n) { grow(n); return w[static_cast<std::size_t>(n)]; }
  void grow(int n) {
    while (static_cast<int>(x.size()) <= n) {
      const int k = static_cast<int>(x.size());
      x.emplace_back(), w.emplace_back();
      if (k > 0) strips_detail::gauss_legendre(k, &x.back(), &w.back());
    }
  }
};

void add(Stress& s, const Stress& d, double f) {
  s.xx += f * d.xx, s.yy += f * d.yy, s.zz += f * d.zz;
  s.xy += f * d.xy, s.xz += f * d.xz, s.yz += f * d.yz;
}

}  // namespace

namespace {

// The stress per unit load of the rectangle region [X, X + A] × [Y, Y + B] seen from (X, Y, z): the
// field point above a corner of the region, sx = sgn A, sy = sgn B. Polar about the corner, two
// triangles split by the diagonal, r = z sinh u (dr = ρ du: the kernels' 1/ρ² near the corner is
// cancelled and their scale z resolved), n_theta × n_u Gauss points per triangle. `pressure`,
// `tx`, `ty`: which kernels. Unsigned: the integral over the region, whatever the signs.
void corner_region(double A, double B, double z, double nu, int n_theta, int n_u, Rules& rules, bool pressure,
                   bool tx, bool ty, Stress& sp, Stress& sx_, Stress& sy_) {
  const double a = std::fabs(A), b = std::fabs(B);
  if (!(a > 0 && b > 0)) return;
  const double sx = A > 0 ? 1 : -1, sy = B > 0 ? 1 : -1;
  const double th0 = std::atan2(b, a);
  rules.grow(std::max(n_theta, n_u));  // before taking references into the rules
  const std::vector<double>& gt = rules.xs(n_theta);
  const std::vector<double>& wt = rules.ws(n_theta);
  const std::vector<double>& gu = rules.xs(n_u);
  const std::vector<double>& wu = rules.ws(n_u);
  for (int tri = 0; tri < 2; ++tri) {
    const double lo = tri == 0 ? 0.0 : th0, hi = tri == 0 ? th0 : 0.5 * kPiG;
    for (std::size_t k = 0; k < gt.size(); ++k) {
      const double th = lo + 0.5 * (hi - lo) * (gt[k] + 1), wth = 0.5 * (hi - lo) * wt[k];
      const double c = std::cos(th), s = std::sin(th);
      const double R = tri == 0 ? a / c : b / s;
      const double um = std::asinh(R / z);
      for (std::size_t m = 0; m < gu.size(); ++m) {
        const double u = 0.5 * um * (gu[m] + 1), w = wth * 0.5 * um * wu[m];
        const double r = z * std::sinh(u), rho = z * std::cosh(u);
        const double dx = -sx * r * c, dy = -sy * r * s;  // field point relative to the load point
        const double ww = w * rho * r;
        if (pressure) add(sp, boussinesq(dx, dy, z, nu), ww);
        if (tx) add(sx_, cerruti_x(dx, dy, z, nu), ww);
        if (ty) add(sy_, cerruti_y(dx, dy, z, nu), ww);
      }
    }
  }
}

}  // namespace

Stress grid_stress(const GridLoad& G, double x, double y, double z, const GridQuadrature& q) {
  static thread_local Rules rules;
  rules.grow(std::max({q.max_points, q.near_theta, q.near_radial}));  // no growth (and moved rules) below
  Stress out;
  const bool tx = !G.qx.empty(), ty = !G.qy.empty();
  const double h = std::max(G.dx, G.dy), hx = 0.5 * G.dx, hy = 0.5 * G.dy;
  for (int j = 0; j < G.ny; ++j) {
    const double yc = G.y0 + j * G.dy;
    const double ly = std::max(0.0, std::fabs(y - yc) - hy);
    for (int i = 0; i < G.nx; ++i) {
      const std::size_t e = static_cast<std::size_t>(i) + static_cast<std::size_t>(G.nx) * static_cast<std::size_t>(j);
      const double p = G.p[e], fx = tx ? G.qx[e] : 0.0, fy = ty ? G.qy[e] : 0.0;
      if (p == 0 && fx == 0 && fy == 0) continue;
      const double xc = G.x0 + i * G.dx;
      const double lx = std::max(0.0, std::fabs(x - xc) - hx);
      const double d = std::sqrt(lx * lx + ly * ly + z * z);
      Stress e_s, e_x, e_y;  // the element's stress per unit load of each kind
      if (d < q.near_distance * h) {
        // Near: the rectangle as the signed sum of the four regions from the field point's
        // projection to its corners, each integrated about that corner (corner_region).
        for (int cx = 0; cx < 2; ++cx)
          for (int cy = 0; cy < 2; ++cy) {
            const double A = xc + (cx ? hx : -hx) - x, B = yc + (cy ? hy : -hy) - y;
            // ∫ over [x1, x2] = ∫ from x to x2 − ∫ from x to x1 in each direction; an oriented
            // integral from x to x + A is sgn(A) times the region's.
            const double sign = (cx ? 1.0 : -1.0) * (cy ? 1.0 : -1.0) * (A > 0 ? 1.0 : -1.0) * (B > 0 ? 1.0 : -1.0);
            Stress rs, rx, ry;
            corner_region(A, B, z, G.nu, q.near_theta, q.near_radial, rules, p != 0, fx != 0, fy != 0, rs, rx, ry);
            add(e_s, rs, sign), add(e_x, rx, sign), add(e_y, ry, sign);
          }
      } else {
        const int n = std::clamp(static_cast<int>(std::ceil(q.points_per_distance * h / d)), 1, q.max_points);
        const std::vector<double>& gx = rules.xs(n);
        const std::vector<double>& gw = rules.ws(n);
        for (int b = 0; b < n; ++b) {
          const double ys = yc + hy * gx[static_cast<std::size_t>(b)];
          for (int a = 0; a < n; ++a) {
            const double xs = xc + hx * gx[static_cast<std::size_t>(a)];
            const double w = gw[static_cast<std::size_t>(a)] * gw[static_cast<std::size_t>(b)] * hx * hy;
            if (p != 0) add(e_s, boussinesq(x - xs, y - ys, z, G.nu), w);
            if (fx != 0) add(e_x, cerruti_x(x - xs, y - ys, z, G.nu), w);
            if (fy != 0) add(e_y, cerruti_y(x - xs, y - ys, z, G.nu), w);
          }
        }
      }
      add(out, e_s, p);
      if (fx != 0) add(out, e_x, fx);
      if (fy != 0) add(out, e_y, fy);
    }
  }
  return out;
}

SubsurfacePeaks grid_subsurface_peaks(const GridLoad& G, const SubsurfaceOptions& o, const GridQuadrature& q) {
  // The loaded rows and, per row, the loaded chord (first to last loaded element, their edges).
  int j_lo = G.ny, j_hi = -1;
  std::vector<std::pair<double, double>> chord(static_cast<std::size_t>(std::max(G.ny, 0)), {NAN, NAN});
  double x_lo = INFINITY, x_hi = -INFINITY;
  for (int j = 0; j < G.ny; ++j)
    for (int i = 0; i < G.nx; ++i) {
      if (!(G.p[static_cast<std::size_t>(i + G.nx * j)] > 0)) continue;
      j_lo = std::min(j_lo, j), j_hi = std::max(j_hi, j);
      auto& c = chord[static_cast<std::size_t>(j)];
      const double l = G.x0 + (i - 0.5) * G.dx, r = G.x0 + (i + 0.5) * G.dx;
      c.first = std::isnan(c.first) ? l : std::min(c.first, l);
      c.second = std::isnan(c.second) ? r : std::max(c.second, r);
      x_lo = std::min(x_lo, l), x_hi = std::max(x_hi, r);
    }
  if (j_hi < 0) return {};
  const double y_lo = G.y0 + (j_lo - 0.5) * G.dy, y_hi = G.y0 + (j_hi + 0.5) * G.dy;
  const double y_half = 0.5 * (y_hi - y_lo);
  StressField F;
  F.stress = [&](double x, double y, double z) { return grid_stress(G, x, y, z, q); };
  F.chord = [&](double y) {
    const int j = std::clamp(static_cast<int>(std::lround((y - G.y0) / G.dy)), j_lo, j_hi);
    const auto& c = chord[static_cast<std::size_t>(j)];
    return std::isnan(c.first) ? std::make_pair(0.5 * (x_lo + x_hi), 0.5 * (x_lo + x_hi)) : c;
  };
  F.depth_scale = std::min(0.5 * (x_hi - x_lo), y_half);
  // The coarse rows over the whole loaded width, from the first loaded row's centre to the last's
  // (the largest stress may lie below an edge row: a patch's pressure lobe at its side); the
  // refinement up to the loaded edges.
  F.ny = std::max(1, 2 * o.ny - 1);
  F.y_lo = G.y0 + j_lo * G.dy, F.y_hi = G.y0 + j_hi * G.dy;
  F.y_min = y_lo, F.y_max = y_hi;
  // Shallower than one element the field is that of the elements' steps of pressure, not of the
  // pressure they sample (5 % of p0 in σ_zz at a quarter element below a Hertzian grid): the
  // search starts one element deep.
  SubsurfaceOptions og = o;
  og.z_min = std::max(o.z_min, std::max(G.dx, G.dy) / F.depth_scale);
  og.z_max = std::max(o.z_max, 2 * og.z_min);
  return field_peaks(F, og);
}

}  // namespace mh
