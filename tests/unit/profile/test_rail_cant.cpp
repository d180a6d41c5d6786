// Rail cant estimated from the head (rail_cant.hpp, profiles.md "Cant estimate"), against the
// cant the generator applied (standard profiles of EN 13674-1 turned by atan(1/N)) and against
// the Manchester benchmark rail, whose file is canted 1:40 (Shackleton & Iwnicki 2008).
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "profile/rail_cant.hpp"
#include "profile/read.hpp"
#include "profile/standard_profiles.hpp"
#include "support/input_errors.hpp"

using namespace mh;

namespace {
const std::string kData = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/profiles/";
constexpr double kDeg = 3.14159265358979323846 / 180.0;
bool has_warning(const RailCantCheck& c, const std::string& part) { return testing::has_warning(c.warnings, part); }
}  // namespace

TEST_CASE("rail cant of the generated 60E1 and 54E1 is the cant they were generated with", "[rail_cant]") {
  // Source: the generator's cant atan(1/N) or the angle (profiles.md §3). Tolerance 0.01°
  // (the issue asks for 0.1°; the estimate is exact on a symmetric head up to the bisection).
  for (const char* name : {"60E1", "54E1"})
    for (const auto& [incl, angle] : {std::pair<Inclination, double>{Inclination::None, 0.0},
                                      {Inclination::In40, std::atan(1.0 / 40)},
                                      {Inclination::In20, std::atan(1.0 / 20)},
                                      {Inclination{Inclination::Mode::Ratio, 30}, std::atan(1.0 / 30)},
                                      {Inclination{Inclination::Mode::Angle, 2.5}, 2.5 * kDeg}}) {
      const Profile p = make_standard_profile(name, incl);
      const RailCant c = estimate_rail_cant(p);
      CAPTURE(name, to_string(incl), c.angle / kDeg, c.why);
      REQUIRE(c.found);
      REQUIRE(c.confident);
      REQUIRE(std::fabs(c.angle - angle) < 0.01 * kDeg);
      // As used with the inclination the generator applied: nothing to warn about.
      REQUIRE(check_rail_cant(p, incl).warnings.empty());
    }
}

TEST_CASE("rail cant of the Manchester rail is its 1:40", "[rail_cant]") {
  // Source: the benchmark rail is UIC60 canted 1:40 in its file (tests/data/profiles/README.md);
  // tolerance 0.01°. The MiniProf copy is the same rail mirrored by its format: same cant.
  for (const char* f : {"MBench_UIC60_v3.prr", "MBench_UIC60_v3.ban"}) {
    const RailCant c = estimate_rail_cant(read_profile(kData + f));
    CAPTURE(f, c.angle / kDeg);
    REQUIRE(c.confident);
    REQUIRE(std::fabs(c.angle - std::atan(1.0 / 40)) < 0.01 * kDeg);
  }
}

TEST_CASE("a canted rail canted again by the case is warned about", "[rail_cant]") {
  // The Manchester rail (1:40 in its file) with "inclination": "1:40": canted twice, 2.86°.
  Profile p = read_profile(kData + "MBench_UIC60_v3.prr");
  rotate_towards_track_centre(p, std::atan(1.0 / 40));
  const RailCantCheck c = check_rail_cant(p, Inclination::In40);
  CAPTURE(c.warnings);
  REQUIRE(std::fabs(c.used.angle - 2 * std::atan(1.0 / 40)) < 0.01 * kDeg);
  REQUIRE(std::fabs(c.file_angle - std::atan(1.0 / 40)) < 0.01 * kDeg);
  REQUIRE(has_warning(c, "looks canted already"));
  // The same file used as-is: no warning.
  REQUIRE(check_rail_cant(read_profile(kData + "MBench_UIC60_v3.prr"), Inclination::AsIs).warnings.empty());
  // An upright 60E1 canted 1:20 by the case: within 0 … 1:20, no warning; twice 1:20 is beyond.
  Profile q = make_standard_profile("60E1", Inclination::In20);
  REQUIRE(check_rail_cant(q, Inclination::AsIs).warnings.empty());
  rotate_towards_track_centre(q, std::atan(1.0 / 20));
  const RailCantCheck c2 = check_rail_cant(q, Inclination::In20);
  REQUIRE(has_warning(c2, "looks canted already"));
  REQUIRE(has_warning(c2, "more than the usual 1:20"));
}

TEST_CASE("a canted rail mirrored in y has a negative cant and is warned about", "[rail_cant]") {
  // The Manchester rail read with --mirror-y: the head leans to the field side, −1:40.
  ProfileReadOptions o;
  o.mirror_y = true;
  const Profile p = read_profile(kData + "MBench_UIC60_v3.prr", o);
  const RailCantCheck c = check_rail_cant(p, Inclination::AsIs);
  CAPTURE(c.used.angle / kDeg, c.warnings);
  REQUIRE(std::fabs(c.used.angle + std::atan(1.0 / 40)) < 0.01 * kDeg);
  REQUIRE(has_warning(c, "mirrored in y"));
}

TEST_CASE("rail cant is not claimed where the head has no axis, and worn heads are checked with their uncertainty", "[rail_cant]") {
  // A circular arc is symmetric about every radius: no cant.
  REQUIRE_FALSE(estimate_rail_cant(read_profile(kData + "circ_r300.prr")).found);
  // Worn measured rails (tests/data/profiles/README.md) give no confident estimate. Before issue
  // #22 that silenced every check; now the checks run with a margin of two standard errors and
  // say "estimate not confident". Table: file, inclination applied, a warning expected (why).
  struct Row { const char* file; Inclination incl; const char* expect; };
  const Row rows[] = {
      {"site_b_hr.prr", Inclination::AsIs, "more than the usual 1:20"},  // 6.08° ± 0.09°, outside 0 … 1:20
      {"site_b_hr.prr", Inclination::In40, "looks canted already"},      // 7.5° as used
      {"avg_low2.ban", Inclination::AsIs, nullptr},                      // 1.37° ± 0.13°: inside
      {"avg_low2.ban", Inclination::In20, "looks canted already"},       // 1.37° in the file, canted again: 4.2°
      {"avg_HR.BAN", Inclination::AsIs, nullptr},                        // no axis within ±10°: not estimated
      {"avg_HR.BAN", Inclination::In20, nullptr},
  };
  for (const Row& r : rows) {
    Profile p = read_profile(kData + r.file);
    rotate_towards_track_centre(p, inclination_angle(r.incl));
    const RailCantCheck c = check_rail_cant(p, r.incl);
    CAPTURE(r.file, to_string(r.incl), c.used.angle / kDeg, c.used.why, c.warnings);
    REQUIRE_FALSE(c.used.confident);
    if (!r.expect) {
      REQUIRE(c.warnings.empty());
    } else {
      REQUIRE(has_warning(c, r.expect));
      REQUIRE(has_warning(c, "estimate not confident"));
    }
  }
}

TEST_CASE("a vanishing cant reads upright, not -1:585778.6 (issue 38)", "[rail_cant][messages]") {
  CHECK(cant_ratio(0.0) == "upright");
  CHECK(cant_ratio(-1.0 / 585778.6) == "upright");  // the cuts' noise on an upright rail
  CHECK(cant_ratio(std::atan(1.0 / 40)) == "1:40");
  CHECK(cant_ratio(-std::atan(1.0 / 20)) == "-1:20");
  CHECK(cant_ratio(std::atan(1.0 / 100000)) == "1:100000");  // 0.00057 deg: still a ratio
}
