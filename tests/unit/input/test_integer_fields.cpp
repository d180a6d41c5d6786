// Integer fields are range-checked as integers before any conversion (issue #10 item 7, second part).
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
