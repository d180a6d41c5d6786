// Smooth profile representation (profile_curve.hpp): exact on circles and lines, one-sided
// windows at curvature jumps. Synthetic profiles; the real files are tested in
// test_geometry.cpp once read.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "profile/curve.hpp"

using mh::Profile;
using mh::ProfileCurve;

namespace {

// Upper arc of a circle of radius R centred (0, -R) (convex, like a rail crown), y in [y0, y1].
Profile crown(double R, double y0, double y1, double dy) {
  Profile p;
  for (double y = y0; y <= y1 + 1e-12; y += dy) {
    p.y.push_back(y);
    p.z.push_back(std::sqrt(R * R - y * y) - R);
  }
  return p;
}

}  // namespace

TEST_CASE("circle profiles give their radius, height and slope", "[curve]") {
  // Source: exact circles; tolerance 1e-6 relative on the radius (the fit is exact on circles,
  // what remains is rounding), 1e-9 m on z.
  for (double R_mm : {10.0, 50.0, 100.0, 300.0}) {
    const double R = R_mm * 1e-3;
    const double half = std::min(0.8 * R, 30e-3);
    Profile p = crown(R, -half, half, 0.1e-3);
    ProfileCurve c(p);
    REQUIRE(c.window_used() == Approx(1e-3));  // exact data: the narrow window
    for (double y = -half + 2.5e-3; y < half - 2.5e-3; y += 0.37e-3) {
      double dz;
      const double z = c.z(y, &dz);
      CAPTURE(R_mm, y);
      REQUIRE(-1.0 / c.kappa(y) == Approx(R).epsilon(1e-6));
      REQUIRE(z == Approx(std::sqrt(R * R - y * y) - R).margin(1e-9));
      REQUIRE(dz == Approx(-y / std::sqrt(R * R - y * y)).epsilon(1e-6).margin(1e-9));
    }
  }
}

TEST_CASE("a steep straight line has zero curvature and its slope", "[curve]") {
  Profile p;
  for (double y = 0; y <= 20e-3; y += 0.1e-3) { p.y.push_back(y); p.z.push_back(2.75 * y + 1e-3); }
  ProfileCurve c(p);
  for (double y = 1e-3; y < 19e-3; y += 0.5e-3) {
    double dz;
    REQUIRE(c.z(y, &dz) == Approx(2.75 * y + 1e-3).margin(1e-12));
    REQUIRE(dz == Approx(2.75).epsilon(1e-9));
    REQUIRE(std::fabs(c.kappa(y)) < 1e-6);  // [1/m]: a radius above 1 km
  }
}

TEST_CASE("at a curvature jump each side keeps the radius of its own arc", "[curve]") {
  // Two tangent arcs: R 300 mm for y < 10 mm, R 80 mm beyond (the 60E1 crown construction).
  // Rule (profile_curve.hpp): one-sided windows near the jump. Tolerance: 1 % on the radius
  // from 0.05 mm from the junction on.
  const double R1 = 0.300, R2 = 0.080, yj = 0.010;
  // Arc 1 centred (0, -R1). Arc 2 tangent at yj: centre on the normal, distance R2 from the point.
  const double zj = std::sqrt(R1 * R1 - yj * yj) - R1;
  const double nx = yj / R1, nz = (zj + R1) / R1;  // unit outward normal at the junction
  const double cy = yj - R2 * nx, cz = zj - R2 * nz;
  Profile p;
  for (double y = -20e-3; y <= 25e-3 + 1e-12; y += 0.1e-3) {
    p.y.push_back(y);
    p.z.push_back(y <= yj ? std::sqrt(R1 * R1 - y * y) - R1
                          : cz + std::sqrt(R2 * R2 - (y - cy) * (y - cy)));
  }
  ProfileCurve c(p);
  for (double d : {0.05e-3, 0.2e-3, 0.5e-3, 1.0e-3, 1.5e-3}) {
    CAPTURE(d);
    REQUIRE(-1.0 / c.kappa(yj - d) == Approx(R1).epsilon(0.01));
    REQUIRE(-1.0 / c.kappa(yj + d) == Approx(R2).epsilon(0.01));
  }
}

TEST_CASE("noise on a crown does not flip the curvature sign", "[curve]") {
  // 300 mm crown with ±2 µm uniform noise (a good measuring device): with the default 1 mm
  // window the curvature must stay negative (convex) everywhere away from the ends.
  Profile p = crown(0.300, -30e-3, 30e-3, 0.1e-3);
  std::mt19937 gen(42);
  std::uniform_real_distribution<double> noise(-2e-6, 2e-6);
  for (auto& z : p.z) z += noise(gen);
  ProfileCurve c(p);
  REQUIRE(c.window_used() == Approx(3e-3));  // noise detected: the measured-profile window
  for (double y = -28e-3; y < 28e-3; y += 0.05e-3) REQUIRE(c.kappa(y) < 0);
}

#include "profile/read.hpp"

TEST_CASE("measured rails: no spurious curvature sign change on the crown", "[curve]") {
  // Criterion: on the crown, within ±10 mm of the head top, every 0.01 mm node is
  // convex (kappa < 0): no sign change. As a sanity bound its radius lies between 20 and 1000 mm
  // (nominal crown 300 mm; the worn heavy-haul crown of site_b_hr.prr reaches 49.8 mm).
  // Files: the measured heavy-haul rail site_b_hr.prr, the EN 15302 reference rail A (table),
  // and the Manchester UIC60 in both its SIMPACK and MiniProf versions.
  const std::string dir = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/profiles/";
  for (const char* f : {"site_b_hr.prr", "EN15302_rail_A.dat", "MBench_UIC60_v3.prr", "MBench_UIC60_v3.ban"}) {
    CAPTURE(f);
    mh::ProfileReadOptions o;
    o.kind = mh::ProfileKind::Rail;
    const Profile p = mh::read_profile(dir + f, o);
    const ProfileCurve c(p);
    const mh::RailLandmarks L = mh::rail_landmarks(p);
    for (int i = -1000; i <= 1000; ++i) {
      const double y = L.y_top + i * 0.01e-3;
      const double k = c.kappa(y);
      REQUIRE(k < 0);
      REQUIRE(-1.0 / k > 0.020);
      REQUIRE(-1.0 / k < 1.000);
    }
  }
}

#include "profile/standard_profiles.hpp"

TEST_CASE("breakpoint rule on the S1002 flange: each side keeps its own radius", "[curve]") {
  // The S1002 flange (EN 13715, profiles.md) is arc D (R 13, concave) – straight E – arc F (R 20)
  // – arc G (R 12) with curvature jumps at S = −38.4267, −39.7645, −49.6625. The radius used next
  // to a jump must be the radius of the section the point lies on (profile_curve.hpp rule), not a
  // blend. Reference: the definition's analytic radius (standard_profile_radius). Tolerance 1 %
  // on the curvature from 0.1 mm (in y) from the junction on; straight E: |kappa| < 0.5 1/m.
  const Profile w = mh::make_standard_profile("S1002");  // canonical: y = S, z = −F(S)
  const ProfileCurve c(w);
  for (double yj : mh::standard_profile_breakpoints("S1002")) {
    if (yj > -0.0380 || yj < -0.0500) continue;  // the flange junctions D/E, E/F, F/G
    for (double d : {0.1e-3, 0.3e-3}) {
      for (int side : {-1, +1}) {
        const double y = yj + side * d;
        const double R = mh::standard_profile_radius("S1002", y, side);  // [m], paper sign
        const double k_expected = std::isfinite(R) ? 1.0 / R : 0.0;      // wheel: 1/R_wxx = +kappa
        CAPTURE(yj, d, side, R);
        if (k_expected == 0.0)
          REQUIRE(std::fabs(c.kappa(y)) < 0.5);
        else
          REQUIRE(c.kappa(y) == Approx(k_expected).epsilon(0.01));
      }
    }
  }
}
