// material.yield_MPa: the yield stress as input. Unless p_lim_MPa is given it selects the yield
// law of the ellipse (Material::yield_law) and the grid methods' cap p_lim = kPlimPerYield σ_y
// (docs/method.md §5.1); p_lim_MPa selects the capped law.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "contact/options.hpp"
#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "core/units.hpp"
#include "input/case_file.hpp"
#include "support/input_errors.hpp"

using namespace mh;
using nlohmann::json;

namespace {
const std::string kPath = testing::manchester_case_path();
json base() { return testing::manchester_case_json(); }
std::string error_of(const json& j) { return testing::case_error(j); }
}  // namespace

TEST_CASE("yield_MPa derives p_lim for the plastic model", "[input][yield]") {
  json j = base();
  j["model"] = "plastic";
  j["material"] = {{"yield_MPa", 500}};
  CaseFile cf = parse_case_json(j, kPath, true);
  CHECK(cf.material.yield == Approx(500e6));
  CHECK(std::isnan(cf.material.yield_rail));
  CHECK(cf.material.p_lim == Approx(kPlimPerYield * 500e6));
  CHECK(cf.material.yield_law);
  // p_lim_MPa takes precedence (the capped law); the yield stress is kept
  j["material"]["p_lim_MPa"] = 1200;
  cf = parse_case_json(j, kPath, true);
  CHECK(cf.material.p_lim == Approx(1200e6));
  CHECK_FALSE(cf.material.yield_law);
  CHECK(cf.material.yield == Approx(500e6));
}

TEST_CASE("yield_MPa per body: the softer body sets p_lim", "[input][yield]") {
  json j = base();
  j["model"] = "plastic";
  j["material"] = {{"E_GPa", 210}, {"nu", 0.3}, {"wheel", {{"yield_MPa", 600}}}, {"rail", {{"yield_MPa", 450}}}};
  CaseFile cf = parse_case_json(j, kPath, true);
  CHECK(cf.material.yield == Approx(600e6));
  CHECK(cf.material.yield_rail == Approx(450e6));
  CHECK(std::isnan(cf.material.E_rail));  // elastic constants stay common
  CHECK(cf.material.p_lim == Approx(kPlimPerYield * 450e6));
  // with per-body elastic constants too
  j["material"] = {{"wheel", {{"E_GPa", 210}, {"nu", 0.3}, {"yield_MPa", 600}}},
                   {"rail", {{"E_GPa", 200}, {"nu", 0.3}, {"yield_MPa", 450}}}};
  cf = parse_case_json(j, kPath, true);
  CHECK(cf.material.E_rail == Approx(200e9));
  CHECK(cf.material.p_lim == Approx(kPlimPerYield * 450e6));
  // the resolved inputs read back to the same material
  json again = base();
  again["model"] = "plastic";
  again["material"] = cf.resolved_json().at("material");
  const CaseFile back = parse_case_json(again, kPath, true);
  CHECK(back.material.yield == Approx(cf.material.yield));
  CHECK(back.material.yield_rail == Approx(cf.material.yield_rail));
  CHECK(back.material.p_lim == Approx(cf.material.p_lim));
  CHECK(back.material.yield_law);  // the echo has no p_lim_MPa, which would select the capped law
}

TEST_CASE("yield_MPa input errors name the field", "[input][yield]") {
  json j = base();
  j["model"] = "plastic";
  j["material"] = {{"yield_MPa", 0.5}};
  CHECK_THAT(error_of(j), Catch::Contains("is it in GPa?"));
  j["material"] = {{"yield_MPa", 500}, {"rail", {{"yield_MPa", 450}}}};
  CHECK_THAT(error_of(j), Catch::Contains("not both"));
  j["material"] = {{"rail", {{"yield_MPa", 450}}}};
  CHECK_THAT(error_of(j), Catch::Contains("/material/wheel/yield_MPa"));
  j["material"] = {{"rail", {{"yield_MPa", 450}, {"p_lim", 3}}}};
  CHECK_THAT(error_of(j), Catch::Contains("p_lim"));
  j["material"] = json::object();
  CHECK_THAT(error_of(j), Catch::Contains("yield_MPa"));  // the plastic model names both ways
  // the elastic model accepts a yield stress (used by indicators), and stays elastic
  j = base();
  j["material"] = {{"yield_MPa", 500}};
  const CaseFile cf = parse_case_json(j, kPath, true);
  CHECK(std::isinf(cf.material.p_lim));
  CHECK(cf.material.yield == Approx(500e6));
}
