// The creep forces of the two tangential solvers against CONTACT's exact solution on 30 Hertzian
// cases nobody in the project tuned to (tests/data/contact_tangential/README.md: a/b = 0.2, 0.5,
// 1, 2, 5 × six creepage sets — pure ξ, η, φ, combined, near saturation, large spin — at
// FN 80 kN, μ 0.3, ν 0.28, G 82 GPa; CONTACT 25.2 module 3, 60 × 60 elements over 1.1 × the
// ellipse). Issue 33 §4: each component, not only the resultant.
//  - FASTSIM per ellipse (the multi-Hertzian method's solver, defaults: 32 × 32, elliptical bound,
//    Kalker's three flexibilities): the median and 95th percentile of |ΔFx|/(μN), |ΔFy|/(μN) and
//    |ΔMz|/(μN c) (c = √(ab)) printed and held at the targets (median ≤ 3 %, 95th ≤ 10 %
//    in force); the spin moment, for which the issue sets no target, is held at what was measured
//    (docs/trust.md "Creep forces").
//  - The exact half-space solver on the same grid, the Hertzian pressure given on it: Fx, Fy
//    within 2 % of μN, Mz within 5 % (of μN c: the relative error of a moment near 0 means
//    nothing), adhesion fraction within 0.05 (issue 33 §4).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "contact/half_space/tangential_rolling.hpp"
#include "contact/tangential/fastsim.hpp"
#include "support/data_csv.hpp"
#include "support/hertz_grid.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;

using Row = mh::test::DataRow;

std::vector<Row> read_module3() { return mh::test::read_data_rows("contact_tangential/module3_hertz.csv"); }

/// The q-quantile of v (nearest rank).
double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const std::size_t k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size()))) - 1;
  return v[std::min(k, v.size() - 1)];
}

}  // namespace

TEST_CASE("FASTSIM per ellipse against CONTACT's exact creep forces on 30 Hertzian cases",
          "[tangential_accuracy][fastsim]") {
  const std::vector<Row> rows = read_module3();
  REQUIRE(rows.size() == 30);
  std::vector<double> ex, ey, em;
  for (const Row& r : rows) {
    const double a = r["a_mm"] * 1e-3, b = r["b_mm"] * 1e-3, N = r["FN_N"], mu = r["mu"], c = std::sqrt(a * b);
    const mh::Creepages cr{r["xi"], r["eta"], r["phi_per_mm"] * 1e3};
    const mh::TangentialResult f = mh::fastsim(cr, a, b, N, mu, r["G_MPa"] * 1e6, r["nu"]);
    ex.push_back(std::fabs(f.Fx - r["exact_Fx_N"]) / (mu * N));
    ey.push_back(std::fabs(f.Fy - r["exact_Fy_N"]) / (mu * N));
    em.push_back(std::fabs(f.Mz - r["exact_Mz_Nmm"] * 1e-3) / (mu * N * c));
  }
  std::printf("FASTSIM vs CONTACT exact, 30 Hertzian cases: |dFx|/muN median %.4f p95 %.4f; |dFy|/muN median %.4f "
              "p95 %.4f; |dMz|/(muN c) median %.4f p95 %.4f\n",
              quantile(ex, 0.5), quantile(ex, 0.95), quantile(ey, 0.5), quantile(ey, 0.95), quantile(em, 0.5),
              quantile(em, 0.95));
  for (const auto* e : {&ex, &ey}) {
    CHECK(quantile(*e, 0.5) <= 0.03);
    CHECK(quantile(*e, 0.95) <= 0.10);
  }
  // Measured 28 Nov 2026: Fx median 0.0000, p95 0.0436; Fy 0.0169, 0.0591; Mz 0.0104, 0.0245.
  CHECK(quantile(em, 0.5) <= 0.016);
  CHECK(quantile(em, 0.95) <= 0.04);
}

TEST_CASE("The exact half-space solver against CONTACT's exact creep forces on 30 Hertzian cases",
          "[tangential_accuracy][tangential_rolling]") {
  const std::vector<Row> rows = read_module3();
  REQUIRE(rows.size() == 30);
  double worst_F = 0, worst_M = 0, worst_adh = 0;
  for (const Row& r : rows) {
    const double a = r["a_mm"] * 1e-3, b = r["b_mm"] * 1e-3, N = r["FN_N"], mu = r["mu"], c = std::sqrt(a * b);
    const int mx = static_cast<int>(r["mx"]), my = static_cast<int>(r["my"]);
    HertzGrid h(a, b, 3 * N / (2 * kPi * a * b), mx, my, r["scale"]);
    for (double& p : h.p) p *= N / h.N;  // the discrete pressure carries FN exactly
    mh::HalfSpaceTangentialSolver s(h.nx, h.ny, h.dx, h.dy, r["G_MPa"] * 1e6, r["nu"]);
    const mh::Creepages cr{r["xi"], r["eta"], r["phi_per_mm"] * 1e3};
    const auto t = s.solve(h.p.data(), h.x0, h.y0, cr, mu);
    INFO("a/b = " << r["a_over_b"] << ", xi = " << cr.xi << ", eta = " << cr.eta << ", phi = " << cr.phi << " 1/m");
    REQUIRE(t.status == mh::TangentialStatus::Ok);
    const double dFx = std::fabs(t.forces.Fx - r["exact_Fx_N"]) / (mu * N);
    const double dFy = std::fabs(t.forces.Fy - r["exact_Fy_N"]) / (mu * N);
    const double dMz = std::fabs(t.forces.Mz - r["exact_Mz_Nmm"] * 1e-3) / (mu * N * c);
    const double dA = std::fabs(t.forces.adhesion_fraction - r["exact_adhesion_fraction"]);
    worst_F = std::max({worst_F, dFx, dFy});
    worst_M = std::max(worst_M, dMz);
    worst_adh = std::max(worst_adh, dA);
    // Measured 29 Nov 2026 (spin slip as CONTACT, eq. R1): worst |ΔF| 0.0013 μN, |ΔMz| 0.0006 μN c,
    // adhesion 0.010 (0.0125, 0.0094, 0.013 with the spin slip at the element centre).
    CHECK(dFx <= 0.02);
    CHECK(dFy <= 0.02);
    CHECK(dMz <= 0.05);
    CHECK(dA <= 0.05);
  }
  std::printf("half-space exact vs CONTACT exact, 30 Hertzian cases: worst |dF|/muN %.4f, |dMz|/(muN c) %.4f, "
              "adhesion %.3f\n", worst_F, worst_M, worst_adh);
}
