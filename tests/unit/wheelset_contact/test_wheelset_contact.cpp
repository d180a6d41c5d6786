// The wheelset call (wheelset_contact/wheelset_contact.hpp): symmetry, mirror, the single-pair
// call, the first-contact heights against the rigid wheelset geometry (geometry/wheelset.hpp, an
// independent contact search), the solved roll, the derivatives against finite differences of
// other steps and against the analytic normal stiffness, and the creep forces' mirror.
// Breaks guarded (each seen to fail, the tests named):
//  - t_Y = y for both wheels (no σ): "mirror symmetry", "each contact is the single-pair call",
//    "first-contact heights", "the yaw lead warning" (and the C test of the single-pair call);
//  - Y_track = y_pair on the right wheel (no σ in add_contact): "a symmetric wheelset", "mirror
//    symmetry", "yaw: the lateral creep forces";
//  - no σ on the right wheel's yaw in the kinematics: "each contact is the single-pair call",
//    "yaw: the lateral creep forces";
//  - first_contact_height without the −gmin: "first-contact heights", "derivatives";
//  - a central difference divided by h instead of 2h: "derivatives";
//  - the roll lever without its r tan γ (a + y_w only): "first-contact heights and the solved roll"
//    (then with the first-order rule; now the rolled geometry's roll is held against the exact
//    rotation, and a pair_pose without its (z0 + R0) sin δ shift fails it: 6.5 mm, 4.17 mrad).
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/multi_hertz/approach_given.hpp"
#include "contact/solve.hpp"
#include "geometry/wheelset.hpp"
#include "profile/standard_profiles.hpp"
#include "wheelset_contact/wheelset_contact.hpp"

namespace {

constexpr double mm = 1e-3;

mh::WheelsetSetup s1002_60e1(bool friction) {
  mh::WheelsetSetup s;
  s.wheel_left = s.wheel_right = mh::make_standard_profile("S1002", mh::Inclination::None);
  s.rail_left = s.rail_right = mh::make_standard_profile("60E1", mh::Inclination::In40);
  if (friction) s.method.tangential.mu = 0.3;
  return s;
}

const mh::WheelsetContact& ws_fixture(bool friction) {
  static const mh::WheelsetContact dry(s1002_60e1(false));
  static const mh::WheelsetContact wet(s1002_60e1(true));
  return friction ? wet : dry;
}

mh::WheelsetPose loads(double y, double Q) {
  mh::WheelsetPose p;
  p.y = y;
  p.Q_left = p.Q_right = Q;
  p.V = 30;
  return p;
}

}  // namespace

TEST_CASE("wheelset: a symmetric wheelset at zero shift gives equal contacts", "[wheelset_contact]") {
  const auto& W = ws_fixture(true);
  mh::WheelsetWorkspace ws;
  mh::WheelsetResult r;
  W.step(loads(0, 50e3), {}, r, ws);
  REQUIRE(r.left.r.status == r.right.r.status);
  REQUIRE(r.left.contacts.size() == r.right.contacts.size());
  REQUIRE(!r.left.contacts.empty());
  for (std::size_t i = 0; i < r.left.contacts.size(); ++i) {
    const auto &L = r.left.contacts[i], &R = r.right.contacts[i];
    CHECK(L.N == Approx(R.N).epsilon(1e-12));
    CHECK(L.gamma == Approx(R.gamma).epsilon(1e-12));
    CHECK(L.Y == Approx(-R.Y).epsilon(1e-12));
    CHECK(L.Y_ws == Approx(-R.Y_ws).epsilon(1e-12));
  }
  // Forces on the wheelset: the lateral ones cancel; the normal forces carry the loads (the creep
  // forces in the inclined contact planes add their own vertical part, equal on both wheels).
  CHECK(std::fabs(r.total.F[1]) < 1e-6 * 50e3);
  CHECK(r.left.r.Fz + r.right.r.Fz == Approx(100e3).epsilon(1e-6));
  CHECK(r.left.on_wheelset.F[2] == Approx(r.right.on_wheelset.F[2]).epsilon(1e-12));
  CHECK(std::fabs(r.roll) < 1e-12);
  // Rolling at the nominal radius on the taping line: no net yaw moment from a centred wheelset.
  CHECK(std::fabs(r.total.M[2]) < 1e-6 * 50e3);
}

TEST_CASE("wheelset: mirror symmetry at +y and -y", "[wheelset_contact]") {
  const auto& W = ws_fixture(true);
  mh::WheelsetWorkspace ws;
  for (double y : {2.0 * mm, 5.5 * mm, 7.5 * mm}) {
    INFO("y = " << y / mm << " mm");
    mh::WheelsetResult p, m;
    W.step(loads(y, 60e3), {}, p, ws);
    W.step(loads(-y, 60e3), {}, m, ws);
    REQUIRE(p.left.contacts.size() == m.right.contacts.size());
    for (std::size_t i = 0; i < p.left.contacts.size(); ++i) {
      CHECK(p.left.contacts[i].N == Approx(m.right.contacts[i].N).epsilon(1e-12));
      CHECK(p.left.contacts[i].Y == Approx(-m.right.contacts[i].Y).epsilon(1e-12));
    }
    CHECK(p.total.F[0] == Approx(m.total.F[0]).margin(1e-6));
    CHECK(p.total.F[1] == Approx(-m.total.F[1]).margin(1e-6));
    CHECK(p.total.F[2] == Approx(m.total.F[2]).margin(1e-6));
    CHECK(p.total.M[2] == Approx(-m.total.M[2]).margin(1e-6));
    CHECK(p.roll == Approx(-m.roll).margin(1e-15));
    // Towards the left rail (y > 0), the left flange pushes the wheelset back to the right.
    if (y > 7 * mm) CHECK(p.total.F[1] < -10e3);
  }
}

TEST_CASE("wheelset: each contact is the single-pair call at t_Y = sigma y", "[wheelset_contact]") {
  const auto& W = ws_fixture(true);
  const mh::WheelsetSetup s = s1002_60e1(true);
  mh::WheelsetWorkspace ws;
  mh::WheelsetPose p = loads(3.1 * mm, 70e3);
  p.Q_right = 40e3;
  p.yaw = 2e-3;
  p.lateral_velocity = 0.05;
  p.yaw_rate = 0.1;
  mh::WheelsetResult r;
  W.step(p, {}, r, ws);
  for (int sigma : {+1, -1}) {
    mh::TrackSetup t = s.track;
    const mh::ContactGeometry G = mh::build_geometry(s.wheel_left, s.rail_left, t, s.geometry);
    mh::MethodOptions o = s.method;
    o.tangential.kin.V = 30;
    o.tangential.kin.yaw = sigma * p.yaw;
    o.tangential.kin.lateral_velocity = sigma * p.lateral_velocity;
    o.tangential.kin.yaw_rate = sigma * p.yaw_rate;
    o.tangential.l_origin = 0.75;
    const double Q = sigma > 0 ? p.Q_left : p.Q_right;
    // The wheelset's roll (the loads differ) rolls each wheel against its rail: the pair's pose.
    const mh::WheelResult& w = sigma > 0 ? r.left : r.right;
    double tY = 0, delta = 0;
    W.pair_pose(sigma, p.y, r.roll, &tY, &delta);
    CHECK(w.tY == tY);
    CHECK(delta == sigma * r.roll);
    CHECK(std::fabs(r.roll) > 1e-5);
    o.multi_hertzian.roll = delta;
    o.tangential.kin.roll = delta;
    const mh::CaseResult c = mh::solve_contact(G, s.material, tY, Q, o);
    REQUIRE(c.loaded.size() == w.r.loaded.size());
    CHECK(c.status == w.r.status);
    CHECK(c.dz == w.r.dz);
    for (std::size_t i = 0; i < c.loaded.size(); ++i) {
      CHECK(c.loaded[i].s.N == w.r.loaded[i].s.N);
      CHECK(c.loaded[i].t.Fx == w.r.loaded[i].t.Fx);
      CHECK(c.loaded[i].t.Fy == w.r.loaded[i].t.Fy);
    }
  }
}

TEST_CASE("wheelset: each wheel judged as the single-pair call, across the flange", "[wheelset_contact]") {
  // The wheelset judges each wheel once, on the answer its roll search keeps (judge_wheel): the
  // status and the warnings must be the single-pair call's at the same t_Y, roll and load,
  // outside_validity included (flange contact near a jump of the contact angle). Broken once:
  // without judge_wheel every wheel was `ok` with no validity warning, and this test failed.
  const auto& W = ws_fixture(true);
  const mh::WheelsetSetup s = s1002_60e1(true);
  mh::TrackSetup t = s.track;
  const mh::ContactGeometry G = mh::build_geometry(s.wheel_left, s.rail_left, t, s.geometry);
  mh::WheelsetWorkspace ws;
  int outside = 0, compared = 0;
  for (double y_mm = 3; y_mm <= 9.01; y_mm += 0.25) {
    mh::WheelsetPose p = loads(y_mm * mm, 60e3);
    mh::WheelsetResult r;
    W.step(p, {}, r, ws);
    for (int sigma : {+1, -1}) {
      const mh::WheelResult& w = sigma > 0 ? r.left : r.right;
      if (mh::is_failure(w.r.status)) continue;
      double tY = 0, delta = 0;
      W.pair_pose(sigma, p.y, r.roll, &tY, &delta);
      mh::MethodOptions o = s.method;
      o.tangential.kin.V = 30;
      o.tangential.l_origin = 0.75;
      o.multi_hertzian.roll = delta;
      o.tangential.kin.roll = delta;
      const mh::CaseResult c = mh::solve_contact(G, s.material, tY, sigma > 0 ? p.Q_left : p.Q_right, o);
      INFO("y " << y_mm << " mm, wheel " << sigma);
      CHECK(c.status == w.r.status);
      REQUIRE(c.warnings.size() == w.r.warnings.size());
      for (std::size_t k = 0; k < c.warnings.size(); ++k) CHECK(c.warnings[k].cls == w.r.warnings[k].cls);
      outside += w.r.status == mh::CaseStatus::OutsideValidity;
      ++compared;
    }
  }
  CHECK(compared > 30);
  CHECK(outside > 0);  // the flange's validity verdicts are part of what is compared
}

TEST_CASE("wheelset: first-contact heights and the solved roll against the rigid wheelset geometry",
          "[wheelset_contact]") {
  // geometry/wheelset.hpp finds each wheel's contact by its own scan of the gap (y towards the
  // RIGHT rail there: y_geom = −y). Its heights h are where the axle touches with the profiles
  // smoothed on a 0.02 mm grid (the tables here: 0.01 mm): 1 µm.
  const auto& W = ws_fixture(false);
  const mh::WheelsetSetup s = s1002_60e1(false);
  mh::Wheelset geo(s.wheel_left, s.wheel_right, s.rail_left, s.rail_right, mh::WheelsetPlacement{});
  mh::WheelsetOptions so;
  so.roll = mh::WheelsetRoll::Solved;
  mh::Wheelset geo_roll(s.wheel_left, s.wheel_right, s.rail_left, s.rail_right, mh::WheelsetPlacement{}, so);
  CHECK(W.rail_origin(+1) == Approx(geo.rail_origin(-1)).margin(1e-9));
  CHECK(W.rail_origin(-1) == Approx(geo.rail_origin(+1)).margin(1e-9));
  mh::WheelsetWorkspace ws;
  for (double y : {-6.0 * mm, -2.0 * mm, 0.0, 1.5 * mm, 4.0 * mm, 6.0 * mm, 6.5 * mm}) {
    INFO("y = " << y / mm << " mm");
    const mh::WheelsetState st = geo.at(-y);
    REQUIRE(st.found);
    CHECK(W.first_contact_height(+1, y) == Approx(st.left.h).margin(1e-6));
    CHECK(W.first_contact_height(-1, -y) == Approx(st.right.h).margin(1e-6));
    // Roll solved, the wheelset 20 µm below the height where both wheels touch at that roll: both
    // carry the same virtual penetration, so both are loaded. The roll does not depend on Z.
    mh::WheelsetPose p;
    p.y = y;
    p.vertical = mh::WheelsetVertical::Position;
    p.solve_roll = true;
    p.Z = W.first_contact_height(+1, y);
    mh::WheelsetResult r;
    W.step(p, {}, r, ws);
    p.Z = W.first_contact_height(+1, y, r.roll, ws) - 20e-6;
    CHECK(W.first_contact_height(-1, y, r.roll, ws) == Approx(p.Z + 20e-6).margin(1e-9));
    W.step(p, {}, r, ws);
    CHECK(r.left.r.dz == Approx(20e-6).margin(1e-9));
    CHECK(r.right.r.dz == Approx(20e-6).margin(1e-9));
    CHECK(r.left.r.Fz > 0);
    CHECK(r.right.r.Fz > 0);
    // The roll where both wheels touch, each rolled against its rail (method.md §3.8), against the
    // exact rotation of geometry/wheelset (roll positive raising the RIGHT end there), an
    // independent contact search: within 1 %, or 2 µrad, also near the flange (6.5 mm: γ 29° on
    // the upright wheel, 4.17 mrad; the first-order rule gave 0.84 mrad there).
    const mh::WheelsetState sr = geo_roll.at(-y);
    REQUIRE(sr.converged);
    CHECK(r.roll == Approx(-sr.roll).margin(std::max(2e-6, 0.01 * std::fabs(sr.roll))));
    CHECK(r.warnings.empty());
  }
}

TEST_CASE("wheelset: derivatives against finite differences of other steps and the analytic stiffness",
          "[wheelset_contact]") {
  const auto& W = ws_fixture(true);
  mh::WheelsetWorkspace ws;
  mh::WheelsetPose p;
  p.y = 3.0 * mm;
  p.yaw = 1e-3;
  p.V = 30;
  p.vertical = mh::WheelsetVertical::Position;
  const double hl = W.first_contact_height(+1, p.y), hr = W.first_contact_height(-1, -p.y);
  p.Z = 0.5 * (hl + hr) - 60e-6;
  mh::WheelsetResult r;
  W.step(p, {}, r, ws);  // the roll where both touch, then 0.02 mrad more (15 µm at a wheel)
  p.solve_roll = false;
  p.roll = r.roll + 2e-5;
  mh::WheelsetStepOptions o;
  o.derivatives = true;
  W.step(p, o, r, ws);
  REQUIRE(r.status != mh::CaseStatus::NoContact);
  // Analytic: Fz of a wheel is Σ N cos γ, N of each ellipse a function of δz = h − Z − σ a φ:
  // dFz/dZ = −Σ dN/dh0 cos² γ (approach_given.hpp, eq. 11) — the creep forces' share aside
  // (FASTSIM's forces scale with N: their vertical part Fs sin γ moves with N too; included by
  // the finite differences, small against N cos γ at tread contact).
  for (const mh::WheelResult* w : {&r.left, &r.right}) {
    double k = 0;
    for (const auto& L : w->r.loaded) k += mh::normal_stiffness(L) * std::cos(L.g.gamma) * std::cos(L.g.gamma);
    CHECK(w->dF_dvertical[2] == Approx(-k).epsilon(0.02));
  }
  // Finite differences of whole steps with other steps (3x the default's).
  auto fd = [&](auto set, double h) {
    mh::WheelsetPose a = p, b = p;
    set(a, h);
    set(b, -h);
    mh::WheelsetResult ra, rb;
    W.step(a, {}, ra, ws);
    W.step(b, {}, rb, ws);
    std::array<double, 3> d;
    for (int k = 0; k < 3; ++k) d[k] = (ra.total.F[k] - rb.total.F[k]) / (2 * h);
    return d;
  };
  const auto dy = fd([](mh::WheelsetPose& q, double h) { q.y += h; }, 3e-5);
  const auto dr = fd([](mh::WheelsetPose& q, double h) { q.roll += h; }, 3e-5);
  const auto dZ = fd([](mh::WheelsetPose& q, double h) { q.Z += h; }, 3e-6);
  for (int k = 0; k < 3; ++k) {
    INFO("component " << k);
    // Tolerance: 2 % of the largest component of each derivative (the differences' truncation,
    // the tables' linear interpolation in t_Y and, the wheels rolled, the rolled minimum's
    // roughness: 0.65 % here, up to 11 % elsewhere on this tread, docs/c-api.md).
    auto scale = [](const std::array<double, 3>& d) { return std::max({std::fabs(d[0]), std::fabs(d[1]), std::fabs(d[2])}); };
    CHECK(r.dF_dy[k] == Approx(dy[k]).margin(0.02 * scale(dy)));
    CHECK(r.dF_droll[k] == Approx(dr[k]).margin(0.02 * scale(dr)));
    CHECK(r.dF_dvertical[k] == Approx(dZ[k]).margin(0.02 * scale(dZ)));
  }
}

TEST_CASE("wheelset: yaw: the lateral creep forces of both wheels act the same way", "[wheelset_contact]") {
  // A centred symmetric wheelset yawed by a small ψ (linear range): both wheels slip sideways
  // alike, so the change of their lateral creep forces in the track frame is the same on both
  // (with the mirror's signs wrong the changes are opposite). The spin's share, pointing outwards
  // on each wheel, is in both steps and drops out of the change.
  const auto& W = ws_fixture(true);
  mh::WheelsetWorkspace ws;
  mh::WheelsetResult r0, r;
  mh::WheelsetPose p = loads(1 * mm, 50e3);
  W.step(p, {}, r0, ws);
  p.yaw = 0.1e-3;
  W.step(p, {}, r, ws);
  REQUIRE(r.left.r.tangential.solved);
  const double dl = r.left.on_wheelset.F[1] - r0.left.on_wheelset.F[1];
  const double dr = r.right.on_wheelset.F[1] - r0.right.on_wheelset.F[1];
  // The two contacts differ at y = 1 mm: t_Y = ±1 mm are other points of S1002 and 60E1, the
  // left ellipse 6.4 × 2.8 mm, the right 4.9 × 6.7 mm (a b 18.0 against 33.0 mm², Kalker's C22 of
  // each shape), so the linear creep forces' change differs by the ellipses, not by the roll:
  // measured 29 Nov 2026 20.7 % with each wheel rolled against its rail, 18.0 % with the wheels
  // upright (roll_in_geometry false; 26 % with the roll search before, stopped at another roll).
  // Held at 30 % (1.45 × the measured); the break it guards (the mirror's signs) gives −100 %.
  CHECK(dl == Approx(dr).epsilon(0.3));
  // Held at ẏ = 0, a wheel rolling along its yawed x slips towards −y at the contact (−Ω r ψ):
  // the rail pushes it towards +y, the way the wheelset would run.
  CHECK(dl > 100);
  CHECK(dr > 100);
}

TEST_CASE("wheelset: the yaw lead warning at flange contact, not at the tread", "[wheelset_contact]") {
  const auto& W = ws_fixture(true);
  mh::WheelsetWorkspace ws;
  mh::WheelsetResult r;
  mh::WheelsetPose p = loads(0, 50e3);
  p.yaw = 5e-3;
  W.step(p, {}, r, ws);
  CHECK(r.warnings.empty());
  p.y = 8 * mm;  // left flange (its roll of several mrad in the geometry: no roll warning)
  W.step(p, {}, r, ws);
  int leads = 0;
  for (const auto& w : r.warnings) {
    if (w.kind != mh::WheelsetWarning::Kind::YawLeadNotModelled) continue;
    ++leads;
    CHECK(w.side == +1);
    CHECK(mh::to_string(w).rfind("yaw_lead_not_modelled:wheel=left:lead_mm=", 0) == 0);
  }
  CHECK(leads == 1);
}

TEST_CASE("wheelset: bad input names the field, the value and the rule", "[wheelset_contact]") {
  const auto& W = ws_fixture(true);
  mh::WheelsetWorkspace ws;
  mh::WheelsetResult r;
  mh::WheelsetPose p = loads(0, -1);
  CHECK_THROWS_WITH(W.step(p, {}, r, ws), Catch::Contains("pose.Q_left = -1 N") && Catch::Contains(">= 0"));
  p = loads(0, 1e3);
  p.V = 0;
  CHECK_THROWS_WITH(W.step(p, {}, r, ws), Catch::Contains("pose.V = 0 m/s"));
}

namespace {

/// The step of the loads pose p (with the position its answer gives when `position`: Z and the
/// roll held) with the derivatives, analytic in the vertical input where the method gives it and
/// by central differences throughout.
std::pair<mh::WheelsetResult, mh::WheelsetResult> analytic_and_differences(const mh::WheelsetContact& W,
                                                                           mh::WheelsetPose p, bool position) {
  mh::WheelsetWorkspace ws;
  mh::WheelsetResult r0, ra, rd;
  W.step(p, {}, r0, ws);
  if (position) {
    p.vertical = mh::WheelsetVertical::Position;
    p.Z = r0.Z;
    p.solve_roll = false;
    p.roll = r0.roll;
  }
  mh::WheelsetStepOptions o;
  o.derivatives = true;
  W.step(p, o, ra, ws);
  o.analytic_vertical = false;
  W.step(p, o, rd, ws);
  return {ra, rd};
}

}  // namespace

TEST_CASE("wheelset: the analytic vertical derivative against central differences of the same step",
          "[wheelset_contact][wheelset_derivatives]") {
  // dF/dZ (position) and dF/dQ (loads) by the approach's analytic slope (vertical_slope: dN/dh0 of
  // each ellipse and FASTSIM's load slope) against the central differences of the same solves
  // (analytic_vertical false: ±1 µm in Z, ±1e-4 Q), on the tread, the flange root and the flange
  // (S1002 on 60E1 1:40 rolled: y 0, 3, 6, 7.5, 8.5 mm, 60 kN), with and without friction.
  // Measured (2 Dec 2026): at most 1.6e-4 of the largest component apart, the differences'
  // truncation (N ∝ h0^1.5 over ±1 µm of a 20–60 µm approach); held at 2.5e-4. In the loads mode
  // dFz/dQ is 1 where the wheel's load is balanced with its creep forces' share.
  // Breaks seen to fail: the creep forces' load slope left out (dFx = dFs = 0); their share left
  // out of dQ; dF/dZ without its sign.
  double worst = 0;
  for (const bool friction : {false, true})
    for (const bool position : {false, true})
      for (const double y : {0.0, 3.0, 6.0, 7.5, 8.5}) {
        mh::WheelsetPose p = loads(y * mm, 60e3);
        p.yaw = 1e-3;
        p.lateral_velocity = 0.01;
        const auto [ra, rd] = analytic_and_differences(ws_fixture(friction), p, position);
        for (const auto& [a, d] : {std::pair{&ra.left, &rd.left}, std::pair{&ra.right, &rd.right}}) {
          INFO("friction " << friction << ", position " << position << ", y " << y << " mm, side " << a->side);
          REQUIRE(a->dF_dvertical_analytic);
          REQUIRE_FALSE(d->dF_dvertical_analytic);
          const double scale = std::max({std::fabs(d->dF_dvertical[0]), std::fabs(d->dF_dvertical[1]), std::fabs(d->dF_dvertical[2])});
          for (int k = 0; k < 3; ++k) {
            INFO("component " << k);
            CHECK(a->dF_dvertical[k] == Approx(d->dF_dvertical[k]).margin(2.5e-4 * scale));
            worst = std::max(worst, std::fabs(a->dF_dvertical[k] - d->dF_dvertical[k]) / scale);
          }
          if (!position) CHECK(a->dF_dvertical[2] == Approx(1).epsilon(1e-12));
        }
        for (int k = 0; k < 3; ++k) CHECK(ra.dF_dvertical[k] == ra.left.dF_dvertical[k] + ra.right.dF_dvertical[k]);
      }
  WARN("analytic against central differences, largest difference / largest component: " << worst);
}

TEST_CASE("wheelset: the vertical derivative of plastic ellipses: analytic without friction, differences with it",
          "[wheelset_contact][wheelset_derivatives]") {
  // The yield law (σ_y 350 MPa: every loaded ellipse plastic at 100 kN on S1002/60E1 1:40): dN/dh0
  // is the law's own, so the analytic derivative holds without friction (measured within 1.7e-5
  // of the differences, 2 Dec 2026; held at 2.5e-4 as above); with friction FASTSIM's load slope
  // assumes Hertz's growth of the patch, which a plastic patch does not follow: differences then
  // (applied to them it was 14 % off in dFx/dQ, loads mode, y = 0; this test fails so).
  for (const bool friction : {false, true}) {
    mh::WheelsetSetup s = s1002_60e1(friction);
    s.material.yield = 350e6;
    REQUIRE(mh::derive_plastic_law(s.material));
    const mh::WheelsetContact W(s);
    for (const bool position : {false, true})
      for (const double y : {0.0, 6.0}) {
        const auto [ra, rd] = analytic_and_differences(W, loads(y * mm, 100e3), position);
        for (const auto& [a, d] : {std::pair{&ra.left, &rd.left}, std::pair{&ra.right, &rd.right}}) {
          INFO("friction " << friction << ", position " << position << ", y " << y << " mm, side " << a->side);
          bool plastic = false;
          for (const auto& L : a->r.loaded) plastic = plastic || (L.s.N > 0 && L.s.plastic);
          REQUIRE(plastic);
          CHECK(a->dF_dvertical_analytic == !friction);
          const double scale = std::max({std::fabs(d->dF_dvertical[0]), std::fabs(d->dF_dvertical[1]), std::fabs(d->dF_dvertical[2])});
          for (int k = 0; k < 3; ++k) CHECK(a->dF_dvertical[k] == Approx(d->dF_dvertical[k]).margin(2.5e-4 * scale));
        }
      }
  }
}
