// Stresses below a grid patch (contact/rcf/grid_subsurface.hpp): the quadrature of one uniformly
// loaded rectangle against the closed form below its centre, the peaks of a Hertzian pressure
// (with and without full-slip traction) sampled on a grid against those of the Hertz field
// (subsurface.hpp, itself checked against closed forms in test_subsurface.cpp), and the
// quadrature's convergence. Tolerances in units of the load's peak pressure.
// Breaks seen to fail: the near rectangles by the Gauss product rule instead of the polar
// quadrature (the rectangle check below its centre), the Cerruti term dropped (five of
// the traction peaks).
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/rcf/grid_subsurface.hpp"

using namespace mh;

namespace {

// σ_zz [per unit q] at depth z below a corner of a rectangle B × L under a uniform pressure q
// (Holl 1940, the Boussinesq solution integrated over the rectangle; Newmark 1935; quoted as the
// corner formula in Poulos & Davis, Elastic Solutions for Soil and Rock Mechanics, 1974, eq. 3.23):
//   σ_z/q = 1/(2π) [atan(BL/(zR)) + BLz/R (1/(B² + z²) + 1/(L² + z²))], R = √(B² + L² + z²).
// Compression: σ_zz = −that.
double corner_sigma_z(double B, double L, double z) {
  const double R = std::sqrt(B * B + L * L + z * z);
  return (std::atan(B * L / (z * R)) + B * L * z / R * (1 / (B * B + z * z) + 1 / (L * L + z * z))) / (2 * M_PI);
}

// A Hertzian pressure p0 √(1 − x²/a² − y²/b²) sampled at the centres of h × h elements, with
// full-slip traction f p along x.
GridLoad hertz_grid(double a, double b, double p0, double f, double h, double nu) {
  GridLoad G;
  G.nx = 2 * static_cast<int>(std::ceil(a / h)) + 1, G.ny = 2 * static_cast<int>(std::ceil(b / h)) + 1;
  G.dx = G.dy = h;
  G.x0 = -h * (G.nx / 2), G.y0 = -h * (G.ny / 2);
  G.nu = nu;
  G.p.assign(static_cast<std::size_t>(G.nx * G.ny), 0.0);
  if (f != 0) G.qx.assign(G.p.size(), 0.0);
  for (int j = 0; j < G.ny; ++j)
    for (int i = 0; i < G.nx; ++i) {
      const double x = G.x0 + i * h, y = G.y0 + j * h, q = 1 - x * x / (a * a) - y * y / (b * b);
      const std::size_t e = static_cast<std::size_t>(i + G.nx * j);
      G.p[e] = q > 0 ? p0 * std::sqrt(q) : 0.0;
      if (f != 0) G.qx[e] = f * G.p[e];
    }
  return G;
}

}  // namespace

TEST_CASE("Grid subsurface: one uniform rectangle against the closed form below its centre", "[rcf][subsurface][grid]") {
  GridLoad G;
  G.nx = G.ny = 1;
  G.dx = 2e-3, G.dy = 1e-3;
  G.p = {1e9};
  for (double t : {0.05, 0.1, 0.3, 1.0, 3.0}) {  // z / dx
    CAPTURE(t);
    const double z = t * G.dx;
    const Stress s = grid_stress(G, 0, 0, z);
    CHECK(s.zz / 1e9 == Approx(-4 * corner_sigma_z(0.5 * G.dx, 0.5 * G.dy, z)).margin(1e-4));  // measured 1e-6
    // Beside the rectangle: the sum of the corner values of four rectangles (superposition).
    const double x = 1.5e-3;  // 0.5 mm beyond its edge
    const double want = corner_sigma_z(x + 1e-3, 0.5e-3, z) - corner_sigma_z(x - 1e-3, 0.5e-3, z);
    CHECK(grid_stress(G, x, 0, z).zz / 1e9 == Approx(-2 * want).margin(1e-4));
  }
}

TEST_CASE("Grid subsurface: a Hertzian pressure on a grid has the Hertz field's peaks", "[rcf][subsurface][grid]") {
  // An ellipse a = 6 mm, b = 4 mm on 0.4 mm elements (15 across a). Measured at f = 0.3: von Mises and
  // principal shear peaks within 3e-4 p0 and 0.002 b of the Hertz field's, τ_eq,a within 7e-4 p0, the
  // orthogonal shear amplitude within 5e-4 p0 (its depth is not compared: the amplitude is flat over
  // 0.40 … 0.47 b, where both searches land anywhere), σ_h within 0.009 p0 (taken at τ_eq,a's depth,
  // as flat).
  const double a = 6e-3, b = 4e-3, p0 = 1e9, nu = 0.3, h = a / 15;
  for (double f : {0.0, 0.3}) {
    CAPTURE(f);
    HertzLoad L;
    L.a = a, L.b = b, L.p0 = p0, L.fx = f, L.nu = nu;
    const SubsurfacePeaks want = subsurface_peaks(L);
    const SubsurfacePeaks got = grid_subsurface_peaks(hertz_grid(a, b, p0, f, h, nu));
    CHECK(got.vm_max / p0 == Approx(want.vm_max / p0).margin(1e-3));
    CHECK(got.vm_z / b == Approx(want.vm_z / b).margin(5e-3));
    CHECK(got.tau_max / p0 == Approx(want.tau_max / p0).margin(1e-3));
    CHECK(got.tau_z / b == Approx(want.tau_z / b).margin(5e-3));
    CHECK(got.tau_orth_amp / p0 == Approx(want.tau_orth_amp / p0).margin(3e-3));
    CHECK(got.tau_eq_amp / p0 == Approx(want.tau_eq_amp / p0).margin(2e-3));
    CHECK(got.sigma_h / p0 == Approx(want.sigma_h / p0).margin(0.02));
    CHECK(got.surface == want.surface);
  }
}

TEST_CASE("Grid subsurface: the quadrature converges", "[rcf][subsurface][grid]") {
  const GridLoad G = hertz_grid(6e-3, 4e-3, 1e9, 0.3, 6e-3 / 20, 0.3);
  GridQuadrature fine;
  fine.near_distance *= 2, fine.near_theta *= 2, fine.near_radial *= 2;
  fine.points_per_distance *= 2, fine.max_points *= 2;
  for (double z : {0.1e-3, 0.5e-3, 2e-3}) {
    CAPTURE(z);
    const Stress s = grid_stress(G, 0.5e-3, 0.3e-3, z), t = grid_stress(G, 0.5e-3, 0.3e-3, z, fine);
    CHECK(von_mises(s) / 1e9 == Approx(von_mises(t) / 1e9).margin(3e-4));  // measured 1.7e-4 at z = 2 mm
    CHECK(s.xz / 1e9 == Approx(t.xz / 1e9).margin(3e-4));
  }
}
