// Issue #13 item 5: every format the tool reads is also written, keeping the kind; read → write →
// read gives the same points to the printed precision (shortest round-trip decimals).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/errors.hpp"
#include "profile/read.hpp"
#include "profile/standard_profiles.hpp"
#include "profile/write.hpp"

namespace {

const std::string kData = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/profiles/";

std::string put(const std::string& name, const std::string& text) {
  const std::string p = "/tmp/mh_profile_write_" + name;
  FILE* f = std::fopen(p.c_str(), "wb");
  REQUIRE(f);
  std::fputs(text.c_str(), f);
  std::fclose(f);
  return p;
}

}  // namespace

TEST_CASE("read, write, read gives the same points in every format", "[profile][write]") {
  struct Src { std::string what; mh::Profile p; };
  mh::Profile high = mh::make_standard_profile("60E1");  // a rail mostly above z = 0 (MiniProf height)
  for (auto& z : high.z) z += 0.015;
  const Src sources[] = {
      {"S1002", mh::make_standard_profile("S1002")},
      {"60E1 1:40", mh::make_standard_profile("60E1", mh::Inclination::In40)},
      {"60E1 raised 15 mm", high},
      {"MBench_UIC60_v3.prr", mh::read_profile(kData + "MBench_UIC60_v3.prr")},
      {"worn_high_mileage.prw", mh::read_profile(kData + "worn_high_mileage.prw")},
      {"avg_low2.ban (cleaned)", mh::read_profile(kData + "avg_low2.ban")},
  };
  const char* exts[] = {"csv", "txt", "dat", "prr", "prw", "ban", "whl", "rail", "wheel", "rai", "whe"};
  for (const auto& src : sources) {
    for (const char* e : exts) {
      const mh::ProfileKind fk = mh::profile_extension_kind(std::string("x.") + e);
      if (fk != mh::ProfileKind::Unknown && fk != src.p.kind) continue;
      INFO(src.what << " as ." << e);
      const std::string path = put("rt." + std::string(e), mh::profile_file_text(src.p, std::string("rt.") + e));
      mh::ProfileReadOptions o;
      o.kind = src.p.kind;
      const mh::Profile q = mh::read_profile(path, o);
      CHECK(q.kind == src.p.kind);
      REQUIRE(q.size() == src.p.size());
      double d = 0;
      for (std::size_t k = 0; k < q.size(); ++k)
        d = std::max({d, std::abs(q.y[k] - src.p.y[k]), std::abs(q.z[k] - src.p.z[k])});
      CHECK(d * 1e3 < 1e-9);  // mm: the shortest round-trip decimals give the doubles back
      CHECK(q.warnings.empty());
    }
  }
}

TEST_CASE("a wheel is not written into a rail file, nor the reverse", "[profile][write]") {
  const mh::Profile w = mh::make_standard_profile("S1002");
  const mh::Profile r = mh::make_standard_profile("54E1");
  const struct { const mh::Profile* p; const char* ext; const char* fix; } rows[] = {
      {&w, "prr", "use .prw"}, {&w, "ban", "use .whl"}, {&w, "rail", "use .wheel"}, {&w, "rai", "use .whe"},
      {&r, "prw", "use .prr"}, {&r, "whl", "use .ban"}, {&r, "wheel", "use .rail"}, {&r, "whe", "use .rai"},
  };
  for (const auto& row : rows) {
    INFO(row.ext);
    try {
      mh::profile_file_text(*row.p, std::string("out.") + row.ext);
      FAIL("no error");
    } catch (const mh::InputError& e) {
      const std::string m = e.what();
      CHECK(m.find("out.") != std::string::npos);
      CHECK(m.find("cannot be written into a") != std::string::npos);
      CHECK(m.find(row.fix) != std::string::npos);
    }
  }
  CHECK_THROWS_WITH(mh::profile_file_text(w, "out.xlsx"), Catch::Contains("unknown output profile format"));
}
