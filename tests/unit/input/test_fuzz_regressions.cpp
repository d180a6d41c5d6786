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
