// Where an equivalent conicity is ok (geometry/conicity_domain.hpp): the flangeway clearance of
// the EN 15302 reference pair and of a thick-flanged wheel, wheels without a flange, the EN 15313
// limits of the wheel measures, and the evidence table as the docs render it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/units.hpp"
#include "geometry/conicity.hpp"
#include "geometry/conicity_domain.hpp"
#include "geometry/wheelset.hpp"
#include "profile/read.hpp"
#include "profile/standard_profiles.hpp"

using namespace mh;

namespace {

constexpr double mm = 1e-3;

std::vector<double> sweep_y() {
  std::vector<double> ys;
  for (int k = -800; k <= 800; ++k) ys.push_back(k / 100.0 * mm);
  return ys;
}

WheelsetPlacement en15302_placement() {
  WheelsetPlacement P;
  P.rails = WheelsetPlacement::Rails::Absolute;
  P.rail_origin_left = P.rail_origin_right = 750 * mm;
  return P;
}

/// [rad] The largest |contact angle| of either wheel over the rows between c's turning points.
double gamma_max(const std::vector<double>& ys, const std::vector<WheelsetState>& st, const ConicityResult& c) {
  double g = 0;
  for (std::size_t k = 0; k < ys.size(); ++k)
    if (ys[k] >= c.y1 - 1e-12 && ys[k] <= c.y2 + 1e-12)
      g = std::max({g, std::fabs(st[k].left.gamma), std::fabs(st[k].right.gamma)});
  return g;
}

std::string status(const ConicityResult& c, const FlangewayClearance& fc, const std::vector<double>& ys,
                   const std::vector<WheelsetState>& st) {
  return conicity_domain(c, fc, gamma_max(ys, st, c)).status;
}

std::vector<double> delta_r(const std::vector<WheelsetState>& st) {
  std::vector<double> dr;
  for (const auto& s : st) dr.push_back(s.delta_r());
  return dr;
}

/// S1002 with its flange `d` thicker: the flange back stays at y = −70 mm, the first 5 mm from it
/// (the back's rounded corner) are stretched by d, everything beyond is moved by d towards the
/// field side (the taping line then lies on the S1002 tread d further in: a flat tread, 1:40).
/// Sd grows by d, Sh and qR stay (S1002: Sd 32.5, Sh 28, qR 10.8 mm).
Profile thick_flange(double d) {  // d = 3.99 mm gives Sd 36.4 mm: the taping line moves onto the tread, which lowers the Sd level
  Profile p = make_standard_profile("S1002");
  for (double& y : p.y) y += d * std::clamp((y + 70 * mm) / (5 * mm), 0.0, 1.0);
  std::vector<double> y, z;  // keep the profile's own y range (−70 mm …)
  for (std::size_t i = 0; i < p.y.size(); ++i) y.push_back(p.y[i]), z.push_back(p.z[i]);
  p.y = y, p.z = z;
  p.source = "constructed: S1002 with a thicker flange";
  return p;
}

}  // namespace

TEST_CASE("EN 15302 wheel A on rail A: amplitudes inside the flangeway clearance are ok, beyond it flange_contact",
          "[wheelset][conicity][domain]") {
  // The reference pair's clearance: rail gauge points at ±1435.164/2 mm (tests/data/en15302),
  // wheel faces at the Sd level at 750 − 70 + Sd mm; wheel A's Sd from its profile.
  const Profile w = make_standard_profile("EN15302-wheel-A");
  const Profile r = make_standard_profile("EN15302-rail-A");
  const Wheelset ws(w, w, r, r, en15302_placement());
  const WheelMeasures m = wheel_measures(w);
  REQUIRE(m.valid);
  const FlangewayClearance fc = flangeway_clearance(ws, m, m);
  REQUIRE(fc.valid);
  const double expected = 1435.164 / 2 - (750 - 70 + m.Sd / mm);
  CHECK(fc.left / mm == Approx(expected).margin(0.002));
  CHECK(fc.right / mm == Approx(expected).margin(0.002));
  CHECK(fc.left + fc.right == Approx(ws.measured_gauge() - (1.360 + 2 * m.Sd)).margin(1e-9));
  WARN("wheel A: Sd " << m.Sd / mm << " mm, clearance " << fc.right / mm << " mm per side");

  const std::vector<double> ys = sweep_y();
  const std::vector<WheelsetState> st = ws.sweep(ys);
  const EquivalentConicity C(ys, delta_r(st));
  // Amplitudes of the standard's table (1 … 7.4 mm): ok up to the clearance, flange_contact
  // beyond, the EN 15302 integral itself ok at all of them.
  for (int i = 0; i <= 32; ++i) {
    const double A = (1.0 + 0.2 * i) * mm;
    const ConicityResult c = C.at(A);
    REQUIRE(c.status == "ok");
    CAPTURE(A / mm);
    CHECK(status(c, fc, ys, st) == (A <= fc.right ? "ok" : "flange_contact"));
  }
  const ConicityResult c74 = C.at(7.4 * mm);
  CHECK(conicity_domain(c74, fc, gamma_max(ys, st, c74)).why ==
        "turning points -7.4 / 7.4 mm beyond the flangeway clearances 4.89 / 4.89 mm (left / right)");
  // The reference pair: Sd 32.69 mm, clearance 4.89 mm; ŷ 4.8 mm, the largest ok amplitude of the
  // table, reaches 11.09° (y = 4.8 mm): the contact-angle bound holds it ok.
  CHECK(m.Sd / mm == Approx(32.69).margin(0.005));
  CHECK(fc.right / mm == Approx(4.89).margin(0.005));
  const ConicityResult c48 = C.at(4.8 * mm);
  CHECK(gamma_max(ys, st, c48) / (mh::units::deg) == Approx(11.09).margin(0.01));
  CHECK(status(c48, fc, ys, st) == "ok");
  CHECK(status(C.at(5.0 * mm), fc, ys, st) == "flange_contact");
}

TEST_CASE("an oscillation on the flange root is flange_contact whatever the clearance", "[wheelset][conicity][domain]") {
  // Wheel A on rail A with the clearance taken as unlimited: the contact-angle bound alone
  // (kTreadContactAngleMax 11.1°) turns ŷ = 5.0 mm (γ 11.78°) to flange_contact, ŷ = 4.8 mm (11.09°) not.
  const Profile w = make_standard_profile("EN15302-wheel-A");
  const Profile r = make_standard_profile("EN15302-rail-A");
  const Wheelset ws(w, w, r, r, en15302_placement());
  const std::vector<double> ys = sweep_y();
  const std::vector<WheelsetState> st = ws.sweep(ys);
  const EquivalentConicity C(ys, delta_r(st));
  FlangewayClearance wide;
  wide.valid = true;
  wide.left = wide.right = 1.0;
  const ConicityResult c48 = C.at(4.8 * mm), c5 = C.at(5.0 * mm);
  CHECK(status(c48, wide, ys, st) == "ok");
  const ConicityDomainVerdict v = conicity_domain(c5, wide, gamma_max(ys, st, c5));
  CHECK(v.status == "flange_contact");
  CHECK(v.why == "contact angle 11.8 deg > 11.1 deg inside the oscillation (flange root)");
}

TEST_CASE("a thick flange (Sd 36.4 mm) narrows the clearance: 3 mm is flange_contact, the measures are outside EN 15313",
          "[wheelset][conicity][domain]") {
  const Profile w = thick_flange(3.99 * mm);
  const WheelMeasures m = wheel_measures(w);
  REQUIRE(m.valid);
  CHECK(m.Sd / mm == Approx(36.4).margin(0.02));
  const Profile r = make_standard_profile("EN15302-rail-A");
  const Wheelset ws(w, w, r, r, en15302_placement());
  const FlangewayClearance fc = flangeway_clearance(ws, m, m);
  REQUIRE(fc.valid);
  CHECK(fc.right / mm == Approx(1435.164 / 2 - (680 + m.Sd / mm)).margin(0.002));  // 1.18 mm
  const std::vector<double> ys = sweep_y();
  const std::vector<WheelsetState> st = ws.sweep(ys);
  const EquivalentConicity C(ys, delta_r(st));
  const ConicityResult c3 = C.at(3 * mm), c1 = C.at(1 * mm);
  REQUIRE(c3.status == "ok");
  CHECK(status(c3, fc, ys, st) == "flange_contact");
  CHECK(status(c1, fc, ys, st) == "ok");
  WARN("Sd 36.4 mm on rail A: tan γe " << c1.tan_gamma_e << " at 1 mm, " << c3.tan_gamma_e << " at 3 mm (flange_contact)");

  const WheelMeasureCheck k = check_wheel_measures(m.Sd, m.Sh, m.qR, 0.920);
  CHECK(k.status == "outside_en15313");
  REQUIRE(k.violations.size() == 1);
  CHECK(std::string(k.violations[0].measure) == "Sd");
  CHECK(k.violations[0].above);
  CHECK(k.violations[0].limit / mm == Approx(33.0));
  CHECK(k.text(0.920).rfind("Sd 36.", 0) == 0);
  CHECK(k.text(0.920).find(" mm > 33 mm (EN 15313, D 920 mm)") != std::string::npos);
}

TEST_CASE("a wheel without a flange is profile_incomplete", "[wheelset][conicity][domain]") {
  // tests/data/field/flat_wheel.txt: S1002 rows y ≥ −20 mm (no flange); and a 16 mm fragment
  // of S1002 around its taping line (|y| ≤ 8 mm): neither has a flange face at the Sd level.
  ProfileReadOptions o;
  o.kind = ProfileKind::Wheel;
  const Profile flat = read_profile(std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/field/flat_wheel.txt", o);
  Profile frag = make_standard_profile("S1002");
  {
    std::vector<double> y, z;
    for (std::size_t i = 0; i < frag.y.size(); ++i)
      if (std::fabs(frag.y[i]) <= 8 * mm) y.push_back(frag.y[i]), z.push_back(frag.z[i]);
    frag.y = y, frag.z = z;
  }
  const Profile r = make_standard_profile("EN15302-rail-A");
  for (const Profile* w : std::vector<const Profile*>{&flat, &frag}) {
    CAPTURE(w->source, w->y.front() / mm, w->y.back() / mm);
    const WheelMeasures m = wheel_measures(*w);
    CHECK(!m.valid);
    const Wheelset ws(*w, *w, r, r, en15302_placement());
    const FlangewayClearance fc = flangeway_clearance(ws, m, m);
    CHECK(!fc.valid);
    CHECK(fc.why.find("no flange face at the Sd level") != std::string::npos);
  }
  // The flangeless wheel on rail A: the integral alone has a figure at 2 mm, outside the domain.
  const WheelMeasures m = wheel_measures(flat);
  const Wheelset ws(flat, flat, r, r, en15302_placement());
  const FlangewayClearance fc = flangeway_clearance(ws, m, m);
  std::vector<double> ys;
  for (int k = -300; k <= 300; ++k) ys.push_back(k / 100.0 * mm);
  const std::vector<WheelsetState> st = ws.sweep(ys);
  const EquivalentConicity C(ys, delta_r(st));
  const ConicityResult c = C.at(2 * mm);
  REQUIRE(c.status == "ok");
  CHECK(status(c, fc, ys, st) == "profile_incomplete");
}

TEST_CASE("EN 15313 limits of Sd, Sh, qR by wheel diameter", "[wheelset][domain]") {
  // Limits (EN 15313:2016 as restated by TSI LOC&PAS Table 2), [mm]: D ≥ 840: Sd 22–33, Sh 27.5–36,
  // qR ≥ 6.5; 760–840: Sd 25–33; 630–760: Sd 27.5–33, Sh 29.5–36; 330–630: Sh 31.5–36.
  struct Row { double D, Sd, Sh, qR; const char* status; const char* text; };
  const Row rows[] = {
      {920, 32.5, 28.0, 10.8, "ok", ""},
      {920, 36.4, 28.0, 10.8, "outside_en15313", "Sd 36.4 mm > 33 mm (EN 15313, D 920 mm)"},
      {920, 21.9, 28.0, 10.8, "outside_en15313", "Sd 21.9 mm < 22 mm (EN 15313, D 920 mm)"},
      {920, 32.5, 36.1, 6.4, "outside_en15313", "Sh 36.1 mm > 36 mm (EN 15313, D 920 mm); qR 6.4 mm < 6.5 mm (EN 15313, D 920 mm)"},
      {920, 32.5, 27.4, 10.8, "outside_en15313", "Sh 27.4 mm < 27.5 mm (EN 15313, D 920 mm)"},
      {800, 24.9, 28.0, 10.8, "outside_en15313", "Sd 24.9 mm < 25 mm (EN 15313, D 800 mm)"},
      {700, 27.4, 29.6, 10.8, "outside_en15313", "Sd 27.4 mm < 27.5 mm (EN 15313, D 700 mm)"},
      {700, 27.5, 29.4, 10.8, "outside_en15313", "Sh 29.4 mm < 29.5 mm (EN 15313, D 700 mm)"},
      {500, 30.0, 31.4, 10.8, "outside_en15313", "Sh 31.4 mm < 31.5 mm (EN 15313, D 500 mm)"},
      {500, 30.0, 31.5, 10.8, "ok", ""},
      {300, 40.0, 40.0, 1.0, "unknown", ""},   // below every band
      {920, NAN, 28.0, 10.8, "unknown", ""},   // a measure missing
  };
  for (const Row& w : rows) {
    CAPTURE(w.D, w.Sd, w.Sh, w.qR);
    const WheelMeasureCheck k = check_wheel_measures(w.Sd * mm, w.Sh * mm, w.qR * mm, w.D * mm);
    CHECK(k.status == w.status);
    CHECK(k.text(w.D * mm) == w.text);
  }
}

TEST_CASE("the conicity's evidence table is the one docs/wheelset.md shows", "[wheelset][domain][docs]") {
  std::ifstream in(std::string(MHCONTACT_SOURCE_DIR) + "/docs/wheelset.md");
  REQUIRE(in.good());
  std::stringstream ss;
  ss << in.rdbuf();
  CHECK(ss.str().find(conicity_evidence_markdown()) != std::string::npos);
}
