// The vertical equilibrium's extrapolated creep forces (contact/tangential/tangential_solve.hpp,
// extrapolate_tangential; contact/solve.cpp): past the first two full solves, each ellipse's
// creep forces are extrapolated linearly in its load where the error, bounded with
// kCreepCurvature, is within the equilibrium's tolerance.
// Breaks guarded (each seen to fail):
//  - the secant's sign flipped (t1 − s (t1 − t0)): "every row ... as FASTSIM at its final load";
//  - kCreepCurvature below 0.18, FASTSIM's largest measured curvature: "FASTSIM's curvature in
//    the Hertz-scaled load" (by its measured values).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "contact/solve.hpp"
#include "contact/tangential/fastsim.hpp"
#include "contact/tangential/tangential_solve.hpp"
#include "manchester_fixture.hpp"

using namespace mh;

namespace {
constexpr double kG = 82e9, kNu = 0.28, kMu = 0.3;

// FASTSIM (default grid, 32 x 32) on the ellipse of aspect a/b loaded by N as Hertz loads it:
// c = √(ab) = c0 (N/N0)^(1/3).
TangentialResult hertz_loaded(const Creepages& cr, double aob, double N) {
  const double N0 = 50e3, c0 = 6e-3;
  const double c = c0 * std::cbrt(N / N0);
  return fastsim(cr, c * std::sqrt(aob), c / std::sqrt(aob), N, kMu, kG, kNu);
}
}  // namespace

TEST_CASE("creep extrapolation: FASTSIM's curvature in the Hertz-scaled load within kCreepCurvature mu/N",
          "[tangential][fastsim][equilibrium]") {
  // The bound extrapolate_tangential's guard assumes, on FASTSIM itself: from the linear limit to
  // full slip, with and without spin, three aspects. The second difference over ±5 % of N (the
  // cells switching between adhesion and slip make F(N) piecewise smooth: a shorter step
  // measures their kinks, not the curvature). Measured largest N |F''| / μ: 0.18 (η −2e-3,
  // φ 0.3 rad/m, a/b 5, half the area adhering), 2.4 times below the bound.
  struct Row { Creepages c; double aob; };
  const Row rows[] = {
      {{1e-5, 0, 0}, 1.0},         {{0, -1e-5, 0}, 1.0},        {{2e-4, -1e-4, 0}, 0.5},    {{1e-3, 5e-4, 0}, 2.0},
      {{0, -6.25e-4, 0.625}, 2.0}, {{5e-4, -3e-4, 1.5}, 1.0},   {{-2e-3, 1e-3, -0.8}, 3.0}, {{1e-2, 0, 0}, 1.0},
      {{0, 0, 3.0}, 0.5},          {{3e-4, 0, 0}, 1.0},         {{0, 6e-4, 0}, 0.3},        {{0, -2e-3, 0.3}, 5.0},
  };
  const double N = 50e3, h = 0.05 * N;
  double worst = 0;
  for (const Row& r : rows) {
    const TangentialResult m = hertz_loaded(r.c, r.aob, N - h), o = hertz_loaded(r.c, r.aob, N),
                           p = hertz_loaded(r.c, r.aob, N + h);
    const double d2x = (p.Fx - 2 * o.Fx + m.Fx) / (h * h), d2y = (p.Fy - 2 * o.Fy + m.Fy) / (h * h);
    const double k = std::max(std::fabs(d2x), std::fabs(d2y)) * N / kMu;
    INFO("xi " << r.c.xi << " eta " << r.c.eta << " phi " << r.c.phi << " a/b " << r.aob << " N|F''|/mu " << k
               << " adhesion " << o.adhesion_fraction);
    CHECK(k <= kCreepCurvature);
    worst = std::max(worst, k);
  }
  // The rows reach the curvature the bound is for (above: 0.18).
  CHECK(worst > 0.1);
}

TEST_CASE("creep extrapolation: every row of the Manchester sweep carries the creep forces of FASTSIM at its final load",
          "[tangential][equilibrium]") {
  // The sweep of bench/tangential/bench_solve_many_python.py (t_Y −6 … 10 mm × Q 10 … 150 kN,
  // 20 × 20; μ 0.3, 30 m/s, yaw 2.4 mrad per mm of t_Y), vertical equilibrium on: each loaded
  // ellipse's Fx, Fy, Mz against FASTSIM solved afresh on its final a, b, N and creepages, within
  // the equilibrium's tolerance: 1e-7 μ N_i (Mz: 1e-7 μ N_i c_i).
  const ContactGeometry& G = testing::manchester_geometry();
  const Material mat = testing::steel();
  MethodOptions mo;
  mo.tangential.mu = 0.3;
  mo.tangential.kin.V = 30;
  mo.tangential.yaw_per_tY = 2.4;
  const double tol = mo.tangential.equilibrium_tolerance;
  double Gs = 0, nu = 0;
  combined_elastic(mat, Gs, nu);
  int rows = 0, extrapolated = 0;
  double worst = 0;
  CaseResult r;
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 20; ++j) {
      const double tY = -6e-3 + 16e-3 * j / 19.0, Q = 10e3 + 140e3 * i / 19.0;
      solve_contact(G, mat, tY, Q, mo, r);
      if (is_failure(r.status) || !r.tangential.solved) continue;
      ++rows;
      bool differs = false;
      for (const LoadedEllipse& L : r.loaded) {
        const TangentialResult t = fastsim(L.t.c, L.s.a, L.s.b, L.s.N, mo.tangential.mu, Gs, nu, mo.tangential.fastsim);
        const double F = mo.tangential.mu * L.s.N, c = std::sqrt(L.s.a * L.s.b);
        const double e = std::max({std::fabs(L.t.Fx - t.Fx) / F, std::fabs(L.t.Fy - t.Fy) / F,
                                   std::fabs(L.t.Mz - t.Mz) / (F * c)});
        INFO("t_Y " << tY << " Q " << Q << " ellipse " << L.ellipse << " error / (mu N) " << e);
        CHECK(e <= tol);
        worst = std::max(worst, e);
        differs = differs || e > 0;
      }
      extrapolated += differs ? 1 : 0;
    }
  }
  INFO("rows " << rows << " extrapolated " << extrapolated << " largest error / (mu N) " << worst);
  CHECK(rows >= 390);
  // The extrapolation is used (rows not bit-identical with a fresh FASTSIM), on most rows.
  CHECK(extrapolated > rows / 2);
}

TEST_CASE("creep extrapolation: refused where the loaded ellipses differ or the step is too long", "[tangential][equilibrium]") {
  // Two anchors of one ellipse at 50 and 40 kN (the secant's |N1 − N0| = 10 kN).
  CaseResult r;
  r.loaded.resize(1);
  LoadedEllipse& L = r.loaded[0];
  L.ellipse = 2;
  L.cos_gamma = 1;
  L.sin_gamma = 0;
  const Creepages cr{2e-4, -1e-4, 0.1};
  auto at = [&](double N) {
    L.s.N = N;
    L.s.a = L.s.b = 6e-3 * std::cbrt(N / 50e3);
    L.t = hertz_loaded(cr, 1.0, N);
    sum_tangential(r, kMu);
  };
  CreepAnchors a0, a1;
  at(50e3);
  a0.take(r);
  at(40e3);
  a1.take(r);
  REQUIRE(a0.n == 1);
  REQUIRE(a1.n == 1);
  const double tol = 1e-7;
  // The longest step the guard allows: ½ k |ΔN| 10 kN = tol (40 kN)².
  const double step = tol * 40e3 * 40e3 / (0.5 * kCreepCurvature * 10e3);
  at(40e3 + 0.9 * step);
  const TangentialResult fresh = L.t;
  CHECK(extrapolate_tangential(r, a0, a1, kMu, tol));
  CHECK(std::fabs(L.t.Fx - fresh.Fx) <= tol * kMu * L.s.N);
  CHECK(std::fabs(L.t.Fy - fresh.Fy) <= tol * kMu * L.s.N);
  at(40e3 + 1.1 * step);
  CHECK_FALSE(extrapolate_tangential(r, a0, a1, kMu, tol));
  at(40e3 + 0.5 * step);
  L.ellipse = 3;  // another ellipse than the anchors'
  CHECK_FALSE(extrapolate_tangential(r, a0, a1, kMu, tol));
}
