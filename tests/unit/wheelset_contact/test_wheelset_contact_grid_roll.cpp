// The wheelset call with a grid method: the roll reaches the strips' and the half-space's gap
// (WheelsetSetup::roll_in_geometry, method.md §3.8). Each wheel's answer is the single-pair solve
// at its pair pose (t_Y, δ) with that roll, and against CONTACT module 1 with the wheelset rolled
// (tests/data/contact/contact_mbench_roll_right_q50.csv, scripts/contact_roll_grid_refs.py) it
// holds what tests/unit/contact/test_grid_roll.cpp holds for the single pair.
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/solve.hpp"
#include "support/data_csv.hpp"
#include "unit/contact/manchester_fixture.hpp"
#include "wheelset_contact/wheelset_contact.hpp"

namespace {

mh::WheelsetSetup grid_setup(mh::Method method, bool roll_in_geometry) {
  mh::WheelsetSetup s;
  s.wheel_left = s.wheel_right = mh::testing::read_test_profile("MBench_S1002_v3.prw", mh::ProfileKind::Wheel);
  s.rail_left = s.rail_right = mh::testing::read_test_profile("MBench_UIC60_v3.prr", mh::ProfileKind::Rail);
  s.material.E = 2 * 82e9 * 1.28;  // CONTACT's G 82 GPa, ν 0.28
  s.material.nu = 0.28;
  s.method.method = method;
  s.roll_in_geometry = roll_in_geometry;
  return s;
}

double total_N(const mh::WheelResult& w) {
  double N = 0;
  for (const mh::ContactPoint& c : w.contacts) N += c.N;
  return N;
}

}  // namespace

TEST_CASE("wheelset call: strips and half-space take the roll (right wheel against CONTACT, 50 kN)",
          "[wheelset_contact][roll][grid_roll][contact]") {
  const mh::CsvTable t = mh::test::read_data_csv("contact/contact_mbench_roll_right_q50.csv");
  for (mh::Method method : {mh::Method::Strips, mh::Method::HalfSpace}) {
    const mh::WheelsetContact W(grid_setup(method, true));
    const mh::WheelsetContact upright(grid_setup(method, false));
    // Y 6.5 mm rolled by −5 mrad (the flange), Y 0 by +5 mrad (the tread): CONTACT's rows 17, 4.
    for (std::size_t i : {std::size_t{16}, std::size_t{3}}) {
      const double Y = mh::test::csv_num(t, i, "Y_mm"), roll = mh::test::csv_num(t, i, "roll_rad");
      mh::WheelsetPose p;
      p.y = -Y * 1e-3;
      p.Q_left = p.Q_right = 50e3;
      p.solve_roll = false;
      p.roll = roll;
      mh::WheelsetWorkspace ws;
      mh::WheelsetResult r, u;
      W.step(p, {}, r, ws);
      upright.step(p, {}, u, ws);
      REQUIRE(!mh::is_failure(r.right.r.status));
      // The single pair at the wheel's pose and roll: the same answer.
      double tY = 0, delta = 0;
      W.pair_pose(-1, p.y, roll, &tY, &delta);
      CHECK(r.right.tY == tY);
      CHECK(r.right.delta == delta);
      mh::MethodOptions opt = W.setup().method;
      opt.multi_hertzian.roll = delta;
      const mh::CaseResult single = mh::solve_contact(W.geometry(-1), W.setup().material, tY, 50e3, opt);
      REQUIRE(single.patches.size() == r.right.r.patches.size());
      CHECK(r.right.r.pmax == Approx(single.pmax).epsilon(1e-9));
      CHECK(r.right.r.area == Approx(single.area).epsilon(1e-9));
      const double FN = mh::test::csv_num(t, i, "FN_N"), pmax = mh::test::csv_num(t, i, "pmax_MPa") * 1e6;
      const double gamma = -mh::test::csv_num(t, i, "deltcp_rad");
      double g = 0, Nmax = -1;
      for (const mh::ContactPoint& c : r.right.contacts)
        if (c.N > Nmax) Nmax = c.N, g = c.gamma;
      INFO(mh::to_string(method) << " Y " << Y << " mm, roll " << roll * 1e3 << " mrad: N " << total_N(r.right) << " vs "
                                 << FN << ", pmax " << r.right.r.pmax * 1e-6 << " vs " << pmax * 1e-6 << " MPa, gamma "
                                 << g << " vs " << gamma << "; upright: N " << total_N(u.right) << ", pmax "
                                 << u.right.r.pmax * 1e-6);
      CHECK(std::fabs(total_N(r.right) - FN) < 0.02 * FN);
      CHECK(std::fabs(r.right.r.pmax / pmax - 1) < 0.05);
      CHECK(std::fabs(g - gamma) < 0.02);
      // The roll's warnings are those of the upright wheels only.
      CHECK(r.warnings.empty());
      CHECK(!u.warnings.empty());
    }
  }
}
