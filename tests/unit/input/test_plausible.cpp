// Plausible ranges, sweep values as written (item 6) and every case checked
// (item 7): through the case-file parser, which the manifest shares.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "input/case_file.hpp"
#include "support/input_errors.hpp"
#include "input/manifest.hpp"

using namespace mh;
using nlohmann::json;

namespace {
const std::string kPath = testing::manchester_case_path();
json base() { return testing::manchester_case_json(); }
std::string error_of(const json& j) { return testing::case_error(j); }
}  // namespace

TEST_CASE("implausible values are refused with the likely unit mistake", "[input][plausible]") {
  REQUIRE(error_of(base()).empty());
  json j = base();
  j["sweep"]["Q_kN"] = {1e5};
  CHECK_THAT(error_of(j), Catch::Contains("did you give newtons?"));
  j["sweep"]["Q_kN"] = {1e12};
  CHECK_THAT(error_of(j), Catch::Contains("did you give newtons?"));
  j["sweep"]["Q_kN"] = {{"from", 10}, {"to", 1e5}, {"step", 10}};
  CHECK_THAT(error_of(j), Catch::Contains("/sweep/Q_kN/to"));
  j = base();
  j["sweep"]["tY_mm"] = {0, 8000};
  CHECK_THAT(error_of(j), Catch::Contains("micrometres"));
  j = base();
  j["material"] = {{"E_GPa", 210000}, {"nu", 0.3}};
  CHECK_THAT(error_of(j), Catch::Contains("is it in MPa?"));
  j["material"] = {{"E_GPa", 210}, {"nu", 0.49}};
  CHECK_THAT(error_of(j), Catch::Contains("plausible range of nu"));
  j["material"] = {{"wheel", {{"E_GPa", 21}}}};
  CHECK_THAT(error_of(j), Catch::Contains("/material/wheel/E_GPa"));
  j = base();
  j["model"] = "plastic";
  j["material"] = {{"p_lim_MPa", 1.1}};
  CHECK_THAT(error_of(j), Catch::Contains("is it in GPa?"));
  j["material"] = {{"p_lim_MPa", 1100}};
  CHECK(error_of(j).empty());
  j = base();
  j["wheel"]["nominal_radius_mm"] = 0.46;
  CHECK_THAT(error_of(j), Catch::Contains("is it in metres?"));
  j = base();
  j.erase("sweep");
  j["cases"] = {{{"tY_mm", 0}, {"Q_kN", 1e5}}};
  CHECK_THAT(error_of(j), Catch::Contains("/cases/0/Q_kN"));
}

TEST_CASE("a manifest refuses implausible values the same way", "[input][plausible]") {
  json m = {{"pairs", {{{"wheel", {{"standard", "S1002"}}}, {"rail", {{"standard", "60E1"}}}}}},
            {"inclination", "1:40"},
            {"sweep", {{"tY_mm", {0}}, {"Q_kN", {100}}}}};
  REQUIRE_NOTHROW(parse_manifest(m, "m.json"));
  m["sweep"]["Q_kN"] = {100000};
  try {
    parse_manifest(m, "m.json");
    FAIL("accepted Q_kN 1e5");
  } catch (const InputError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("did you give newtons?"));
  }
}

TEST_CASE("range sweep values print as the decimals the user wrote", "[input][sweep]") {
  json j = base();
  j["sweep"]["tY_mm"] = {{"from", 0}, {"to", 1}, {"step", 0.3}};
  CaseFile cf = parse_case_json(j, kPath, true);
  REQUIRE(cf.sweep_tY_mm.size() == 4);  // 1 is not on the grid: the last value is 0.9
  CHECK(format_number(cf.sweep_tY_mm.at(3)) == "0.9");
  CHECK(cf.sweep_tY_mm.at(3) == 0.9);
  j["sweep"]["tY_mm"] = {{"from", -10}, {"to", 12}, {"step", 0.1}};
  cf = parse_case_json(j, kPath, true);
  REQUIRE(cf.sweep_tY_mm.size() == 221);  // `to` on the grid is included
  for (std::uint64_t i = 0; i < cf.sweep_tY_mm.size(); ++i) {
    const std::string s = format_number(cf.sweep_tY_mm.at(i));
    CAPTURE(i, s);
    CHECK(s.size() <= 5);  // "-10", "10.9", "-0.1", never "10.900000000000002"
  }
  CHECK(cf.sweep_tY_mm.at(209) == 10.9);
  CHECK(format_number(cf.sweep_tY_mm.at(220)) == "12");
  j["sweep"]["tY_mm"] = {{"from", 0}, {"to", 0.9}, {"step", 0.3}};
  REQUIRE(parse_case_json(j, kPath, true).sweep_tY_mm.size() == 4);
  j["sweep"]["Q_kN"] = {{"from", 0.05}, {"to", 0.35}, {"step", 0.1}};
  cf = parse_case_json(j, kPath, true);
  REQUIRE(cf.sweep_Q_kN.size() == 4);
  CHECK(format_number(cf.sweep_Q_kN.at(2)) == "0.25");
  CHECK(format_number(cf.sweep_Q_kN.at(3)) == "0.35");
}

TEST_CASE("every case of a long list is range-checked, not a sample", "[input][cases]") {
  json j = base();
  j.erase("sweep");
  json cases = json::array();
  for (int i = 0; i < 200000; ++i) cases.push_back({{"tY_mm", 0}, {"Q_kN", 100}});
  cases[1]["tY_mm"] = 75;  // outside the plausible t_Y range
  j["cases"] = cases;
  CHECK_THAT(error_of(j), Catch::Contains("/cases/1/tY_mm"));
  cases[1]["tY_mm"] = 0;
  cases[1]["Q_kN"] = 0.001;
  j["cases"] = cases;
  CHECK_THAT(error_of(j), Catch::Contains("/cases/1/Q_kN"));
  // In range but outside the default geometry range: the geometry grid covers it, at any index.
  cases[1]["Q_kN"] = 100;
  cases[1]["tY_mm"] = 45;
  j["cases"] = cases;
  const CaseFile cf = parse_case_json(j, kPath, true);
  CHECK(cf.geometry.tY_max >= 0.045 - 1e-12);
}
