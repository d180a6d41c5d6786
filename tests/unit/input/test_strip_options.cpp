// The strip method's options in a case file (README "The case file", "strips"): end_gap_tol is read,
// echoed in the resolved inputs, and refused with its JSON path when negative.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "input/case_file.hpp"

using namespace mh;

TEST_CASE("strips.end_gap_tol: read, resolved, refused below zero", "[input][strips]") {
  const std::string path = std::string(MHCONTACT_SOURCE_DIR) + "/cases/manchester-strips.json";
  nlohmann::json j = read_json_file(path);
  CHECK(parse_case_json(j, path, true).strips.strips.end_gap_tol == 0.05);  // the default
  for (double v : {0.0, 0.2, 1e9}) {
    j["strips"]["end_gap_tol"] = v;
    const CaseFile cf = parse_case_json(j, path, true);
    CHECK(cf.strips.strips.end_gap_tol == v);
    CHECK(cf.resolved_json()["strips"]["end_gap_tol"].get<double>() == v);
  }
  for (nlohmann::json bad : {nlohmann::json(-0.01), nlohmann::json("0.05"), nlohmann::json(nullptr)}) {
    CAPTURE(bad.dump());
    j["strips"]["end_gap_tol"] = bad;
    try {
      parse_case_json(j, path, true);
      FAIL("accepted end_gap_tol = " << bad.dump());
    } catch (const InputError& e) {
      CHECK_THAT(e.where(), Catch::Contains("/strips/end_gap_tol"));
    }
  }
}
