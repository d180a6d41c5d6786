// Contact tables (docs/tables.md): the interpolant against closed forms (a bilinear field is
// reproduced exactly; values and first derivatives continuous across cells; a contact present
// at one node fades in and out from N = 0), the file round trip and its errors, and the
// interpolation error of a worn measured pair's table against direct strip solves at points that
// were not used to make or refine it.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "contact/solve.hpp"
#include "core/errors.hpp"
#include "input/case_file.hpp"
#include "input/contact_table.hpp"
#include "jobs/contact_table_make.hpp"
#include "jobs/run.hpp"
#include "support/table_fixture.hpp"
#include "wheelset_contact/wheelset_contact.hpp"

namespace {

using namespace mh;

// A hand-made table: t_Y nodes 0, 1, 2.5, 3 mm (uneven), Q nodes 10, 20, 30, 50 kN; track 1 at
// every node with N = f(t_Y, Q); track 2 only at node (2, 1).
template <class F>
ContactTableData synthetic(F f, bool second_track) {
  ContactTableData d;
  d.tY = {0, 1e-3, 2.5e-3, 3e-3};
  d.Q = {10e3, 20e3, 30e3, 50e3};
  d.n_tracks = second_track ? 2 : 1;
  const std::size_t nk = static_cast<std::size_t>(d.n_tracks);
  d.node_status.assign(16, CaseStatus::Ok);
  d.cell_coarse.assign(9, 0);
  d.present.assign(16 * nk, 0);
  d.v.assign(16 * nk * kTableQuantities, 0.0);
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) {
      d.present[(i * 4 + j) * nk] = 1;
      double* v = &d.v[d.at(i, j, 0)];
      v[kTabN] = f(d.tY[i], d.Q[j]);
      v[kTabYRail] = 0.01 + 2 * d.tY[i];
      v[kTabGamma] = 0.02;
      v[kTabPmax] = 1e9;
      if (second_track) {
        double* w = &d.v[d.at(i, j, 1)];
        w[kTabYRail] = -0.03;
        if (i == 2 && j == 1) {
          d.present[(i * 4 + j) * nk + 1] = 1;
          w[kTabN] = 5e3;
          w[kTabPmax] = 8e8;
        }
      }
    }
  return d;
}

double N_of(const TableAnswer& a, int track) {
  for (int k = 0; k < std::min(a.n_contacts, kTableMaxContacts); ++k)
    if (a.c[static_cast<std::size_t>(k)].track == track) return a.c[static_cast<std::size_t>(k)].v[kTabN];
  return 0;
}

// The maker's options of these tests: two threads, no progress lines, `refine` rounds.
TableMakeOptions quiet_options(int refine) {
  TableMakeOptions opt;
  opt.threads = 2;
  opt.quiet = true;
  opt.refine = refine;
  return opt;
}

}  // namespace

TEST_CASE("table lookup reproduces a bilinear field and its derivatives exactly", "[tables]") {
  // f = 3 kN + 2 kN/mm t_Y + 0.4 Q: PCHIP gives the exact slopes of a linear function and the
  // zero cross slope is exact for it, so the bicubic Hermite surface is f itself.
  auto f = [](double t, double Q) { return 3e3 + 2e6 * t + 0.4 * Q; };
  const ContactTableLookup look(synthetic(f, false));
  TableAnswer a;
  for (double t : {0.0, 0.3e-3, 1e-3, 1.7e-3, 2.9e-3, 3e-3})
    for (double Q : {10e3, 14e3, 29.9e3, 41e3, 50e3}) {
      look.lookup(t, Q, 0.0, a);
      REQUIRE(a.status == CaseStatus::Ok);
      REQUIRE(a.n_contacts == 1);
      CHECK(a.c[0].v[kTabN] == Approx(f(t, Q)).epsilon(1e-12));
      CHECK(a.c[0].d_dtY[kTabN] == Approx(2e6).epsilon(1e-9));
      CHECK(a.c[0].d_dQ[kTabN] == Approx(0.4).epsilon(1e-9));
      CHECK(a.c[0].v[kTabYRail] == Approx(0.01 + 2 * t).epsilon(1e-12));
    }
  look.lookup(3.01e-3, 20e3, 0.0, a);
  CHECK(a.status == CaseStatus::OutOfRange);
  CHECK(a.n_contacts == 0);
  look.lookup(1e-3, 60e3, 0.0, a);
  CHECK(a.status == CaseStatus::OutOfRange);
}

TEST_CASE("table lookup: values and first derivatives continuous across cells", "[tables]") {
  auto f = [](double t, double Q) { return Q * (1.2 + std::sin(900 * t)) + 1e-4 * Q * Q; };
  const ContactTableLookup look(synthetic(f, false));
  TableAnswer a, b;
  const double e = 1e-12;  // [m]: far below a cell
  // Across the interior t_Y nodes (1 and 2.5 mm) and Q nodes (20, 30 kN).
  for (double t : {1e-3, 2.5e-3})
    for (double Q : {12e3, 27e3, 44e3}) {
      look.lookup(t - e, Q, 0.0, a);
      look.lookup(t + e, Q, 0.0, b);
      CHECK(std::fabs(a.c[0].v[kTabN] - b.c[0].v[kTabN]) < 1e-3);  // [N]
      CHECK(a.c[0].d_dtY[kTabN] == Approx(b.c[0].d_dtY[kTabN]).epsilon(1e-6).margin(1.0));  // [N/m]
    }
  for (double Q : {20e3, 30e3})
    for (double t : {0.4e-3, 1.9e-3}) {
      look.lookup(t, Q - 1e-6, 0.0, a);
      look.lookup(t, Q + 1e-6, 0.0, b);
      CHECK(std::fabs(a.c[0].v[kTabN] - b.c[0].v[kTabN]) < 1e-3);
      CHECK(a.c[0].d_dQ[kTabN] == Approx(b.c[0].d_dQ[kTabN]).epsilon(1e-6).margin(1e-6));  // [-]
    }
  // The derivatives returned are those of the values (central differences inside a cell).
  for (double t : {0.4e-3, 1.6e-3, 2.7e-3})
    for (double Q : {13e3, 35e3}) {
      look.lookup(t, Q, 0.0, a);
      const double h = 1e-8;
      look.lookup(t + h, Q, 0.0, b);
      TableAnswer c;
      look.lookup(t - h, Q, 0.0, c);
      CHECK(a.c[0].d_dtY[kTabN] == Approx((b.c[0].v[kTabN] - c.c[0].v[kTabN]) / (2 * h)).epsilon(1e-5));
      look.lookup(t, Q + 1e-3, 0.0, b);
      look.lookup(t, Q - 1e-3, 0.0, c);
      CHECK(a.c[0].d_dQ[kTabN] == Approx((b.c[0].v[kTabN] - c.c[0].v[kTabN]) / 2e-3).epsilon(1e-5));
    }
}

TEST_CASE("table lookup: a contact present at one node fades in and out without a step", "[tables]") {
  const ContactTableLookup look(synthetic([](double, double Q) { return Q; }, true));
  TableAnswer a;
  // Along t_Y at the node's Q (20 kN) and between Q nodes: N of track 2 from 0 up to 5 kN at
  // t_Y = 2.5 mm and back, never negative, never a step larger than the slope allows.
  for (double Q : {20e3, 24e3}) {
    double prev = 0, peak = 0;
    const int n = 3000;
    for (int s = 0; s <= n; ++s) {
      const double t = 3e-3 * s / n;
      look.lookup(t, Q, 0.0, a);
      const double N2 = N_of(a, 2);
      CHECK(N2 >= 0);
      CHECK(std::fabs(N2 - prev) < 20.0);  // [N] per 1 µm step: continuous
      if (t < 1e-3) CHECK(N2 == 0);         // cells not touching the node: exactly nothing
      prev = N2;
      peak = std::max(peak, N2);
    }
    CHECK(prev == Approx(0).margin(1e-9));
    // Its force derivative is continuous where it leaves zero (t_Y = 1 mm: the node before).
    TableAnswer b;
    look.lookup(1e-3 - 1e-12, Q, 0.0, a);
    look.lookup(1e-3 + 1e-12, Q, 0.0, b);
    double d_before = 0, d_after = 0;
    for (int k = 0; k < a.n_contacts; ++k)
      if (a.c[static_cast<std::size_t>(k)].track == 2) d_before = a.c[static_cast<std::size_t>(k)].d_dtY[kTabN];
    for (int k = 0; k < b.n_contacts; ++k)
      if (b.c[static_cast<std::size_t>(k)].track == 2) d_after = b.c[static_cast<std::size_t>(k)].d_dtY[kTabN];
    CHECK(d_before == Approx(d_after).margin(1.0));  // [N/m]
    if (Q == 20e3) CHECK(peak == Approx(5e3).epsilon(1e-12));
    else CHECK(peak < 5e3);
  }
}

TEST_CASE("table file: round trip and errors naming the file and line", "[tables]") {
  ContactTableData d = synthetic([](double t, double Q) { return Q * (1 + 100 * t); }, true);
  d.header = {{"schema", kContactTableSchema}, {"tY_mm_nodes", {0, 1, 2.5, 3}}, {"Q_kN_nodes", {10, 20, 30, 50}},
              {"roll_mrad_nodes", {0}}, {"tracks", 2}, {"coarse_cells", {{1, 2, 0}}}};
  d.cell_coarse[1 * 3 + 2] = 1;
  const std::string path = "/tmp/mhcontact_test_table_" + std::to_string(::getpid()) + ".csv";
  {
    std::ofstream o(path);
    write_contact_table(d, o);
  }
  const ContactTableData r = read_contact_table(path);
  REQUIRE(r.v.size() == d.v.size());
  for (std::size_t k = 0; k < d.v.size(); ++k) CHECK(r.v[k] == Approx(d.v[k]).epsilon(1e-14).margin(1e-300));
  CHECK(r.present == d.present);
  CHECK(r.cell_coarse == d.cell_coarse);
  TableAnswer a;
  ContactTableLookup(r).lookup(1.6e-3, 35e3, 0.0, a);  // in cell (1, 2)
  CHECK(a.coarse);
  CHECK(a.status == CaseStatus::OutsideValidity);

  std::stringstream all;
  all << std::ifstream(path).rdbuf();
  const std::string text = all.str();
  auto write = [&](const std::string& s) { std::ofstream(path) << s; };
  // Truncated: the row count.
  write(text.substr(0, text.rfind('\n', text.size() - 2) + 1));
  CHECK_THROWS_WITH(read_contact_table(path), Catch::Contains(path) && Catch::Contains("regenerate"));
  // Another schema.
  std::string other = text;
  other.replace(other.find(kContactTableSchema), std::string(kContactTableSchema).size(), "mhcontact.table/0");
  write(other);
  CHECK_THROWS_WITH(read_contact_table(path), Catch::Contains(path + ":1") && Catch::Contains("mhcontact.table/2"));
  // A bad number on line 5.
  std::string bad = text;
  std::size_t at = 0;
  for (int l = 0; l < 4; ++l) at = bad.find('\n', at) + 1;
  bad.replace(bad.find(',', bad.find(',', bad.find(',', bad.find(',', bad.find(',', bad.find(',', at) + 1) + 1) + 1) + 1) + 1) + 1, 1,
              "x");
  write(bad);
  CHECK_THROWS_WITH(read_contact_table(path), Catch::Contains(path + ":5") && Catch::Contains("N_kN"));
  std::remove(path.c_str());
}

TEST_CASE("table of a worn measured pair: N within 1 % of Q and pmax within 3 % of direct strip solves", "[tables]") {
  // The done-when pair (worn_high_mileage on site_b_hr, docs/tables.md) at the default spacing
  // of docs/tables.md (t_Y 1 mm, Q 40 kN), checked at points off the cell centres the maker
  // measured and refined on: quarter points in t_Y, 0.3 of the cell in Q.
  const test::TestTable tab("worn-table.json");
  const CaseFile& cf = tab.cf;
  const PairGeometry& pg = tab.pg;
  const TableMade& made = tab.made;
  CHECK(made.data.header["coarse_cells"].empty());
  const ContactTableLookup look(made.data);
  TableAnswer a;
  CaseResult r;
  int compared = 0;
  for (double t_mm = -5.75; t_mm < 6; t_mm += 1.5)
    for (double Q_kN : {32.0, 72.0, 112.0}) {
      const double t = t_mm * 1e-3, Q = Q_kN * 1e3;
      r = solve_contact(pg.geo, cf.material, t, Q, cf.method_options());
      look.lookup(t, Q, 0.0, a);
      REQUIRE(r.status == CaseStatus::Ok);
      REQUIRE(a.status == CaseStatus::Ok);
      REQUIRE(r.patches.size() == 1);
      REQUIRE(a.n_contacts == 1);
      INFO("t_Y = " << t_mm << " mm, Q = " << Q_kN << " kN");
      CHECK(std::fabs(a.c[0].v[kTabN] - r.patches[0].N) / Q < 0.01);
      CHECK(a.c[0].v[kTabPmax] == Approx(r.pmax).epsilon(0.03));
      CHECK(a.c[0].v[kTabArea] == Approx(r.area).epsilon(0.05));
      CHECK(std::fabs(a.c[0].v[kTabYRail] - r.patches[0].y_r) < 0.5e-3);
      ++compared;
    }
  CHECK(compared == 24);
}

TEST_CASE("table: a cell whose area misses its tolerance is coarse and not ok", "[tables]") {
  // The measured MiniProf pair avg_wheel on avg_HR (1:40) by `auto`, without refinement: the
  // interpolated total area at some cell centres is off the direct solve by more than tol_area
  // (5 %; 10.9 % measured at 30 kN where the solving method changes between the nodes). Such a
  // cell must answer outside_validity (coarse) like one missing N or pmax: a table row is `ok`
  // only where every quantity it reports was found within its tolerance. Broken on purpose (the
  // area left out of the cell criterion, as before): the cells stayed ok and this test failed.
  const std::string data = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/profiles/";
  nlohmann::json j = {{"wheel", {{"profile", data + "avg_wheel.whl"}, {"nominal_radius_mm", 460}}},
                      {"rail", {{"profile", data + "avg_HR.BAN"}, {"inclination", "1:40"}}},
                      {"material", {{"E_GPa", 210}, {"nu", 0.28}}},
                      {"method", "auto"},
                      {"sweep", {{"tY_mm", {{"from", -6}, {"to", 9}, {"step", 1.5}}}, {"Q_kN", {30, 90, 150}}}}};
  const CaseFile cf = parse_case_json(j, data + "table_area.json", true);
  const PairGeometry pg = build_pair_geometry(cf);
  std::ostringstream err;
  const TableMakeOptions opt = quiet_options(0);
  const TableMade made = make_contact_table(cf, pg, opt, err);
  const std::size_t nQ = made.data.Q.size();
  REQUIRE(made.checks.size() == (made.data.tY.size() - 1) * (nQ - 1));
  int area_only = 0;
  for (std::size_t c = 0; c < made.checks.size(); ++c) {
    const TableCheckError& e = made.checks[c];
    if (!e.compared || !(e.e_area > opt.tol_area)) continue;
    area_only += e.e_N <= opt.tol_N && e.e_pmax <= opt.tol_pmax;
    const nlohmann::json cell = {c / (nQ - 1), c % (nQ - 1), 0};
    INFO("cell " << cell.dump() << ": area off by " << e.e_area);
    bool coarse = false;
    for (const auto& x : made.data.header["coarse_cells"]) coarse = coarse || x == cell;
    CHECK(coarse);
    // The check's record of the table's answer is the written table's (coarse: not ok), so the
    // header's count direct_ok_table_ok leaves it out.
    CHECK(e.table != CaseStatus::Ok);
    // And the lookup at the centre says so.
    const ContactTableLookup look(made.data);
    TableAnswer a;
    look.lookup(e.tY, e.Q, 0.0, a);
    CHECK(a.status != CaseStatus::Ok);
  }
  CHECK(area_only > 0);  // the pair has such cells (else the test tests nothing)
}

TEST_CASE("table refinement in Q: one 120 kN load interval is halved until N, pmax and area hold", "[tables]") {
  // tests/data/tables/worn-table-q.json: the worn measured pair of the test above, t_Y -3 ... 3 mm,
  // with Q nodes 20 and 140 kN only: along Q the peak pressure grows about as Q^(1/3) and the
  // area as Q^(2/3) (Hertz), so the interpolant between two load nodes (a straight line) misses
  // pmax by 8.2 % and the area by 8.4 % at the cell centres (`mhcontact table ... --refine 0`)
  // while t_Y at 1 mm is fine. The maker must halve Q, not t_Y, and then hold the tolerances at loads it
  // neither checked nor refined on (0.3 and 0.7 of the 120 kN span, quarter points in t_Y)
  // against direct strip solves. Broken on purpose (no Q interval ever marked for halving): the
  // maker halved t_Y three times in vain (to 0.125 mm), Q kept its 2 nodes, cells stayed coarse,
  // and this test failed.
  const CaseFile cf = load_case_file(std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/tables/worn-table-q.json", true);
  const PairGeometry pg = build_pair_geometry(cf);
  std::ostringstream err;
  TableMakeOptions opt;
  opt.threads = 2;
  opt.quiet = true;
  const TableMade made = make_contact_table(cf, pg, opt, err);
  INFO("Q nodes " << made.data.header["Q_kN_nodes"].dump() << ", t_Y nodes " << made.data.header["tY_mm_nodes"].dump());
  CHECK(made.data.nQ() > 2);
  CHECK(made.data.nT() == 7);  // t_Y at 1 mm holds: not halved
  CHECK(made.data.header["coarse_cells"].empty());
  const ContactTableLookup look(made.data);
  TableAnswer a;
  CaseResult r;
  int compared = 0;
  for (double t_mm = -2.75; t_mm < 3; t_mm += 1.5)
    for (double Q_kN : {56.0, 104.0}) {
      const double t = t_mm * 1e-3, Q = Q_kN * 1e3;
      r = solve_contact(pg.geo, cf.material, t, Q, cf.method_options());
      look.lookup(t, Q, 0.0, a);
      REQUIRE(r.status == CaseStatus::Ok);
      REQUIRE(a.status == CaseStatus::Ok);
      REQUIRE(r.patches.size() == 1);
      REQUIRE(a.n_contacts == 1);
      INFO("t_Y = " << t_mm << " mm, Q = " << Q_kN << " kN");
      CHECK(std::fabs(a.c[0].v[kTabN] - r.patches[0].N) / Q < 0.01);
      CHECK(a.c[0].v[kTabPmax] == Approx(r.pmax).epsilon(0.03));
      CHECK(a.c[0].v[kTabArea] == Approx(r.area).epsilon(0.05));
      ++compared;
    }
  CHECK(compared == 8);
}

TEST_CASE("a wheelset from two pair tables: lookups at t_Y = +y (left) and -y (right) are the wheelset call's wheels", "[tables]") {
  // docs/tables.md: a table is one pair; a wheelset is the left pair's table at t_Y = y and the
  // right pair's at t_Y = -y (the wheelset call's placement, docs/c-api.md "Frame"), each at its
  // wheel's load. The worn measured pair on both sides (one table serves both) against the
  // wheelset call by the strip method with unequal loads: each wheel's Fy and Fz (pair frame)
  // within the table's tolerance of N (1 % of that wheel's Q). Broken on purpose (the right
  // wheel looked up at t_Y = +y): the right wheel's Fy missed at 4 of its 6 points, by up to
  // 3.1 % of Q, and this failed.
  const test::TestTable tab("worn-table.json");
  const ContactTableLookup look(tab.made.data);
  const WheelsetContact ws(tab.pg.geo, tab.pg.geo, tab.cf.track, tab.cf.material, tab.cf.method_options(), {});
  WheelsetWorkspace work;
  WheelsetResult r;
  TableAnswer a;
  WheelsetPose pose;
  pose.Q_left = 60e3;
  pose.Q_right = 95e3;
  int compared = 0;
  for (double y_mm = -5.3; y_mm < 6; y_mm += 1.9) {
    pose.y = y_mm * 1e-3;
    ws.step(pose, WheelsetStepOptions(), r, work);
    for (const WheelResult* w : {&r.left, &r.right}) {
      const double Q = w == &r.left ? pose.Q_left : pose.Q_right;
      INFO("y = " << y_mm << " mm, " << (w == &r.left ? "left" : "right") << " wheel, t_Y = " << w->tY * 1e3 << " mm");
      REQUIRE(w->r.status == CaseStatus::Ok);
      look.lookup(w == &r.left ? pose.y : -pose.y, Q, 0.0, a);
      REQUIRE(a.status == CaseStatus::Ok);
      CHECK(std::fabs(a.Fy - w->r.Fy) / Q < 0.01);
      CHECK(std::fabs(a.Fz - Q) / Q < 0.01);
      ++compared;
    }
  }
  CHECK(compared == 12);
}

TEST_CASE("table with dropped t_Y nodes: its error is that of the table written, one check per final cell", "[tables]") {
  // The shipped example's pair (S1002 on 60E1 at 1:20, strips) over t_Y 5.7 ... 7.7 mm and Q 20
  // ... 180 kN, two rounds of refinement: t_Y nodes at the flange onset where a load has no answer
  // (at 180 kN: 6.7 mm, where the contact jumps from the flange root onto the flange) are dropped
  // (docs/tables.md "Nodes without an answer"), which makes another interpolant (new cells span
  // them, their neighbours' slopes change). The error the header reports must be the written
  // table's against direct solves at its own cells' centres, made here by solve_contact. Broken
  // once (the checks of the grid before the drop kept, as before 29 Nov 2026): 32 checks against
  // 24 cells (1 Dec 2026; in the shipped example then the cells spanning the dropped nodes, pmax
  // off by up to 32 %, went unreported).
  CaseFile cf = load_case_file(std::string(MHCONTACT_SOURCE_DIR) + "/cases/s1002-60e1-table.json", true);
  cf.sweep_tY_mm = SweepAxis();
  cf.sweep_tY_mm.list = {5.7, 6.7, 7.7};
  cf.sweep_tY_mm.n = 3;
  cf.sweep_Q_kN = SweepAxis();
  cf.sweep_Q_kN.list = {20, 60, 100, 140, 180};
  cf.sweep_Q_kN.n = 5;
  const PairGeometry pg = build_pair_geometry(cf);
  std::ostringstream err;
  const TableMakeOptions opt = quiet_options(2);
  const TableMade made = make_contact_table(cf, pg, opt, err);
  REQUIRE(!made.data.header["dropped_tY_mm"].empty());
  const std::size_t nT = made.data.tY.size(), nQ = made.data.Q.size();
  REQUIRE(made.checks.size() == (nT - 1) * (nQ - 1));
  const ContactTableLookup look(made.data);
  TableAnswer a;
  double worst_pmax = 0;
  int compared = 0;
  for (std::size_t c = 0; c < made.checks.size(); ++c) {
    const std::size_t i = c / (nQ - 1), j = c % (nQ - 1);
    const double t = std::round(0.5 * (made.data.tY[i] + made.data.tY[i + 1]) * 1e9) * 1e-9;  // the maker's rounding to 1e-6 mm
    const double Q = 0.5 * (made.data.Q[j] + made.data.Q[j + 1]);
    const TableCheckError& e = made.checks[c];
    INFO("cell " << i << ", " << j << ": t_Y " << t * 1e3 << " mm, Q " << Q * 1e-3 << " kN");
    CHECK(e.tY == Approx(t).margin(1e-12));
    CHECK(e.Q == Approx(Q).margin(1e-9));
    const CaseResult r = solve_contact(pg.geo, cf.material, t, Q, cf.method_options());
    if (!e.compared) continue;
    REQUIRE(r.status != CaseStatus::NotConverged);
    look.lookup(t, Q, 0.0, a);
    double pmax = 0, area = 0;
    for (int k = 0; k < std::min(a.n_contacts, kTableMaxContacts); ++k) {
      pmax = std::max(pmax, a.c[static_cast<std::size_t>(k)].v[kTabPmax]);
      area += a.c[static_cast<std::size_t>(k)].v[kTabArea];
    }
    // The written table's peak pressure and area at the centre against the direct solve's.
    CHECK(e.e_pmax == Approx(std::fabs(pmax - r.pmax) / r.pmax).margin(1e-9));
    CHECK(e.e_area == Approx(std::fabs(area - r.area) / r.area).margin(1e-9));
    worst_pmax = std::max(worst_pmax, e.e_pmax);
    ++compared;
  }
  CHECK(compared > 0);
  CHECK(made.data.header["error"]["pmax"]["max"].get<double>() == Approx(worst_pmax).epsilon(1e-12));
}
