// Stresses below a grid patch (contact/rcf/grid_subsurface.hpp) against CONTACT's subsurface
// stresses (tests/data/contact_subsurface/, made by scripts/contact_subsurface_refs.py): the same
// piecewise-constant element loads that CONTACT solved and then loaded into its own subsurface
// calculation (exact influence functions of a uniformly loaded rectangle), the stresses at the
// same points. Both sides compute the stresses of the SAME loading, so the comparison tests the
// stress computation alone: a discrete Hertzian patch and a wheel–rail patch of the Manchester
// benchmark, each frictionless and in steady rolling with partial slip.
// Tolerances in MPa, about 1.5 × the largest difference measured over each case's points (about
// 2.5e-4 of the largest stress: the quadrature's, it falls tenfold with the quadrature doubled).
// Broken once to see it fail: grid_stress adding the traction along y with its sign reversed
// (both rolling cases and the doubled-quadrature check fail; the frictionless ones pass).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/rcf/grid_subsurface.hpp"
#include "support/contact_elements.hpp"
#include "support/data_csv.hpp"

using namespace mh;
using mh::test::csv_num;
using mh::test::read_data_csv;

namespace {

constexpr double kMPa = 1e6, kMm = 1e-3;

// CONTACT's loaded elements of one case as a GridLoad (element centres on a regular grid).
GridLoad contact_load(const std::string& name) {
  const CsvTable cases = read_data_csv("contact_subsurface/cases.csv");
  std::size_t r = 0;
  while (r < cases.rows.size() && cases.rows[r][0] != name) ++r;
  REQUIRE(r < cases.rows.size());
  const CsvTable e = read_data_csv("contact_subsurface/" + name + "_elements.csv");
  REQUIRE(!e.rows.empty());
  GridLoad G = mh::test::grid_load_from_elements(e, csv_num(cases, r, "dx_mm") * kMm, csv_num(cases, r, "dy_mm") * kMm,
                                                 csv_num(cases, r, "nu"), "y_mm", "py_MPa");
  const bool traction = std::any_of(G.qx.begin(), G.qx.end(), [](double q) { return q != 0; }) ||
                        std::any_of(G.qy.begin(), G.qy.end(), [](double q) { return q != 0; });
  if (!traction) G.qx.clear(), G.qy.clear();
  return G;
}

struct Difference {
  double max_MPa = 0;    // largest |σ_ij − σ_ij(CONTACT)| over the points and components
  double scale_MPa = 0;  // largest |σ_ij(CONTACT)|
};

Difference compare(const std::string& name, const GridQuadrature& q = {}) {
  const GridLoad G = contact_load(name);
  const CsvTable s = read_data_csv("contact_subsurface/" + name + "_stresses.csv");
  REQUIRE(s.rows.size() > 500);
  Difference d;
  const char* cols[6] = {"sxx_MPa", "syy_MPa", "szz_MPa", "sxy_MPa", "sxz_MPa", "syz_MPa"};
  for (std::size_t k = 0; k < s.rows.size(); ++k) {
    const Stress t = grid_stress(G, csv_num(s, k, "x_mm") * kMm, csv_num(s, k, "y_mm") * kMm, csv_num(s, k, "z_mm") * kMm, q);
    const double mine[6] = {t.xx, t.yy, t.zz, t.xy, t.xz, t.yz};
    for (int c = 0; c < 6; ++c) {
      const double ref = csv_num(s, k, cols[c]);
      d.max_MPa = std::max(d.max_MPa, std::fabs(mine[c] / kMPa - ref));
      d.scale_MPa = std::max(d.scale_MPa, std::fabs(ref));
    }
  }
  return d;
}

}  // namespace

TEST_CASE("Grid subsurface: CONTACT's stresses below its own grid patches", "[rcf][subsurface][grid][contact]") {
  struct Row {
    const char* name;
    double tol_MPa;  // measured: see the comment of each row
  };
  const Row rows[] = {
      {"hertz_frictionless", 0.55},   // measured 0.364 MPa (largest stress 1589 MPa)
      {"hertz_rolling", 0.55},        // 0.358 MPa (1588 MPa)
      {"mbench_frictionless", 0.3},   // 0.189 MPa (670 MPa)
      {"mbench_rolling", 0.3},        // 0.189 MPa (662 MPa)
  };
  for (const Row& r : rows) {
    CAPTURE(r.name);
    const Difference d = compare(r.name);
    CAPTURE(d.max_MPa, d.scale_MPa);
    CHECK(d.max_MPa <= r.tol_MPa);
  }
  // The difference is the quadrature's (GridQuadrature): doubled, it falls tenfold towards
  // CONTACT's closed-form rectangles (measured 0.012 MPa; CONTACT's 6 printed digits: 1e-3 MPa).
  GridQuadrature q2;
  q2.near_theta = 16, q2.near_radial = 24, q2.points_per_distance = 24, q2.max_points = 32;
  CHECK(compare("mbench_rolling", q2).max_MPa <= 0.02);
}
