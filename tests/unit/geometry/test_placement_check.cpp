// The placement check (geometry/placement_check.hpp, docs/profiles.md "Placement check"): a pair
// placed by gauge positioning whose main contact at t_Y = 0 is not on the tread of both profiles
// is refused before any case is solved. A wheel measured from its flange back whose
// taping line was never found stood with its flange tip on the rail crown, and 66 cases ran ok.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "geometry/contact_geometry.hpp"
#include "geometry/placement_check.hpp"
#include "profile/read.hpp"
#include "profile/standard_profiles.hpp"

using namespace mh;

namespace {
const std::string kSrc = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/";

Profile wheel(const std::string& name) {
  if (name == "S1002") return make_standard_profile("S1002", Inclination::None, 0.1e-3);
  ProfileReadOptions o;
  o.kind = ProfileKind::Wheel;
  return read_profile(kSrc + name, o);
}

/// The message of the InputError build_geometry throws, "" when it builds.
std::string refusal(const Profile& w, const Profile& r, const TrackSetup& t, ContactGeometry* out = nullptr) {
  GeometryOptions opt;
  opt.tY_min = -2e-3, opt.tY_max = 2e-3, opt.tY_step = 0.05e-3;
  try {
    const ContactGeometry G = build_geometry(w, r, t, opt);
    if (out) *out = G;
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("placement check: pairs on the tread pass, a flange tip or a flange on the crown is refused", "[placement]") {
  const Profile rail = make_standard_profile("60E1", Inclination::In40, 0.1e-3);
  // Table: wheel, expected refusal ("" = placed), figures at t_Y = 0 (contact angle [deg],
  // rolling radius − nominal [mm]) with tolerances.
  struct Row { const char* wheel; const char* refused; double gamma_deg, dr_mm, tol_gamma, tol_dr; };
  const Row rows[] = {
      {"S1002", "", 1.40, -0.09, 0.05, 0.05},                              // the tread, near the taping line
      {"field/old_wheel_loop.whl", "", 1.35, -0.09, 0.1, 0.1},             // taping line found (loop cleaned)
      {"profiles/avg_wheel.whl", "", 2.89, 0.23, 0.1, 0.1},               // measured, worn
      {"profiles/worn_high_mileage.prw", "", -0.60, -0.16, 0.1, 0.1},
      {"field/tip_start_wheel.whl", "origin y = 0, its taping line, lies outside its profile (y 15 … 130 mm)", 0, 0, 0, 0},  // its tip on the crown
      {"profiles/flat_ang200.prw", "contact angle is -11.459 deg", -11.459, 5.76, 0.01, 0.05},  // a 0.2 rad cone
  };
  for (const Row& row : rows) {
    CAPTURE(row.wheel);
    const Profile w = wheel(row.wheel);
    ContactGeometry G;
    const std::string msg = refusal(w, rail, TrackSetup{}, &G);
    if (*row.refused == '\0') {
      REQUIRE(msg.empty());
      const PlacementCheck pc = check_placement(G);
      REQUIRE(pc.ok);
      CHECK(pc.main.gamma / units::deg == Approx(row.gamma_deg).margin(row.tol_gamma));
      CHECK((pc.main.r_roll - pc.nominal_radius) * 1e3 == Approx(row.dr_mm).margin(row.tol_dr));
    } else {
      CAPTURE(msg);
      REQUIRE(msg.find(row.refused) != std::string::npos);
      CHECK(msg.find("t_Y = 0: contact at rail y") != std::string::npos);  // the numbers
      CHECK(msg.find("track.positioning \"explicit\"") != std::string::npos);  // the way out
      // The same pair placed explicitly is the user's placement: not checked.
      TrackSetup t;
      t.positioning = TrackSetup::Positioning::Explicit;
      t.lateral_offset = 0;
      CHECK(refusal(w, rail, t).empty());
    }
  }
  // The refused wheel's figures: the flange tip (wheel y ≈ 15 mm from the flange back, which it
  // keeps as its origin) stands on the crown at a contact angle of 1.5 deg, which alone looks fine.
  ContactGeometry G;
  TrackSetup t;
  t.positioning = TrackSetup::Positioning::Explicit;
  t.lateral_offset = -3.4e-3;  // where the gauge rule puts the wheel's origin on 60E1 at 1:40
  REQUIRE(refusal(wheel("field/tip_start_wheel.whl"), rail, t, &G).empty());
  const PlacementCheck pc = check_placement(G);
  CHECK_FALSE(pc.ok);
  CHECK(pc.main.y_w * 1e3 == Approx(15.0).margin(1.0));
  CHECK(std::fabs(pc.main.gamma / units::deg) < 2.0);  // the round flange tip on the crown: a tread-like angle
}

TEST_CASE("placement: a wheel without a flange placed by the gauge rule gets a warning", "[placement]") {
  const Profile rail = make_standard_profile("60E1", Inclination::In40, 0.1e-3);
  ContactGeometry G;
  REQUIRE(refusal(wheel("field/flat_wheel.txt"), rail, TrackSetup{}, &G).empty());
  REQUIRE(G.warnings.size() == 1);
  CHECK(G.warnings[0].find("the wheel has no flange") != std::string::npos);
  CHECK_FALSE(G.has_flange);
  TrackSetup t;
  t.positioning = TrackSetup::Positioning::Explicit;
  REQUIRE(refusal(wheel("field/flat_wheel.txt"), rail, t, &G).empty());
  CHECK(G.warnings.empty());
  REQUIRE(refusal(wheel("S1002"), rail, TrackSetup{}, &G).empty());
  CHECK(G.warnings.empty());
}
