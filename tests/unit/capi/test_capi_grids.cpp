// The C interface's pressure and traction grids (include/mhcontact.h, the last section;
// docs/c-api.md "Pressure and traction grids"): mhc_result_grid against pressure.csv of
// `mhcontact run --pressure-grid` on the same case file (the command's file against the library
// call, value for value at the file's full digits), for FASTSIM ellipses and a half-space patch
// with friction; one physical check (full slip: |(px, py)| = mu p at every point); the size query,
// a too small capacity and the grids not kept, each a clear error.
// Breaks seen to fail: px not turned to the rail's sign in grids.cpp ("pressure.csv's numbers",
// every px row); FASTSIM's traction bound scaled by 1.01 in traction_grid.cpp ("full slip");
// solve_case not keeping the tractions with keep_grids ("pressure.csv's numbers": traction 0).
#include <catch2/catch.hpp>

#include <mhcontact.h>

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "cli.hpp"
#include "support/case_text.hpp"
#include "support/data_csv.hpp"

namespace fs = std::filesystem;

namespace {
const std::string kSrc = MHCONTACT_SOURCE_DIR;

using Row = mh::test::TextRow;
using mh::test::read_text_rows;

/// A case's grid through the C interface: the size query, then the arrays.
struct Grid {
  mhc_grid g{};
  std::vector<int32_t> contact, slip;
  std::vector<double> x, s, y_rail, p, p_el, px, py;
};

Grid grid_of(mhc_workspace* ws, int32_t n) {
  Grid G;
  G.g.struct_size = sizeof G.g;
  REQUIRE(mhc_result_grid(ws, n, &G.g) == MHC_OK);
  const std::size_t m = G.g.n_points;
  G.contact.resize(m), G.slip.resize(m), G.x.resize(m), G.s.resize(m), G.y_rail.resize(m), G.p.resize(m),
      G.p_el.resize(m), G.px.resize(m), G.py.resize(m);
  G.g.capacity = m;
  G.g.contact = G.contact.data(), G.g.slip = G.slip.data(), G.g.x_m = G.x.data(), G.g.s_m = G.s.data();
  G.g.y_rail_m = G.y_rail.data(), G.g.p_Pa = G.p.data(), G.g.p_elastic_Pa = G.p_el.data();
  G.g.px_Pa = G.px.data(), G.g.py_Pa = G.py.data();
  REQUIRE(mhc_result_grid(ws, n, &G.g) == MHC_OK);
  REQUIRE(G.g.n_points == m);
  return G;
}

struct Handles {
  mhc_pair* pair = nullptr;
  mhc_workspace* ws = nullptr;
  explicit Handles(const std::string& case_file) {
    REQUIRE(mhc_pair_from_case_file(case_file.c_str(), &pair) == MHC_OK);
    REQUIRE(mhc_workspace_create(pair, &ws) == MHC_OK);
  }
  ~Handles() {
    mhc_workspace_free(ws);
    mhc_pair_free(pair);
  }
};

/// Run `case_file` with --pressure-grid n and compare every row of pressure.csv with the C call's
/// point (the file at --digits max: shortest round trip, so the same double or a different one).
/// Returns the rows compared.
std::size_t compare_with_command(const std::string& case_file, int n, bool patches) {
  const std::string dir = fs::temp_directory_path() / ("mhcontact_capi_grids_" + std::to_string(::getpid()));
  std::ostringstream o, e;
  REQUIRE(mh::run_cli({"run", case_file, "-o", dir, "--digits", "max", "-q", "--format", "csv", "--pressure-grid",
                       std::to_string(n), "--force"}, o, e) == 0);
  const auto cases = read_text_rows(dir + "/cases.csv");
  const auto pressure = read_text_rows(dir + "/pressure.csv");
  fs::remove_all(dir);
  REQUIRE(!cases.empty());
  Handles h(case_file);
  REQUIRE(mhc_workspace_keep_grids(h.ws, 1) == MHC_OK);
  std::size_t row = 0;
  for (const Row& c : cases) {
    mhc_result r;
    r.struct_size = sizeof r;
    // As the case file's reader: mm * 1e-3, kN * 1e3.
    REQUIRE(mhc_solve_load(h.pair, h.ws, std::stod(c.at("tY_mm")) * 1e-3, 0.0, std::stod(c.at("Q_kN")) * 1e3, &r) ==
            MHC_OK);
    const Grid G = grid_of(h.ws, n);
    CHECK(G.g.method == (patches ? MHC_METHOD_HALF_SPACE : MHC_METHOD_MULTI_HERTZIAN));
    CHECK(G.g.traction == 1);
    for (std::size_t k = 0; k < G.g.n_points; ++k, ++row) {
      REQUIRE(row < pressure.size());
      const Row& w = pressure[row];
      INFO("case " << c.at("case") << ", point " << k);
      REQUIRE(w.at("case") == c.at("case"));
      CHECK(std::stoi(w.at(patches ? "patch" : "ellipse")) == G.contact[k]);
      // The file's units by the writer's conversions (x * 1e3 for mm, p / 1e6 for MPa).
      CHECK(std::stod(w.at("x_mm")) == G.x[k] * 1e3);
      CHECK(std::stod(w.at(patches ? "s_mm" : "y_mm")) == G.s[k] * 1e3);
      if (patches) CHECK(std::stod(w.at("y_rail_mm")) == G.y_rail[k] * 1e3);
      else CHECK(std::isnan(G.y_rail[k]));
      CHECK(std::stod(w.at("p_MPa")) == G.p[k] / 1e6);
      CHECK(std::stod(w.at("px_MPa")) == G.px[k] / 1e6);
      CHECK(std::stod(w.at("py_MPa")) == G.py[k] / 1e6);
      CHECK(std::stoi(w.at("slip")) == G.slip[k]);
    }
  }
  CHECK(row == pressure.size());
  return row;
}

}  // namespace

TEST_CASE("C grids: mhc_result_grid gives pressure.csv's numbers, FASTSIM ellipses", "[capi][grids]") {
  // cases/manchester-tangential.json: five t_Y (one and two ellipses), mu 0.3, yaw with t_Y.
  const std::size_t rows = compare_with_command(kSrc + "/cases/manchester-tangential.json", 9, false);
  CHECK(rows >= 5 * 81);
}

TEST_CASE("C grids: mhc_result_grid gives pressure.csv's numbers, a half-space patch", "[capi][grids]") {
  // cases/manchester-halfspace.json's pair with friction and kinematics, one case.
  std::string j = mh::test::manchester_halfspace_case(
            "\"friction\": {\"coefficient\": 0.3}, \"kinematics\": {\"speed_m_s\": 30, \"yaw_mrad_per_mm\": 2.4},\n"
            "  \"sweep\": {\"tY_mm\": [2], \"Q_kN\": [10]}\n}\n");
  const std::string path = fs::temp_directory_path() / ("mhcontact_capi_grids_hs_" + std::to_string(::getpid()) + ".json");
  { std::ofstream(path) << j; }
  const std::size_t rows = compare_with_command(path, 2, true);
  fs::remove(path);
  CHECK(rows > 100);  // the patch's elements in contact (0.2 mm)
}

TEST_CASE("C grids: in full slip |(px, py)| = mu p at every point", "[capi][grids]") {
  // A large longitudinal creepage saturates every FASTSIM cell (Kalker: full slip once
  // |xi| C11 G a b / (3 mu N) >> 1); then the traction is mu times the pressure at each point
  // (Coulomb's law), pointing against the slip, within 0.3 %.
  Handles h(kSrc + "/cases/manchester-tangential.json");
  mhc_tangential_options t;
  mhc_tangential_options_init(&t);
  t.mu = 0.3;
  t.creepages_given = 1;
  t.xi = 0.05;
  REQUIRE(mhc_pair_set_tangential(h.pair, &t) == MHC_OK);
  REQUIRE(mhc_workspace_keep_grids(h.ws, 1) == MHC_OK);
  for (const double tY : {0.0, 2e-3, 6e-3}) {
    mhc_result r;
    r.struct_size = sizeof r;
    REQUIRE(mhc_solve_load(h.pair, h.ws, tY, 0.0, 50e3, &r) == MHC_OK);
    REQUIRE(r.n_contacts >= 1);
    const Grid G = grid_of(h.ws, 15);
    REQUIRE(G.g.traction == 1);
    std::size_t loaded = 0;
    for (std::size_t k = 0; k < G.g.n_points; ++k) {
      if (!(G.p[k] > 0)) continue;
      ++loaded;
      INFO("t_Y " << tY << " m, point " << k << ": x " << G.x[k] << " m, s " << G.s[k] << " m, p " << G.p[k] << " Pa");
      CHECK(G.slip[k] == 1);
      CHECK(std::hypot(G.px[k], G.py[k]) == Approx(0.3 * G.p[k]).epsilon(0.003));
      // xi alone: the traction lies along x.
      CHECK(std::fabs(G.py[k]) < 0.003 * 0.3 * G.p[k]);
    }
    CHECK(loaded > 100);
  }
}

TEST_CASE("C grids: size query, capacity, not kept, arguments", "[capi][grids]") {
  Handles h(kSrc + "/cases/manchester-tangential.json");
  mhc_result r;
  r.struct_size = sizeof r;
  mhc_grid g{};
  g.struct_size = sizeof g;
  // Solved without keep_grids: refused, the message says what to call.
  REQUIRE(mhc_solve_load(h.pair, h.ws, 2e-3, 0.0, 10e3, &r) == MHC_OK);
  CHECK(mhc_result_grid(h.ws, 10, &g) == MHC_ERR_ARGUMENT);
  CHECK(std::string(mhc_last_message()).find("mhc_workspace_keep_grids(ws, 1)") != std::string::npos);
  CHECK(mhc_workspace_keep_grids(h.ws, 2) == MHC_ERR_ARGUMENT);
  CHECK(std::string(mhc_last_message()).find("keep = 2") != std::string::npos);
  REQUIRE(mhc_workspace_keep_grids(h.ws, 1) == MHC_OK);
  REQUIRE(mhc_solve_load(h.pair, h.ws, 2e-3, 0.0, 10e3, &r) == MHC_OK);
  // The size query: n x n per loaded ellipse.
  REQUIRE(mhc_result_grid(h.ws, 10, &g) == MHC_OK);
  CHECK(g.n_points == static_cast<std::size_t>(r.n_contacts) * 100);
  CHECK(g.traction == 1);
  // Too small: the field, the size needed.
  std::vector<double> p(g.n_points - 1);
  g.capacity = p.size();
  g.p_Pa = p.data();
  CHECK(mhc_result_grid(h.ws, 10, &g) == MHC_ERR_ARGUMENT);
  CHECK(std::string(mhc_last_message()).find("out->capacity = " + std::to_string(p.size())) != std::string::npos);
  CHECK(std::string(mhc_last_message()).find(std::to_string(p.size() + 1) + " points") != std::string::npos);
  CHECK(g.n_points == p.size() + 1);
  CHECK(mhc_result_grid(h.ws, 1, &g) == MHC_ERR_ARGUMENT);
  CHECK(std::string(mhc_last_message()).find("n = 1") != std::string::npos);
  g.struct_size = 8;
  CHECK(mhc_result_grid(h.ws, 10, &g) == MHC_ERR_ARGUMENT);
  CHECK(std::string(mhc_last_message()).find("sizeof(mhc_grid)") != std::string::npos);
  // Back to nothing kept: refused again.
  REQUIRE(mhc_workspace_keep_grids(h.ws, 0) == MHC_OK);
  REQUIRE(mhc_solve_load(h.pair, h.ws, 2e-3, 0.0, 10e3, &r) == MHC_OK);
  g.struct_size = sizeof g;
  CHECK(mhc_result_grid(h.ws, 10, &g) == MHC_ERR_ARGUMENT);
  // A case without contact: no points.
  REQUIRE(mhc_workspace_keep_grids(h.ws, 1) == MHC_OK);
  REQUIRE(mhc_solve_load(h.pair, h.ws, 2e-3, 0.0, 0.0, &r) == MHC_OK);
  g.p_Pa = nullptr;
  REQUIRE(mhc_result_grid(h.ws, 10, &g) == MHC_OK);
  CHECK(g.n_points == 0);
}
