// The strip method (docs/method.md §9) as a method of runs, against CONTACT's exact results on the
// Manchester pair (tests/data/contact, Q = 50 kN) and against this project's half-space solver.
// Tolerances at about 1.5 times the worst error measured (printed by the test; 28 Nov 2026):
// single-region contact (16 cases) pmax 1 % (measured 0.63 %), area 6.5 % (4.27 %), approach
// 1.5 % (0.98 %); two regions (gauge shoulder, t_Y = 5 mm) 2 % (1.25 %), 1.5 % (0.99 %), 0.2 %
// (0.12 %). Until then held at 5 / 10 / 3 % and 10 / 15 / 5 %. t_Y = 0 mm (wide conformal tread patch) missed
// them with the estimated strip extents alone (pmax −8.5 %); its extents are now refined until the
// deformed gap closes at every strip end (docs/strips.md), as are those of t_Y = 1 and 5 mm.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "contact/half_space/half_space_method.hpp"
#include "contact/solve.hpp"
#include "contact/strips/strip_method.hpp"
#include "geometry/gap.hpp"
#include "input/case_file.hpp"
#include "jobs/run.hpp"
#include "support/measured_pair.hpp"
#include "output/csv_table.hpp"

namespace {

struct Fixture {
  mh::CaseFile cf;
  mh::PairGeometry pg;
};

const Fixture& manchester() {
  static const Fixture f = [] {
    Fixture x;
    x.cf = mh::load_case_file(std::string(MHCONTACT_SOURCE_DIR) + "/cases/manchester-strips.json", true);
    x.pg = mh::build_pair_geometry(x.cf);
    return x;
  }();
  return f;
}

double cell(const mh::CsvTable& t, std::size_t row, const char* col) {
  return std::stod(t.rows[row][static_cast<std::size_t>(t.column(col))]);
}

}  // namespace

TEST_CASE("strip method against CONTACT on the Manchester sweep at Q = 50 kN", "[strips][contact_reference]") {
  const mh::CsvTable ref = mh::read_csv_file(std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/contact/contact_mbench_right_q50_dx0.2.csv");
  const Fixture& F = manchester();
  REQUIRE(ref.rows.size() == 17);
  double worst[2][3] = {};  // [single region, two regions][pmax, area, approach], printed below
  for (std::size_t i = 0; i < ref.rows.size(); ++i) {
    const double tY = cell(ref, i, "y_ws_mm");
    INFO("t_Y = " << tY << " mm");
    const mh::CaseResult r = mh::solve_strip_method(F.pg.geo, F.cf.material, tY * 1e-3, 50e3, F.cf.strips);
    REQUIRE(r.status == mh::CaseStatus::Ok);
    const double pmax = cell(ref, i, "pmax_MPa") * 1e6, area = cell(ref, i, "area_mm2") * 1e-6;
    const double dz = cell(ref, i, "vertical_approach_mm") * 1e-3;
    const bool two_regions = tY == 5;
    // Measured worst (28 Nov 2026): single region 0.63 / 4.27 / 0.98 %, two regions 1.25 / 0.99 / 0.12 %.
    const double tol_p = two_regions ? 0.02 : 0.01, tol_a = two_regions ? 0.015 : 0.065;
    const double tol_z = two_regions ? 0.002 : 0.015;
    // The patches whose estimated extents miss the end gap by more than end_gap_tol (0.05) are
    // refined: measured 0.17, 0.07 and 0.13 at t_Y = 0, 1 and 5 mm, at most 0.034 elsewhere.
    REQUIRE(r.patches.size() == 1);
    CHECK(r.patches[0].refined == (tY == 0 || tY == 1 || tY == 5));
    CHECK(r.patches[0].end_gap_error < (r.patches[0].refined ? 0.25 : 0.05));
    double* w = worst[two_regions ? 1 : 0];
    w[0] = std::max(w[0], std::fabs(r.pmax / pmax - 1));
    w[1] = std::max(w[1], std::fabs(r.area / area - 1));
    w[2] = std::max(w[2], std::fabs(r.approach / dz - 1));
    CHECK(r.pmax == Approx(pmax).epsilon(tol_p));
    CHECK(r.area == Approx(area).epsilon(tol_a));
    CHECK(r.approach == Approx(dz).epsilon(tol_z));
    CHECK(r.Fz == Approx(50e3).epsilon(1e-6));
  }
  std::printf("strips against CONTACT, worst: single region (16 cases) pmax %.3f %%, area %.3f %%, approach %.3f %%; "
              "two regions (t_Y = 5 mm) pmax %.3f %%, area %.3f %%, approach %.3f %%\n",
              100 * worst[0][0], 100 * worst[0][1], 100 * worst[0][2], 100 * worst[1][0], 100 * worst[1][1],
              100 * worst[1][2]);
}

TEST_CASE("small flange patches: strips against a converged half-space reference", "[strips]") {
  // Manchester pair, Q = 10 kN, t_Y = 8 and 8.5 mm: flange patches 13-16 mm² across 8-12 strips of
  // 0.2 mm. Against the half-space solver on its 0.2 mm grid the strip areas look 8.5 % low, but
  // that reference is not converged: the element-count area of a grid solution falls as the grid is
  // refined (17.04, 16.46, 16.10, 15.88 mm² at 0.2, 0.1, 0.05, 0.025 mm for t_Y = 8 mm) and the
  // strips (15.58 mm² at 0.2 mm, 15.98 at 0.05 mm) sit at its limit. Reference: the half-space
  // solver at dx = ds = 0.025 mm (64 times the elements). Measured: strips area -1.9 % and
  // +3.3 %, pmax +0.2 % and +0.9 %, approach -1.0 % and -0.0 % (docs/strips.md).
  const Fixture& F = manchester();
  mh::HalfSpaceOptions fine;
  fine.dx = fine.ds = 0.025e-3;
  mh::HalfSpaceOptions coarse;  // 0.2 mm, the default grid, without its local refinement
  coarse.max_refinements = 0;
  for (double tY : {8.0, 8.5}) {
    INFO("t_Y = " << tY << " mm");
    const mh::CaseResult ref = mh::solve_half_space(F.pg.geo, F.cf.material, tY * 1e-3, 10e3, fine);
    const mh::CaseResult hs = mh::solve_half_space(F.pg.geo, F.cf.material, tY * 1e-3, 10e3, coarse);
    const mh::CaseResult st = mh::solve_strip_method(F.pg.geo, F.cf.material, tY * 1e-3, 10e3, F.cf.strips);
    REQUIRE(ref.status == mh::CaseStatus::Ok);
    REQUIRE(hs.status == mh::CaseStatus::Ok);
    REQUIRE(st.status == mh::CaseStatus::Ok);
    CHECK(st.area == Approx(ref.area).epsilon(0.04));
    CHECK(st.pmax == Approx(ref.pmax).epsilon(0.02));
    CHECK(st.approach == Approx(ref.approach).epsilon(0.02));
    // The coarse reference's area is the larger by 7-13 %: the 8.5 % of the 99-case comparison
    // (docs/strips.md) is the reference's grid, not the strips'.
    CHECK(hs.area > 1.05 * ref.area);
  }
}

TEST_CASE("strip method against the half-space solver on S1002 / 60E1 1:40", "[strips]") {
  mh::CaseFile cf = mh::load_case_file(std::string(MHCONTACT_SOURCE_DIR) + "/cases/s1002-60e1.json", true);
  const mh::PairGeometry pg = mh::build_pair_geometry(cf);
  // Single-region tread and flange contacts of this pair (t_Y where both methods find one patch).
  int compared = 0;
  for (double tY : {-4.0, -1.0, 3.0, 9.0}) {
    INFO("t_Y = " << tY << " mm");
    const mh::CaseResult hs = mh::solve_half_space(pg.geo, cf.material, tY * 1e-3, 50e3, cf.half_space);
    const mh::CaseResult st = mh::solve_strip_method(pg.geo, cf.material, tY * 1e-3, 50e3, cf.strips);
    REQUIRE(hs.status == mh::CaseStatus::Ok);
    REQUIRE(st.status == mh::CaseStatus::Ok);
    if (hs.n_contacts != 1 || st.n_contacts != 1) continue;
    ++compared;
    CHECK(st.pmax == Approx(hs.pmax).epsilon(0.05));
    CHECK(st.area == Approx(hs.area).epsilon(0.10));
    CHECK(st.approach == Approx(hs.approach).epsilon(0.03));
  }
  CHECK(compared >= 3);
}

TEST_CASE("strip method against the half-space solver on two measured pairs", "[strips]") {
  // Measured profiles from tests/data/profiles (README there): a worn wheel on a worn heavy-haul
  // rail, and a MiniProf wheel on a MiniProf rail, both rails laid at 1:40; Q = 50 kN, 0.2 mm
  // elements and strips. Single-region tread contacts over t_Y = -6 ... 8 mm, where the estimated
  // extents are kept; on the MiniProf pair also the conformal flange root of the worn wheel
  // (9.5, 10.5 mm) and its flange on the coarsely measured gauge corner (11 mm), where the
  // estimate missed by up to 22 % in peak pressure and the extents are now refined
  // (docs/strips.md, "Measured pairs", has the whole sweep). The single-region tolerances hold
  // on all of them.
  struct Pair { const char* wheel; const char* rail; };
  for (const Pair& p : {Pair{"worn_high_mileage.prw", "site_b_hr.prr"}, Pair{"avg_wheel.whl", "avg_HR.BAN"}}) {
    const mh::CaseFile cf = mh::testing::measured_pair_case(p.wheel, p.rail, 0, 50);
    const mh::PairGeometry pg = mh::build_pair_geometry(cf);
    const bool miniprof = std::string(p.wheel) == "avg_wheel.whl";
    std::vector<double> tYs = {-6.0, -2.0, 2.0, 6.0, 8.0};
    if (miniprof) tYs.insert(tYs.end(), {9.5, 10.5, 11.0});
    for (double tY : tYs) {
      INFO(p.wheel << " on " << p.rail << ", t_Y = " << tY << " mm");
      const mh::CaseResult hs = mh::solve_half_space(pg.geo, cf.material, tY * 1e-3, 50e3, cf.half_space);
      const mh::CaseResult st = mh::solve_strip_method(pg.geo, cf.material, tY * 1e-3, 50e3, cf.strips);
      REQUIRE(hs.status == mh::CaseStatus::Ok);
      REQUIRE(st.status == mh::CaseStatus::Ok);
      REQUIRE(hs.n_contacts == 1);
      REQUIRE(st.n_contacts == 1);
      CHECK(st.pmax == Approx(hs.pmax).epsilon(0.05));
      CHECK(st.area == Approx(hs.area).epsilon(0.10));
      CHECK(st.approach == Approx(hs.approach).epsilon(0.03));
      // Refined where the estimate missed: 9.5, 10.5 and 11 mm. At 9.5 mm it missed on the
      // unsmoothed MiniProf wheel, did not on the wheel smoothed at a fixed 5 mm, and misses again
      // on the default surface, whose length from the noise is shortened at the worn flange root
      // to keep its geometry (profiles.md §7); the accuracy above holds on all three.
      CHECK(st.patches[0].refined == (tY > 9));
    }
  }
}

TEST_CASE("strip method plastic: a cap above the peak changes nothing, a low cap carries the load", "[strips]") {
  const Fixture& F = manchester();
  mh::StripMethodOptions o = F.cf.strips;
  o.keep_strips = true;
  const double Q = 50e3, tY = 3e-3;
  const mh::CaseResult el = mh::solve_strip_method(F.pg.geo, F.cf.material, tY, Q, o);
  REQUIRE(el.status == mh::CaseStatus::Ok);
  mh::Material high = F.cf.material;
  high.p_lim = 1.5 * el.pmax;
  const mh::CaseResult same = mh::solve_strip_method(F.pg.geo, high, tY, Q, o);
  REQUIRE(same.status == mh::CaseStatus::Ok);
  CHECK(same.pmax == el.pmax);
  CHECK(same.area == el.area);
  CHECK(same.approach == el.approach);
  mh::Material low = F.cf.material;
  low.p_lim = 900e6;
  const mh::CaseResult pl = mh::solve_strip_method(F.pg.geo, low, tY, Q, o);
  REQUIRE(pl.status == mh::CaseStatus::Ok);
  CHECK(pl.pmax == Approx(low.p_lim).epsilon(1e-12));
  CHECK(pl.area > el.area);
  CHECK(pl.patches[0].plastic_area > 0);
  CHECK(pl.Fz == Approx(Q).epsilon(1e-6));
  // The capped strip pressure min(q √(1 − t²), p_lim) integrated over every strip is the patch load:
  // ∫ = q a Φ(r) ds with r = p_lim / q, Φ(r) = r √(1 − r²) + asin r (§9.6), by direct quadrature here.
  const mh::PatchResult& P = pl.patches[0];
  double N = 0;
  const int n = 4000;
  for (const auto& st : P.strips) {
    double s = 0;
    for (int k = 0; k < n; ++k) {
      const double t = -1 + (k + 0.5) * 2.0 / n;
      s += std::min(st.q * std::sqrt(1 - t * t), low.p_lim) * (2.0 / n) * st.a;
    }
    N += s * F.cf.strips.ds;
  }
  CHECK(N == Approx(P.N).epsilon(2e-4));
}

TEST_CASE("auto keeps the multi-Hertzian answer where it is valid and hands the rest to the strips", "[strips][auto]") {
  const Fixture& F = manchester();
  mh::MethodOptions mo = F.cf.method_options();
  mo.method = mh::Method::Auto;
  // t_Y = -4: one smooth tread ellipse; t_Y = 5: tread and gauge-corner contacts 6.5 mm apart at
  // their edges interact; t_Y = 0: the tread ellipse fails the Hertz validity test.
  const mh::CaseResult a = mh::solve_contact(F.pg.geo, F.cf.material, -4e-3, 50e3, mo);
  CHECK(a.method == mh::Method::MultiHertzian);
  const mh::CaseResult b = mh::solve_contact(F.pg.geo, F.cf.material, 5e-3, 50e3, mo);
  CHECK(b.method == mh::Method::Strips);
  REQUIRE(!b.warnings.empty());
  // Ellipse 3 (gauge corner) also fails the mean edge-gap test (0.114 > 0.1), which is checked
  // first; with that limit relaxed, the interaction rule alone hands the case over.
  CHECK(mh::warning_text(b.warnings[0]).rfind("auto:strips:ellipse 3 not Hertzian", 0) == 0);
  mh::MethodOptions lax = mo;
  lax.multi_hertzian.validity.max_gap_mean_error = 1.0;
  const mh::CaseResult bi = mh::solve_contact(F.pg.geo, F.cf.material, 5e-3, 50e3, lax);
  CHECK(bi.method == mh::Method::Strips);
  REQUIRE(!bi.warnings.empty());
  CHECK(mh::warning_text(bi.warnings[0]).rfind("auto:strips:ellipses 2 and 3 interact", 0) == 0);
  const mh::CaseResult c = mh::solve_contact(F.pg.geo, F.cf.material, 0.0, 50e3, mo);
  CHECK(c.method == mh::Method::Strips);
  // t_Y = 8: the flange patch reaches the end of the wheel's R13 arc (multi-Hertzian pmax +22 %
  // against CONTACT): handed over by the mean edge-gap test.
  const mh::CaseResult d = mh::solve_contact(F.pg.geo, F.cf.material, 8e-3, 50e3, mo);
  CHECK(d.method == mh::Method::Strips);
  REQUIRE(!d.warnings.empty());
  CHECK(mh::warning_text(d.warnings[0]).rfind("auto:strips:ellipse 4 not Hertzian", 0) == 0);
  // A strip solve that does not converge (here made so: two approach iterations allowed) falls
  // back to the half-space method, and the warnings say both steps.
  mh::MethodOptions starved = mo;
  starved.strips.strips.max_iterations = 2;
  const mh::CaseResult e = mh::solve_contact(F.pg.geo, F.cf.material, 0.5e-3, 10e3, starved);
  CHECK(e.status == mh::CaseStatus::Ok);
  CHECK(e.method == mh::Method::HalfSpace);
  REQUIRE(e.warnings.size() >= 2);
  CHECK(mh::warning_text(e.warnings[0]).rfind("auto:strips:", 0) == 0);
  CHECK(mh::warning_text(e.warnings[1]) == "auto:half-space:strips not converged");
  CHECK(e.Fz == Approx(10e3).epsilon(1e-4));
}

TEST_CASE("a strip entering the patch takes up its load from zero", "[strips]") {
  // Manchester pair, t_Y = 0.5 mm, Q = 10 kN. Before the tail strips were widened (docs/method.md
  // §9 item 7), a strip entering the patch got a vanishing extent but the full interpenetration
  // as its collocation right-hand side: amplitude 1.3e7 MPa, N(δ) jumping across the target load,
  // the case not_converged (docs/strips.md, "Load jumps"). Reference: this project's half-space
  // solution of the case, pmax 627.1 MPa, area 47.36 mm² (tolerances of a single region).
  const Fixture& F = manchester();
  const mh::CaseResult r = mh::solve_contact(F.pg.geo, F.cf.material, 0.5e-3, 10e3, F.cf.method_options());
  REQUIRE(r.status == mh::CaseStatus::Ok);
  CHECK(r.Fz == Approx(10e3).epsilon(1e-6));
  for (const auto& w : r.warnings) CHECK(w.cls != mh::WarningClass::StripOutlier);
  CHECK(r.pmax == Approx(627.1e6).epsilon(0.05));
  CHECK(r.area == Approx(47.36e-6).epsilon(0.10));
}

TEST_CASE("a strip case that does not converge keeps its closest iterate", "[strips]") {
  // Two approach iterations are not enough for the load control of this case: the row is
  // not_converged, says why, and keeps the closest iterate's forces (docs/outputs.md "Failed
  // rows") instead of zeros, but no pressures: a grid iterate's peak is not bounded by anything
  // (grid_checks.hpp, withhold_unconverged_pressures).
  const Fixture& F = manchester();
  mh::MethodOptions mo = F.cf.method_options();
  mo.strips.strips.max_iterations = 2;
  const mh::CaseResult r = mh::solve_contact(F.pg.geo, F.cf.material, 0.5e-3, 10e3, mo);
  REQUIRE(r.status == mh::CaseStatus::NotConverged);
  CHECK(r.message.find("load not reached within max_iterations") != std::string::npos);
  REQUIRE(r.n_contacts >= 1);
  CHECK(r.Fz == Approx(10e3).epsilon(0.2));
  CHECK(r.approach > 0);
  CHECK(std::isnan(r.pmax));
  CHECK(std::isnan(r.area));
  CHECK(r.patches.empty());
}

TEST_CASE("strips in the plastic model: strongly capped flange contacts settle", "[strips]") {
  // Manchester pair, Q = 100 kN, p_lim = 900 MPa (cases/manchester-plastic.json), t_Y = 7 and
  // 8.5 mm: the strip method used to start from the multi-Hertzian plastic approach (2.7 mm at
  // 7 mm), placed its plane across the whole profile and never settled. Then its capped strips
  // reached beyond their overlap (area +13 %, approach −38 % and −66 %; docs/strips.md). Against
  // the plastic half-space solution (measured: area +4.4 % and +1.3 %, approach −5.7 % and
  // −9.1 %, the capped strips taking their whole rigid overlap): ok, the load carried, the cap
  // held, area within 5 %, approach within 12 %.
  const mh::CaseFile cf = mh::load_case_file(std::string(MHCONTACT_SOURCE_DIR) + "/cases/manchester-plastic.json", true);
  const mh::PairGeometry pg = mh::build_pair_geometry(cf);
  mh::MethodOptions mo = cf.method_options();
  mo.strips.keep_strips = true;
  for (double tY : {7e-3, 8.5e-3}) {
    CAPTURE(tY);
    mo.method = mh::Method::Strips;
    const mh::CaseResult r = mh::solve_contact(pg.geo, cf.material, tY, 100e3, mo);
    INFO(r.message);
    // At 8.5 mm the main contact has passed the steepest flange point (flange_climb, docs/method.md
    // §3.7): informational (docs/status.md). Both rows are loaded beyond the capped law's evidence
    // (p0_el/p_lim above 1.85, docs/trust.md "Evidence domains"): outside_validity by
    // beyond_evidence alone, no warning of the strip method's own checks.
    using WCs = std::vector<mh::WarningClass>;
    REQUIRE(r.status == mh::CaseStatus::OutsideValidity);
    REQUIRE(mh::validity_failures(r.warnings) == WCs{mh::WarningClass::BeyondEvidence});
    CHECK(r.Fz == Approx(100e3).epsilon(1e-4));
    CHECK(r.pmax <= cf.material.p_lim * (1 + 1e-9));

    mo.method = mh::Method::HalfSpace;
    const mh::CaseResult h = mh::solve_contact(pg.geo, cf.material, tY, 100e3, mo);
    REQUIRE(h.status == mh::CaseStatus::OutsideValidity);
    REQUIRE(mh::validity_failures(h.warnings) == WCs{mh::WarningClass::BeyondEvidence});
    CHECK(r.area == Approx(h.area).epsilon(0.05));
    CHECK(r.approach == Approx(h.approach).epsilon(0.12));
    // auto hands the plastic flange patch at 7 mm (it fails the Hertz validity test) to the strip
    // method; at 8.5 mm the multi-Hertzian ellipse passes it and is kept.
    mo.method = mh::Method::Auto;
    const mh::CaseResult a = mh::solve_contact(pg.geo, cf.material, tY, 100e3, mo);
    CHECK(a.status == mh::CaseStatus::OutsideValidity);
    CHECK(mh::has_class(a.warnings, mh::WarningClass::BeyondEvidence));
    CHECK(a.method == (tY < 8e-3 ? mh::Method::Strips : mh::Method::MultiHertzian));
  }
  // No hole inside a capped patch. A refinement used to restart a capped strip from its
  // lengthened extent run backwards through the lengthening, which shrank it up to 30 times
  // (t_Y = 9 mm: strips of 1.8 and 1.6 mm between ones of 22-26 mm); it restarts from its
  // extent before lengthening (StripState::a_elastic). Interior strips: at least half as long as
  // the shorter neighbour (measured: smooth, 14.6 ... 33.1 ... 19.2 mm).
  mo.method = mh::Method::Strips;
  const mh::CaseResult r9 = mh::solve_contact(pg.geo, cf.material, 9e-3, 100e3, mo);
  // With flange_climb (informational) and beyond_evidence, as at 8.5 mm.
  REQUIRE(mh::validity_failures(r9.warnings) == std::vector<mh::WarningClass>{mh::WarningClass::BeyondEvidence});
  REQUIRE(r9.patches.size() == 1);
  // The capped strips' elastic amplitudes differ from their neighbours' by more than the outlier
  // factor (flagged when the flag compared amplitudes: checked), but their peaks are all p_lim: the
  // flag compares peak pressures, no strip_outlier.
  for (const auto& w : r9.warnings) CHECK(w.cls != mh::WarningClass::StripOutlier);
  const auto& S9 = r9.patches[0].strips;
  REQUIRE(S9.size() > 10);
  for (std::size_t k = 1; k + 1 < S9.size(); ++k) {
    CAPTURE(S9[k].y_r);
    CHECK(S9[k].a >= 0.5 * std::min(S9[k - 1].a, S9[k + 1].a));
  }
}

TEST_CASE("strip method: two patches share one rigid approach, and their forces balance the load", "[strips][two_patches]") {
  // The case of "half-space: two patches share one rigid approach" (test_half_space.cpp): the
  // Manchester pair, Q = 10 kN, t_Y = 4.9, 5.0, 5.1 mm, d_comb = 4 mm: tread and gauge corner as
  // two patches (no CONTACT reference has two). Checks: two patches; Σ N_k cos γ_k = Q (eq. 10) to
  // 2e-7 (force_rtol 1e-7); each patch's approach δ_k = (δz − min g) cos γ_k with g the vertical
  // undeformed gap of the geometry over the patch's rail-y range, to 0.5 µm (measured at most
  // 0.16 µm: the gap minimum is sampled at the strip centres, ds = 0.2 mm); each patch's normal force
  // against the half-space method's on the same patches, within 1 % of Q (measured at most 0.15 %).
  const Fixture& F = manchester();
  mh::StripMethodOptions so = F.cf.strips;
  so.d_comb = 4e-3;
  mh::HalfSpaceOptions ho = F.cf.half_space;
  ho.d_comb = 4e-3;
  const double Q = 10e3;
  for (double tY : {4.9e-3, 5.0e-3, 5.1e-3}) {
    INFO("t_Y = " << tY * 1e3 << " mm");
    const mh::CaseResult r = mh::solve_strip_method(F.pg.geo, F.cf.material, tY, Q, so);
    const mh::CaseResult hs = mh::solve_half_space(F.pg.geo, F.cf.material, tY, Q, ho);
    REQUIRE(r.status == mh::CaseStatus::Ok);
    REQUIRE(hs.status == mh::CaseStatus::Ok);
    REQUIRE(r.patches.size() == 2);
    REQUIRE(hs.patches.size() == 2);
    CHECK(r.patches[1].y_r - r.patches[0].y_r > 8e-3);  // gauge corner, then tread
    const mh::WheelRailGap gap(F.pg.geo, tY);
    double Fz = 0;
    for (std::size_t k = 0; k < 2; ++k) {
      const mh::PatchResult& P = r.patches[k];
      INFO("patch " << P.patch << " at rail y " << P.y_r * 1e3 << " mm, N " << P.N << " N");
      const double cg = std::cos(P.gamma);
      Fz += P.N * cg;
      double g_min = INFINITY;
      const double y0 = P.y_r + (P.s_lo - so.ds) * cg, y1 = P.y_r + (P.s_hi + so.ds) * cg;
      for (int i = 0; i <= 4000; ++i) g_min = std::min(g_min, gap.g(y0 + (y1 - y0) * i / 4000));
      CHECK(std::fabs(P.approach - (r.approach - g_min) * cg) <= 0.5e-6);
      CHECK(std::fabs(P.N - hs.patches[k].N) <= 0.01 * Q);
    }
    CHECK(std::fabs(Fz - Q) <= 2e-7 * Q);
  }
}
