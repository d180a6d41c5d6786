// The placement check (geometry/placement_check.hpp, docs/profiles.md "Placement check"): a pair
// placed by gauge positioning whose placement is implausible (no taping line, a mirrored wheel,
// the flange on the rail head or tens of millimetres inside the track) is refused before any case
// is solved, with the explicit placement that reproduces it. A wheel measured from its flange back
// whose taping line was never found stood with its flange tip on the rail crown, and 66 cases ran
// ok; a correctly placed thick flange whose centred contact is on its flange root was refused by
// the contact-angle rule this check had before.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "geometry/contact_geometry.hpp"
#include "geometry/placement_check.hpp"
#include "profile/profile.hpp"
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

TEST_CASE("placement check: placed wheels pass whatever their contact at t_Y = 0, misplaced ones are refused",
          "[placement]") {
  const Profile rail = make_standard_profile("60E1", Inclination::In40, 0.1e-3);
  const double z_gauge = rail_landmarks(rail).z_gauge;
  // Table: wheel, expected refusal ("" = placed), figures at t_Y = 0 (contact angle [deg],
  // rolling radius − nominal [mm], flange clearance at the gauge point [mm]) with tolerances.
  // The figures are the check's own (what it reports), the expectation is the placement: each
  // wheel below is placed as built (its taping line, its flange back at −70 mm).
  struct Row { const char* wheel; const char* refused; double gamma_deg, dr_mm, clearance_mm, tol; };
  const Row rows[] = {
      {"S1002", "", 1.40, -0.09, 6.59, 0.1},                                // the tread, near the taping line
      {"field/old_wheel_loop.whl", "", 1.35, -0.09, 6.59, 0.15},            // taping line found (loop cleaned)
      {"profiles/avg_wheel.whl", "", 2.89, 0.23, NAN, 0.1},               // measured, worn
      {"profiles/worn_high_mileage.prw", "", -0.60, -0.16, NAN, 0.1},
      // A thick flange (Sd 36.4 mm), placed by the rule: its contact at t_Y = 0 is on the flange
      // root, 17 deg; the contact-angle rule of old refused it ("beyond ±10 deg").
      {"profiles/constructed/thick_flange_wheel.csv", "", 17.10, 3.03, 2.70, 0.1},
      {"field/tip_start_wheel.whl", "origin y = 0, its taping line, lies outside its profile (y 15 … 130 mm)", 0, 0, 0, 0},  // its tip on the crown
  };
  for (const Row& row : rows) {
    CAPTURE(row.wheel);
    const Profile w = wheel(row.wheel);
    ContactGeometry G;
    const std::string msg = refusal(w, rail, TrackSetup{}, &G);
    if (*row.refused == '\0') {
      REQUIRE(msg.empty());
      const PlacementCheck pc = check_placement(G, z_gauge);
      REQUIRE(pc.ok);
      CHECK(pc.main.gamma / units::deg == Approx(row.gamma_deg).margin(row.tol));
      CHECK((pc.main.r_roll - pc.nominal_radius) * 1e3 == Approx(row.dr_mm).margin(row.tol));
      REQUIRE(pc.flange_measured);
      CHECK(pc.flange_clearance >= 0);
      if (!std::isnan(row.clearance_mm)) CHECK(pc.flange_clearance * 1e3 == Approx(row.clearance_mm).margin(row.tol));
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
  const PlacementCheck pc = check_placement(G, z_gauge);
  CHECK_FALSE(pc.ok);
  CHECK(pc.main.y_w * 1e3 == Approx(15.0).margin(1.0));
  CHECK(std::fabs(pc.main.gamma / units::deg) < 2.0);  // the round flange tip on the crown: a tread-like angle
}

TEST_CASE("placement check: tens of millimetres off, a mirrored wheel: refused, with the explicit placement to copy",
          "[placement]") {
  const Profile rail = make_standard_profile("60E1", Inclination::In40, 0.1e-3);
  const Profile s1002 = wheel("S1002");
  Profile mirrored = s1002;  // y -> -y: the flange on the field side
  for (std::size_t i = 0; i < mirrored.y.size(); ++i) mirrored.y[i] = -s1002.y[s1002.y.size() - 1 - i];
  for (std::size_t i = 0; i < mirrored.z.size(); ++i) mirrored.z[i] = s1002.z[s1002.z.size() - 1 - i];
  TrackSetup wide, narrow, ok_narrow;
  wide.flange_back_distance = 1.430;      // 35 mm too far out: the flange on the rail head
  narrow.flange_back_distance = 1.260;    // 50 mm too far in: clearance 55.9 mm
  ok_narrow.flange_back_distance = 1.300; // 30 mm in, clearance 36.6 mm: within the 40 mm limit
  struct Row { const Profile* w; const TrackSetup* t; const char* refused; };
  const Row rows[] = {
      {&s1002, &wide, "its flange does not reach down to the rail's gauge point"},
      {&s1002, &narrow, "its flange stands 55.923 mm inside the rail's gauge point, more than 40 mm"},
      {&mirrored, &ok_narrow, "lies on the field side of the taping line: a mirrored profile"},
      {&s1002, &ok_narrow, ""},
  };
  for (const Row& row : rows) {
    CAPTURE(row.refused, row.t->flange_back_distance);
    const std::string msg = refusal(*row.w, rail, *row.t);
    if (*row.refused == '\0') {
      CHECK(msg.empty());
      continue;
    }
    CAPTURE(msg);
    REQUIRE(msg.find(row.refused) != std::string::npos);
    // The explicit placement that reproduces the refused one: copied, it gives the offset the
    // gauge rule computed (method.md §7), and the pair builds (the user's placement, not checked).
    const std::string key = "\"lateral_offset_mm\": ";
    const std::size_t at = msg.find(key);
    REQUIRE(at != std::string::npos);
    CHECK(msg.find("\"positioning\": \"explicit\", \"lateral_offset_mm\"") != std::string::npos);
    const double off_mm = std::stod(msg.substr(at + key.size()));
    const RailLandmarks L = rail_landmarks(rail, row.t->gauge_height);
    const double gauge_off = (L.y_gauge - row.t->gauge / 2) + (row.t->flange_back_distance / 2 - row.t->flange_back_position);
    CHECK(off_mm * 1e-3 == Approx(gauge_off).margin(1e-9));
    TrackSetup ex = *row.t;
    ex.positioning = TrackSetup::Positioning::Explicit;
    ex.lateral_offset = off_mm * 1e-3;
    ContactGeometry G;
    CHECK(refusal(*row.w, rail, ex, &G).empty());
    CHECK(G.y_offset == Approx(gauge_off).margin(1e-9));
  }
  // The numbers of the placement (docs/profiles.md quotes them).
  CHECK_THAT(refusal(s1002, rail, narrow),
             Catch::Contains("; flange tip at rail y -108.035 mm, 16.011 mm below the rail's gauge point (rail y "
                             "-35.535 mm), flange clearance 55.923 mm there: gauge positioning misplaces the wheel"));
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
