// A table's validation at random points (docs/tables.md "How it is made", step 6): points
// that are neither nodes nor check points of the table made, and figures in its header that are
// those of direct solves there, recomputed here from the written file and the run's own solve.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "contact/solve.hpp"
#include "input/contact_table.hpp"
#include "jobs/contact_table_make.hpp"
#include "support/table_fixture.hpp"

namespace {
using namespace mh;

// The peak pressure and total area of a lookup's contacts.
void pmax_area(const TableAnswer& a, double& pmax, double& area) {
  pmax = area = 0;
  for (int k = 0; k < std::min(a.n_contacts, kTableMaxContacts); ++k) {
    pmax = std::max(pmax, a.c[static_cast<std::size_t>(k)].v[kTabPmax]);
    area += a.c[static_cast<std::size_t>(k)].v[kTabArea];
  }
}

}  // namespace

TEST_CASE("table validation: random points off the nodes and check points, figures those of direct solves", "[tables]") {
  // The S1002/60E1 roll table of docs/tables.md (strips, t_Y −2 … 4 mm, 40 … 120 kN, ±4 mrad):
  // refined, with coarse cells, so that the validation sees table statuses other than ok.
  const test::TestTable tab("cases/s1002-60e1-roll-table.json");
  const TableMade& made = tab.made;
  const nlohmann::json& h = made.data.header;
  REQUIRE(h.contains("validation"));
  const nlohmann::json& v = h["validation"];
  const TableMakeOptions def;
  REQUIRE(made.validation.size() == static_cast<std::size_t>(def.validate));
  CHECK(v["points"].get<int>() == def.validate);
  CHECK(v["seed"].get<std::uint64_t>() == kTableValidationSeed);

  // Inside the ranges, spread over them, and on no node and no cell centre of the final grid.
  const auto tY = h["tY_mm_nodes"].get<std::vector<double>>();
  const auto Q = h["Q_kN_nodes"].get<std::vector<double>>();
  const auto R = h["roll_mrad_nodes"].get<std::vector<double>>();
  auto on_grid = [](const std::vector<double>& x, double p) {
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (std::fabs(p - x[i]) < 1e-6) return true;
      if (i + 1 < x.size() && std::fabs(p - 0.5 * (x[i] + x[i + 1])) < 1e-6) return true;
    }
    return false;
  };
  int lower_half = 0, on_a_grid_line = 0;
  for (const TableCheckError& e : made.validation) {
    const double t = e.tY * 1e3, q = e.Q * 1e-3, r = e.roll * 1e3;
    CHECK(t >= tY.front());
    CHECK(t <= tY.back());
    CHECK(q >= Q.front());
    CHECK(q <= Q.back());
    CHECK(r >= R.front());
    CHECK(r <= R.back());
    lower_half += t < 0.5 * (tY.front() + tY.back());
    on_a_grid_line += on_grid(tY, t) && on_grid(Q, q) && on_grid(R, r);
  }
  CHECK(on_a_grid_line == 0);
  CHECK(lower_half > 30);
  CHECK(lower_half < 70);

  // The status counts add up; the table's coarse cells show as table statuses other than ok.
  const auto& st = v["status"];
  CHECK(st["both_ok"].get<int>() + st["table_ok_direct_not"].get<int>() == st["table_ok"].get<int>());
  CHECK(st["both_ok"].get<int>() + st["direct_ok_table_not"].get<int>() == st["direct_ok"].get<int>());
  CHECK(v["pmax"]["checked"].get<int>() == st["both_ok"].get<int>());

  // Each listed worst point, and every tenth point, recomputed: the table read back from its file
  // (the bytes a caller gets), the direct answer by the run's own solve of the rolled wheel.
  std::stringstream file;
  write_contact_table(made.data, file);
  std::size_t ln = 0;
  const ContactTableLookup look(read_contact_table(file, "table.csv", ln, kContactTableSchema));
  MethodOptions mo = tab.cf.method_options();
  std::vector<nlohmann::json> pts(v["worst"].begin(), v["worst"].end());
  REQUIRE(pts.size() == 5);
  for (std::size_t k = 0; k < made.validation.size(); k += 10) {
    const TableCheckError& e = made.validation[k];
    pts.push_back({{"tY_mm", e.tY * 1e3}, {"Q_kN", e.Q * 1e-3}, {"roll_mrad", e.roll * 1e3}});
  }
  double worst_listed = 0;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const double t = pts[k]["tY_mm"].get<double>() * 1e-3, q = pts[k]["Q_kN"].get<double>() * 1e3,
                 r = pts[k]["roll_mrad"].get<double>() * 1e-3;
    mo.multi_hertzian.roll = r;
    const CaseResult d = solve_contact(tab.pg.geo, tab.cf.material, t, q, mo);
    TableAnswer a;
    look.lookup(t, q, r, a);
    INFO("t_Y " << t * 1e3 << " mm, Q " << q * 1e-3 << " kN, roll " << r * 1e3 << " mrad");
    if (k < 5) {  // a worst point: both ok, its listed errors those measured here
      REQUIRE(d.status == CaseStatus::Ok);
      REQUIRE(a.status == CaseStatus::Ok);
      double pmax, area;
      pmax_area(a, pmax, area);
      CHECK(pts[k]["pmax"].get<double>() == Approx(std::fabs(pmax - d.pmax) / d.pmax).margin(1e-9));
      CHECK(pts[k]["area"].get<double>() == Approx(std::fabs(area - d.area) / d.area).margin(1e-9));
      worst_listed = std::max(worst_listed, pts[k]["pmax"].get<double>());
    } else {  // every tenth point: its statuses those of the file's lookup and the direct solve
      const TableCheckError& e = made.validation[(k - 5) * 10];
      CHECK(e.direct == d.status);
      CHECK(e.table == a.status);
    }
  }
  CHECK(v["pmax"]["max"].get<double>() >= worst_listed);
  WARN("S1002/60E1 roll table, validation at " << made.validation.size() << " random points: table ok "
       << st["table_ok"] << ", direct ok " << st["direct_ok"] << "; pmax max " << 100 * v["pmax"]["max"].get<double>()
       << " %, " << v["beyond"] << " ok answers beyond a tolerance");
}
