// The wheelset's roll in the contact geometry against CONTACT module 1
// (tests/data/contact_tangential/mbench_roll_right.csv: the Manchester pair's right wheel at
// Y = 0, 2, 4 mm, the roll A-2.2's kinematic one −1 … +1 mrad, FZ 10 kN, μ 0.3, V 2 m/s, no yaw).
// The multi-Hertzian method with FASTSIM, each wheel rolled against its rail (method.md §3.8), the
// right wheel loaded with 10 kN at CONTACT's roll (pose.solve_roll false).
//
// Held at about 1.5 times the differences measured on 29 Nov 2026 (table in docs/c-api.md, "Roll"; ours, upright and CONTACT),
// per Y: the contact angle within 0.015 / 0.0006 / 0.0019 rad, N within 10 N (CONTACT prints four
// digits), Fx within 25 / 5.4 / 7.8 % of μN, Fs within 2.5 / 2.1 / 2.5 %, Mz within 0.4 N m at Y 2
// and 4 mm. At Y = 0 the tread contact is nearly conformal: one Hertz ellipse with FASTSIM is 11 %
// of μN off in Fx with no roll at all, and its spin moment is a quarter of CONTACT's (−1.3 against
// −4.6 N m: not held there); the roll's own effect is what the wide band still checks (the
// upright wheel is 79 % off).
// Break seen to fail: the wheel kept upright (the old behaviour: the roll 0 in the geometry):
// γ on 17 of the 27 rows, Fx and Fs on 3 each, N on 2.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "unit/contact/manchester_fixture.hpp"
#include "support/data_csv.hpp"
#include "wheelset_contact/wheelset_contact.hpp"

namespace {

mh::WheelsetSetup roll_setup() {
  mh::WheelsetSetup s;
  s.wheel_left = s.wheel_right = mh::testing::read_test_profile("MBench_S1002_v3.prw", mh::ProfileKind::Wheel);
  s.rail_left = s.rail_right = mh::testing::read_test_profile("MBench_UIC60_v3.prr", mh::ProfileKind::Rail);
  s.material = mh::testing::steel();
  s.method.method = mh::Method::MultiHertzian;
  s.method.tangential.mu = 0.3;
  return s;
}

struct Row {
  int id;
  double Y, roll, droll, gamma, N, Fx, Fs, Mz;
};

struct Ours {
  double gamma, N, Fx, Fs, Mz, Y;
  bool ok;
};

// The right wheel with the wheelset at CONTACT's Y and ROLL (y = −Y, φ = ROLL: both frames roll
// positive towards lowering the right wheel), its load 10 kN at the given roll.
Ours right_wheel(const mh::WheelsetContact& W, const Row& c, double vpitch, bool roll_in_geometry) {
  mh::WheelsetPose p;
  p.y = -c.Y * 1e-3;
  p.Q_left = p.Q_right = 10e3;
  p.solve_roll = false;
  p.roll = roll_in_geometry ? c.roll : 0.0;
  p.V = 2;
  p.pitch_rate = -vpitch;
  mh::WheelsetWorkspace ws;
  mh::WheelsetResult r;
  W.step(p, {}, r, ws);
  Ours o{};
  o.ok = !mh::is_failure(r.right.r.status) && !r.right.contacts.empty();
  if (!o.ok) return o;
  // The loaded contacts: one on these tread cases; sums and the N-weighted angle otherwise.
  for (const mh::ContactPoint& k : r.right.contacts) {
    o.N += k.N;
    o.gamma += k.N * k.gamma;
    o.Fx += -k.Fx;  // on the rail, as CONTACT's
    o.Fs += -k.Fs;
    o.Mz += -k.Mn;
    o.Y += k.N * k.Y;
  }
  o.gamma /= o.N;
  o.Y /= o.N;
  return o;
}

}  // namespace

TEST_CASE("wheelset call: the roll in the contact geometry against CONTACT module 1 (Manchester right wheel)",
          "[wheelset_contact][roll][contact]") {
  const mh::CsvTable t = mh::test::read_data_csv("contact_tangential/mbench_roll_right.csv");
  REQUIRE(t.rows.size() == 27);
  const mh::WheelsetContact W(roll_setup());
  const double mu = 0.3;
  // Per Y (0, 2, 4 mm): |γ − γ_CONTACT| [rad], |Fx − FX| and |Fs − FS| as fractions of μN.
  struct Tol { double gamma, F, Fs; };
  const Tol tol[3] = {{0.015, 0.25, 0.025}, {0.0006, 0.054, 0.021}, {0.0019, 0.078, 0.025}};
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    Row c;
    c.id = static_cast<int>(mh::test::csv_num(t, i, "case"));
    c.Y = mh::test::csv_num(t, i, "tY_mm");
    c.roll = mh::test::csv_num(t, i, "roll_rad");
    c.droll = mh::test::csv_num(t, i, "droll_rad");
    c.gamma = -mh::test::csv_num(t, i, "deltcp_rad");
    c.N = mh::test::csv_num(t, i, "FN_N");
    c.Fx = mh::test::csv_num(t, i, "FX_N");
    c.Fs = mh::test::csv_num(t, i, "FS_N");
    c.Mz = mh::test::csv_num(t, i, "MN_Nmm") * 1e-3;
    const double vpitch = mh::test::csv_num(t, i, "vpitch_rad_s");
    const Ours a = right_wheel(W, c, vpitch, true), b = right_wheel(W, c, vpitch, false);
    REQUIRE(a.ok);
    REQUIRE(b.ok);
    const double muN = mu * c.N;
    const Tol& k = c.Y == 0 ? tol[0] : c.Y == 2 ? tol[1] : tol[2];
    INFO("case " << c.id << ": Y " << c.Y << " mm, roll " << c.roll * 1e3 << " mrad (" << c.droll * 1e3
                 << " off the kinematic); gamma " << a.gamma << " vs " << c.gamma << " (upright " << b.gamma << "), N "
                 << a.N << " vs " << c.N << ", Fx " << a.Fx << " vs " << c.Fx << " (upright " << b.Fx << "), Fs " << a.Fs
                 << " vs " << c.Fs << " (upright " << b.Fs << "), Mz " << a.Mz << " vs " << c.Mz << " N m");
    CHECK(std::abs(a.gamma - c.gamma) < k.gamma);
    CHECK(std::abs(a.N - c.N) < 10.0);
    CHECK(std::abs(a.Fx - c.Fx) < k.F * muN);
    CHECK(std::abs(a.Fs - c.Fs) < k.Fs * muN);
    if (c.Y > 0) CHECK(std::abs(a.Mz - c.Mz) < 0.4);
  }
}

TEST_CASE("wheelset call: A-2.2's flange cases with CONTACT's roll in the geometry (right wheel)",
          "[wheelset_contact][roll][contact][a22]") {
  // tests/data/contact_tangential/mbench_a22_right.csv, t_Y 6.5 … 10 mm: the wheelset yawed 2.4 mrad
  // per mm and rolled by its kinematic roll (ROLL, −4.4 … −11.3 mrad), 10 kN on the right wheel at
  // CONTACT's roll (pose.solve_roll false), multi-Hertzian with FASTSIM. Measured 29 Nov 2026:
  // N within 0.6 % of CONTACT's FN and the flange contact angle within 0.014 rad; the wheel kept
  // upright (the old behaviour) is 15–36 % off in N and 0.27–0.66 rad in γ: the flange N error
  // the comparison had put on the yaw was the roll. Held at 1 % and 0.021 rad.
  // Break seen to fail: p.roll 0 here (the wheel upright): all 8 rows on N and on γ.
  const mh::CsvTable t = mh::test::read_data_csv("contact_tangential/mbench_a22_right.csv");
  const mh::WheelsetContact W(roll_setup());
  int compared = 0;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const double tY = mh::test::csv_num(t, i, "tY_mm");
    if (tY < 6.5) continue;
    mh::WheelsetPose p;
    p.y = -tY * 1e-3;
    p.yaw = -mh::test::csv_num(t, i, "yaw_mrad") * 1e-3;
    p.Q_left = p.Q_right = 10e3;
    p.V = mh::test::csv_num(t, i, "vs_mm_s") * 1e-3;
    p.pitch_rate = -mh::test::csv_num(t, i, "vpitch_rad_s");
    p.solve_roll = false;
    p.roll = mh::test::csv_num(t, i, "roll_rad");
    mh::WheelsetWorkspace ws;
    mh::WheelsetResult r;
    W.step(p, {}, r, ws);
    REQUIRE(!mh::is_failure(r.right.r.status));
    double N = 0, gamma = 0;
    for (const mh::ContactPoint& k : r.right.contacts) N += k.N, gamma = std::max(gamma, k.gamma);
    const double FN = mh::test::csv_num(t, i, "FN_N"), g = -mh::test::csv_num(t, i, "deltcp_rad");
    INFO("t_Y " << tY << " mm, roll " << p.roll * 1e3 << " mrad: N " << N << " vs " << FN << ", gamma " << gamma
                << " vs " << g);
    CHECK(std::abs(N - FN) < 0.01 * FN);
    CHECK(std::abs(gamma - g) < 0.021);
    ++compared;
  }
  CHECK(compared == 8);
}

TEST_CASE("wheelset call: the rolled wheel's roll lever is the slope of its first-contact height",
          "[wheelset_contact][roll]") {
  // roll_lever(side, y, φ) (eq. 3.8.2 differentiated at the rolled minimum) against central
  // differences of first_contact_height(side, y, φ) (±1 µrad), tread and flange, both wheels:
  // the slope of the loads mode's roll search. Measured 29 Nov 2026: within 0.34 % of the lever,
  // or 0.37 mm where it is short (16 mm at y 7.5 mm, 9 mrad: the flange), the rolled wheel point
  // being first order in δ; held at 0.5 % or 0.5 mm.
  // Break seen to fail: the rotation's term tan γ z̃_w left out (10 of the 60 samples, the
  // flange ones, where z̃_w is large).
  const mh::WheelsetContact W(roll_setup());
  mh::WheelsetWorkspace ws;
  int compared = 0;
  for (double y : {-7e-3, -3e-3, 0.0, 2e-3, 5e-3, 7.5e-3})
    for (double phi : {-6e-3, -1e-3, 0.4e-3, 3e-3, 9e-3})
      for (int side : {+1, -1}) {
        const double h = 1e-6;
        const double fp = W.first_contact_height(side, y, phi + h, ws), fm = W.first_contact_height(side, y, phi - h, ws);
        const double fd = (fp - fm) / (2 * h), L = W.roll_lever(side, y, phi, ws);
        INFO("y " << y * 1e3 << " mm, roll " << phi * 1e3 << " mrad, side " << side << ": lever " << L
                  << " m, dh/droll " << fd << " m");
        REQUIRE(std::isfinite(fd));
        CHECK(-side * L == Approx(fd).margin(std::max(5e-4, 0.005 * std::fabs(L))));
        ++compared;
      }
  CHECK(compared == 60);
}
