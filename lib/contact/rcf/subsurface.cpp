// Stresses below a Hertzian ellipse with full-slip traction (subsurface.hpp).
#include "contact/rcf/subsurface.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

#include "contact/strips/strip_influence.hpp"  // gauss_legendre, the library's one Gauss–Legendre rule

namespace mh {

namespace {

constexpr double kPi = 3.14159265358979323846;

void add(Stress& s, const Stress& d, double w) {
  s.xx += w * d.xx, s.yy += w * d.yy, s.zz += w * d.zz;
  s.xy += w * d.xy, s.xz += w * d.xz, s.yz += w * d.yz;
}

}  // namespace

// Boussinesq: unit normal force pressing on the surface at the origin, stress at (x, y, z)
// relative to it (Johnson 1985 eq. 3.20, in cylindrical components turned to Cartesian; the
// term (1 − z/ρ)/r² written 1/(ρ(ρ + z)) so that it has no cancellation near the axis).
Stress boussinesq(double x, double y, double z, double nu) {
  const double r2 = x * x + y * y, rho2 = r2 + z * z, rho = std::sqrt(rho2);
  const double rho5 = rho2 * rho2 * rho, k = 1 - 2 * nu, g = 1 / (2 * kPi);
  const double A = 1 / (rho * (rho + z));
  const double c2 = r2 > 0 ? x * x / r2 : 0.5, s2 = r2 > 0 ? y * y / r2 : 0.5, cs = r2 > 0 ? x * y / r2 : 0.0;
  const double sr = g * (k * A - 3 * z * r2 / rho5);
  const double st = -g * k * (A - z / (rho2 * rho));
  Stress s;
  s.xx = sr * c2 + st * s2;
  s.yy = sr * s2 + st * c2;
  s.xy = (sr - st) * cs;
  s.zz = -3 * g * z * z * z / rho5;
  s.xz = -3 * g * x * z * z / rho5;
  s.yz = -3 * g * y * z * z / rho5;
  return s;
}

// Cerruti: unit tangential force along +x on the surface at the origin (Johnson 1985 eqs.
// 3.22–3.23). Checked symbolically: equilibrium, the Beltrami–Michell compatibility equations,
// a traction-free surface away from the origin, and a net shear −1 on every plane z = const.
Stress cerruti_x(double x, double y, double z, double nu) {
  const double rho2 = x * x + y * y + z * z, rho = std::sqrt(rho2);
  const double rho3 = rho2 * rho, rho5 = rho3 * rho2, k = 1 - 2 * nu, g = 1 / (2 * kPi);
  const double rz = rho + z, rz2 = rz * rz, rz3 = rz2 * rz;
  Stress s;
  s.xx = -g * (3 * x * x * x / rho5 - k * (x / rho3 - 3 * x / (rho * rz2) + x * x * x / (rho3 * rz2) + 2 * x * x * x / (rho2 * rz3)));
  s.yy = -g * (3 * x * y * y / rho5 - k * (x / rho3 - x / (rho * rz2) + x * y * y / (rho3 * rz2) + 2 * x * y * y / (rho2 * rz3)));
  s.xy = -g * (3 * x * x * y / rho5 + k * (y / (rho * rz2) - x * x * y / (rho3 * rz2) - 2 * x * x * y / (rho2 * rz3)));
  s.zz = -3 * g * x * z * z / rho5;
  s.xz = -3 * g * x * x * z / rho5;
  s.yz = -3 * g * x * y * z / rho5;
  return s;
}

// The Cerruti solution of a unit force along +y: cerruti_x with x and y exchanged.
Stress cerruti_y(double x, double y, double z, double nu) {
  const Stress t = cerruti_x(y, x, z, nu);
  Stress s;
  s.xx = t.yy, s.yy = t.xx, s.zz = t.zz, s.xy = t.xy, s.xz = t.yz, s.yz = t.xz;
  return s;
}

namespace {

struct Rule {
  std::vector<double> x, w;
  explicit Rule(int n) { strips_detail::gauss_legendre(n, &x, &w); }
};

}  // namespace

double von_mises(const Stress& s) {
  const double d1 = s.xx - s.yy, d2 = s.yy - s.zz, d3 = s.zz - s.xx;
  return std::sqrt(0.5 * (d1 * d1 + d2 * d2 + d3 * d3) + 3 * (s.xy * s.xy + s.xz * s.xz + s.yz * s.yz));
}

double max_shear(const Stress& s) {
  Eigen::Matrix3d m;
  m << s.xx, s.xy, s.xz, s.xy, s.yy, s.yz, s.xz, s.yz, s.zz;
  const Eigen::Vector3d e = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m, Eigen::EigenvaluesOnly).eigenvalues();
  return 0.5 * (e(2) - e(0));
}

Stress hertz_stress(const HertzLoad& L, double X, double Y, double z, const SubsurfaceOptions& o) {
  static thread_local int cached[3] = {0, 0, 0};
  static thread_local Rule rt(1), rn(1), rf(1);
  if (cached[0] != o.n_theta) rt = Rule(o.n_theta), cached[0] = o.n_theta;
  if (cached[1] != o.n_near) rn = Rule(o.n_near), cached[1] = o.n_near;
  if (cached[2] != o.n_far) rf = Rule(o.n_far), cached[2] = o.n_far;
  Stress out;
  const double ia2 = 1 / (L.a * L.a), ib2 = 1 / (L.b * L.b);
  const double C = X * X * ia2 + Y * Y * ib2 - 1;
  const bool traction = L.fx != 0 || L.fy != 0;
  // p along the ray from the field point's projection: 1 − ρ_e² = −(A r² + B r + C) = A (r − r1)(r2 − r).
  auto load = [&](double r, double c, double s, double w) {
    const double xs = X + r * c, ys = Y + r * s;   // the load point
    const double q = 1 - xs * xs * ia2 - ys * ys * ib2;
    if (q <= 0) return;
    const double p = L.p0 * std::sqrt(q) * w;
    const double dx = X - xs, dy = Y - ys;          // field point relative to the load point
    add(out, boussinesq(dx, dy, z, L.nu), p);
    if (traction) {
      if (L.fx != 0) add(out, cerruti_x(dx, dy, z, L.nu), L.fx * p);
      if (L.fy != 0) add(out, cerruti_y(dx, dy, z, L.nu), L.fy * p);
    }
  };
  const int panels = 8;
  const double dth = 2 * kPi / panels;
  for (int P = 0; P < panels; ++P) {
    for (std::size_t it = 0; it < rt.x.size(); ++it) {
      const double th = dth * (P + 0.5 * (rt.x[it] + 1)), wth = 0.5 * dth * rt.w[it];
      const double c = std::cos(th), s = std::sin(th);
      const double A = c * c * ia2 + s * s * ib2, B = 2 * (X * c * ia2 + Y * s * ib2);
      const double disc = B * B - 4 * A * C;
      if (disc <= 0) continue;
      const double sq = std::sqrt(disc);
      const double r1 = (-B - sq) / (2 * A), r2 = (-B + sq) / (2 * A);
      if (r2 <= 0) continue;
      if (r1 >= 0) {
        // Outside the ellipse: [r1, r2] with a square-root edge at both ends, r = mid − h cos φ.
        const double mid = 0.5 * (r1 + r2), h = 0.5 * (r2 - r1);
        for (std::size_t k = 0; k < rf.x.size(); ++k) {
          const double ph = 0.5 * kPi * (rf.x[k] + 1), wph = 0.5 * kPi * rf.w[k];
          const double r = mid - h * std::cos(ph);
          load(r, c, s, wth * wph * h * std::sin(ph) * r);
        }
        continue;
      }
      // Inside: near panel [0, m] in u = asinh(r/z) (dr = ρ du), far panel [m, r2] with
      // r = r2 − (r2 − m) v² (the square-root edge becomes smooth in v).
      const double m = std::min(8 * z, 0.5 * r2);
      const double um = std::asinh(m / z);
      for (std::size_t k = 0; k < rn.x.size(); ++k) {
        const double u = 0.5 * um * (rn.x[k] + 1), wu = 0.5 * um * rn.w[k];
        const double r = z * std::sinh(u), rho = z * std::cosh(u);
        load(r, c, s, wth * wu * rho * r);
      }
      const double span = r2 - m;
      for (std::size_t k = 0; k < rf.x.size(); ++k) {
        const double v = 0.5 * (rf.x[k] + 1), wv = 0.5 * rf.w[k];
        const double r = r2 - span * v * v;
        load(r, c, s, wth * wv * 2 * span * v * r);
      }
    }
  }
  return out;
}

namespace {

// The pass of the load along x at fixed (y, z) (equivalently the field point moving through a
// fixed load): its von Mises peak and the amplitude measures of SubsurfacePeaks, on nx points
// across the loaded chord at y (0.98 of it), the unloaded state (0) included.
struct Pass {
  double vm = 0, vm_x = 0;
  double tau_orth_amp = 0, tau_eq_amp = 0, sigma_h_at_vm = 0, tau_max = 0;
};
Pass pass_at(const StressField& F, double y, double z, int nx) {
  Pass P;
  const std::pair<double, double> chord = F.chord(y);
  const double mid = 0.5 * (chord.first + chord.second), half = 0.5 * (chord.second - chord.first) * 0.98;
  Stress lo, hi;  // componentwise min and max, starting from the unloaded state
  for (int i = 0; i < nx; ++i) {
    const double x = nx > 1 ? mid - half + 2 * half * i / (nx - 1) : mid;
    const Stress s = F.stress(x, y, z);
    const double vm = von_mises(s);
    if (vm > P.vm) P.vm = vm, P.vm_x = x, P.sigma_h_at_vm = (s.xx + s.yy + s.zz) / 3;
    P.tau_max = std::max(P.tau_max, max_shear(s));
    lo.xx = std::min(lo.xx, s.xx), hi.xx = std::max(hi.xx, s.xx);
    lo.yy = std::min(lo.yy, s.yy), hi.yy = std::max(hi.yy, s.yy);
    lo.zz = std::min(lo.zz, s.zz), hi.zz = std::max(hi.zz, s.zz);
    lo.xy = std::min(lo.xy, s.xy), hi.xy = std::max(hi.xy, s.xy);
    lo.xz = std::min(lo.xz, s.xz), hi.xz = std::max(hi.xz, s.xz);
    lo.yz = std::min(lo.yz, s.yz), hi.yz = std::max(hi.yz, s.yz);
  }
  Stress amp;
  amp.xx = 0.5 * (hi.xx - lo.xx), amp.yy = 0.5 * (hi.yy - lo.yy), amp.zz = 0.5 * (hi.zz - lo.zz);
  amp.xy = 0.5 * (hi.xy - lo.xy), amp.xz = 0.5 * (hi.xz - lo.xz), amp.yz = 0.5 * (hi.yz - lo.yz);
  P.tau_orth_amp = amp.xz;
  P.tau_eq_amp = von_mises(amp) / std::sqrt(3.0);  // √J2 of the amplitude tensor
  return P;
}

// The largest of g(z) on [z_lo, z_hi] by golden-section search, to tol [m].
template <class G>
double golden_max(double z_lo, double z_hi, double tol, G g, double* arg) {
  const double r = 0.5 * (std::sqrt(5.0) - 1);
  double a = z_lo, b = z_hi, c = b - r * (b - a), d = a + r * (b - a);
  double gc = g(c), gd = g(d);
  while (b - a > tol) {
    if (gc >= gd) b = d, d = c, gd = gc, c = b - r * (b - a), gc = g(c);
    else a = c, c = d, gc = gd, d = a + r * (b - a), gd = g(d);
  }
  const double z = gc >= gd ? c : d;
  *arg = z;
  return std::max(gc, gd);
}

}  // namespace

SubsurfacePeaks field_peaks(const StressField& F, const SubsurfaceOptions& o) {
  SubsurfacePeaks R;
  const double c = F.depth_scale;
  const int ny = std::max(1, F.ny), nz = std::max(1, o.nz);
  // Depths denser near the surface: z = c (z_min + (z_max − z_min) t²), t uniform.
  auto depth = [&](int k) {
    const double t = nz > 1 ? double(k) / (nz - 1) : 0.0;
    return c * (o.z_min + (o.z_max - o.z_min) * t * t);
  };
  auto row = [&](int j) {
    return ny > 1 ? F.y_lo + (F.y_hi - F.y_lo) * j / (ny - 1) : 0.5 * (F.y_lo + F.y_hi);
  };
  // The coarse scan: every row × every depth, each quantity's value kept.
  enum { kVm, kTau, kOrth, kEq, kQ };
  std::vector<double> table(static_cast<std::size_t>(kQ * ny * nz));
  auto at = [&](int q, int j, int k) -> double& {
    return table[static_cast<std::size_t>((q * ny + j) * nz + k)];
  };
  auto value = [](int q, const Pass& P) {
    return q == kVm ? P.vm : q == kTau ? P.tau_max : q == kOrth ? P.tau_orth_amp : P.tau_eq_amp;
  };
  for (int j = 0; j < ny; ++j)
    for (int k = 0; k < nz; ++k) {
      const Pass P = pass_at(F, row(j), depth(k), o.nx);
      for (int q = 0; q < kQ; ++q) at(q, j, k) = value(q, P);
    }
  // Each quantity refined from its best coarse point of each of its (at most) two best lateral
  // maxima (a patch of two lobes): in depth between the grid's neighbours of that depth, then
  // across between the neighbouring rows (to y_min, y_max beyond the outer rows), then in depth
  // again about the depth found. A peak on the shallowest depth stays there (the surface itself is
  // not searched).
  const double tol = 1e-3 * c;
  const double dy = ny > 1 ? (F.y_hi - F.y_lo) / (ny - 1) : 0.0;
  const double y_min = std::isnan(F.y_min) ? F.y_lo : F.y_min, y_max = std::isnan(F.y_max) ? F.y_hi : F.y_max;
  struct Found { double v = -1, y = 0, z = 0; int k = 0; };
  constexpr double kSecond = 0.9;
  auto search = [&](int q) {
    std::vector<double> best(static_cast<std::size_t>(ny));
    std::vector<int> kb(static_cast<std::size_t>(ny));
    for (int j = 0; j < ny; ++j) {
      const auto u = static_cast<std::size_t>(j);
      best[u] = -1;
      for (int k = 0; k < nz; ++k)
        if (at(q, j, k) > best[u]) best[u] = at(q, j, k), kb[u] = k;
    }
    std::vector<int> cand;  // the rows of the lateral maxima, best first
    for (int j = 0; j < ny; ++j) {
      const auto u = static_cast<std::size_t>(j);
      if ((j == 0 || best[u] >= best[u - 1]) && (j == ny - 1 || best[u] > best[u + 1])) cand.push_back(j);
    }
    std::sort(cand.begin(), cand.end(), [&](int a, int b) { return best[static_cast<std::size_t>(a)] > best[static_cast<std::size_t>(b)]; });
    // A second lateral maximum only when its coarse value is within kSecond of the best's.
    if (cand.size() > 1 && best[static_cast<std::size_t>(cand[1])] < kSecond * best[static_cast<std::size_t>(cand[0])]) cand.resize(1);
    if (cand.size() > 2) cand.resize(2);
    Found out;
    for (int j : cand) {
      const int k = kb[static_cast<std::size_t>(j)];
      Found f{best[static_cast<std::size_t>(j)], row(j), depth(k), k};
      auto g_z = [&](double zz) { return value(q, pass_at(F, f.y, zz, o.nx)); };
      auto g_y = [&](double yy) { return value(q, pass_at(F, yy, f.z, o.nx)); };
      double arg = 0;
      if (ny > 1) {
        const double lo = std::max(y_min, f.y - dy), hi = std::min(y_max, f.y + dy);
        const double v = golden_max(lo, hi, o.y_tol * c, g_y, &arg);
        if (v > f.v) f.v = v, f.y = arg;
      }
      if (k > 0) {
        const double v = golden_max(depth(k - 1), depth(std::min(k + 1, nz - 1)), tol, g_z, &arg);
        if (v > f.v) f.v = v, f.z = arg;
      }
      if (f.v > out.v) out = f;
    }
    return out;
  };
  const Found vm = search(kVm), tau = search(kTau), orth = search(kOrth), eq = search(kEq);
  // The von Mises and principal shear peaks refined along x too, between the pass's neighbours of
  // its best point.
  const Pass Pv = pass_at(F, vm.y, vm.z, o.nx);
  const std::pair<double, double> cv = F.chord(vm.y);
  const double hx = o.nx > 1 ? 0.98 * (cv.second - cv.first) / (o.nx - 1) : 0.0;
  R.vm_max = vm.v, R.vm_y = vm.y, R.vm_z = vm.z, R.vm_x = Pv.vm_x;
  if (hx > 0) {
    double arg = 0;
    const double v = golden_max(Pv.vm_x - hx, Pv.vm_x + hx, tol, [&](double x) { return von_mises(F.stress(x, vm.y, vm.z)); }, &arg);
    if (v > R.vm_max) R.vm_max = v, R.vm_x = arg;
  }
  R.surface = vm.k == 0;
  R.tau_max = tau.v, R.tau_z = tau.z;
  {
    // Its x: the pass's best point (pass_at keeps the largest value, not where).
    double xb = 0, vb = -1;
    const std::pair<double, double> ct = F.chord(tau.y);
    const double mid = 0.5 * (ct.first + ct.second), half = 0.49 * (ct.second - ct.first);
    for (int i = 0; i < o.nx; ++i) {
      const double x = o.nx > 1 ? mid - half + 2 * half * i / (o.nx - 1) : mid;
      const double v = max_shear(F.stress(x, tau.y, tau.z));
      if (v > vb) vb = v, xb = x;
    }
    const double h = o.nx > 1 ? 2 * half / (o.nx - 1) : 0.0;
    if (h > 0) {
      double arg = 0;
      R.tau_max = std::max(R.tau_max, golden_max(xb - h, xb + h, tol, [&](double x) { return max_shear(F.stress(x, tau.y, tau.z)); }, &arg));
    }
  }
  R.tau_orth_amp = orth.v, R.tau_orth_z = orth.z;
  R.tau_eq_amp = eq.v, R.tau_eq_z = eq.z;
  R.sigma_h = pass_at(F, eq.y, eq.z, o.nx).sigma_h_at_vm;
  return R;
}

SubsurfacePeaks subsurface_peaks(const HertzLoad& L, const SubsurfaceOptions& o) {
  if (!(L.a > 0 && L.b > 0 && L.p0 > 0)) return {};
  StressField F;
  F.stress = [&](double x, double y, double z) { return hertz_stress(L, x, y, z, o); };
  F.chord = [&](double y) {
    const double h = L.a * std::sqrt(std::max(0.0, 1 - y * y / (L.b * L.b)));
    return std::make_pair(-h, h);
  };
  F.depth_scale = std::min(L.a, L.b);
  F.ny = L.fy == 0 ? 1 : std::max(1, o.ny);  // y = 0 is a symmetry plane when f_y = 0
  F.y_lo = F.ny > 1 ? -0.8 * L.b : 0.0;
  F.y_hi = F.ny > 1 ? 0.8 * L.b : 0.0;
  F.y_min = F.ny > 1 ? -L.b : 0.0;  // the lateral refinement may reach the edges
  F.y_max = F.ny > 1 ? L.b : 0.0;
  return field_peaks(F, o);
}

}  // namespace mh
