// A failed row does not look like a result (issue #10 item 8): out_of_range, no_contact and
// invalid_pair rows leave every result field empty in CSV and null in JSON.
#include <catch2/catch.hpp>
#include <cmath>
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
                                         "Fz_kN", "Fy_kN", "pmax_MPa", "area_mm2"};
  const std::vector<std::size_t> cols = {5, 6, 7, 8, 10, 11, 12, 13};  // in cases_csv_header()
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
