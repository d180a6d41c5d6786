// A failed row does not look like a result: out_of_range, no_contact and
// invalid_pair rows leave every result field empty in CSV and null in JSON.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <string>
#include <nlohmann/json.hpp>

#include "output/case_tables.hpp"

using namespace mh;

namespace {
std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> v(1);
  for (char c : line) {
    if (c == ',') v.emplace_back();
    else if (c != '\n') v.back() += c;
  }
  return v;
}
}  // namespace

TEST_CASE("failed rows: empty CSV cells, JSON null, same convention for every failure", "[output]") {
  CasePoint cp;
  cp.tY_mm = 99;
  cp.Q_kN = 100;
  const std::vector<std::string> keys = {"dz_virtual_mm", "approach_mm", "iterations", "residual",
                                         "Fz_kN", "Fy_kN", "Y_over_Q", "pmax_MPa", "area_mm2"};
  const std::vector<std::size_t> cols = {5, 6, 7, 8, 10, 11, 12, 13, 14};  // in cases_csv_header()
  const auto header = split(cases_csv_header());
  for (std::size_t i = 0; i < cols.size(); ++i) REQUIRE(header[cols[i]] == keys[i]);
  struct Kind { CaseStatus st; const char* text; double fill; };
  for (const Kind& k : {Kind{CaseStatus::OutOfRange, nullptr, 0.0}, Kind{CaseStatus::NoContact, nullptr, 0.0},
                        Kind{CaseStatus::Ok, "invalid_pair", NAN}}) {
    CaseResult r;
    r.status = k.st;
    r.dz = r.approach = r.residual = r.Fz = r.Fy = r.pmax = r.area = k.fill;
    r.message = "why";
    Formatted f;
    format_case(7, cp, r, false, true, true, f, k.text);
    const auto row = split(f.cases);
    CAPTURE(f.cases, f.json);
    REQUIRE(row.size() == header.size());
    REQUIRE(row[1] == "99");
    REQUIRE(row[9] == "0");  // n_contacts: a count, 0
    for (std::size_t c : cols) REQUIRE(row[c].empty());
    const auto j = nlohmann::json::parse(f.json);
    for (const std::string& key : keys) REQUIRE(j.at(key).is_null());
  }
  // An ok row keeps its numbers.
  CaseResult ok;
  ok.dz = 1e-4;
  ok.Fz = 1e5;
  Formatted f;
  format_case(0, cp, ok, false, true, true, f);
  REQUIRE(split(f.cases)[5] == "0.1");
  REQUIRE_FALSE(nlohmann::json::parse(f.json).at("Fz_kN").is_null());
}

TEST_CASE("not_converged rows keep their last iterate", "[output]") {
  // README "Output tables": a not_converged row keeps its last iterate, its residual says how far
  // it is from equilibrium; only out_of_range, no_contact and invalid_pair rows are empty. Columns
  // read by name from cases_csv_header().
  CasePoint cp;
  cp.tY_mm = 0;
  cp.Q_kN = 50;
  CaseResult r;
  r.status = CaseStatus::NotConverged;
  r.message = "equilibrium not reached in 1 iterations";
  r.dz = 2e-5;
  r.approach = 4e-5;
  r.iterations = 1;
  r.residual = 0.0425;
  r.Fz = 52.125e3;
  r.Fy = 2e3;
  r.pmax = 955e6;
  r.area = 124e-6;
  r.n_contacts = 2;
  Formatted f;
  format_case(3, cp, r, false, true, true, f);
  const auto header = split(cases_csv_header()), row = split(f.cases);
  CAPTURE(f.cases);
  REQUIRE(row.size() == header.size());
  auto cell = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    REQUIRE(it != header.end());
    return row[static_cast<std::size_t>(it - header.begin())];
  };
  CHECK(cell("status") == "not_converged");
  CHECK(cell("dz_virtual_mm") == "0.02");
  CHECK(cell("approach_mm") == "0.04");
  CHECK(cell("iterations") == "1");
  CHECK(cell("residual") == "0.0425");
  CHECK(cell("Fz_kN") == "52.125");
  CHECK(cell("pmax_MPa") == "955");
  CHECK(cell("n_contacts") == "2");
  CHECK_THAT(cell("message"), Catch::Contains("not reached"));
  const auto j = nlohmann::json::parse(f.json);
  CHECK(j.at("status") == "not_converged");
  CHECK(j.at("residual").get<double>() == 0.0425);
  CHECK(j.at("Fz_kN").get<double>() == 52.125);
}

TEST_CASE("not_converged grid rows: forces of the last iterate, no peak pressure or area", "[output]") {
  // docs/outputs.md "Failed rows": a grid method's not_converged row keeps approach, forces and
  // residual, its pmax_MPa and area_mm2 are empty (null), never the iterate's (0.2-2.9 million
  // MPa on a worn measured flange) nor "nan". Break guarded: write pmax with rnum().
  CasePoint cp;
  cp.tY_mm = 5;
  cp.Q_kN = 50;
  CaseResult r;
  r.status = CaseStatus::NotConverged;
  r.method = Method::HalfSpace;
  r.message = "the contact patches did not settle";
  r.approach = 1e-4;
  r.residual = 0.01;
  r.Fz = 50.5e3;
  r.pmax = NAN;  // withhold_unconverged_pressures (grid_checks.hpp)
  r.area = NAN;
  r.n_contacts = 1;
  Formatted f;
  format_case(1, cp, r, false, true, true, f);
  const auto header = split(cases_csv_header()), row = split(f.cases);
  auto cell = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    REQUIRE(it != header.end());
    return row[static_cast<std::size_t>(it - header.begin())];
  };
  CHECK(cell("status") == "not_converged");
  CHECK(cell("approach_mm") == "0.1");
  CHECK(cell("Fz_kN") == "50.5");
  CHECK(cell("pmax_MPa").empty());
  CHECK(cell("area_mm2").empty());
  const auto j = nlohmann::json::parse(f.json);
  CHECK(j.at("pmax_MPa").is_null());
  CHECK(j.at("area_mm2").is_null());
  CHECK(j.at("Fz_kN").get<double>() == 50.5);
}
