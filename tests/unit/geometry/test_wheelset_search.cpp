// The wheelset's pruned contact search (geometry/wheelset.hpp: blocks of scan samples skipped by
// a bound on the lowest gap they can hold) against the plain scan that evaluates every sample
// (WheelsetOptions::full_scan), on measured worn wheels and rails (tests/data/profiles), both
// wheels, y = −8 … 8 mm every 0.05 mm, and at the jumps of the contact point, located by
// bisection on y with the plain scan, where two points touch. The bound only decides which
// samples are evaluated, so the results must be identical, bit for bit: contact points, radii,
// angles, two-point and off-profile flags, the second point, and the sweep's jump flags. The
// sweep's rows must also be those of at() (the sweep mirrors the right wheel for the left).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "geometry/wheelset.hpp"
#include "profile/read.hpp"
#include "profile/standard_profiles.hpp"

using mh::Profile;

namespace {

constexpr double mm = 1e-3;

Profile read(const std::string& name, mh::ProfileKind kind) {
  mh::ProfileReadOptions o;
  o.kind = kind;
  return mh::read_profile(std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/profiles/" + name, o);
}

void same_contact(const mh::WheelContact& a, const mh::WheelContact& b) {
  CHECK(a.y_w == b.y_w);
  CHECK(a.y_r == b.y_r);
  CHECK(a.z_w == b.z_w);
  CHECK(a.r == b.r);
  CHECK(a.gamma == b.gamma);
  CHECK(a.h == b.h);
  CHECK(a.two_point == b.two_point);
  CHECK(a.y_r_second == b.y_r_second);
  CHECK(a.off_profile == b.off_profile);
}

}  // namespace

TEST_CASE("wheelset contact search: the pruned scan gives the plain scan's contacts, two-point contacts and jumps, "
          "measured wheels",
          "[wheelset][search]") {
  const char* wheels[] = {"avg_wheel.whl", "worn_high_mileage.prw", "MBench_S1002_v3.prw"};
  const char* rails[] = {"avg_HR.BAN", "MBench_UIC60_v3.prr"};
  mh::WheelsetPlacement P;  // standard gauge 1435 mm at 14 mm, flange back 1360 mm
  int rows = 0, two_point = 0, jumps = 0;
  for (const char* wn : wheels)
    for (const char* rn : rails) {
      CAPTURE(wn, rn);
      const Profile w = read(wn, mh::ProfileKind::Wheel), r = read(rn, mh::ProfileKind::Rail);
      mh::WheelsetOptions o;
      o.max_displacement = 8 * mm;
      const mh::Wheelset fast(w, w, r, r, P, o);
      o.full_scan = true;
      const mh::Wheelset plain(w, w, r, r, P, o);
      std::vector<double> ys;
      for (int k = -160; k <= 160; ++k) ys.push_back(k * 0.05 * mm);
      const std::vector<mh::WheelsetState> a = fast.sweep(ys), b = plain.sweep(ys);
      for (std::size_t k = 0; k < ys.size(); ++k) {
        CAPTURE(ys[k] / mm);
        REQUIRE(b[k].found);
        CHECK(a[k].found);
        same_contact(a[k].left, b[k].left);
        same_contact(a[k].right, b[k].right);
        // The sweep (which takes the left wheel at y from the right wheel at −y on these mirrored
        // wheelsets) gives each row as at() does, but for the jump flags it adds.
        const mh::WheelsetState one = fast.at(ys[k]);
        for (int side : {-1, +1}) {
          mh::WheelContact x = side < 0 ? a[k].left : a[k].right, y1 = side < 0 ? one.left : one.right;
          CHECK((!y1.two_point || x.two_point));
          x.two_point = y1.two_point;
          same_contact(x, y1);
        }
        ++rows;
        if (k == 0) continue;
        for (int side : {-1, +1}) {
          const mh::WheelContact &c = side < 0 ? b[k].left : b[k].right, &p = side < 0 ? b[k - 1].left : b[k - 1].right;
          if (std::fabs(c.y_r - p.y_r) <= o.jump_distance) continue;
          ++jumps;
          // A jump between rows k − 1 and k: bisect on y (plain scan) to where the contact leaves
          // its old place; there the old and the new place touch together (a two-point row) when
          // the jump is a change of contact point, not a fast slide of one.
          double lo = ys[k - 1], hi = ys[k];
          for (int it = 0; it < 40; ++it) {
            const double ym = 0.5 * (lo + hi);
            const mh::WheelContact m = side < 0 ? plain.at(ym).left : plain.at(ym).right;
            (std::fabs(m.y_r - p.y_r) < std::fabs(m.y_r - c.y_r) ? lo : hi) = ym;
          }
          for (double yb : {lo, hi}) {
            CAPTURE(side, yb / mm);
            const mh::WheelsetState sa = fast.at(yb), sb = plain.at(yb);
            same_contact(sa.left, sb.left);
            same_contact(sa.right, sb.right);
            two_point += (side < 0 ? sb.left : sb.right).two_point;
            ++rows;
          }
        }
      }
    }
  WARN("pruned against plain scan: " << rows << " rows, " << jumps << " jumps, " << two_point
                                     << " two-point contacts at the jumps");
  // Both kinds of row were exercised.
  CHECK(jumps >= 10);
  CHECK(two_point >= 10);
}

// The sweep shares its rows by the library's parallel loop (core/parallel.hpp): the same states
// whatever the thread count, the mirrored shortcut and roll solved alike.
TEST_CASE("wheelset sweep: the same states on 1 and 3 threads", "[wheelset]") {
  const mh::Profile w = mh::make_standard_profile("S1002", mh::Inclination::None);
  const mh::Profile r = mh::make_standard_profile("60E1", mh::Inclination::In40);
  std::vector<double> ys;
  for (int i = -400; i <= 400; ++i) ys.push_back(i * 2e-5);
  for (mh::WheelsetRoll roll : {mh::WheelsetRoll::None, mh::WheelsetRoll::Solved}) {
    mh::WheelsetOptions o;
    o.roll = roll;
    const mh::Wheelset W(w, w, r, r, mh::WheelsetPlacement{}, o);
    const auto a = W.sweep(ys, 1), b = W.sweep(ys, 3);
    REQUIRE(a.size() == b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
      CHECK(a[k].left.y_r == b[k].left.y_r);
      CHECK(a[k].right.y_r == b[k].right.y_r);
      CHECK((a[k].roll == b[k].roll || (std::isnan(a[k].roll) && std::isnan(b[k].roll))));
      CHECK(a[k].left.two_point == b[k].left.two_point);
    }
  }
}
