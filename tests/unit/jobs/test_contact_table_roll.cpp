// Contact tables with a roll axis (docs/tables.md "Roll"): the tricubic interpolant against a
// closed form (a field linear in t_Y, Q and the roll reproduced exactly with its derivatives;
// values and d/droll continuous across roll nodes), a table without a roll axis asked at another
// roll, the file round trip of a three-axis table, and the interpolation error of a worn measured
// pair's table over ±3 mrad against direct strip solves of the rolled wheel at points that were
// not used to make or refine it, and its shards (a rolled wheelset from such tables:
// test_wheelset_table.cpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "contact/solve.hpp"
#include "input/case_file.hpp"
#include "input/contact_table.hpp"
#include "jobs/contact_table_make.hpp"
#include "jobs/contact_table_shards.hpp"
#include "jobs/run.hpp"
#include "support/table_fixture.hpp"

namespace {

using namespace mh;

// A hand-made three-axis table: t_Y nodes 0, 1, 2.5 mm, Q nodes 10, 30, 40 kN, roll nodes −2,
// −0.5, 0, 3 mrad (uneven); one track, N = f(t_Y, Q, roll) and the contact angle 0.02 + 5 roll.
template <class F>
ContactTableData rolled_synthetic(F f) {
  ContactTableData d;
  d.tY = {0, 1e-3, 2.5e-3};
  d.Q = {10e3, 30e3, 40e3};
  d.roll = {-2e-3, -0.5e-3, 0, 3e-3};
  d.n_tracks = 1;
  const std::size_t nn = d.nR() * d.nT() * d.nQ();
  d.node_status.assign(nn, CaseStatus::Ok);
  d.cell_coarse.assign(d.nRc() * (d.nT() - 1) * (d.nQ() - 1), 0);
  d.present.assign(nn, 1);
  d.v.assign(nn * kTableQuantities, 0.0);
  for (std::size_t m = 0; m < d.nR(); ++m)
    for (std::size_t i = 0; i < d.nT(); ++i)
      for (std::size_t j = 0; j < d.nQ(); ++j) {
        double* v = &d.v[d.at(m, i, j, 0)];
        v[kTabN] = f(d.tY[i], d.Q[j], d.roll[m]);
        v[kTabGamma] = 0.02 + 5 * d.roll[m];
        v[kTabPmax] = 1e9;
      }
  return d;
}

}  // namespace

TEST_CASE("table with a roll axis reproduces a trilinear field and its derivatives exactly", "[tables]") {
  // f = 3 kN + 2 kN/mm t_Y + 0.4 Q + 1 kN/mrad roll: PCHIP gives the exact slopes of a linear
  // function along each axis, and the Hermite cubic with exact end slopes is the line; the cross
  // terms are 0, so zero cross slopes are exact too.
  auto f = [](double t, double Q, double r) { return 3e3 + 2e6 * t + 0.4 * Q + 1e6 * r; };
  const ContactTableLookup look(rolled_synthetic(f));
  TableAnswer a;
  int n = 0;
  for (double t = 0; t <= 2.5e-3; t += 0.31e-3)
    for (double Q = 10e3; Q <= 40e3; Q += 4.3e3)
      for (double r = -2e-3; r <= 3e-3; r += 0.37e-3) {
        look.lookup(t, Q, r, a);
        REQUIRE(a.status == CaseStatus::Ok);
        REQUIRE(a.n_contacts == 1);
        CHECK(a.c[0].v[kTabN] == Approx(f(t, Q, r)).margin(1e-6));
        CHECK(a.c[0].d_dtY[kTabN] == Approx(2e6).margin(1e-3));
        CHECK(a.c[0].d_dQ[kTabN] == Approx(0.4).margin(1e-9));
        CHECK(a.c[0].d_droll[kTabN] == Approx(1e6).margin(1e-3));
        CHECK(a.c[0].v[kTabGamma] == Approx(0.02 + 5 * r).margin(1e-12));
        // ∂Fy/∂δ by the product rule: N' sin γ + N cos γ γ'.
        const double g = 0.02 + 5 * r, N = f(t, Q, r);
        CHECK(a.dFy_droll == Approx(1e6 * std::sin(g) + N * std::cos(g) * 5).epsilon(1e-9));
        ++n;
      }
  CHECK(n > 500);
  // Outside the roll range: out_of_range, as outside t_Y or Q.
  look.lookup(1e-3, 20e3, 3.01e-3, a);
  CHECK(a.status == CaseStatus::OutOfRange);
  look.lookup(1e-3, 20e3, -2.01e-3, a);
  CHECK(a.status == CaseStatus::OutOfRange);
}

TEST_CASE("table with a roll axis: values and d/droll continuous across roll nodes", "[tables]") {
  // A field curved along the roll (N ∝ exp(roll / 1 mrad)): PCHIP's node slopes are one per node,
  // so the value and its derivative along the roll agree on both sides of an inner roll node.
  auto f = [](double t, double Q, double r) { return (5e3 + 1e6 * t + 0.1 * Q) * std::exp(r / 1e-3); };
  const ContactTableLookup look(rolled_synthetic(f));
  TableAnswer a, b;
  for (double node : {-0.5e-3, 0.0})
    for (double t : {0.3e-3, 1.7e-3})
      for (double Q : {15e3, 35e3}) {
        const double e = 1e-12;
        look.lookup(t, Q, node - e, a);
        look.lookup(t, Q, node + e, b);
        REQUIRE(a.n_contacts == 1);
        REQUIRE(b.n_contacts == 1);
        CHECK(a.c[0].v[kTabN] == Approx(b.c[0].v[kTabN]).margin(1e-3));  // [N]: 2e-12 rad apart
        CHECK(a.c[0].d_droll[kTabN] == Approx(b.c[0].d_droll[kTabN]).epsilon(1e-6));
        CHECK(a.c[0].d_dtY[kTabN] == Approx(b.c[0].d_dtY[kTabN]).epsilon(1e-6));
        // The derivative is that of the interpolant: central differences agree.
        const double h = 1e-7;
        look.lookup(t, Q, node + 0.3e-3 + h, a);
        look.lookup(t, Q, node + 0.3e-3 - h, b);
        TableAnswer c;
        look.lookup(t, Q, node + 0.3e-3, c);
        CHECK(c.c[0].d_droll[kTabN] == Approx((a.c[0].v[kTabN] - b.c[0].v[kTabN]) / (2 * h)).epsilon(1e-5));
        CHECK(c.dFy_droll == Approx((a.Fy - b.Fy) / (2 * h)).epsilon(1e-5));
      }
}

TEST_CASE("a table without a roll axis asked at another roll: its answer, at best outside_validity", "[tables]") {
  ContactTableData d = rolled_synthetic([](double, double Q, double) { return 0.5 * Q; });
  // Keep the layer at roll 0 only.
  const std::size_t per = d.nT() * d.nQ();
  d.v.assign(d.v.begin() + static_cast<long>(2 * per * kTableQuantities), d.v.begin() + static_cast<long>(3 * per * kTableQuantities));
  d.present.assign(per, 1);
  d.node_status.assign(per, CaseStatus::Ok);
  d.roll = {0.0};
  d.cell_coarse.assign(d.nRc() * (d.nT() - 1) * (d.nQ() - 1), 0);
  const ContactTableLookup look(d);
  TableAnswer a, b;
  look.lookup(1e-3, 20e3, 0.0, a);
  CHECK(a.status == CaseStatus::Ok);
  CHECK_FALSE(a.off_roll);
  look.lookup(1e-3, 20e3, 1e-3, b);
  CHECK(b.status == CaseStatus::OutsideValidity);
  CHECK(b.off_roll);
  REQUIRE(b.n_contacts == 1);
  CHECK(b.c[0].v[kTabN] == a.c[0].v[kTabN]);  // the one layer's answer
  CHECK(b.dFy_droll == 0);
  // A roll that is not a number: out_of_range, as a t_Y that is not.
  look.lookup(1e-3, 20e3, std::nan(""), b);
  CHECK(b.status == CaseStatus::OutOfRange);
}

TEST_CASE("table file with a roll axis: round trip, coarse cells by (t_Y, Q, roll) cell", "[tables]") {
  ContactTableData d = rolled_synthetic([](double t, double Q, double r) { return 1e3 + 1e6 * t + 0.3 * Q + 1e6 * r; });
  d.header = {{"schema", kContactTableSchema}, {"tY_mm_nodes", {0, 1, 2.5}}, {"Q_kN_nodes", {10, 30, 40}},
              {"roll_mrad_nodes", {-2, -0.5, 0, 3}}, {"tracks", 1}, {"coarse_cells", {{1, 0, 2}}}};
  d.cell_coarse[d.cell(2, 1, 0)] = 1;
  const std::string path = "/tmp/mhcontact_test_table_roll_" + std::to_string(::getpid()) + ".csv";
  {
    std::ofstream o(path);
    write_contact_table(d, o);
  }
  const ContactTableData r = read_contact_table(path);
  REQUIRE(r.nR() == 4);
  CHECK(r.roll[3] == Approx(3e-3).epsilon(1e-15));
  REQUIRE(r.v.size() == d.v.size());
  for (std::size_t k = 0; k < d.v.size(); ++k) CHECK(r.v[k] == Approx(d.v[k]).epsilon(1e-14).margin(1e-300));
  CHECK(r.cell_coarse == d.cell_coarse);
  TableAnswer a;
  ContactTableLookup(r).lookup(1.5e-3, 20e3, 1e-3, a);  // in cell (1, 0) of roll cell 2 (0 ... 3 mrad)
  CHECK(a.coarse);
  CHECK(a.status == CaseStatus::OutsideValidity);
  ContactTableLookup(r).lookup(1.5e-3, 20e3, -1e-3, a);  // the same (t_Y, Q) cell of roll cell 0
  CHECK_FALSE(a.coarse);
  // Rows out of order (two roll layers swapped) are refused, naming the line.
  std::stringstream all;
  all << std::ifstream(path).rdbuf();
  std::string text = all.str();
  const std::size_t at = text.find("\n0,10,-0.5,");
  REQUIRE(at != std::string::npos);
  text.replace(at + 1, 10, "0,10,-2,");
  std::ofstream(path) << text;
  CHECK_THROWS_WITH(read_contact_table(path), Catch::Contains(path + ":") && Catch::Contains("roll outer"));
  std::remove(path.c_str());
}

TEST_CASE("table of a worn measured pair over ±3 mrad of roll: N within 1 % of Q, pmax within 3 % of the rolled wheel's direct solves",
          "[tables]") {
  // The done-when pair (worn_high_mileage on site_b_hr) by strips, t_Y −8 ... 8 mm (1 mm), Q 20 ...
  // 140 kN (40 kN), roll −3 ... 3 mrad (1 mrad): the maker measures and refines at cell centres;
  // this test checks at other points: t_Y at quarter points, Q at 0.3 of a cell, the roll at a
  // quarter of a roll cell, each against a direct strip solve of the wheel rolled by that roll.
  const test::TestTable tab("worn-table-roll.json");
  const CaseFile& cf = tab.cf;
  const PairGeometry& pg = tab.pg;
  const TableMade& made = tab.made;
  REQUIRE(made.data.nR() >= 7);
  CHECK(made.data.header["coarse_cells"].empty());
  const ContactTableLookup look(made.data);
  TableAnswer a;
  CaseResult r;
  MethodOptions mo = cf.method_options();
  int compared = 0;
  double worst_pmax = 0, worst_N = 0;
  for (double t_mm = -5.75; t_mm < 6; t_mm += 1.5)
    for (double Q_kN : {32.0, 112.0})
      for (double roll_mrad : {-2.75, -0.25, 1.75}) {
        const double t = t_mm * 1e-3, Q = Q_kN * 1e3, roll = roll_mrad * 1e-3;
        mo.multi_hertzian.roll = roll;
        r = solve_contact(pg.geo, cf.material, t, Q, mo);
        look.lookup(t, Q, roll, a);
        INFO("t_Y = " << t_mm << " mm, Q = " << Q_kN << " kN, roll = " << roll_mrad << " mrad");
        REQUIRE(r.status == CaseStatus::Ok);
        REQUIRE(a.status == CaseStatus::Ok);
        REQUIRE(r.patches.size() == 1);
        REQUIRE(a.n_contacts == 1);
        CHECK(std::fabs(a.c[0].v[kTabN] - r.patches[0].N) / Q < 0.01);
        CHECK(a.c[0].v[kTabPmax] == Approx(r.pmax).epsilon(0.03));
        CHECK(a.c[0].v[kTabArea] == Approx(r.area).epsilon(0.05));
        CHECK(std::fabs(a.c[0].v[kTabYRail] - r.patches[0].y_r) < 0.5e-3);
        worst_pmax = std::max(worst_pmax, std::fabs(a.c[0].v[kTabPmax] / r.pmax - 1));
        worst_N = std::max(worst_N, std::fabs(a.c[0].v[kTabN] - r.patches[0].N) / Q);
        ++compared;
      }
  CHECK(compared == 48);
  WARN("worn pair, roll table: " << compared << " points off the nodes and centres: pmax max " << 100 * worst_pmax
                                  << " %, N max " << 100 * worst_N << " % of Q");
  // The roll matters at these points: a roll-0 lookup misses the rolled wheel's pmax by more than
  // the table's tolerance (4.5 % measured).
  double worst_upright = 0;
  for (double t_mm = -3.75; t_mm < 4; t_mm += 1.5) {
    const double t = t_mm * 1e-3, Q = 32e3;
    mo.multi_hertzian.roll = 2.75e-3;
    r = solve_contact(pg.geo, cf.material, t, Q, mo);
    look.lookup(t, Q, 0.0, a);
    worst_upright = std::max(worst_upright, std::fabs(a.c[0].v[kTabPmax] / r.pmax - 1));
  }
  WARN("the same table looked up upright against the wheel rolled by 2.75 mrad (32 kN): pmax off by up to "
       << 100 * worst_upright << " %");
  CHECK(worst_upright > 0.03);
}

TEST_CASE("table shards with a roll axis: the merged table is byte for byte the one-process table", "[tables]") {
  nlohmann::json j = read_json_file(std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/tables/worn-table-roll.json");
  j["sweep"] = {{"tY_mm", {-2, -1, 0}}, {"Q_kN", {40, 100}}, {"roll_mrad", {-2, 0, 2}}};
  const CaseFile cf = parse_case_json(j, std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/tables/roll-shards.json", true);
  TableMakeOptions opt;
  opt.threads = 2;
  opt.quiet = true;
  opt.refine = 1;
  opt.check_points = GENERATE(1, 3);  // the quarter points of three check points a cell go to the shards too
  const std::string dir = "/tmp/mhcontact_roll_shards_" + std::to_string(::getpid());
  std::ostringstream out, err;
  REQUIRE(table_job(cf, opt, dir + "-one.csv", out, err) <= 1);
  std::vector<std::string> parts;
  for (int k = 1; k <= 3; ++k) {
    parts.push_back(dir + "-part" + std::to_string(k) + ".json");
    REQUIRE(table_shard_job(cf, opt, std::to_string(k) + "/3", parts.back(), out, err) == 0);
  }
  REQUIRE(table_job(cf, opt, dir + "-merged.csv", out, err, parts) <= 1);
  std::stringstream a, b;
  a << std::ifstream(dir + "-one.csv").rdbuf();
  b << std::ifstream(dir + "-merged.csv").rdbuf();
  CHECK(a.str().find("\"roll_mrad_nodes\":[-2.0,0.0,2.0]") != std::string::npos);
  CHECK(a.str() == b.str());
  for (const auto& p : parts) std::remove(p.c_str());
  std::remove((dir + "-one.csv").c_str());
  std::remove((dir + "-merged.csv").c_str());
}

TEST_CASE("three check points a cell: the centre and the diagonal's quarter points, cells missing at a quarter point coarse",
          "[tables]") {
  // S1002 on 60E1 1:40 with a roll axis (cases/s1002-60e1-roll-table.json), unrefined: with one
  // check point a cell, 12 of 48 cells miss a tolerance at their centre; the quarter points
  // find more (docs/tables.md "Checking a table at random points": the one-point table answers
  // `ok` beyond 3 % in peak pressure at 4 of 298 random points). Every cell coarse at its centre
  // stays coarse, and the header says how many points a cell was checked at.
  const CaseFile cf = load_case_file(std::string(MHCONTACT_SOURCE_DIR) + "/cases/s1002-60e1-roll-table.json", true);
  const PairGeometry pg = build_pair_geometry(cf);
  TableMakeOptions opt;
  opt.threads = 2;
  opt.quiet = true;
  opt.refine = 0;
  std::ostringstream err;
  const TableMade one = make_contact_table(cf, pg, opt, err);
  opt.check_points = 3;
  const TableMade three = make_contact_table(cf, pg, opt, err);
  const std::size_t cells = one.data.cell_coarse.size();
  REQUIRE(three.data.cell_coarse.size() == cells);
  CHECK(one.checks.size() == cells);
  CHECK(three.checks.size() == 3 * cells);
  CHECK(three.data.header["check_points"] == 3);
  CHECK(one.data.header["check_points"] == 1);
  std::size_t n1 = 0, n3 = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    n1 += one.data.cell_coarse[c];
    n3 += three.data.cell_coarse[c];
    if (one.data.cell_coarse[c]) CHECK(three.data.cell_coarse[c]);
    // The centre's check is the same; the other two lie inside the cell, off its centre.
    CHECK(three.checks[3 * c].tY == one.checks[c].tY);
    CHECK(three.checks[3 * c + 1].tY < three.checks[3 * c].tY);
    CHECK(three.checks[3 * c + 2].roll > three.checks[3 * c].roll);
  }
  CHECK(n1 == 12);
  CHECK(n3 > n1);
  WARN("unrefined S1002/60E1 roll table: " << n1 << " coarse cells checked at their centres, " << n3 << " at three points");
}
