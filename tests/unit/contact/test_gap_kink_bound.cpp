// The bound that lets the gap-corner test (hertz_validity.hpp, gap_kink) pass a patch without
// sampling its gap (geometry/gap.hpp, gap_kink_bound), and the verdicts and figures of gap_kink
// with the bound against the samples alone, on the Manchester pair (smooth) and on the
// unsmoothed worn measured flange (a corner of the gap).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "contact/ellipse/hertz_validity.hpp"
#include "contact/multi_hertz/multi_hertz.hpp"
#include "geometry/gap.hpp"
#include "input/case_file.hpp"
#include "jobs/run.hpp"
#include "manchester_fixture.hpp"
#include "support/measured_pair.hpp"

TEST_CASE("gap_kink_bound: never below the samples' slope jump, on every Manchester patch", "[gap_kink]") {
  // The bound against the samples themselves (gap_kink without the bound), whether or not it is
  // small enough to pass the test. Break guarded (seen failing): without the deviation term
  // 4 (η + ε)/h the bound falls below the samples at 180 patches (the nodes' slopes differ from
  // their chords by ~1e-3, a sub-grid wiggle the samples see); the bound halved, at 119; the
  // kinks of the bin after each centre left out of its sum (the binned sums, 28 Nov 2026), here
  // and in the three tests below.
  const mh::ContactGeometry& G = mh::testing::manchester_geometry();
  const mh::Material mat = mh::testing::steel();
  int found = 0, total = 0;
  for (double tY = -6e-3; tY <= 10e-3 + 1e-9; tY += 0.25e-3)
    for (double Q : {10e3, 50e3, 100e3, 150e3}) {
      const mh::CaseResult r = mh::solve_multi_hertz(G, mat, tY, Q);
      const mh::WheelRailGap gap(G, tY);
      for (const mh::LoadedEllipse& L : r.loaded) {
        const double b = L.s.b, h = b / 40;
        const mh::GapKink full = mh::gap_kink(gap, L.g, L.B, b, L.s.p0, 0.5 * mat.E_star(), r.approach, {}, false);
        // The polylines spaced at most h/2 and at most h (gap_kink tries the latter first).
        for (const double spacing : {0.5 * h, h}) {
          const mh::KinkBound kb = mh::gap_kink_bound(gap, mh::plane_at(gap, L.g.y_r), -b, h, 161, L.B, r.approach, spacing);
          ++total;
          if (!kb.found) continue;
          ++found;
          CAPTURE(tY, Q, L.ellipse, b, spacing, kb.dtheta, full.dtheta);
          CHECK(kb.dtheta >= full.dtheta);
        }
      }
    }
  CHECK(found == total);  // no gauge face, no steep turn of the normals on this pair
}

namespace {
struct Tally {
  int ellipses = 0, bounded = 0, failed = 0;
  double worst_excess = 0;  // largest sampled − bounded kink ratio where bounded (must be ≤ 0)
};
void compare(const mh::ContactGeometry& G, const mh::Material& mat, double tY, double Q, Tally& t) {
  const mh::CaseResult r = mh::solve_multi_hertz(G, mat, tY, Q);
  const mh::WheelRailGap gap(G, tY);
  for (const mh::LoadedEllipse& L : r.loaded) {
    const mh::GapKink fast = mh::gap_kink(gap, L.g, L.B, L.s.b, L.s.p0, 0.5 * mat.E_star(), r.approach);
    const mh::GapKink full = mh::gap_kink(gap, L.g, L.B, L.s.b, L.s.p0, 0.5 * mat.E_star(), r.approach, {}, false);
    CAPTURE(tY, Q, L.ellipse, fast.kink_ratio, full.kink_ratio, fast.bounded);
    ++t.ellipses;
    CHECK(fast.valid == full.valid);
    CHECK_FALSE(full.bounded);
    if (fast.bounded) {
      ++t.bounded;
      CHECK(fast.kink_ratio >= full.kink_ratio);
      t.worst_excess = std::max(t.worst_excess, full.kink_ratio - fast.kink_ratio);
    } else {
      // The samples decide, with their figure: those of the centres the bound does not pass, in
      // runs whose first Newton solves start cold (the figure's last bits may differ).
      CHECK(fast.kink_ratio == Approx(full.kink_ratio).epsilon(1e-9));
    }
    if (!full.valid) ++t.failed;
  }
}
}  // namespace

TEST_CASE("gap_kink: the bound passes most Manchester patches, never one the samples fail, and never understates", "[gap_kink]") {
  const mh::ContactGeometry& G = mh::testing::manchester_geometry();
  Tally t;
  for (double tY = -6e-3; tY <= 10e-3 + 1e-9; tY += 0.25e-3)
    for (double Q : {10e3, 50e3, 100e3, 150e3}) compare(G, mh::testing::steel(), tY, Q, t);
  INFO(t.ellipses << " ellipses, " << t.bounded << " passed by the bound, " << t.failed << " failed");
  // The rows the samples fail (t_Y 5–5.5 mm at 10 kN, docs/methods.md) fail with the bound too.
  CHECK(t.failed >= 1);
  CHECK(t.worst_excess <= 0);
  // Measured 28 Nov 2026: 271 of 297 (91 %), 252 of them on the polylines spaced at most h (the
  // first try, half the kinks to sum; 163 at 2h, 56 at 4h); the rest are the flange-root patches at t_Y
  // 4.75–7.25 mm (sampled ratios 0.04–0.33, the bound 2–4 times the samples there), two tread
  // patches at 150 kN, and the 6 the samples fail. The figure the speed of the judge rests on
  // (with the kinks' 1/(D0 D1) taken as 1 it passes 245: this check fails).
  // Break guarded (seen failing): the bound's Δθ halved passes patches the samples put above it
  // (the bounded ratio below the sampled one, and a verdict changed).
  CHECK(t.bounded >= 0.9 * t.ellipses);
}

TEST_CASE("gap_kink: a corner of the gap is never passed by the bound", "[gap_kink]") {
  // The unsmoothed worn measured flange at t_Y = 13.5 mm (test_auto_rule.cpp: kink ratio 5.4).
  const mh::CaseFile cf = mh::testing::measured_pair_case("avg_wheel.whl", "avg_HR.BAN", 13.5, 50, {{"smoothing_mm", 0}});
  const mh::PairGeometry pg = mh::build_pair_geometry(cf);
  Tally t;
  compare(pg.geo, cf.material, 13.5e-3, 50e3, t);
  CHECK(t.failed >= 1);
  CHECK(t.bounded < t.ellipses);
}


TEST_CASE("gap_curvature_bound: never below the samples' slope jump, and passes the tread patches", "[gap_kink]") {
  // The coarse bound (the range of the gap's plane-frame curvature over the span) against the
  // samples themselves, on every Manchester patch (smooth: tread and flange) and the worn measured
  // pair smoothed by default (tread, flange root, flange), and S1002/60E1 1:20 from their definitions.
  const mh::Material mat = mh::testing::steel();
  int found = 0, passed = 0, total = 0;
  double worst = 0;  // the largest sampled Δθ over the bound where found (must stay ≤ 1)
  auto check = [&](const mh::ContactGeometry& G, double tY, double Q) {
    const mh::CaseResult r = mh::solve_multi_hertz(G, mat, tY, Q);
    const mh::WheelRailGap gap(G, tY);
    for (const mh::LoadedEllipse& L : r.loaded) {
      const double b = L.s.b, h = b / 40;
      const mh::GapKink full = mh::gap_kink(gap, L.g, L.B, b, L.s.p0, 0.5 * mat.E_star(), r.approach, {}, false);
      const mh::KinkBound qb = mh::gap_curvature_bound(gap, mh::plane_at(gap, L.g.y_r), -b, h, 161, L.B, r.approach);
      ++total;
      if (!qb.found) continue;
      ++found;
      CAPTURE(tY, Q, L.ellipse, b, qb.dtheta, full.dtheta);
      CHECK(qb.dtheta >= full.dtheta);
      worst = std::max(worst, full.dtheta / qb.dtheta);
      if (0.5 * mat.E_star() * qb.dtheta / (2 * M_PI * L.s.p0) <= 0.1) ++passed;
    }
  };
  const mh::ContactGeometry& G = mh::testing::manchester_geometry();
  for (double tY = -6e-3; tY <= 10e-3 + 1e-9; tY += 0.25e-3)
    for (double Q : {10e3, 50e3, 100e3, 150e3}) check(G, tY, Q);
  const int manchester_total = total, manchester_passed = passed;
  const mh::CaseFile cf = mh::testing::measured_pair_case("avg_wheel.whl", "avg_HR.BAN", 0, 50, {});
  const mh::PairGeometry pg = mh::build_pair_geometry(cf);
  for (double tY = -4e-3; tY <= 12e-3 + 1e-9; tY += 0.5e-3)
    for (double Q : {20e3, 80e3, 140e3}) check(pg.geo, tY, Q);
  // The standard pair generated from its definitions (circular arcs and polynomials, no noise).
  const mh::CaseFile sf = mh::load_case_file(std::string(MHCONTACT_SOURCE_DIR) + "/cases/s1002-60e1-table.json", true);
  const mh::PairGeometry sg = mh::build_pair_geometry(sf);
  for (double tY = -4e-3; tY <= 10e-3 + 1e-9; tY += 0.5e-3)
    for (double Q : {20e3, 80e3, 140e3}) check(sg.geo, tY, Q);
  INFO(total << " patches (" << manchester_total << " Manchester), bound found on " << found << ", passing " << passed
             << " (" << manchester_passed << " Manchester); largest samples / bound " << worst);
  // Measured 1 Dec 2026: found on all 495, passing 415 (236 of the 297 Manchester patches: the
  // tread ones; not the flange roots, where the curvature changes across the patch), the largest
  // samples / bound 0.78 (on S1002/60E1).
  // Break guarded (seen failing): the kinks' range taken over half the span (samples / bound 3.1),
  // the range's half width halved (1.04); the kinks per length not divided by D³ (passing fewer).
  // Not seen here: the trapezoid error term or the deviation η left out (0.85, 0.86): on these
  // pairs the range's own width covers them; they are there for the inequality.
  CHECK(worst <= 1);
  CHECK(found == total);
  CHECK(manchester_passed >= 225);
}

TEST_CASE("gap_curvature_bound and gap_kink on the trust corpus: never below the samples, the same verdicts", "[gap_kink]") {
  // The 7 pairs of tests/data/contact/field/trust.json (measured MiniProf and other field files,
  // generated standards), each as configured, unsmoothed and smoothed at 1 mm, t_Y −6 … 12 mm every
  // 0.25 mm at 10, 60 and 150 kN: inputs the bound was not developed on. Measured 1 Dec 2026:
  // 4,875 patches, the curvature bound found on 4,788 and passing 2,666, the largest samples /
  // bound 0.80; gap_kink's verdict with the bounds that of the samples alone on every patch.
  // Break guarded (seen failing): the range's half width halved (299 checks); gap_kink passing a
  // patch on half the curvature bound (17 verdicts changed).
  const mh::Material mat = mh::testing::steel();
  const std::string dir = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/contact/field/";
  std::ifstream in(dir + "trust.json");
  nlohmann::json trust;
  in >> trust;
  int found = 0, total = 0;
  double worst = 0;
  for (const auto& p : trust["pairs"])
    for (const double smoothing_mm : {-1.0, 0.0, 1.0}) {  // −1: as configured
      nlohmann::json c = p["case"];
      if (smoothing_mm >= 0) c["geometry"]["smoothing_mm"] = smoothing_mm;
      c["sweep"] = {{"tY_mm", {0}}, {"Q_kN", {50}}};
      const mh::CaseFile cf = mh::parse_case_json(c, dir + "trust.json", true);
      const mh::PairGeometry pg = mh::build_pair_geometry(cf);
      for (double tY = -6e-3; tY <= 12e-3 + 1e-9; tY += 0.25e-3)
        for (const double Q : {10e3, 60e3, 150e3}) {
          const mh::CaseResult r = mh::solve_multi_hertz(pg.geo, cf.material, tY, Q);
          const mh::WheelRailGap gap(pg.geo, tY);
          for (const mh::LoadedEllipse& L : r.loaded) {
            const double b = L.s.b, h = b / 40;
            const mh::GapKink full = mh::gap_kink(gap, L.g, L.B, b, L.s.p0, 0.5 * mat.E_star(), r.approach, {}, false);
            const mh::GapKink fast = mh::gap_kink(gap, L.g, L.B, b, L.s.p0, 0.5 * mat.E_star(), r.approach);
            const mh::KinkBound qb = mh::gap_curvature_bound(gap, mh::plane_at(gap, L.g.y_r), -b, h, 161, L.B, r.approach);
            CAPTURE(p["name"].get<std::string>(), smoothing_mm, tY, Q, L.ellipse, qb.dtheta, full.dtheta);
            CHECK(fast.valid == full.valid);
            ++total;
            if (!qb.found) continue;
            ++found;
            CHECK(qb.dtheta >= full.dtheta);
            worst = std::max(worst, full.dtheta / qb.dtheta);
          }
        }
    }
  INFO(total << " patches, the curvature bound found on " << found << ", the largest samples / bound " << worst);
  CHECK(total >= 4000);
  CHECK(found >= 0.9 * total);
  CHECK(worst <= 1);
}
