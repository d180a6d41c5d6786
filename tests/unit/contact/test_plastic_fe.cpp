// The ellipse law against the project's own 3-D finite-element reference (scripts/fe/ellip3d.py,
// tables in tests/data/fe/, their provenance in their '#' lines; scripts/fe/README.md says what
// was validated and to what accuracy). Crossed cylinders R 460 x 300 mm, E = 210 GPa, nu = 0.3.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "contact/ellipse/ellipse_law.hpp"
#include "contact/options.hpp"
#include "output/csv_table.hpp"
#include "support/fe_table.hpp"

using namespace mh;

namespace {
constexpr double kPi = 3.14159265358979323846;

using mh::testing::read_fe_table;
double num(const CsvTable& t, std::size_t row, const char* col) { return mh::testing::fe_num(t, row, col); }

Material steel() {
  Material m;
  m.E = 210e9;
  m.nu = 0.3;
  return m;
}

// The pair's curvature sums [1/m] of the crossed cylinders R 460 x 300 mm (method.md §2, eq. 1).
constexpr double kA = 1.0 / (2 * 0.460), kB = 1.0 / (2 * 0.300);

// The pair's curvature sums [1/m] from the principal relative radii [m]: R_roll along the rolling
// direction (A, the library's x), R_trans across it (B) (method.md §2, eq. 1).
struct Shape {
  const char* name;
  double A, B;
};
constexpr Shape kFlange{"flange-like R 460 x 15 mm", 1.0 / (2 * 0.460), 1.0 / (2 * 0.015)};
constexpr Shape kConformal{"conformal-ish R 460 x 3000 mm", 1.0 / (2 * 0.460), 1.0 / (2 * 3.000)};

// Hertz of the library at the FE load against an elastic FE table (the FE's validation): semi-axes
// sorted (the FE's a is the larger one, along the model's x), centre pressure.
void check_elastic(const char* table, const Shape& g, double tol_axes, double tol_p) {
  const CsvTable t = read_fe_table(table);
  REQUIRE(t.rows.size() >= 2);
  const EllipseLaw L = make_ellipse_law(g.A, g.B, steel(), true);
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const EllipseState s = ellipse_state_for_force(L, num(t, i, "N_N"));
    const double a = std::max(s.a, s.b) * 1e3, b = std::min(s.a, s.b) * 1e3;
    CAPTURE(table, i, num(t, i, "N_N"), num(t, i, "a_fe_mm") / a - 1, num(t, i, "b_fe_mm") / b - 1);
    CHECK(std::fabs(num(t, i, "a_fe_mm") / a - 1) <= tol_axes);
    CHECK(std::fabs(num(t, i, "b_fe_mm") / b - 1) <= tol_axes);
    CHECK(std::fabs(num(t, i, "p_centre_fe_MPa") / (s.p0 * 1e-6) - 1) <= tol_p);
  }
}

// Bands [lo, hi] of law/FE - 1 for the area pi a b and the approach.
struct Band {
  double area_lo, area_hi, approach_lo, approach_hi;
};

// The ellipse law (yield law, or the capped law with p_lim = 2.1 sigma_y) at the FE load of every
// row of a plastic FE table, against the FE area and block-corrected approach.
void check_law(const char* table, const Shape& g, bool yield_law, const Band& band) {
  const CsvTable t = read_fe_table(table);
  REQUIRE(!t.rows.empty());
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    Material mat = steel();
    mat.yield = num(t, i, "sigma_y_MPa") * 1e6;
    mat.p_lim = p_lim_from_yield(mat.yield);
    mat.yield_law = yield_law;
    const EllipseLaw L = make_ellipse_law(g.A, g.B, mat, true);
    const EllipseState s = ellipse_state_for_force(L, num(t, i, "N_N"));
    const double area = kPi * s.a * s.b * 1e6, area_fe = num(t, i, "area_mm2");
    const double approach = s.approach * 1e3, approach_fe = num(t, i, "delta_mm");
    CAPTURE(table, g.name, yield_law, i, num(t, i, "p0el_over_sy"), area / area_fe - 1, approach / approach_fe - 1);
    CHECK(area / area_fe - 1 >= band.area_lo);
    CHECK(area / area_fe - 1 <= band.area_hi);
    CHECK(approach / approach_fe - 1 >= band.approach_lo);
    CHECK(approach / approach_fe - 1 <= band.approach_hi);
  }
}
}  // namespace

TEST_CASE("elastic ellipse against the 3-D FE model (validation of the FE, ellip3d_hertz.csv)", "[plastic][fe]") {
  // The FE model on its finest mesh (n = 8 elements per semi-axis) against the library's Hertz
  // ellipse at the FE load (scripts/fe/README.md): semi-axes within 2.5 % (the FE patch ends
  // between two surface nodes; measured +0.7 … +2.3 %), centre pressure within 0.5 % (measured
  // −0.24 … +0.03 %).
  const CsvTable t = read_fe_table("ellip3d_hertz.csv");
  REQUIRE(t.rows.size() >= 4);
  // (the library's p0 at the FE load is Hertz's 3N/(2π a b); kA, kB are the pair's sums)
  const EllipseLaw L = make_ellipse_law(kA, kB, steel(), true);
  double n_max = 0;
  for (std::size_t i = 0; i < t.rows.size(); ++i) n_max = std::max(n_max, num(t, i, "n"));
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    if (num(t, i, "n") != n_max) continue;
    const EllipseState s = ellipse_state_for_force(L, num(t, i, "N_N"));
    CAPTURE(i, num(t, i, "N_N"));
    CHECK(std::fabs(num(t, i, "a_fe_mm") / (s.a * 1e3) - 1) <= 0.025);
    CHECK(std::fabs(num(t, i, "b_fe_mm") / (s.b * 1e3) - 1) <= 0.025);
    CHECK(std::fabs(num(t, i, "p_centre_fe_MPa") / (s.p0 * 1e-6) - 1) <= 0.005);
  }
}

TEST_CASE("elastic ellipse against the 3-D FE model, flange-like and conformal-ish shapes", "[plastic][fe]") {
  // The same FE model on two other shapes (scripts/fe/README.md), n = 8, two loads each, against
  // the library's Hertz at the FE load: the flange-like R 460 x 15 mm (a/b = 9.0, elongated
  // bricks; with a penalty scaled to the patch) and the conformal-ish R 460 x 3000 mm (a/b = 3.4,
  // a across the track). Measured: semi-axes -1.2 … +2.3 % (flange), +0.03 … +2.2 % (conformal);
  // centre pressure -0.27 … -0.05 % and -0.17 … +0.05 %. Held as the R 460 x 300 table is.
  check_elastic("ellip3d_R460x15_hertz.csv", kFlange, 0.025, 0.005);
  check_elastic("ellip3d_R460x3000_hertz.csv", kConformal, 0.025, 0.005);
}

TEST_CASE("elastic ellipse against the 3-D FE model, second mesh level (n = 12, conformal-ish)", "[plastic][fe]") {
  // The conformal-ish mesh refined from 8 to 12 elements per semi-axis (24 300 nodes;
  // scripts/fe/README.md, "Second mesh level"). Measured against the library's Hertz at the FE
  // load: centre pressure +0.07, +0.16 %; semi-axes +2.85 % (both, at 0.8 of the mesh's peak)
  // and +0.16, +0.64 %. The semi-axes do not come closer than on n = 8: the edge is found to a
  // fraction of an element (at 0.8 p0 the Hertz edge lies 0.28 element short of a node and the
  // estimate stops at that node), 0.3 element being 3.1 % of a at 9.7 elements. Held at 3 %
  // (semi-axes) and 0.5 % (pressure).
  check_elastic("ellip3d_R460x3000_hertz_n12.csv", kConformal, 0.03, 0.005);
}

TEST_CASE("capped ellipse law (p_lim = 2.1 sigma_y) against the 3-D FE table: the deviations method.md §5.1 states", "[plastic][fe]") {
  // Elastic–perfectly-plastic crossed cylinders (ellip3d_R460x300_sy350.csv, and two rows at
  // sigma_y = 500 MPa in ellip3d_R460x300_sy500.csv; in the dimensionless
  // form area/area_el, δ/δ_el against p0_el/σ_y the rows hold for every σ_y: the model is
  // self-similar, scripts/fe/README.md). The capped law (a user's p_lim_MPa) with p_lim = 2.1 σ_y
  // at the FE load, against the FE area π a b and the FE approach (block-corrected). This pins
  // the capped law's deviation to what method.md §5.1 states: area 2 … 9 % smaller than the
  // FE's, approach within 2 % (measured −8.8 … −1.9 % and −1.9 … +0.1 %); bands with 0.5 % of room.
  for (const char* name : {"ellip3d_R460x300_sy350.csv", "ellip3d_R460x300_sy500.csv"}) {
    const CsvTable t = read_fe_table(name);
    REQUIRE(t.rows.size() >= 2);
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      Material mat = steel();
      mat.yield = num(t, i, "sigma_y_MPa") * 1e6;
      mat.p_lim = p_lim_from_yield(mat.yield);
      const EllipseLaw L = make_ellipse_law(kA, kB, mat, true);
      const EllipseState s = ellipse_state_for_force(L, num(t, i, "N_N"));
      const double area = kPi * s.a * s.b * 1e6, area_fe = num(t, i, "area_mm2");
      const double approach = s.approach * 1e3, approach_fe = num(t, i, "delta_mm");
      CAPTURE(name, i, num(t, i, "p0el_over_sy"), area / area_fe - 1, approach / approach_fe - 1);
      CHECK(area / area_fe - 1 >= -0.095);
      CHECK(area / area_fe - 1 <= -0.015);
      CHECK(approach / approach_fe - 1 >= -0.025);
      CHECK(approach / approach_fe - 1 <= 0.005);
    }
  }
}

TEST_CASE("yield law against the 3-D FE table: area and approach within 5 %", "[plastic][fe][yield]") {
  // The law used when the yield stress is given (method.md §5.1: Hertz up to p_y = 1.6 σ_y, slope
  // β = 0.3 above; one calibration for all loads and both yield stresses), at the FE load,
  // against the FE area π a b and approach (block-corrected) of both tables, p0_el/σ_y 1.5 … 3.9:
  // both within 5 % (the aim; measured area −3.0 … +0.4 %, approach −1.2 … +0.4 %).
  for (const char* name : {"ellip3d_R460x300_sy350.csv", "ellip3d_R460x300_sy500.csv"}) {
    const CsvTable t = read_fe_table(name);
    REQUIRE(t.rows.size() >= 2);
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      Material mat = steel();
      mat.yield = num(t, i, "sigma_y_MPa") * 1e6;
      mat.p_lim = p_lim_from_yield(mat.yield);
      mat.yield_law = true;
      const EllipseLaw L = make_ellipse_law(kA, kB, mat, true);
      const EllipseState s = ellipse_state_for_force(L, num(t, i, "N_N"));
      const double area = kPi * s.a * s.b * 1e6, area_fe = num(t, i, "area_mm2");
      const double approach = s.approach * 1e3, approach_fe = num(t, i, "delta_mm");
      CAPTURE(name, i, num(t, i, "p0el_over_sy"), area / area_fe - 1, approach / approach_fe - 1);
      CHECK(std::fabs(area / area_fe - 1) <= 0.05);
      CHECK(std::fabs(approach / approach_fe - 1) <= 0.05);
    }
  }
}

TEST_CASE("yield law against the 3-D FE tables of a flange-like and a conformal-ish ellipse", "[plastic][fe][yield]") {
  // The same law (method.md §5.1), not re-calibrated, against the FE of two other shapes at
  // sigma_y = 350 MPa (scripts/fe/README.md): the flange-like R 460 x 15 mm (a/b = 9, a along the
  // rolling direction) and the conformal-ish R 460 x 3000 mm (a/b = 3.4, a across the track).
  // Flange: area and approach within the 5 % aim (measured area +0.3, +2.2, +2.4, −1.2 % and
  // approach −0.0 … +0.8 % at p0_el/σ_y = 1.5, 2.0, 3.0, 3.9; at 3.9 the FE's b is clipped at its
  // last closed node, a lower bound: a p² extrapolation of the nodal pressures puts the edge
  // 2 % further, which would make the area −3 %, still inside).
  check_law("ellip3d_R460x15_sy350.csv", kFlange, true, {-0.05, 0.05, -0.05, 0.05});
  // Conformal: approach within 5 % (measured −0.6 … +0.4 %, p0_el/σ_y = 1.5 … 3.9). The area
  // misses the aim at the highest load: a KNOWN LIMIT, held at its measured value, not tuned away:
  // −5.4 % at 3.9 (−1.1 %, +0.6 %, +1.1 % at 1.5, 2.0, 3.0; at 1.5 the law is Hertz, and its
  // −1.1 % is the FE's own edge bias). Not the patch's shape alone: the flange at 3.9 grows as
  // much along its short axis and its area matches; the FE area of this row (1.39 area_el against
  // 1.34, 1.36 on the other shapes) carries the n = 8 edge error, up to about +3 % where, as here,
  // the edges are not clipped (method.md §5.1). Lower band: the measured deviation with 0.6 % of
  // room.
  check_law("ellip3d_R460x3000_sy350.csv", kConformal, true, {-0.06, 0.05, -0.05, 0.05});
  // The same row at 3.9 on the second mesh level (n = 12; scripts/fe/README.md "Second mesh level,
  // plastic"): FE area/area_el 1.366 against 1.393 on n = 8, approach, peak and plastic strain
  // within 1 % of n = 8. Against it the law is inside the 5 % aim: area −3.4 %, approach −0.6 %.
  // The n = 8 miss was for the most part the FE's edge error.
  check_law("ellip3d_R460x3000_sy350_n12.csv", kConformal, true, {-0.05, 0.05, -0.05, 0.05});
}

TEST_CASE("capped ellipse law (p_lim = 2.1 sigma_y) against the flange-like and conformal-ish FE tables", "[plastic][fe]") {
  // The deviations method.md §5.1 states for the other shapes: area up to 5 % smaller than the
  // FE's (measured flange −3.8 … +0.3 %, conformal −5.1 … −1.1 %; at p0_el/σ_y = 1.52 the capped
  // law is Hertz and its +0.3 %, −1.1 % are the FE's own edge bias), approach −1.3 … +0.2 %;
  // bands with 0.5 % of room or more.
  check_law("ellip3d_R460x15_sy350.csv", kFlange, false, {-0.045, 0.008, -0.02, 0.007});
  check_law("ellip3d_R460x3000_sy350.csv", kConformal, false, {-0.058, -0.005, -0.02, 0.005});
}
