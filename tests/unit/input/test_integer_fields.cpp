// Integer fields are range-checked as integers before any conversion.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "input/case_file.hpp"

using namespace mh;

TEST_CASE("solver.max_iterations: 4294967297 and other out-of-range integers are refused", "[input]") {
  const std::string path = std::string(MHCONTACT_SOURCE_DIR) + "/cases/manchester.json";
  nlohmann::json j = read_json_file(path);
  j["solver"] = {{"max_iterations", 30}};
  REQUIRE(parse_case_json(j, path, true).solver.max_iterations == 30);
  for (nlohmann::json bad : {nlohmann::json(4294967297ull), nlohmann::json(-4294967295ll), nlohmann::json(0),
                             nlohmann::json(10001), nlohmann::json(18446744073709551615ull)}) {
    CAPTURE(bad.dump());
    j["solver"] = {{"max_iterations", bad}};
    REQUIRE_THROWS_AS(parse_case_json(j, path, true), InputError);
  }
}

TEST_CASE("half_space.max_iterations and strips.gauss_points: range-checked as integers", "[input]") {
  const std::string path = std::string(MHCONTACT_SOURCE_DIR) + "/cases/manchester.json";
  nlohmann::json j = read_json_file(path);
  j["half_space"] = {{"max_iterations", 500}};
  REQUIRE(parse_case_json(j, path, true).half_space.cg.max_iterations == 500);
  for (nlohmann::json bad : {nlohmann::json(4294967297ull), nlohmann::json(18446744073709551615ull), nlohmann::json(0),
                             nlohmann::json(100001), nlohmann::json(2.5), nlohmann::json(-1)}) {
    CAPTURE(bad.dump());
    j["half_space"] = {{"max_iterations", bad}};
    REQUIRE_THROWS_AS(parse_case_json(j, path, true), InputError);
  }
  j.erase("half_space");
  j["strips"] = {{"gauss_points", 8}};
  REQUIRE(parse_case_json(j, path, true).strips.strips.gauss_points == 8);
  for (nlohmann::json bad : {nlohmann::json(4294967304ull), nlohmann::json(18446744073709551614ull), nlohmann::json(7),
                             nlohmann::json(258), nlohmann::json(0)}) {
    CAPTURE(bad.dump());
    j["strips"] = {{"gauss_points", bad}};
    REQUIRE_THROWS_AS(parse_case_json(j, path, true), InputError);
  }
}
