// Stresses below a Hertzian ellipse (contact/rcf/subsurface.hpp) against the closed forms of
// tests/support/hertz_subsurface_reference.hpp: the circular contact on its axis (Johnson 1985
// eq. 3.45) and the line contact with and without full-slip traction (McEwen 1949), the latter
// as an ellipse 100 times longer than wide: its centre section differs from plane strain by the
// finite length, 4e-3 p0 in σ_x and σ_y (1e-2 p0 at 40 times, so ∝ a/b: the ellipse's, not the
// quadrature's), 6e-5 p0 in σ_z and σ_xz. Tolerances in units of p0.
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/rcf/subsurface.hpp"
#include "support/hertz_subsurface_reference.hpp"

using namespace mh;
using mh::testing::hertz_circle_axis;
using mh::testing::mcewen;

TEST_CASE("Subsurface: circular Hertz contact on its axis against Johnson eq. 3.45", "[rcf][subsurface]") {
  HertzLoad L;
  L.a = L.b = 1e-3;
  L.p0 = 1e9;
  L.nu = 0.3;
  for (double t : {0.05, 0.2, 0.48, 1.0, 2.5}) {
    CAPTURE(t);
    const Stress s = hertz_stress(L, 0, 0, t * L.a);
    const auto ref = hertz_circle_axis(t, L.nu);
    CHECK(std::fabs(s.zz / L.p0 - ref.z) < 1e-3);
    CHECK(std::fabs(s.xx / L.p0 - ref.r) < 1e-3);
    CHECK(std::fabs(s.yy / L.p0 - ref.r) < 1e-3);
    CHECK(std::fabs(s.xz / L.p0) < 1e-6);
  }
  // The classic peak (Johnson §3.4: τ1 = 0.31 p0 at z = 0.48 a for ν = 0.3), the closed form's
  // own maximum by a fine scan, and the library's search.
  double tmax = 0, zmax = 0;
  for (int i = 1; i <= 20000; ++i) {
    const double t = i * 1e-4;
    const auto r = hertz_circle_axis(t, L.nu);
    if (0.5 * (r.r - r.z) > tmax) tmax = 0.5 * (r.r - r.z), zmax = t;
  }
  CHECK(tmax == Approx(0.31).margin(0.005));
  CHECK(zmax == Approx(0.48).margin(0.01));
  const SubsurfacePeaks P = subsurface_peaks(L);
  CHECK(P.tau_max / L.p0 == Approx(tmax).margin(1e-3));
  CHECK(P.tau_z / L.a == Approx(zmax).margin(0.01));
  CHECK(!P.surface);
}

TEST_CASE("Subsurface: line contact with and without traction against McEwen", "[rcf][subsurface]") {
  HertzLoad L;
  L.a = 1e-3;
  L.b = 100e-3;
  L.p0 = 1e9;
  L.nu = 0.3;
  for (double f : {0.0, 0.2, 0.4}) {
    L.fx = f;
    for (double x : {-0.9, -0.4, 0.0, 0.5, 0.87}) {
      for (double z : {0.1, 0.5, 0.78, 1.2}) {
        CAPTURE(f, x, z);
        const Stress s = hertz_stress(L, x * L.a, 0, z * L.a);
        const auto ref = mcewen(x, z, f, L.nu);
        CHECK(std::fabs(s.xx / L.p0 - ref.xx) < 5e-3);
        CHECK(std::fabs(s.zz / L.p0 - ref.zz) < 2e-4);
        CHECK(std::fabs(s.xz / L.p0 - ref.xz) < 2e-4);
        CHECK(std::fabs(s.yy / L.p0 - ref.yy) < 5e-3);
      }
    }
  }
  // The classic peaks of the frictionless line contact (Johnson §7.2: (σ1 − σ3)/2 = 0.30 p0 at
  // 0.78 a; orthogonal shear ±0.25 p0 at 0.5 a, its amplitude over a pass 0.25 p0).
  L.fx = 0;
  const SubsurfacePeaks P = subsurface_peaks(L);
  CHECK(P.tau_max / L.p0 == Approx(0.300).margin(3e-3));
  CHECK(P.tau_z / L.a == Approx(0.786).margin(0.02));
  CHECK(P.tau_orth_amp / L.p0 == Approx(0.250).margin(3e-3));
  CHECK(P.tau_orth_z / L.a == Approx(0.50).margin(0.02));
}

TEST_CASE("Subsurface: traction moves the von Mises peak to the surface (line contact)", "[rcf][subsurface]") {
  // The closed form's own answer: the traction f* at which McEwen's largest von Mises stress
  // (plane strain, ν = 0.3) moves from below the surface to it, by a scan; then the library's
  // search on either side of it.
  auto peak_depth = [](double f) {
    double best = 0, zb = 0;
    for (int k = 0; k <= 300; ++k) {
      const double z = k == 0 ? 1e-6 : k * 0.005;
      for (int i = -240; i <= 240; ++i) {
        const auto s = mcewen(i * 0.005, z, f, 0.3);
        const double d1 = s.xx - s.yy, d2 = s.yy - s.zz, d3 = s.zz - s.xx;
        const double vm = std::sqrt(0.5 * (d1 * d1 + d2 * d2 + d3 * d3) + 3 * s.xz * s.xz);
        if (vm > best) best = vm, zb = z;
      }
    }
    return zb;
  };
  double f_star = 0;
  for (int i = 0; i <= 60; ++i) {
    const double f = i * 0.01;
    if (peak_depth(f) < 1e-3) { f_star = f; break; }
  }
  CAPTURE(f_star);
  CHECK(f_star > 0.2);
  CHECK(f_star < 0.35);  // "about 0.3" (Johnson §7.2)
  HertzLoad L;
  L.a = 1e-3;
  L.b = 100e-3;
  L.p0 = 1e9;
  L.fx = f_star - 0.05;
  const SubsurfacePeaks below = subsurface_peaks(L);
  CHECK(!below.surface);
  CHECK(below.vm_z / L.a > 0.1);
  L.fx = f_star + 0.05;
  const SubsurfacePeaks at = subsurface_peaks(L);
  CHECK(at.surface);
}
