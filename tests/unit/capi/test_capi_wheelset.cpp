// The wheelset call of the C interface (include/mhcontact.h, its last section): each wheel equals
// the single-pair call at t_Y = ±y, the result versioned by size both ways (an older, smaller
// struct is filled up to its size and not beyond; a newer, larger one gets the library's fields
// and its struct_size back), the interface version, bad input, the batch against single steps,
// the wheelset warnings as text.
// Breaks guarded (each seen to fail):
//  - fill_wheelset_result copying sizeof(full) whatever struct_size: "an older, smaller result"
//    fails (the guard bytes are overwritten);
//  - t_Y = y on the right wheel: "each wheel is the single-pair call" fails.
#include <catch2/catch.hpp>

#include <mhcontact.h>

#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

namespace {

struct Fixture {
  mhc_profile *wheel = nullptr, *rail = nullptr;
  mhc_pair* pair = nullptr;
  mhc_wheelset* ws = nullptr;
  mhc_wheelset* ws_normal = nullptr;  ///< the same without friction: normal contact only
  Fixture() {
    REQUIRE(mhc_profile_standard("S1002", &wheel) == MHC_OK);
    REQUIRE(mhc_profile_standard("60E1", &rail) == MHC_OK);
    mhc_pair_options o;
    mhc_pair_options_init(&o);
    o.rail_inclination = 40;
    REQUIRE(mhc_pair_create(wheel, rail, &o, &pair) == MHC_OK);
    mhc_wheelset_options wo;
    mhc_wheelset_options_init(&wo);
    wo.mu = 0.3;
    // The same pair on both sides: the right one is its mirror image (canonical frames).
    REQUIRE(mhc_wheelset_create(pair, pair, &wo, &ws) == MHC_OK);
    mhc_wheelset_options_init(&wo);
    REQUIRE(mhc_wheelset_create(pair, pair, &wo, &ws_normal) == MHC_OK);
  }
  ~Fixture() {
    mhc_wheelset_free(ws);
    mhc_wheelset_free(ws_normal);
    mhc_pair_free(pair);
    mhc_profile_free(wheel);
    mhc_profile_free(rail);
  }
};

const Fixture& fx() {
  static const Fixture f;
  return f;
}

mhc_wheelset_pose pose(double y, double QL, double QR) {
  mhc_wheelset_pose p;
  std::memset(&p, 0, sizeof p);
  p.struct_size = sizeof p;
  p.vertical = MHC_VERTICAL_LOADS;
  p.y_m = y;
  p.Q_left_N = QL;
  p.Q_right_N = QR;
  p.V_m_per_s = 30;
  p.pitch_rate_rad_per_s = NAN;
  return p;
}

struct Ws {
  mhc_wheelset_workspace* w = nullptr;
  Ws() { REQUIRE(mhc_wheelset_workspace_create(fx().ws, &w) == MHC_OK); }
  ~Ws() { mhc_wheelset_workspace_free(w); }
};

}  // namespace

TEST_CASE("C wheelset: the interface version is negotiable at run time", "[capi][wheelset_contact]") {
  int32_t oldest = -1;
  CHECK(mhc_interface_version(&oldest) == MHC_INTERFACE_VERSION);
  CHECK(oldest == 1);
  CHECK(mhc_interface_version(nullptr) == MHC_INTERFACE_VERSION);
}

TEST_CASE("C wheelset: each wheel is the single-pair call at its t_Y and relative roll", "[capi][wheelset_contact]") {
  // Normal contact only: the single-pair call has no friction (with it, the creep forces' vertical
  // share enters each wheel's load balance, docs/method.md §10 eq. 10.1; checked below).
  mhc_wheelset_workspace* w0 = nullptr;
  REQUIRE(mhc_wheelset_workspace_create(fx().ws_normal, &w0) == MHC_OK);
  mhc_wheelset_result r;
  r.struct_size = sizeof r;
  const mhc_wheelset_pose p = pose(4e-3, 60e3, 45e3);
  REQUIRE(mhc_wheelset_step(fx().ws_normal, w0, &p, &r) == MHC_OK);
  mhc_wheelset_workspace_free(w0);
  mhc_workspace* pw = nullptr;
  REQUIRE(mhc_workspace_create(fx().pair, &pw) == MHC_OK);
  for (int side = 0; side < 2; ++side) {
    mhc_result s;
    s.struct_size = sizeof s;
    // The wheelset's roll (the loads differ) rolls each wheel against its rail by sigma roll, its
    // t_Y shifted by the rotation about the axle centre (docs/method.md section 3 item 8): the
    // single-pair call at the wheel's own t_Y with that relative roll.
    const mhc_wheelset_wheel& wh = r.wheel[side];
    const double tY = wh.tY_m, delta = side == 0 ? r.roll_rad : -r.roll_rad;
    CHECK(std::fabs(r.roll_rad) > 1e-5);
    CHECK(std::fabs(tY - (side == 0 ? p.y_m : -p.y_m)) < 0.47 * std::fabs(r.roll_rad));
    REQUIRE(mhc_solve_load(fx().pair, pw, tY, delta, side == 0 ? p.Q_left_N : p.Q_right_N, &s) == MHC_OK);
    CHECK(wh.status == s.status);
    CHECK(wh.warnings == s.warnings);
    CHECK(wh.n_warnings == s.n_warnings);
    CHECK(wh.Fz_pair_N == Approx(s.Fz_N).epsilon(1e-12));
    CHECK(wh.dz_m == s.dz_m);
    REQUIRE(wh.n_contacts == s.n_contacts);
    for (int i = 0; i < s.n_contacts && i < MHC_MAX_CONTACTS; ++i) {
      CHECK(wh.contact[i].N_N == s.contact[i].N_N);
      CHECK(wh.contact[i].gamma_rad == s.contact[i].gamma_rad);
      CHECK(wh.contact[i].flags == s.contact[i].flags);
      // The rail point in the track frame: the left rail's field side is +y, the right one's -y.
      CHECK(std::copysign(1.0, wh.contact[i].y_track_m) == (side == 0 ? 1.0 : -1.0));
    }
  }
  mhc_workspace_free(pw);
  CHECK(r.wheel[0].Fz_pair_N + r.wheel[1].Fz_pair_N == Approx(105e3).epsilon(1e-12));
  // With friction each wheel's vertical force, normal and creep forces together, carries its
  // load (to the equilibrium's 1e-7 Q), and the normal forces alone do not.
  Ws w;
  mhc_wheelset_result rf;
  rf.struct_size = sizeof rf;
  REQUIRE(mhc_wheelset_step(fx().ws, w.w, &p, &rf) == MHC_OK);
  for (int side = 0; side < 2; ++side) {
    const double Q = side == 0 ? p.Q_left_N : p.Q_right_N;
    CHECK(rf.wheel[side].Fz_pair_N == Approx(Q).epsilon(1e-6));
    double N_cos = 0;
    for (int i = 0; i < rf.wheel[side].n_contacts && i < MHC_MAX_CONTACTS; ++i)
      N_cos += rf.wheel[side].contact[i].N_N * std::cos(rf.wheel[side].contact[i].gamma_rad);
    CHECK(std::fabs(N_cos - Q) > 1e-6 * Q);
  }
}

TEST_CASE("C wheelset: an older, smaller result is filled up to its size and a newer, larger one gets the library's",
          "[capi][wheelset_contact]") {
  Ws w;
  const mhc_wheelset_pose p = pose(2e-3, 50e3, 50e3);
  mhc_wheelset_result full;
  full.struct_size = sizeof full;
  REQUIRE(mhc_wheelset_step(fx().ws, w.w, &p, &full) == MHC_OK);
  // An older header's struct: the wheelset's own fields only (it ends where `wheel` begins).
  const std::size_t old_size = offsetof(mhc_wheelset_result, wheel);
  std::vector<unsigned char> buf(sizeof(mhc_wheelset_result) + 64, 0xab);
  auto* old = reinterpret_cast<mhc_wheelset_result*>(buf.data());
  old->struct_size = old_size;
  REQUIRE(mhc_wheelset_step(fx().ws, w.w, &p, old) == MHC_OK);
  CHECK(old->struct_size == old_size);
  CHECK(std::memcmp(reinterpret_cast<const char*>(old) + sizeof(size_t), reinterpret_cast<const char*>(&full) + sizeof(size_t),
                    old_size - sizeof(size_t)) == 0);
  for (std::size_t i = old_size; i < buf.size(); ++i) REQUIRE(buf[i] == 0xab);
  // A newer header's, larger struct: the library's fields, struct_size says how many bytes.
  std::vector<unsigned char> big(sizeof(mhc_wheelset_result) + 64, 0xcd);
  auto* nw = reinterpret_cast<mhc_wheelset_result*>(big.data());
  nw->struct_size = big.size();
  REQUIRE(mhc_wheelset_step(fx().ws, w.w, &p, nw) == MHC_OK);
  CHECK(nw->struct_size == sizeof(mhc_wheelset_result));
  CHECK(nw->F_N[1] == full.F_N[1]);
  for (std::size_t i = sizeof(mhc_wheelset_result); i < big.size(); ++i) REQUIRE(big[i] == 0xcd);
  // Too small for the first version: refused, naming the sizes.
  mhc_wheelset_result tiny;
  tiny.struct_size = 8;
  CHECK(mhc_wheelset_step(fx().ws, w.w, &p, &tiny) == MHC_ERR_ARGUMENT);
  CHECK(std::string(mhc_last_message()).find("out->struct_size = 8: must be at least") != std::string::npos);
  // Options of an older header (before the FASTSIM grid): accepted, the grid at its defaults.
  mhc_wheelset_options o;
  mhc_wheelset_options_init(&o);
  o.struct_size = offsetof(mhc_wheelset_options, fastsim_nx);
  mhc_wheelset* ws2 = nullptr;
  CHECK(mhc_wheelset_create(fx().pair, fx().pair, &o, &ws2) == MHC_OK);
  mhc_wheelset_free(ws2);
}

TEST_CASE("C wheelset: bad input is an argument error naming the field, the value and the rule",
          "[capi][wheelset_contact]") {
  Ws w;
  mhc_wheelset_result r;
  r.struct_size = sizeof r;
  mhc_wheelset_pose p = pose(0, -5, 1e3);
  CHECK(mhc_wheelset_step(fx().ws, w.w, &p, &r) == MHC_ERR_ARGUMENT);
  CHECK(std::string(mhc_last_message()) == "pose.Q_left = -5 N: a vertical load must be >= 0 and finite");
  p = pose(0, 1e3, 1e3);
  p.V_m_per_s = 0;
  CHECK(mhc_wheelset_step(fx().ws, w.w, &p, &r) == MHC_ERR_ARGUMENT);
  CHECK(std::string(mhc_last_message()).rfind("pose.V = 0 m/s", 0) == 0);
  p = pose(0, 1e3, 1e3);
  p.struct_size = 16;
  CHECK(mhc_wheelset_step(fx().ws, w.w, &p, &r) == MHC_ERR_ARGUMENT);
  p = pose(0, 1e3, 1e3);
  p.vertical = 7;
  CHECK(mhc_wheelset_step(fx().ws, w.w, &p, &r) == MHC_ERR_ARGUMENT);
  CHECK(std::string(mhc_last_message()).find("pose.vertical = 7") != std::string::npos);
  // The axle height given needs the multi-Hertzian method (the approach-prescribed solve).
  mhc_pair_options o;
  mhc_pair_options_init(&o);
  o.rail_inclination = 40;
  o.method = MHC_METHOD_HALF_SPACE;
  mhc_pair* hs = nullptr;
  REQUIRE(mhc_pair_create(fx().wheel, fx().rail, &o, &hs) == MHC_OK);
  mhc_wheelset* whs = nullptr;
  REQUIRE(mhc_wheelset_create(hs, hs, nullptr, &whs) == MHC_OK);
  mhc_wheelset_workspace* wsh = nullptr;
  REQUIRE(mhc_wheelset_workspace_create(whs, &wsh) == MHC_OK);
  p = pose(0, 0, 0);
  p.vertical = MHC_VERTICAL_POSITION;
  p.solve_roll = 1;
  p.Z_m = 1.0;
  CHECK(mhc_wheelset_step(whs, wsh, &p, &r) == MHC_ERR_UNSUPPORTED);
  CHECK(std::string(mhc_last_message()).find("needs the multi-hertzian method, not half-space") != std::string::npos);
  // Pairs of different methods make no wheelset.
  mhc_wheelset* mixed = nullptr;
  CHECK(mhc_wheelset_create(fx().pair, hs, nullptr, &mixed) == MHC_ERR_ARGUMENT);
  CHECK(std::string(mhc_last_message()).find("build both pairs with the same method") != std::string::npos);
  mhc_wheelset_workspace_free(wsh);
  mhc_wheelset_free(whs);
  mhc_pair_free(hs);
}

TEST_CASE("C wheelset: a batch on two threads equals single steps, the wheelset warnings as text",
          "[capi][wheelset_contact]") {
  std::vector<mhc_wheelset_pose> poses;
  for (int i = 0; i < 600; ++i) {
    mhc_wheelset_pose p = pose(-8e-3 + 16e-3 * i / 599.0, 50e3 + 10 * i, 50e3);
    p.yaw_rad = 5e-3;
    poses.push_back(p);
  }
  std::vector<mhc_wheelset_result> many(poses.size());
  many[0].struct_size = sizeof(mhc_wheelset_result);
  REQUIRE(mhc_wheelset_step_many(fx().ws, poses.size(), poses.data(), many.data(), 2) == MHC_OK);
  Ws w;
  bool lead_seen = false;
  for (std::size_t i = 0; i < poses.size(); i += 37) {
    mhc_wheelset_result one;
    one.struct_size = sizeof one;
    REQUIRE(mhc_wheelset_step(fx().ws, w.w, &poses[i], &one) == MHC_OK);
    CHECK(std::memcmp(&one, &many[i], sizeof one) == 0);
    if (one.wheelset_warnings & MHC_WHEELSET_WARN_YAW_LEAD_LEFT) {
      lead_seen = true;
      int found = 0;
      for (int k = 0; k < mhc_wheelset_n_wheelset_warnings(w.w); ++k)
        found += std::string(mhc_wheelset_warning_text(w.w, -1, k)).rfind("yaw_lead_not_modelled:wheel=left:lead_mm=", 0) == 0;
      CHECK(found == 1);
    }
  }
  CHECK(lead_seen);
}

TEST_CASE("C wheelset: each wheel's warnings as data agree with their text, and a short struct is refused",
          "[capi][wheelset_contact]") {
  // Across the flange: some wheel of some step carries warnings (checked below, not assumed).
  Ws w;
  int seen = 0;
  for (double y_mm = -10; y_mm <= 10; y_mm += 1) {
    mhc_wheelset_result r;
    r.struct_size = sizeof r;
    const mhc_wheelset_pose p = pose(y_mm * 1e-3, 110e3, 110e3);
    REQUIRE(mhc_wheelset_step(fx().ws, w.w, &p, &r) == MHC_OK);
    for (int32_t side = 0; side < 2; ++side) {
      for (int32_t k = 0; k < mhc_wheelset_n_warnings(w.w, side); ++k) {
        INFO("y " << y_mm << " mm, side " << side << ", warning " << k);
        mhc_warning wd;
        wd.struct_size = sizeof wd;
        REQUIRE(mhc_wheelset_warning(w.w, side, k, &wd) == MHC_OK);
        const std::string text = mhc_wheelset_warning_text(w.w, side, k);
        CHECK(text.rfind(std::string(wd.class_name) + ":", 0) == 0);
        ++seen;
        wd.struct_size = sizeof wd - 8;
        CHECK(mhc_wheelset_warning(w.w, side, k, &wd) == MHC_ERR_ARGUMENT);
        CHECK(std::string(mhc_last_message()).rfind("out->struct_size = ", 0) == 0);
      }
      mhc_warning out_of_range;
      out_of_range.struct_size = sizeof out_of_range;
      CHECK(mhc_wheelset_warning(w.w, side, mhc_wheelset_n_warnings(w.w, side), &out_of_range) == MHC_ERR_ARGUMENT);
    }
    mhc_warning bad_side;
    bad_side.struct_size = sizeof bad_side;
    CHECK(mhc_wheelset_warning(w.w, 2, 0, &bad_side) == MHC_ERR_ARGUMENT);
    CHECK(std::string(mhc_last_message()).rfind("side = 2", 0) == 0);
  }
  CHECK(seen > 0);
}

TEST_CASE("C wheelset: roll_in_geometry 0 keeps the wheels upright, 1 (the default) rolls them, other values refused",
          "[capi][wheelset_contact][roll]") {
  // y 3 mm, 50 kN a wheel: the roll solved (0.18 mrad); rolled, each pair's t_Y moves by the
  // rotation about the axle centre (eq. 3.8.2, about 0.46 mm per mrad); upright it is ±y exactly.
  // Break seen to fail: the field not passed on (mhc_wheelset_create ignoring it): the upright
  // t_Y checks.
  mhc_wheelset_options o;
  mhc_wheelset_options_init(&o);
  CHECK(o.roll_in_geometry == 1);
  o.mu = 0.3;
  o.roll_in_geometry = 0;
  mhc_wheelset* up = nullptr;
  REQUIRE(mhc_wheelset_create(fx().pair, fx().pair, &o, &up) == MHC_OK);
  mhc_wheelset_workspace* wu = nullptr;
  REQUIRE(mhc_wheelset_workspace_create(up, &wu) == MHC_OK);
  Ws w;
  mhc_wheelset_pose p = pose(3e-3, 50e3, 50e3);
  mhc_wheelset_result ru, rr;
  ru.struct_size = rr.struct_size = sizeof ru;
  REQUIRE(mhc_wheelset_step(up, wu, &p, &ru) == MHC_OK);
  REQUIRE(mhc_wheelset_step(fx().ws, w.w, &p, &rr) == MHC_OK);
  CHECK(ru.wheel[0].tY_m == 3e-3);
  CHECK(ru.wheel[1].tY_m == -3e-3);
  CHECK(std::fabs(rr.roll_rad) > 1e-5);
  CHECK(std::fabs(rr.wheel[0].tY_m - 3e-3) > 1e-6);
  mhc_wheelset_workspace_free(wu);
  mhc_wheelset_free(up);
  o.roll_in_geometry = 2;
  mhc_wheelset* bad = nullptr;
  CHECK(mhc_wheelset_create(fx().pair, fx().pair, &o, &bad) == MHC_ERR_ARGUMENT);
  CHECK(std::string(mhc_last_message()).rfind("options.roll_in_geometry = 2: must be 1", 0) == 0);
}
