// Rail heads built from any number of tangent arcs and any flank inclination
// (standard_profiles.hpp RailHeadDefinition): 60E2 and 49E1 (EN 13674-1:2017), and the EN 15302
// reference profiles wheel A and rail A generated from their closed forms.
//
// Reference values: tests/data/rails/README.md (rails-en13674.md, "Values to test against":
// derived from the EN 13674-1:2017 construction as transcribed in rohrbecka/EN13674
// P60E2.swift l.25–31 and l.59–65, P49E1.swift l.25–30 and l.54–59), printed to 4 decimals:
// tolerance 1e-4 mm (the rounding of the printed values is ≤ 5e-5 mm).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "profile/profile.hpp"
#include "profile/read.hpp"
#include "profile/standard_profiles.hpp"

using mh::Inclination;
using mh::Profile;

namespace {

constexpr double mm = 1e-3;
constexpr double kTol_mm = 1e-4;  // rails-en13674.md prints 4 decimals

struct ArcRow {
  double R;             // [mm]
  double yc, zc;        // centre [mm]
  double y1, z1;        // end point [mm]
};
struct RailRow {
  const char* name;
  double flank_n;
  std::vector<ArcRow> arcs;
  double half_width14;  // [mm] half-width 14 mm below the crown
  std::vector<double> end_slope_deg;  // surface slope at the end of each arc
};

const RailRow kRails[] = {
    {"60E2", 20,
     {{200, 0, -200, 11.8890, -0.3537},
      {70, 7.7278, -70.2299, 24.4565, -2.2582},
      {16, 20.6328, -17.7946, 35.3870, -11.6048},
      {8, 28.0099, -14.6997, 35.9999, -14.3002}},
     35.9792,
     {3.408, 13.826, 67.241, 87.138}},
    {"49E1", 17.2,
     {{300, 0, -300, 7.6335, -0.0971},
      {80, 5.5979, -80.0712, 23.4175, -2.0811},
      {13, 20.5218, -14.7545, 33.4999, -13.9999}},
     33.4999,
     {1.458, 12.870, 86.673}},
    // 60E1 and 54E1 through the same general construction (rails-en13674.md; 60E1 agrees with
    // profiles.md and GENSYS' create_UIC60).
    {"60E1", 20,
     {{300, 0, -300, 10.228, std::nan("")}, {80, 7.5005, -80.1279, 26.0265, std::nan("")}, {13, 23.0160, -14.9491, 35.9998, -14.3000}},
     35.9813,
     {}},
    {"54E1", 20,
     {{300, 0, -300, 10.012, std::nan("")}, {80, 7.3421, -80.1225, 24.8635, std::nan("")}, {13, 22.0163, -14.7492, 35.0001, -14.1001}},
     34.9947,
     {}},
};

bool near_mm(double v_m, double ref_mm, double tol_mm = kTol_mm) {
  return std::isnan(ref_mm) || std::abs(v_m / mm - ref_mm) <= tol_mm;
}

/// y [m] > 0 on the field side where the definition is `z` [m] below the crown (bisection).
double field_y_at(const std::string& name, double z, double a, double b) {
  for (int i = 0; i < 200; ++i) {
    const double m = 0.5 * (a + b);
    (mh::standard_profile_z(name, m) > z ? a : b) = m;
  }
  return 0.5 * (a + b);
}

}  // namespace

TEST_CASE("60E2, 49E1 (and 60E1, 54E1): every arc's centre and end point to 1e-4 mm", "[stdprof][rails]") {
  for (const RailRow& r : kRails) {
    CAPTURE(r.name);
    const mh::RailHeadDefinition d = mh::rail_head_definition(r.name);
    CHECK(d.flank_n == r.flank_n);
    const mh::RailHeadConstruction c = mh::construct_rail_head(d);
    REQUIRE(c.arcs.size() == r.arcs.size());
    for (std::size_t k = 0; k < c.arcs.size(); ++k) {
      CAPTURE(k, r.arcs[k].R);
      const mh::RailArc& a = c.arcs[k];
      CHECK(a.R / mm == Approx(r.arcs[k].R).margin(1e-12));
      CHECK(near_mm(a.yc, r.arcs[k].yc));
      CHECK(near_mm(a.zc, r.arcs[k].zc));
      CHECK(near_mm(a.y1, r.arcs[k].y1));
      CHECK(near_mm(a.z1, r.arcs[k].z1));
      // Tangency: consecutive centres R_k − R_{k+1} apart (60E2: 130, 54, 8; 49E1: 220, 67), and
      // the junction on both circles.
      if (k + 1 < c.arcs.size()) {
        const mh::RailArc& b = c.arcs[k + 1];
        CHECK(std::hypot(b.yc - a.yc, b.zc - a.zc) / mm == Approx(r.arcs[k].R - r.arcs[k + 1].R).margin(1e-9));
        CHECK(std::hypot(a.y1 - b.yc, a.z1 - b.zc) / mm == Approx(r.arcs[k + 1].R).margin(1e-9));
        CHECK(b.y0 == a.y1);
        CHECK(b.z0 == a.z1);
      }
      // Slope of the surface at the arc's end: atan((y1 − yc) / (z1 − zc)), 3 decimals (°).
      if (!r.end_slope_deg.empty())
        CHECK(std::atan2(a.y1 - a.yc, a.z1 - a.zc) * 180 / M_PI == Approx(r.end_slope_deg[k]).margin(5e-4));
    }
    // The last arc ends tangent to the flank: the flank's slope there is 1 : flank_n to the vertical.
    CHECK(c.yt == c.arcs.back().y1);
    double s = 0;
    mh::standard_profile_z(r.name, c.yt + 0.01 * mm, &s);
    CHECK(s == Approx(-r.flank_n).epsilon(1e-12));
    // Half-width 14 mm below the crown (the gauge point of the upright rail), on the definition
    // and on the generated 0.1 mm nodes (rail_landmarks: linear between nodes, chord error of
    // 0.1 mm nodes on R8 ≤ 1.6e-4 mm).
    const double y14 = field_y_at(r.name, -14 * mm, c.arcs.back().yc, c.y_end);
    CHECK(near_mm(y14, r.half_width14));
    const Profile p = mh::make_standard_profile(r.name);
    const mh::RailLandmarks L = mh::rail_landmarks(p);
    REQUIRE(L.has_gauge);
    CHECK(std::abs(-L.y_gauge - y14) <= 2e-4 * mm);
    CHECK(L.y_top == 0.0);
    CHECK(L.z_top == 0.0);
  }
}

TEST_CASE("the head's lower corner: fillet centre and tangency points to 1e-4 mm, below what a wheel reaches", "[stdprof][rails]") {
  // Reference: an independent construction (corner point K of the flank and the under-head line,
  // the centre on the corner's bisector at R_f / sin(half the corner angle) from K, the tangency
  // points at R_f / tan(half angle) from K along each edge), from the same definition
  // (rails-en13674.md: flank 1:20, R3, under-head line 1:2.75 through (0, −51), 54E1 (0, −49.4);
  // 49E1 1:17.2, R2, 1:3 through (0, −51.5)), evaluated in double precision on 28 Nov 2026 and
  // printed to 4 decimals. The construction (construct_rail_head) solves the two offset lines.
  struct Row {
    const char* name;
    double R, yc, zc, y_flank, z_flank, y_under, z_under;  // [mm]
  };
  const Row rows[] = {
      {"60E1", 3, 34.0523, -35.4251, 37.0486, -35.2753, 35.0776, -38.2445},
      {"54E1", 3, 33.0017, -34.2072, 35.9979, -34.0574, 34.0269, -37.0266},
      {"60E2", 3, 34.0524, -35.4251, 37.0487, -35.2753, 35.0777, -38.2445},
      {"49E1", 2, 32.9163, -38.4197, 34.9129, -38.3036, 33.5487, -40.3171},
  };
  const double tol = 1.0001 * kTol_mm * mm;  // the reference's rounding: ≤ 5e-5 mm
  for (const Row& r : rows) {
    CAPTURE(r.name);
    const mh::RailHeadConstruction c = mh::construct_rail_head(mh::rail_head_definition(r.name));
    const mh::RailArc& f = c.fillet;
    CHECK(f.R == Approx(r.R * mm).margin(1e-15));
    CHECK(f.yc == Approx(r.yc * mm).margin(tol));
    CHECK(f.zc == Approx(r.zc * mm).margin(tol));
    CHECK(f.y0 == Approx(r.y_flank * mm).margin(tol));
    CHECK(f.z0 == Approx(r.z_flank * mm).margin(tol));
    CHECK(c.y_under == Approx(r.y_under * mm).margin(tol));
    CHECK(c.z_under == Approx(r.z_under * mm).margin(tol));
    CHECK(f.y1 == Approx((r.yc + r.R) * mm).margin(tol));  // the widest point, level with the centre
    CHECK(f.z1 == Approx(r.zc * mm).margin(tol));
    // The fillet starts below the flank the profiles keep (20 mm) and below the region a read
    // rail keeps as touchable (ProfileCheckLimits::kRailContactDepth_mm, 25 mm).
    CHECK(f.z0 < -mh::ProfileCheckLimits::kRailContactDepth_mm * mm);
    CHECK(f.z0 < c.z_end);
  }
}

TEST_CASE("60E2 and 49E1 generated: junctions are nodes, value and slope continuous, symmetric", "[stdprof][rails]") {
  for (const std::string name : {"60E2", "49E1"}) {
    CAPTURE(name);
    const mh::RailHeadConstruction c = mh::construct_rail_head(mh::rail_head_definition(name));
    const Profile p = mh::make_standard_profile(name);
    const auto b = mh::standard_profile_breakpoints(name);
    REQUIRE(b.size() == 2 * c.arcs.size());  // the arcs' ends on both sides, the crown top is no breakpoint
    for (double yb : b) {
      CAPTURE(yb / mm);
      double sl = 0, sr = 0;
      const double zl = mh::standard_profile_z(name, yb, &sl, -1), zr = mh::standard_profile_z(name, yb, &sr, +1);
      CHECK(std::abs(zl - zr) <= 1e-9 * mm);
      CHECK(std::abs(sl - sr) <= 1e-9);
      CHECK(std::find(p.y.begin(), p.y.end(), yb) != p.y.end());
    }
    for (std::size_t i = 0; i < p.size(); ++i) REQUIRE(p.z[i] == Approx(mh::standard_profile_z(name, -p.y[i])).margin(1e-15));
    CHECK(p.z.front() == Approx(-20 * mm).margin(1e-15));
    // Radii of the definition at each arc's middle (paper sign: convex rail positive).
    for (const mh::RailArc& a : c.arcs)
      CHECK(mh::standard_profile_radius(name, 0.5 * (a.y0 + a.y1)) == Approx(a.R).epsilon(1e-14));
  }
  // The 60E2 flank turns vertical at 1:20 and is left out (warning naming R8); 49E1's 1:17.2 flank
  // stays 0.47° short of vertical and is kept.
  const Profile e2 = mh::make_standard_profile("60E2", Inclination::In20);
  REQUIRE(e2.warnings.size() == 1);
  CHECK(e2.warnings[0].find("R8/flank") != std::string::npos);
  const Profile e49 = mh::make_standard_profile("49E1", Inclination::In20);
  CHECK(e49.warnings.empty());
  for (std::size_t i = 1; i < e49.size(); ++i) REQUIRE(e49.y[i] > e49.y[i - 1]);
}

TEST_CASE("EN 15302 wheel A and rail A from their closed forms", "[stdprof][en15302]") {
  // Closed forms: tests/data/en15302/README.md (EN 15302:2021 appendix I as transcribed in
  // rohrbecka/EN15302). Values computed from those formulas by hand (r = radius increase, d =
  // depth below the rail reference), 1e-4 mm.
  struct Pt { const char* name; double y, z; };
  const Pt pts[] = {
      {"EN15302-wheel-A", -70, -9.51926},        // flange back: 9.51926 + √(20.5² − 20.5²)
      {"EN15302-wheel-A", -55, -28.00065},       // flange tip: 16.00065 + 12
      {"EN15302-wheel-A", 18.4173, 0.49194},     // end of the R345 tread arc
      {"EN15302-wheel-A", 60, 2.49192},          // r = 1.50804 − 0.066666·60 = −2.49192
      {"EN15302-rail-A", 0, -1.8601e-6},         // R300: 299.48349 − √(300² − 17.5966²)
      {"EN15302-rail-A", 14.29829, 0.491775},    // top of the field-side R80, the highest point
      {"EN15302-rail-A", -15, -1.4978141},       // gauge-side R80: 80.277908 − √(80² − 13.9175²)
      {"EN15302-rail-A", -30, -8.0466665},       // gauge-side R13: 15.899044 − √(13² − 10.36051²)
      {"EN15302-rail-A", 35, -3.9069377},        // field-side R13: 13.598369 − √(13² − 8.66465²)
  };
  for (const Pt& q : pts) {
    CAPTURE(q.name, q.y);
    CHECK(mh::standard_profile_z(q.name, q.y * mm) / mm == Approx(q.z).margin(1e-4));
  }
  const Profile w = mh::make_standard_profile("EN15302-wheel-A");
  CHECK(w.kind == mh::ProfileKind::Wheel);
  CHECK(mh::wheel_landmarks(w).y_tip == Approx(-55 * mm).margin(1e-12));
  const Profile r = mh::make_standard_profile("EN15302-rail-A");
  // The gauge point 14 mm below the highest point lies at local y ≈ −32.42 mm (README).
  const mh::RailLandmarks L = mh::rail_landmarks(r);
  REQUIRE(L.has_gauge);
  CHECK(L.y_gauge / mm == Approx(-32.42).margin(0.005));
  // Rail A is defined canted 1:20: no further inclination.
  REQUIRE_THROWS_AS(mh::make_standard_profile("EN15302-rail-A", Inclination::In40), mh::InputError);
  REQUIRE_NOTHROW(mh::make_standard_profile("EN15302-rail-A", Inclination::AsIs));
  REQUIRE_THROWS_AS(mh::rail_head_definition("EN15302-rail-A"), mh::InputError);
}
