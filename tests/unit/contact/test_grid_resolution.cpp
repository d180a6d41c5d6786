// How many elements (strips) across a contact patch the grid methods need: a convergence study on
// Hertzian patches of known closed form (tests/support/hertz_reference.hpp, Johnson §3.6, §4.2).
// A fixed patch is resolved by n = 2, 3, 4, 6, 8, 12, 16, 24 elements across its narrow axis 2b
// (element size 2b/n, square for the half-space), the grid shifted by 0, 1/4 and 1/2 element
// against the patch centre (a real patch falls anywhere on its grid); the errors in peak pressure
// and area against the closed form give the minimum count for the methods' stated peak accuracy
// (kPeakRtolGrid, grid_checks.hpp), which the under_resolved check uses (docs/half_space.md,
// "Elements across a patch"; docs/strips.md, "Strips across a patch").
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "contact/grid/grid_checks.hpp"
#include "contact/half_space/normal_cg.hpp"
#include "contact/solve.hpp"
#include "contact/strips/strip_patch.hpp"
#include "input/case_file.hpp"
#include "jobs/run.hpp"
#include "support/hertz_reference.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;
const double kE = 210e9, kNu = 0.28;  // steel on steel
const double kH = 2.0 * (1.0 - kNu * kNu) / (kPi * kE);                  // [1/Pa] the solvers' compliance
const double kEstar = mh::testing::johnson_modulus(kE, kNu, kE, kNu);  // [Pa] Johnson's E*, the reference's

// The patch: a wheel-like curvature B across (narrow axis b along s), A = lambda B along x.
constexpr double kB = 1.0 / (2 * 0.3), kN = 50e3;  // [1/m], [N]
const int kCounts[] = {2, 3, 4, 6, 8, 12, 16, 24};
const double kOffsets[] = {0.0, 0.25, 0.5};  // grid shift along s, in elements

struct Point {
  int n = 0;             // elements across 2b by construction
  int counted = 0;       // elements_across() of the solution (worst over the offsets)
  double peak_err = 0;   // largest |pmax / p0 − 1| over the offsets
  double area_err = 0;   // largest |area / (π a b) − 1| over the offsets
};

Point half_space_point(double lambda, int n) {
  const mh::testing::HertzReference hz = mh::testing::hertz_reference(lambda * kB, kB, kN, kEstar);
  const double h = 2 * hz.b / n;
  const int nx = 2 * static_cast<int>(std::ceil(1.3 * hz.a / h)) + 2;
  const int ns = 2 * static_cast<int>(std::ceil(1.3 * hz.b / h)) + 4;
  const mh::InfluenceGrid C(nx, ns, h, h, kH);
  Point pt{n, 1 << 30, 0, 0};
  for (double off : kOffsets) {
    std::vector<double> g(static_cast<std::size_t>(nx) * ns), p(g.size(), 0.0);
    for (int j = 0; j < ns; ++j)
      for (int i = 0; i < nx; ++i) {
        const double x = (i - 0.5 * (nx - 1)) * h, s = (j - 0.5 * (ns - 1) + off) * h;
        g[static_cast<std::size_t>(i + nx * j)] = lambda * kB * x * x + kB * s * s;
      }
    const mh::NormalCGResult r = mh::solve_normal_load(C, g.data(), kN, INFINITY, p.data());
    REQUIRE(r.status == mh::GridStatus::Ok);
    const double pmax = *std::max_element(p.begin(), p.end());
    const double area = std::count_if(p.begin(), p.end(), [](double v) { return v > 0; }) * h * h;
    pt.counted = std::min(pt.counted, mh::elements_across(p, nx, ns));
    pt.peak_err = std::max(pt.peak_err, std::fabs(pmax / hz.p0 - 1));
    pt.area_err = std::max(pt.area_err, std::fabs(area / (kPi * hz.a * hz.b) - 1));
  }
  return pt;
}

Point strip_point(double lambda, int n) {
  const mh::testing::HertzReference hz = mh::testing::hertz_reference(lambda * kB, kB, kN, kEstar);
  const double ds = 2 * hz.b / n;
  const int ns = 2 * static_cast<int>(std::ceil(1.6 * hz.b / ds)) + 5;
  Point pt{n, 1 << 30, 0, 0};
  for (double off : kOffsets) {
    mh::StripGeometry geo;
    geo.ds = ds;
    for (int j = 0; j < ns; ++j) {
      const double s = (j - 0.5 * (ns - 1) + off) * ds;
      geo.s.push_back(s);
      geo.g.push_back(kB * s * s);
      geo.A.push_back(lambda * kB);
      geo.xc.push_back(0.0);
    }
    const mh::StripResult r = mh::solve_strips_load(geo, kH, kN, INFINITY);  // the method's defaults
    REQUIRE(r.status == mh::StripStatus::Ok);
    std::vector<double> q(geo.s.size(), 0.0);
    for (const mh::StripState& st : r.strips) q[static_cast<std::size_t>(st.index)] = st.q;
    pt.counted = std::min(pt.counted, mh::elements_across(q, 1, ns));
    pt.peak_err = std::max(pt.peak_err, std::fabs(r.pmax / hz.p0 - 1));
    pt.area_err = std::max(pt.area_err, std::fabs(r.area / (kPi * hz.a * hz.b) - 1));
  }
  return pt;
}

}  // namespace

TEST_CASE("elements across a patch: convergence of the grid methods on Hertz patches", "[resolution]") {
  for (const bool strips : {false, true}) {
    const int n_min = strips ? mh::kMinAcrossStrips : mh::kMinAcrossHalfSpace;
    const double peak_tol = strips ? mh::kPeakRtolStrips : mh::kPeakRtolHalfSpace;
    const double area_tol = strips ? mh::kAreaRtolStrips : INFINITY;  // the half-space's area: not covered
    int below = 0;  // the study's count just below n_min: it must miss the accuracy on some patch
    for (int m : kCounts)
      if (m < n_min) below = m;
    bool below_fails = false;
    for (const double lambda : {1.0, 0.1}) {
      const mh::testing::HertzReference hz = mh::testing::hertz_reference(lambda * kB, kB, kN, kEstar);
      std::printf("  %s, A/B = %g (a/b = %.2f, b = %.3f mm, p0 = %.0f MPa)\n", strips ? "strips" : "half-space", lambda,
                  hz.a / hz.b, hz.b * 1e3, hz.p0 / 1e6);
      std::printf("    n across 2b | counted (min) | peak error, worst | area error, worst\n");
      for (int n : kCounts) {
        const Point pt = strips ? strip_point(lambda, n) : half_space_point(lambda, n);
        std::printf("    %11d | %13d | %16.2f %% | %16.2f %%\n", pt.n, pt.counted, 100 * pt.peak_err,
                    100 * pt.area_err);
        INFO((strips ? "strips" : "half-space") << ", A/B = " << lambda << ", n = " << n);
        CHECK(pt.counted == n);  // elements_across counts the patch's narrow axis as constructed
        if (n >= n_min) {
          CHECK(pt.peak_err <= peak_tol);
          CHECK(pt.area_err <= area_tol);
        }
        if (n == below) below_fails = below_fails || pt.peak_err > peak_tol || pt.area_err > area_tol;
      }
    }
    INFO((strips ? "strips" : "half-space") << ": the count below the minimum reaches the accuracy on every patch");
    CHECK(below_fails);
  }
}

// A narrow flange patch (S1002 on 60E1 1:40, generated, t_Y = 10 mm, Q = 20 kN: CONTACT's patch at
// 0.2 mm is 1.2 mm wide, tests/data/contact/field/contact_S1002_60E1_1-40.csv) has fewer elements
// across than the study's minimum on the half-space's default 0.2 mm grid (6 < 8) and on 0.5 mm
// strips (2 < 4; the default 0.2 mm strips give 5). Without refinement it is under_resolved
// (outside_validity); with it (the default) it is refined locally until its peak settles, and then
// agrees with a solve of the whole case on a grid fine enough from the start (0.05 mm half-space
// elements, 0.05 mm strips), within the method's peak tolerance.
TEST_CASE("a narrow flange patch is refined until it converges, or is under_resolved", "[resolution][status]") {
  mh::CaseFile cf = mh::load_case_file(std::string(MHCONTACT_SOURCE_DIR) + "/cases/s1002-60e1.json", true);
  const mh::PairGeometry pg = mh::build_pair_geometry(cf);
  const double tY = 10e-3, Q = 20e3;
  for (const mh::Method m : {mh::Method::HalfSpace, mh::Method::Strips}) {
    const bool strips = m == mh::Method::Strips;
    const int n_min = strips ? mh::kMinAcrossStrips : mh::kMinAcrossHalfSpace;
    const double peak_tol = strips ? mh::kPeakRtolStrips : mh::kPeakRtolHalfSpace;
    auto solve = [&](int max_refinements, double element) {
      mh::MethodOptions opt = cf.method_options();
      opt.method = m;
      opt.half_space.max_refinements = opt.strips.max_refinements = max_refinements;
      if (element > 0) opt.half_space.dx = opt.half_space.ds = opt.strips.ds = element;
      return mh::solve_contact(pg.geo, cf.material, tY, Q, opt);
    };
    auto has_class = [](const mh::CaseResult& r, const std::string& cls) {
      for (const mh::Warning& w : r.warnings)
        if (mh::warning_text(w).rfind(cls + ":", 0) == 0) return true;
      return false;
    };
    INFO("method " << mh::to_string(m));
    // The default grid without refinement: too few elements across, not ok.
    const double coarse_element = strips ? 0.5e-3 : 0.0;  // 0: the default
    const mh::CaseResult coarse = solve(0, coarse_element);
    INFO("coarse: " << mh::to_string(coarse.status) << " " << coarse.message);
    REQUIRE(coarse.patches.size() == 1);
    const mh::PatchResult& pc = coarse.patches[0];
    std::printf("  %s, no refinement: %d across at %.3f mm, pmax %.1f MPa, area %.2f mm2, %s\n", mh::to_string(m),
                pc.elements_across, pc.element * 1e3, pc.pmax / 1e6, pc.area * 1e6, mh::to_string(coarse.status));
    CHECK(pc.elements_across < n_min);
    CHECK(coarse.status == mh::CaseStatus::OutsideValidity);
    CHECK(has_class(coarse, "under_resolved"));
    // The default: refined locally, ok, and within the peak tolerance of the fine solve.
    const mh::CaseResult refined = solve(mh::HalfSpaceOptions().max_refinements, coarse_element);
    const mh::CaseResult fine = solve(0, 0.05e-3);
    INFO("refined: " << mh::to_string(refined.status) << " " << refined.message);
    REQUIRE(refined.patches.size() == 1);
    REQUIRE(fine.patches.size() == 1);
    const mh::PatchResult &pr = refined.patches[0], &pf = fine.patches[0];
    std::printf("  %s, refined: %d across at %.3f mm, pmax %.1f MPa, area %.2f mm2, %s; fine grid: %d across at "
                "%.3f mm, pmax %.1f MPa, area %.2f mm2, %s\n",
                mh::to_string(m), pr.elements_across, pr.element * 1e3, pr.pmax / 1e6, pr.area * 1e6,
                mh::to_string(refined.status), pf.elements_across, pf.element * 1e3, pf.pmax / 1e6, pf.area * 1e6,
                mh::to_string(fine.status));
    CHECK(refined.status == mh::CaseStatus::Ok);
    CHECK_FALSE(has_class(refined, "under_resolved"));
    CHECK(pr.elements_across >= n_min);
    CHECK(pr.element < pc.element);
    CHECK(pf.elements_across >= n_min);
    CHECK(std::fabs(pr.pmax / pf.pmax - 1) <= peak_tol);
    CHECK(refined.Fz == Approx(Q).epsilon(1e-5));
  }
}
