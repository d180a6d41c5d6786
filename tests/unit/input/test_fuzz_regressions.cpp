// Replays the fuzz seed corpora and every kept fuzz finding (tests/fuzz/regressions/TARGET/*)
// through the same harnesses as the libFuzzer targets, in the normal (and sanitizer) test suite.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "fuzz/harness.hpp"

namespace fs = std::filesystem;

namespace {
int replay(const std::string& target, int (*one)(const uint8_t*, size_t)) {
  int n = 0;
  for (const char* kind : {"corpus", "regressions"}) {
    const fs::path dir = fs::path(MHCONTACT_SOURCE_DIR) / "tests" / "fuzz" / kind / target;
    if (!fs::is_directory(dir)) continue;
    for (const auto& e : fs::directory_iterator(dir)) {
      std::ifstream in(e.path(), std::ios::binary);
      std::stringstream ss;
      ss << in.rdbuf();
      const std::string d = ss.str();
      INFO(e.path().string());
      REQUIRE(one(reinterpret_cast<const uint8_t*>(d.data()), d.size()) == 0);
      ++n;
    }
  }
  return n;
}
}  // namespace

TEST_CASE("fuzz corpora and regressions: profile readers", "[fuzz]") { REQUIRE(replay("profile", mh::fuzz::profile_one) >= 15); }
TEST_CASE("fuzz corpora and regressions: case files and manifests", "[fuzz]") { REQUIRE(replay("casefile", mh::fuzz::casefile_one) >= 4); }
TEST_CASE("fuzz corpora and regressions: CSV reader", "[fuzz]") { REQUIRE(replay("csv", mh::fuzz::csv_one) >= 5); }

TEST_CASE("fuzz harness invariants can fail", "[fuzz]") {
  // The checks the harnesses return kBroken on: a NaN or null among the resolved inputs, an
  // error message with a raw control byte or without a location.
  CHECK(mh::fuzz::all_finite(nlohmann::json{{"a", 1.5}, {"b", {1, 2}}}));
  CHECK_FALSE(mh::fuzz::all_finite(nlohmann::json{{"a", std::nan("")}}));
  CHECK_FALSE(mh::fuzz::all_finite(nlohmann::json{{"a", nullptr}}));
  CHECK(mh::fuzz::good_error(mh::InputError("f.json: /x", "1", "must be > 0")));
  CHECK_FALSE(mh::fuzz::good_error(mh::InputError("", "1", "must be > 0")));
  // A case file whose load is implausible is refused (an InputError, not a case with Q = 1e5).
  const std::string text = R"({"wheel": {"profile": {"standard": "S1002"}}, "rail": {"profile": {"standard": "60E1"},
    "inclination": "1:40"}, "sweep": {"tY_mm": [0], "Q_kN": [100000]}})";
  CHECK(mh::fuzz::casefile_one(reinterpret_cast<const uint8_t*>(text.data()), text.size()) == 0);
}
