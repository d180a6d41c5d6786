// Every format the tool reads is also written, keeping the kind; read → write →
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
      {"60E1 1:20 (vertical gauge face)", mh::make_standard_profile("60E1", mh::Inclination::In20)},
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
      REQUIRE(q.face_y.size() == src.p.face_y.size());
      for (std::size_t k = 0; k < q.face_y.size(); ++k) {
        CHECK(q.face_y[k] == q.y[0]);  // still vertical
        d = std::max({d, std::abs(q.face_y[k] - src.p.face_y[k]), std::abs(q.face_z[k] - src.p.face_z[k])});
      }
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

TEST_CASE("EN 15313 wheel measures of S1002 new are the nominal values", "[profile][measures]") {
  for (double step : {0.1e-3, 0.5e-3}) {
    const mh::WheelMeasures M = mh::wheel_measures(mh::make_standard_profile("S1002", mh::Inclination::None, step));
    REQUIRE(M.valid);
    CHECK(M.Sh * 1e3 == Approx(28.0).margin(0.1));
    CHECK(M.Sd * 1e3 == Approx(32.5).margin(0.1));
    CHECK(M.qR * 1e3 == Approx(10.8).margin(0.1));
  }
  // measured: the Manchester S1002 file and the MiniProf old-style copy of S1002 give the same
  const mh::WheelMeasures F = mh::wheel_measures(mh::read_profile(kData + "MBench_S1002_v3.prw"));
  REQUIRE(F.valid);
  CHECK(F.Sh * 1e3 == Approx(28.0).margin(0.1));
  CHECK(F.Sd * 1e3 == Approx(32.5).margin(0.1));
  CHECK(F.qR * 1e3 == Approx(10.8).margin(0.1));
  const mh::WheelMeasures O = mh::wheel_measures(mh::read_profile(kData + "constructed/old_style_wheel.whl"));
  REQUIRE(O.valid);
  CHECK(O.Sd * 1e3 == Approx(32.5).margin(0.1));
  // a profile without a flange has none, and says why
  const mh::WheelMeasures N = mh::wheel_measures(mh::read_profile(kData + "flat_plane.prw"));
  CHECK_FALSE(N.valid);
  CHECK(!N.why.empty());
}

TEST_CASE("any inclination 1:N or an angle, the old strings keep their meaning", "[profile][inclination]") {
  CHECK(mh::parse_inclination("1:40") == mh::Inclination::In40);
  CHECK(mh::parse_inclination("1:20") == mh::Inclination::In20);
  CHECK(mh::parse_inclination("none") == mh::Inclination::None);
  CHECK(mh::parse_inclination("as-is") == mh::Inclination::AsIs);
  for (const char* s : {"as-is", "none", "1:40", "1:20", "1:30", "1:7.5", "2.5deg", "0deg"})
    CHECK(mh::to_string(mh::parse_inclination(s)) == s);
  CHECK(mh::inclination_angle(mh::parse_inclination("1:30")) == Approx(std::atan(1.0 / 30)));
  CHECK(mh::inclination_angle(mh::parse_inclination("2.5deg")) == Approx(2.5 * 3.14159265358979323846 / 180));
  for (const char* s : {"1:3", "1:", "1:x", "1:40 ", "12deg", "-1deg", "deg", "1/40", ""})
    CHECK_THROWS_AS(mh::parse_inclination(s), std::invalid_argument);
  // The crown of 60E1 at 1:30 gets the slope +1/30 at the rotated crown top's former position.
  const mh::Profile p = mh::make_standard_profile("60E1", mh::parse_inclination("1:30"));
  std::size_t k = 0;
  while (p.y[k + 1] < 0) ++k;
  CHECK((p.z[k + 1] - p.z[k]) / (p.y[k + 1] - p.y[k]) == Approx(1.0 / 30).margin(2e-3));
  CHECK_THROWS_AS(mh::make_standard_profile("S1002", mh::parse_inclination("1:30")), mh::InputError);
}

TEST_CASE("a rail file with a vertical gauge flank is read with its face", "[profile][write][flank]") {
  // The rail CONTACT read for the S1002/60E1 1:20 references (tests/data/contact/field/inputs,
  // README there): the generated 60E1 turned 1:20, its flank written as points of one y, from
  // 21.787 mm below the top up to the R13/flank tangency (5.7 mm). Read back: that flank is the
  // face, z(y) starts at the tangency point, and nothing is dropped as jitter.
  const mh::Profile r = mh::read_profile(std::string(MHCONTACT_SOURCE_DIR) +
                                         "/tests/data/contact/field/inputs/S1002_60E1_1-20/rail.prr");
  REQUIRE(r.face_y.size() == 58);
  CHECK(r.face_z.back() == Approx(-21.787024e-3).margin(1e-12));
  CHECK(r.y[0] == Approx(-35.240789e-3).margin(1e-12));
  for (double y : r.face_y) CHECK(y == r.y[0]);
  CHECK(r.warnings.empty());
  // Canted again (1:40): the face turns with the points, overhanging, and is clipped like any
  // flank that turns under; no face is left and y stays increasing.
  mh::Profile twice = r;
  mh::rotate_towards_track_centre(twice, std::atan(1.0 / 40));
  CHECK(twice.face_y.empty());
  CHECK(twice.size() < r.size() + r.face_y.size());
  for (std::size_t k = 1; k < twice.size(); ++k) REQUIRE(twice.y[k] > twice.y[k - 1]);
  REQUIRE(twice.warnings.size() == 1);
  CHECK(twice.warnings[0].find("clipped") != std::string::npos);
  // A face shorter than 2 mm (a measured face repeating a rounded y) is not a face: dropped as jitter.
  std::string text = "y_mm,z_mm\n-30,-20\n-30,-19\n";
  for (int i = 0; i <= 60; ++i) text += std::to_string(-29.5 + i) + "," + std::to_string(-0.001 * (i - 30) * (i - 30)) + "\n";
  mh::ProfileReadOptions o;
  o.kind = mh::ProfileKind::Rail;
  const mh::Profile m = mh::read_profile(put("short_face.csv", text), o);
  CHECK(m.face_y.empty());
}
