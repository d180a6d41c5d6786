// The rolled wheel–rail gap of the grid methods (WheelRailGap with a roll δ, geometry/rolled_gap.hpp,
// method.md §3.8) against an independent computation: the wheel's profile points rotated by δ about
// the profile's origin one by one (every 1 µm of the gap's wheel curve), the rolled wheel's height
// at a rail y by direct search of the rotated points around it (linear between them: an error of
// κ h²/8 < 0.1 nm), the vertical distance to the rail there, and its minimum over the gap's range
// by a 1 µm scan. On S1002 / 60E1 1:40 (exact profiles) and on the worn measured pair avg_wheel.whl
// on avg_HR.BAN 1:40 (tests/data/profiles, its wheel smoothed for contact), at t_Y −5 … 8 mm and
// δ = ±10, ±25 mrad. And the first contact against candidates_at(t, δ)'s main candidate (on the
// unsmoothed pair only: the candidates use the unsmoothed curves).
//
// Tolerances: the rolled gap's heights within 0.05 µm of the reference over the gap's range (the
// rolled curve is resampled on 10 µm nodes: cubic Hermite between exact nodes); its minimum
// (wheel_lift) within 0.01 µm of the reference's. Measured 29 Nov 2026: heights within 0.0061 µm
// (S1002/60E1) and 0.00003 µm (worn), minima within 0.0033 µm. The candidates: their main point
// within 0.25 mm of the gap's first contact (measured 0.081 mm); every candidate's separation at its
// own rail point within 0.0005 µm of the exact rotation (rolled_wheel_at's facing point is exact:
// Newton on the facing condition; measured 0.0002 µm, the reference's interpolation 0.1 nm), the
// main one's within 0.1 µm of the reference's minimum (measured 0.063 µm, t_Y 6 mm, 10 mrad: the
// refinement's scan of 6 sub-intervals around the strip the first-order scan picks). A first-order
// facing point misses O(δ² y_w z_w') (cos δ ≠ 1): 52 µm at t_Y 8 mm and −25 mrad on the flange,
// 12 µm at −10 mrad, 0.35 µm on the tread at 25 mrad.
// Break seen to fail: the rotation's sign flipped in rolled_wheel_curve (sin δ → −sin δ).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <thread>
#include <vector>

#include "geometry/contact_geometry.hpp"
#include "geometry/gap.hpp"
#include "geometry/rolled_gap.hpp"
#include "profile/standard_profiles.hpp"
#include "unit/contact/manchester_fixture.hpp"

namespace {

constexpr double mm = 1e-3, um = 1e-6;

// The wheel curve's points every 1 µm rotated by δ about the origin: (Y, Z) in the wheel frame.
struct RotatedPoints {
  std::vector<double> Y, Z;
  RotatedPoints(const mh::ProfileCurve& W, double roll) {
    const double c = std::cos(roll), s = std::sin(roll);
    for (double y = W.y_min(); y <= W.y_max(); y += 1 * um) {
      const double z = W.z(y);
      Y.push_back(y * c - z * s);
      Z.push_back(y * s + z * c);
    }
  }
  // The rotated wheel's height at wheel-frame y (direct search for the rotated points around it;
  // NaN where none: outside, or where the rotated points are not increasing).
  double at(double y) const {
    for (std::size_t i = 0; i + 1 < Y.size(); ++i)
      if (Y[i] <= y && y <= Y[i + 1] && Y[i + 1] > Y[i]) return Z[i] + (Z[i + 1] - Z[i]) * (y - Y[i]) / (Y[i + 1] - Y[i]);
    return std::numeric_limits<double>::quiet_NaN();
  }
};

struct Worst { double height = 0, lift = 0, y_first = 0, sep_first = 0, sep_point = 0; };

// The candidates against the reference (see the header): separation, contact point.
constexpr double kPointTol = 0.0005 * um, kMinTol = 0.1 * um, kYTol = 0.25 * mm;

void check_pair(const mh::ContactGeometry& G, const char* name, bool compare_candidates) {
  Worst w;
  for (double t : {-5 * mm, 0.0, 3 * mm, 6 * mm, 8 * mm}) {
    const mh::WheelRailGap up(G, t);
    const mh::ProfileCurve& R = up.rail_curve();
    const double s = G.y_offset + t;
    for (double roll : {-25e-3, -10e-3, 10e-3, 25e-3}) {
      INFO(name << ": t_Y " << t / mm << " mm, roll " << roll * 1e3 << " mrad");
      const mh::WheelRailGap gap(G, t, std::nan(""), roll);
      REQUIRE(gap.roll() == roll);
      const RotatedPoints P(up.wheel_curve(), roll);
      // The reference's minimum over the gap's range, scanning rail y by 1 µm (the rotated points
      // walked along, each rail y's pair found by a direct search from the last one).
      double gref = std::numeric_limits<double>::infinity();
      std::size_t i = 0;
      for (double y = gap.y_min(); y <= gap.y_max(); y += 1 * um) {
        const double yw = y - s;
        while (i + 2 < P.Y.size() && P.Y[i + 1] < yw) ++i;
        if (!(P.Y[i] <= yw && yw <= P.Y[i + 1])) continue;
        const double zw = P.Z[i] + (P.Z[i + 1] - P.Z[i]) * (yw - P.Y[i]) / (P.Y[i + 1] - P.Y[i]);
        gref = std::min(gref, zw - R.z(y));
      }
      REQUIRE(std::isfinite(gref));
      w.lift = std::max(w.lift, std::fabs(gap.wheel_lift() - gref));
      CHECK(std::fabs(gap.wheel_lift() - gref) < 0.01 * um);
      // Heights every 0.25 mm over the gap's range, at least 1 mm inside its ends.
      for (double y = gap.y_min() + 1 * mm; y <= gap.y_max() - 1 * mm; y += 0.25 * mm) {
        const double zref = P.at(y - s);
        if (std::isnan(zref)) continue;
        const double d = std::fabs(gap.g(y) + gap.wheel_lift() - (zref - R.z(y)));
        w.height = std::max(w.height, d);
        CHECK(d < 0.05 * um);
      }
      if (compare_candidates) {
        std::vector<mh::CandidateGeom> c(G.n_ellipses());
        int m = 0;
        REQUIRE(G.candidates_at(t, roll, c.data(), &m));
        // Every candidate's separation at its own rail point against the rotated points' (the
        // exact rotation), and the main one's against the reference's minimum.
        for (std::size_t e = 0; e < c.size(); ++e) {
          const double zref = P.at(c[e].y_r - s);
          if (std::isnan(zref)) continue;
          const double dg = std::fabs(c[e].sep - (zref - R.z(c[e].y_r)));
          w.sep_point = std::max(w.sep_point, dg);
          CHECK(dg < kPointTol);
        }
        const double dy = std::fabs(gap.y_first_contact() - c[m].y_r), dm = std::fabs(c[m].sep - gref);
        w.y_first = std::max(w.y_first, dy);
        w.sep_first = std::max(w.sep_first, dm);
        CHECK(dy < kYTol);    // the same contact point
        CHECK(dm < kMinTol);  // the same first contact
      }
    }
  }
  WARN(name << ": largest differences: heights " << w.height / um << " µm, lift " << w.lift / um
            << " µm, first contact y " << w.y_first / um << " µm, the main candidate's separation against the reference's minimum "
            << w.sep_first / um << " µm, every candidate's against the reference at its point " << w.sep_point / um << " µm");
}

}  // namespace

TEST_CASE("rolled gap: the rotated wheel's heights and first contact, S1002/60E1 and a worn measured pair",
          "[geometry][roll][rolled_gap]") {
  mh::GeometryOptions o;
  const mh::ContactGeometry std_pair = mh::build_geometry(
      mh::make_standard_profile("S1002"), mh::make_standard_profile("60E1", mh::Inclination::In40), mh::TrackSetup{}, o);
  check_pair(std_pair, "S1002/60E1 1:40", !mh::smoothed_for_contact(std_pair));
  mh::Profile rail = mh::testing::read_test_profile("avg_HR.BAN", mh::ProfileKind::Rail);
  mh::rotate_towards_track_centre(rail, std::atan(1.0 / 40));
  const mh::ContactGeometry worn = mh::build_geometry(
      mh::testing::read_test_profile("avg_wheel.whl", mh::ProfileKind::Wheel), rail, mh::TrackSetup{}, o);
  check_pair(worn, "avg_wheel on avg_HR 1:40", !mh::smoothed_for_contact(worn));
}

TEST_CASE("rolled gap: δ = 0 is the upright gap, bit for bit", "[geometry][roll][rolled_gap]") {
  const mh::ContactGeometry& G = mh::testing::manchester_geometry();
  for (double t : {-4 * mm, 2 * mm, 7.5 * mm}) {
    const mh::WheelRailGap a(G, t), b(G, t, std::nan(""), 0.0);
    CHECK(a.wheel_lift() == b.wheel_lift());
    CHECK(a.y_first_contact() == b.y_first_contact());
    CHECK(&a.wheel_curve() == &b.wheel_curve());
    for (double y = a.y_min(); y <= a.y_max(); y += 0.5 * mm) {
      CHECK(a.g(y) == b.g(y));
      CHECK(a.z_wheel(y, 3 * mm) == b.z_wheel(y, 3 * mm));
      CHECK(a.rolling_radius(y) == b.rolling_radius(y));
    }
  }
}

// The rolled wheel curves are kept per thread (gap.cpp, rolled_curve): a gap at a roll met before
// takes the kept curve, a new roll is built in place of a curve no gap holds any more. Either must
// be the curve a new build gives, bit for bit: each gap here (made after gaps at other rolls, some
// still alive, more rolls than the thread keeps) against the rolled_wheel_curve of that roll made
// afresh, node by node, and its first contact against a gap made on a new thread (whose kept
// curves are all new builds). Seen to fail with the kept curves looked up without their roll.
TEST_CASE("rolled gap: curves kept and rebuilt in place are those built afresh, bit for bit",
          "[geometry][roll][rolled_gap]") {
  const mh::ContactGeometry& G = mh::testing::manchester_geometry();
  const mh::ProfileCurve& W = G.wheel_gap_curve ? *G.wheel_gap_curve : *G.wheel_curve;
  std::vector<mh::WheelRailGap> held;  // some gaps kept alive: their curves may not be rebuilt
  held.reserve(4);
  const double rolls[] = {3e-3, -7e-3, 11e-3, 3e-3, -2e-3, 5e-3, 13e-3, -9e-3, 1e-3, 6e-3, 3e-3, -7e-3, 8e-3, -4e-3};
  for (std::size_t k = 0; k < std::size(rolls); ++k) {
    const double roll = rolls[k], t = (k % 2 ? 1.5 : 6.5) * mm;
    const mh::WheelRailGap gap(G, t, std::nan(""), roll);
    if (k % 4 == 1 && held.size() < held.capacity()) held.emplace_back(G, t, std::nan(""), roll);
    const mh::ProfileCurve fresh = mh::rolled_wheel_curve(W, roll);
    const mh::ProfileCurve& kept = gap.wheel_curve();
    INFO("roll " << roll * 1e3 << " mrad, gap " << k);
    REQUIRE(kept.nodes() == fresh.nodes());
    bool same = kept.y_min() == fresh.y_min() && kept.y_max() == fresh.y_max();
    for (std::size_t i = 0; i < fresh.nodes() && same; ++i) {
      double d1 = 0, d2 = 0;
      const double y = fresh.node_y(i);
      same = kept.node_y(i) == y && kept.z(y, &d1) == fresh.z(y, &d2) && d1 == d2 && kept.kappa(y) == fresh.kappa(y);
    }
    CHECK(same);
    double lift = 0, y_first = 0;
    std::thread([&] {
      const mh::WheelRailGap other(G, t, std::nan(""), roll);
      lift = other.wheel_lift();
      y_first = other.y_first_contact();
    }).join();
    CHECK(gap.wheel_lift() == lift);
    CHECK(gap.y_first_contact() == y_first);
  }
}

// The gap near a solved case's candidate (WheelRailGap(G, t, y_near), the judge's gap): the
// samples within ±0.2 mm of y_near, against the whole-profile search (every sample of the gap's
// range). From the main candidate's y_r (what the judge gives), wherever the whole search's
// minimum lies within the ±0.2 mm: the same first contact and lift, bit for bit. A walk downhill
// from y_near's sample would not do: the joints of a profile's pieces step the gap by a few nm
// and leave local minima up to 6 samples from the deepest (the Manchester pair at t_Y 5.58 mm:
// 45 nm above it, 0.064 mm away; a judge's gap_kink 0.103 for 0.102 in one row of the
// 1,000,000-case sweep). Near every candidate: a lift no smaller than the whole search's (1 nm:
// the refinements between samples differ) and a point within the ±0.2 mm. On the Manchester
// pair, S1002/60E1 1:40 and the worn measured pair (smoothed for contact), t_Y −6 … 10 mm every
// 0.05 mm.
// Break seen to fail: the window searched by a walk downhill from y_near's sample (61 rows).
TEST_CASE("gap near a candidate: the whole search's first contact, bit for bit", "[geometry][gap]") {
  mh::GeometryOptions o;
  mh::Profile rail = mh::testing::read_test_profile("avg_HR.BAN", mh::ProfileKind::Rail);
  mh::rotate_towards_track_centre(rail, std::atan(1.0 / 40));
  const mh::ContactGeometry worn = mh::build_geometry(
      mh::testing::read_test_profile("avg_wheel.whl", mh::ProfileKind::Wheel), rail, mh::TrackSetup{}, o);
  const mh::ContactGeometry std_pair = mh::build_geometry(
      mh::make_standard_profile("S1002"), mh::make_standard_profile("60E1", mh::Inclination::In40), mh::TrackSetup{}, o);
  const mh::ContactGeometry& manchester = mh::testing::manchester_geometry();
  int mains = 0;
  for (const mh::ContactGeometry* G : {&manchester, &std_pair, &worn}) {
    const char* name = G == &worn ? "worn" : G == &manchester ? "Manchester" : "S1002/60E1";
    std::vector<mh::CandidateGeom> cand(G->n_ellipses());
    for (double t = -6 * mm; t <= 10 * mm; t += 0.05 * mm) {
      if (!G->covers(t)) continue;
      const mh::WheelRailGap full(*G, t);
      int main = 0;
      G->candidates_at(t, cand.data(), &main);
      for (int i = 0; i < static_cast<int>(G->n_ellipses()); ++i) {
        const mh::CandidateGeom& c = cand[static_cast<std::size_t>(i)];
        if (!std::isfinite(c.y_r)) continue;
        INFO(name << ": t_Y " << t / mm << " mm, candidate " << i << " at y_r " << c.y_r / mm << " mm");
        const mh::WheelRailGap near(*G, t, c.y_r);
        CHECK(near.wheel_lift() >= full.wheel_lift() - 1e-9);
        CHECK(std::fabs(near.y_first_contact() - c.y_r) <= 0.22 * mm);
        if (i != main || std::fabs(c.y_r - full.y_first_contact()) > 0.19 * mm) continue;
        CHECK(near.wheel_lift() == full.wheel_lift());
        CHECK(near.y_first_contact() == full.y_first_contact());
        ++mains;
      }
    }
  }
  CHECK(mains > 500);
}
