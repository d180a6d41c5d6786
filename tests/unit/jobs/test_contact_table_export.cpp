// The export of a contact table on a regular grid (docs/tables.md "Export for MBS codes"): its
// file read back against direct lookups of the table at every grid point (the interpolation is
// the table's own: a format test), its errors; and, on the worn measured pair, the export read
// bilinearly against direct strip solves at points off the table's nodes and off the export's
// grid, within the bound its header states (an independent check: the grid method itself).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "contact/solve.hpp"
#include "core/errors.hpp"
#include "input/case_file.hpp"
#include "input/contact_table.hpp"
#include "jobs/contact_table_export.hpp"
#include "jobs/contact_table_make.hpp"
#include "jobs/run.hpp"

namespace {

using namespace mh;

// A hand-made table: t_Y nodes 0, 1, 2.5, 3 mm (uneven), Q nodes 10, 20, 30, 50 kN; track 1
// everywhere with N = Q (1 + 100 t_Y); track 2 only at node (2, 1), so that it fades in and out
// between the export's points.
ContactTableData synthetic() {
  ContactTableData d;
  d.tY = {0, 1e-3, 2.5e-3, 3e-3};
  d.Q = {10e3, 20e3, 30e3, 50e3};
  d.n_tracks = 2;
  d.node_status.assign(16, CaseStatus::Ok);
  d.node_status[3 * 4 + 3] = CaseStatus::OutsideValidity;
  d.cell_coarse.assign(9, 0);
  d.present.assign(32, 0);
  d.v.assign(32 * kTableQuantities, 0.0);
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) {
      d.present[(i * 4 + j) * 2] = 1;
      double* v = &d.v[d.at(i, j, 0)];
      v[kTabN] = d.Q[j] * (1 + 100 * d.tY[i]);
      v[kTabYRail] = 0.01 + 2 * d.tY[i];
      v[kTabGamma] = 0.02;
      v[kTabPmax] = 1e9 + 1e4 * d.Q[j];
      v[kTabArea] = 1e-4;
      double* w = &d.v[d.at(i, j, 1)];
      w[kTabYRail] = -0.03;
      w[kTabGamma] = 0.5;
      if (i == 2 && j == 1) {
        d.present[(i * 4 + j) * 2 + 1] = 1;
        w[kTabN] = 5e3;
        w[kTabPmax] = 8e8;
        w[kTabArea] = 2e-5;
      }
    }
  d.header = {{"schema", kContactTableSchema}, {"tY_mm_nodes", {0, 1, 2.5, 3}}, {"Q_kN_nodes", {10, 20, 30, 50}},
              {"roll_mrad_nodes", {0}}, {"tracks", 2}, {"coarse_cells", nlohmann::json::array()}};
  return d;
}

}  // namespace

TEST_CASE("table export: the file read back is the table's lookup at every grid point", "[tables]") {
  const ContactTableData d = synthetic();
  TableExportOptions opt;
  opt.tY_step_mm = 0.25;
  opt.Q_step_kN = 5;
  const ContactTableData ex = export_contact_table(d, "synthetic.csv", "00", opt);
  REQUIRE(ex.nT() == 13);
  REQUIRE(ex.nQ() == 9);
  const std::string path = "/tmp/mhcontact_test_export_" + std::to_string(::getpid()) + ".csv";
  {
    std::ofstream o(path);
    write_contact_table(ex, o);
  }
  const ContactTableData r = read_contact_table(path, kContactTableExportSchema);
  CHECK(r.header["schema"] == kContactTableExportSchema);
  CHECK(r.header["source"]["sha256"] == "00");
  REQUIRE(r.nT() == ex.nT());
  REQUIRE(r.nQ() == ex.nQ());
  const ContactTableLookup look(d);
  TableAnswer a, b;
  int present = 0, faded = 0;
  for (std::size_t i = 0; i < r.nT(); ++i)
    for (std::size_t j = 0; j < r.nQ(); ++j) {
      const double t = 0.25e-3 * static_cast<double>(i), Q = 10e3 + 5e3 * static_cast<double>(j);
      INFO("t_Y = " << t * 1e3 << " mm, Q = " << Q * 1e-3 << " kN");
      REQUIRE(r.tY[i] == Approx(t).margin(1e-15));
      REQUIRE(r.Q[j] == Approx(Q).epsilon(1e-15));
      look.lookup(t, Q, 0.0, a);
      CHECK(r.node_status[i * r.nQ() + j] == a.status);
      // Every track the lookup reports is a present row with its values; every other track's
      // row is absent with zero force, pressure and sizes.
      for (int k = 0; k < 2; ++k) {
        const double* v = &r.v[r.at(i, j, k)];
        const TableContact* c = nullptr;
        for (int n = 0; n < a.n_contacts; ++n)
          if (a.c[static_cast<std::size_t>(n)].track == k + 1) c = &a.c[static_cast<std::size_t>(n)];
        CHECK(static_cast<bool>(r.present[(i * r.nQ() + j) * 2 + static_cast<std::size_t>(k)]) == (c != nullptr));
        for (int q = 0; q < kTableQuantities; ++q) {
          if (c) CHECK(v[q] == Approx(c->v[static_cast<std::size_t>(q)]).epsilon(1e-14).margin(1e-300));
          else if (kTableColumns[q].fades) CHECK(v[q] == 0);
        }
        (c ? present : faded) += k == 1;
      }
      // Read bilinearly, the export gives its grid values back at its points.
      export_linear(r, t, Q, 0.0, b);
      CHECK(b.n_contacts == a.n_contacts);
      CHECK(b.Fy == Approx(a.Fy).epsilon(1e-13));
    }
  // The second track fades in and out between the export's points.
  CHECK(present > 0);
  CHECK(faded > 0);
  // The node with outside_validity: its four cells' points carry it.
  look.lookup(2.9e-3, 45e3, 0.0, a);
  export_linear(r, 2.9e-3, 45e3, 0.0, b);
  CHECK(a.status == CaseStatus::OutsideValidity);
  CHECK(b.status == CaseStatus::OutsideValidity);
  // The measured error: 0 for a field bilinear in each cell along the grid lines... the first
  // track is linear in t_Y and Q (N) and its pmax linear too: read bilinearly at the table's
  // nodes the export reproduces them.
  CHECK(r.header["error"]["at_table_nodes"]["checked"].get<int>() > 0);
  CHECK(r.header["error"]["at_table_nodes"]["pmax"]["max"].get<double>() < 1e-12);
  // No error bound against the method without the table's own error.
  CHECK_FALSE(r.header["error"].contains("against_method"));

  // Errors: an export is not a table (and back), a step that does not divide the range.
  CHECK_THROWS_WITH(read_contact_table(path), Catch::Contains(path + ":1") && Catch::Contains("mhcontact.table/2"));
  opt.tY_step_mm = 0.4;
  CHECK_THROWS_WITH(export_contact_table(d, "synthetic.csv", "00", opt),
                    Catch::Contains("--tY-step-mm") && Catch::Contains("0 ... 3 mm") && Catch::Contains("synthetic.csv"));
  std::remove(path.c_str());
}

TEST_CASE("table export of a worn measured pair: read bilinearly, within its stated bound of direct strip solves",
          "[tables]") {
  // The done-when pair of docs/tables.md at the default spacing, exported at the default grid
  // (0.25 mm, 10 kN), read bilinearly at points that are neither table nodes, cell centres of the
  // table, nor export grid points, against direct solves by the strip method.
  const CaseFile cf = load_case_file(std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/tables/worn-table.json", true);
  const PairGeometry pg = build_pair_geometry(cf);
  std::ostringstream err;
  TableMakeOptions mo;
  mo.threads = 2;
  mo.quiet = true;
  const TableMade made = make_contact_table(cf, pg, mo, err);
  const ContactTableData ex = export_contact_table(made.data, "worn-table.csv", "00", TableExportOptions{});
  CHECK(ex.nT() == 65);
  CHECK(ex.nQ() == 13);
  const auto& bound = ex.header["error"]["against_method"];
  const double bN = bound["N"]["bound"], bp = bound["pmax"]["bound"], bA = bound["area"]["bound"];
  // The resampling adds little to the table's own tolerances at this grid.
  CHECK(bN < 0.0125);
  CHECK(bp < 0.04);
  TableAnswer a;
  CaseResult r;
  int compared = 0;
  double worst_N = 0, worst_p = 0, worst_A = 0;
  for (double t_mm : {-6.9, -4.6, -2.35, -0.1, 2.15, 4.4, 6.6})
    for (double Q_kN : {27.0, 83.0, 131.0}) {
      const double t = t_mm * 1e-3, Q = Q_kN * 1e3;
      export_linear(ex, t, Q, 0.0, a);
      if (a.status != CaseStatus::Ok) continue;
      r = solve_contact(pg.geo, cf.material, t, Q, cf.method_options());
      REQUIRE(r.status == CaseStatus::Ok);
      INFO("t_Y = " << t_mm << " mm, Q = " << Q_kN << " kN");
      double N = 0;
      for (const PatchResult& p : r.patches) N += p.N;
      double Ne = 0, pe = 0, Ae = 0;
      for (int k = 0; k < a.n_contacts; ++k) {
        Ne += a.c[static_cast<std::size_t>(k)].v[kTabN];
        pe = std::max(pe, a.c[static_cast<std::size_t>(k)].v[kTabPmax]);
        Ae += a.c[static_cast<std::size_t>(k)].v[kTabArea];
      }
      REQUIRE(r.patches.size() == 1);
      REQUIRE(a.n_contacts == 1);
      worst_N = std::max(worst_N, std::fabs(Ne - N) / Q);
      worst_p = std::max(worst_p, std::fabs(pe - r.pmax) / r.pmax);
      worst_A = std::max(worst_A, std::fabs(Ae - r.area) / r.area);
      CHECK(std::fabs(Ne - N) / Q <= bN);
      CHECK(std::fabs(pe - r.pmax) / r.pmax <= bp);
      CHECK(std::fabs(Ae - r.area) / r.area <= bA);
      ++compared;
    }
  INFO("worst N " << worst_N << " of Q (bound " << bN << "), pmax " << worst_p << " (" << bp << "), area " << worst_A
                  << " (" << bA << ")");
  CHECK(compared == 21);
}
