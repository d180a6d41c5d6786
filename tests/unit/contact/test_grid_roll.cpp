// The grid methods (strips, half-space) with the wheel rolled against its rail (method.md §3.8,
// WheelRailGap with a roll) against CONTACT module 1 with the wheelset rolled
// (tests/data/contact/contact_mbench_roll_right_q50.csv, scripts/contact_roll_grid_refs.py: the
// Manchester pair's right wheel, S1002 on UIC60 1:40, FZ 50 kN, frictionless, 0.2 mm elements,
// D_SEP 8 mm, D_COMB 4 mm, the wheelset at Y 0, 4, 5, 6.5, 8 mm rolled by −10 … +10 mrad, no yaw).
// The wheelset's right wheel at y = −Y rolled by φ = ROLL is the pair at (t_Y, δ) of
// WheelsetContact::pair_pose (eq. 3.8.2).
// Break seen to fail: strip_options / half_space_options (solve.cpp) not passing the roll (the
// wheel upright at the rolled t_Y): see the report of branch rollgrid.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "contact/solve.hpp"
#include "support/data_csv.hpp"
#include "unit/contact/manchester_fixture.hpp"
#include "wheelset_contact/wheelset_contact.hpp"

namespace {

const mh::WheelsetContact& manchester_wheelset() {
  static const mh::WheelsetContact W = [] {
    mh::WheelsetSetup s;
    s.wheel_left = s.wheel_right = mh::testing::read_test_profile("MBench_S1002_v3.prw", mh::ProfileKind::Wheel);
    s.rail_left = s.rail_right = mh::testing::read_test_profile("MBench_UIC60_v3.prr", mh::ProfileKind::Rail);
    s.material = mh::testing::steel();
    return mh::WheelsetContact(s);
  }();
  return W;
}

// CONTACT's materials: G 82 GPa, ν 0.28 for both bodies (E = 2 G (1 + ν)).
mh::Material contact_steel() {
  mh::Material m;
  m.E = 2 * 82e9 * 1.28;
  m.nu = 0.28;
  return m;
}

struct Compared {
  double y = 0, N = 0, pmax = 0, area = 0, gamma = 0;
  int patches = 0;
};

// The answer of `method` for CONTACT's row i, and the row's reference.
mh::CaseResult solve_row(mh::Method method, double Y, double roll, double* delta) {
  const mh::WheelsetContact& W = manchester_wheelset();
  double tY = 0;
  W.pair_pose(-1, -Y * 1e-3, roll, &tY, delta);
  mh::MethodOptions opt;
  opt.method = method;
  opt.multi_hertzian.roll = *delta;
  return mh::solve_contact(W.geometry(-1), contact_steel(), tY, 50e3, opt);
}

// The patch of largest N (CONTACT reports one patch per case here).
Compared ours(const mh::CaseResult& r) {
  Compared c;
  double Nmax = -1;
  for (const mh::PatchResult& P : r.patches) {
    c.N += P.N;
    if (P.N > Nmax) Nmax = P.N, c.y = P.y_r, c.gamma = P.gamma;
  }
  c.pmax = r.pmax;
  c.area = r.area;
  c.patches = static_cast<int>(r.patches.size());
  return c;
}

}  // namespace

TEST_CASE("strips and half-space with a roll against CONTACT (Manchester right wheel, 50 kN)",
          "[grid_roll][contact][half_space][strips]") {
  const mh::CsvTable t = mh::test::read_data_csv("contact/contact_mbench_roll_right_q50.csv");
  REQUIRE(t.rows.size() == 25);
  for (mh::Method method : {mh::Method::HalfSpace, mh::Method::Strips}) {
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      const double Y = mh::test::csv_num(t, i, "Y_mm"), roll = mh::test::csv_num(t, i, "roll_rad");
      double delta = 0;
      const mh::CaseResult r = solve_row(method, Y, roll, &delta);
      const Compared c = ours(r);
      const double y_ref = mh::test::csv_num(t, i, "ycp_r_mm") * 1e-3, N_ref = mh::test::csv_num(t, i, "FN_N");
      const double p_ref = mh::test::csv_num(t, i, "pmax_MPa") * 1e6, a_ref = mh::test::csv_num(t, i, "area_mm2") * 1e-6;
      const double g_ref = -mh::test::csv_num(t, i, "deltcp_rad");
      // Measured 29 Nov 2026 (worst of the 25 rows; half-space / strips): pmax 1.5 / 1.2 %, area
      // 3.1 / 4.5 %, contact point 0.024 / 0.024 mm, contact angle 0.0010 / 0.0010 rad, N 0.053 %
      // (CONTACT prints 4 digits). Held at about 1.5 times that.
      const bool hs = method == mh::Method::HalfSpace;
      CHECK(r.status == mh::CaseStatus::Ok);
      CHECK(c.patches == 1);
      CHECK(std::fabs(c.pmax / p_ref - 1) < (hs ? 0.023 : 0.018));
      CHECK(std::fabs(c.area / a_ref - 1) < (hs ? 0.047 : 0.068));
      CHECK(std::fabs(c.y - y_ref) < 0.036e-3);
      CHECK(std::fabs(c.gamma - g_ref) < 0.0015);
      CHECK(std::fabs(c.N / N_ref - 1) < 0.0008);
      std::printf("%s Y %4.1f roll %+6.1f mrad: %s %d patches, y %8.3f / %8.3f mm, gamma %7.4f / %7.4f, N %7.0f / %7.0f,"
                  " pmax %6.0f / %6.0f MPa (%+5.1f %%), area %6.2f / %6.2f mm2 (%+5.1f %%)\n",
                  mh::to_string(method), Y, roll * 1e3, mh::to_string(r.status), c.patches, c.y * 1e3,
                  y_ref * 1e3, c.gamma, g_ref, c.N, N_ref, c.pmax * 1e-6, p_ref * 1e-6, 100 * (c.pmax / p_ref - 1),
                  c.area * 1e6, a_ref * 1e6, 100 * (c.area / a_ref - 1));
    }
  }
}

TEST_CASE("half-space rolled against the upright half-space on the wheel profile rotated by hand",
          "[grid_roll][half_space]") {
  // The wheel profile's points rotated by δ about its origin one by one, (y, z) → (y cos δ − z sin δ,
  // y sin δ + z cos δ), and the pair built again from them (the placement depends on the rail's
  // gauge point only), then solved upright at the same t_Y: the rolled solve's gap is the
  // same rotation of the smoothed curve (rolled_gap.hpp). What differs: the smoothing of the rotated
  // points, and the rolling radius (about the rolled axle against the horizontal one: δ y_w).
  const mh::Profile wheel = mh::testing::read_test_profile("MBench_S1002_v3.prw", mh::ProfileKind::Wheel);
  const mh::Profile rail = mh::testing::read_test_profile("MBench_UIC60_v3.prr", mh::ProfileKind::Rail);
  const mh::ContactGeometry& G = mh::testing::manchester_geometry();
  const mh::Material mat = mh::testing::steel();
  for (double delta : {-10e-3, 10e-3}) {
    mh::Profile turned = wheel;
    const double c = std::cos(delta), s = std::sin(delta);
    for (std::size_t k = 0; k < wheel.y.size(); ++k) {
      turned.y[k] = wheel.y[k] * c - wheel.z[k] * s;
      turned.z[k] = wheel.y[k] * s + wheel.z[k] * c;
    }
    const mh::ContactGeometry T = mh::build_geometry(turned, rail, mh::TrackSetup{}, mh::GeometryOptions{});
    REQUIRE(T.y_offset == G.y_offset);
    for (double tY : {-2e-3, 3e-3, 6e-3}) {
      mh::MethodOptions opt;
      opt.method = mh::Method::HalfSpace;
      opt.multi_hertzian.roll = delta;
      const mh::CaseResult rolled = mh::solve_contact(G, mat, tY, 50e3, opt);
      opt.multi_hertzian.roll = 0;
      const mh::CaseResult by_hand = mh::solve_contact(T, mat, tY, 50e3, opt);
      const Compared a = ours(rolled), b = ours(by_hand);
      // Measured 29 Nov 2026 (δ ±10 mrad, t_Y −2, 3, 6 mm): pmax within 0.04 %, area equal to the
      // element, contact point within 0.6 µm, N within 1 N. Held at about 1.5 times that.
      // Break seen to fail: the roll not passed (the same break as the test above).
      CHECK(rolled.status == mh::CaseStatus::Ok);
      CHECK(a.patches == b.patches);
      CHECK(std::fabs(a.pmax / b.pmax - 1) < 6e-4);
      CHECK(std::fabs(a.area / b.area - 1) < 1e-4);
      CHECK(std::fabs(a.y - b.y) < 0.9e-6);
      CHECK(std::fabs(a.N - b.N) < 1.5);
      std::printf("by hand: delta %+5.1f mrad tY %4.1f mm: %d / %d patches, y %8.4f / %8.4f mm, N %7.0f / %7.0f, pmax %7.1f / %7.1f MPa (%+6.2f %%), area %6.2f / %6.2f mm2 (%+6.2f %%)\n",
                  delta * 1e3, tY * 1e3, a.patches, b.patches, a.y * 1e3, b.y * 1e3, a.N, b.N, a.pmax * 1e-6,
                  b.pmax * 1e-6, 100 * (a.pmax / b.pmax - 1), a.area * 1e6, b.area * 1e6, 100 * (a.area / b.area - 1));
    }
  }
}
