// The traction columns of pressure.csv (px_MPa, py_MPa, slip; docs/outputs.md "pressure.csv"):
// the same grid points as the pressure, the tractions on the rail, kept only when asked.
// References: Coulomb's full sliding (|p| = μ p at every point of the multi-Hertzian grid, the
// traction along the creepage on the rail), and, for the grid methods, the patch's own forces and
// adhesion fraction (the rows are the elements those sums were taken over).
// Breaks seen to fail: the rail's sign dropped (px on the wheel: the sign check); the kept
// half-space tractions negated (the sums); every seventh element flagged slip (the adhesion
// fraction); the strips' traction rows dropped (no rows).
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "../contact/manchester_fixture.hpp"
#include "contact/solve.hpp"
#include "output/case_tables.hpp"

using namespace mh;

namespace {

std::vector<std::vector<std::string>> rows_of(const std::string& s) {
  std::vector<std::vector<std::string>> out;
  std::istringstream in(s);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::string c;
    std::istringstream ls(line);
    while (std::getline(ls, c, ',')) cells.push_back(c);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    out.push_back(cells);
  }
  return out;
}

MethodOptions friction(Method m, Creepages c, bool keep) {
  MethodOptions o;
  o.method = m;
  o.tangential.mu = 0.3;
  o.tangential.source = TangentialOptions::Source::Creepages;
  o.tangential.creep = c;
  o.tangential.keep_traction = keep;
  return o;
}

}  // namespace

TEST_CASE("pressure.csv traction columns, multi-Hertzian: full sliding is mu p on the rail at every point",
          "[traction][output]") {
  const ContactGeometry& G = testing::manchester_geometry();
  const CaseResult r = solve_contact(G, testing::steel(), 0.0, 50e3, friction(Method::MultiHertzian, {0.05, 0, 0}, true));
  REQUIRE(!r.loaded.empty());
  REQUIRE(r.ellipse_traction.size() == r.loaded.size());
  CHECK(pressure_csv_header(false, true) == "case,ellipse,x_mm,y_mm,p_MPa,px_MPa,py_MPa,slip\n");
  std::string s;
  format_pressure(7, r, false, 21, s, true);
  const auto rows = rows_of(s);
  REQUIRE(rows.size() == 21 * 21 * r.loaded.size());
  double worst = 0;
  int inside = 0;
  for (const auto& row : rows) {
    REQUIRE(row.size() == 8);
    const double p = std::stod(row[4]), px = std::stod(row[5]), py = std::stod(row[6]);
    if (!(p > 0)) {
      CHECK(px == 0);
      CHECK(row[7] == "0");
      continue;
    }
    ++inside;
    CHECK(row[7] == "1");
    CHECK(px > 0);  // on the rail: along ξ > 0 (the wheel's slip), docs/tangential.md
    worst = std::max(worst, std::abs(std::hypot(px, py) - 0.3 * p) / (0.3 * p));
  }
  CHECK(inside > 200);
  CHECK(worst < 3e-3);  // FASTSIM's bound normalised on its cells: 0.22 % (test_traction_grid.cpp)
  // Not kept: the columns are there, empty.
  const CaseResult r0 = solve_contact(G, testing::steel(), 0.0, 50e3, friction(Method::MultiHertzian, {0.05, 0, 0}, false));
  CHECK(r0.ellipse_traction.empty());
  format_pressure(7, r0, false, 3, s, true);
  for (const auto& row : rows_of(s)) {
    REQUIRE(row.size() == 8);
    CHECK(row[5].empty());
    CHECK(row[7].empty());
  }
  // Without friction: the table of before.
  format_pressure(7, r0, false, 3, s, false);
  for (const auto& row : rows_of(s)) CHECK(row.size() == 5);
}

TEST_CASE("pressure.csv traction columns, half-space: the patch's elements, their sums the patch's forces",
          "[traction][output][half_space]") {
  const ContactGeometry& G = testing::manchester_geometry();
  MethodOptions o = friction(Method::HalfSpace, {8e-4, -5e-4, 0.2}, true);
  const CaseResult r = solve_contact(G, testing::steel(), 0.0, 50e3, o);
  REQUIRE(r.patches.size() == 1);
  const PatchResult& P = r.patches[0];
  REQUIRE(P.t.solved);
  REQUIRE(!P.traction.empty());
  CHECK(P.traction.nx == P.nx);
  CHECK(P.traction.pn == P.p);
  CHECK(patch_pressure_csv_header(true) == "case,patch,x_mm,s_mm,y_rail_mm,p_MPa,px_MPa,py_MPa,slip\n");
  std::string with, without;
  format_patch_pressure(3, r, with, true);
  format_patch_pressure(3, r, without, false);
  const auto rw = rows_of(with), ro = rows_of(without);
  REQUIRE(rw.size() == ro.size());
  REQUIRE(static_cast<int>(rw.size()) == P.n_elements);
  double Fx = 0, Fy = 0, adh = 0;
  for (std::size_t i = 0; i < rw.size(); ++i) {
    REQUIRE(rw[i].size() == 9);
    for (int c = 0; c < 6; ++c) CHECK(rw[i][c] == ro[i][c]);  // the same points and pressures
    Fx += std::stod(rw[i][6]);
    Fy += std::stod(rw[i][7]);
    adh += rw[i][8] == "0";
  }
  const double dA = P.dx * P.ds * 1e6;  // mm², the tractions in MPa: N
  // On the rail: minus the forces on the wheel (TangentialResult).
  CHECK(Fx * dA == Approx(-P.t.Fx).epsilon(1e-9));
  CHECK(Fy * dA == Approx(-P.t.Fy).epsilon(1e-9));
  CHECK(adh / static_cast<double>(rw.size()) == Approx(P.t.adhesion_fraction).margin(1e-12));
  CHECK(P.t.adhesion_fraction > 0.05);
  CHECK(P.t.adhesion_fraction < 0.95);
}

TEST_CASE("pressure.csv traction columns, strips: the grid of the strips' pressure, carrying N",
          "[traction][output][strips]") {
  const ContactGeometry& G = testing::manchester_geometry();
  const CaseResult r = solve_contact(G, testing::steel(), 0.0, 50e3, friction(Method::Strips, {8e-4, -5e-4, 0.2}, true));
  REQUIRE(!r.patches.empty());
  std::string s;
  format_patch_pressure(0, r, s, true);
  const auto rows = rows_of(s);
  REQUIRE(!rows.empty());
  for (const PatchResult& P : r.patches) {
    REQUIRE(P.t.solved);
    REQUIRE(!P.traction.empty());
    double N = 0, Fx = 0;
    for (const auto& row : rows) {
      if (std::stoi(row[1]) != P.patch) continue;
      REQUIRE(row.size() == 9);
      N += std::stod(row[5]);
      Fx += std::stod(row[6]);
    }
    const double dA = P.traction.dx * P.traction.ds * 1e6;
    CHECK(N * dA == Approx(P.N).epsilon(1e-9));  // the raster is scaled to carry N (solve.cpp)
    CHECK(Fx * dA == Approx(-P.t.Fx).epsilon(1e-9));
  }
  // Without the tractions kept the strip method writes no element rows (as before).
  const CaseResult r0 = solve_contact(G, testing::steel(), 0.0, 50e3, friction(Method::Strips, {8e-4, -5e-4, 0.2}, false));
  format_patch_pressure(0, r0, s, true);
  CHECK(s.empty());
}
