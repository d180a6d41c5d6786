// FASTSIM's load slope (contact/tangential/fastsim.hpp, FastsimOptions::load_slope): dF/dN at
// fixed creepages of a Hertz-loaded ellipse (a, b ∝ N^(1/3)), from Kalker's similarity and the
// derivative marched beside the tractions, against central differences of FASTSIM itself at
// N ± h with the ellipse scaled as Hertz scales it (an independent evaluation: two plain solves).
// The vertical equilibrium's first step aims with it (contact/solve.cpp, equilibrium_slope).
// Breaks guarded (each seen to fail):
//  - the slip cells' derivative without the projection term (dp scaled only): "against central
//    differences" (partial and full slip rows);
//  - the similarity's 1/3 replaced by 1/2: "against central differences" (every row);
//  - the tangent's increment with the spin's gradient (gxy instead of gx): "against central
//    differences" (the rows with spin).
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/tangential/fastsim.hpp"

using namespace mh;

namespace {
constexpr double G = 82e9, nu = 0.28, mu = 0.3;

// FASTSIM on the ellipse of aspect a/b loaded by N as Hertz loads it: c = √(ab) = c0 (N/N0)^(1/3).
TangentialResult solve(const Creepages& cr, double aob, double N, bool slope, int n = 16) {
  const double N0 = 50e3, c0 = 6e-3;
  const double c = c0 * std::cbrt(N / N0);
  FastsimOptions o;
  o.nx = o.ny = n;
  o.load_slope = slope;
  return fastsim(cr, c * std::sqrt(aob), c / std::sqrt(aob), N, mu, G, nu, o);
}
}  // namespace

TEST_CASE("FASTSIM load slope: against central differences of FASTSIM in the Hertz-scaled load",
          "[tangential][fastsim]") {
  // Creepages from the linear limit to full slip, with and without spin, three aspects.
  struct Row { Creepages c; double aob; };
  const Row rows[] = {
      {{1e-5, 0, 0}, 1.0},          {{0, -1e-5, 0}, 1.0},          {{2e-4, -1e-4, 0}, 0.5},
      {{1e-3, 5e-4, 0}, 2.0},       {{0, -6.25e-4, 0.625}, 2.0},   {{5e-4, -3e-4, 1.5}, 1.0},
      {{-2e-3, 1e-3, -0.8}, 3.0},   {{1e-2, 0, 0}, 1.0},           {{0, 0, 3.0}, 0.5},
  };
  const double N = 50e3;
  for (const Row& r : rows) {
    const TangentialResult t = solve(r.c, r.aob, N, true);
    // The central difference; its error (the march's cells switching between adhesion and slip
    // within ±h, and h²) is below 3e-4 μ here, measured by halving h: the tolerance 1e-3 μ.
    const double h = 1e-3 * N;
    const TangentialResult p = solve(r.c, r.aob, N + h, false), m = solve(r.c, r.aob, N - h, false);
    const double dFx = (p.Fx - m.Fx) / (2 * h), dFy = (p.Fy - m.Fy) / (2 * h);
    INFO("xi " << r.c.xi << " eta " << r.c.eta << " phi " << r.c.phi << " a/b " << r.aob << " dFx/dN " << t.dFx_dN
               << " fd " << dFx << " dFy/dN " << t.dFy_dN << " fd " << dFy << " adhesion " << t.adhesion_fraction);
    CHECK(std::fabs(t.dFx_dN - dFx) < 1e-3 * mu);
    CHECK(std::fabs(t.dFy_dN - dFy) < 1e-3 * mu);
  }
}

TEST_CASE("FASTSIM load slope: the forces are the same bit for bit with or without it, NaN without",
          "[tangential][fastsim]") {
  for (int n : {8, 16, 32}) {
    const Creepages c{5e-4, -3e-4, 1.5};
    const TangentialResult a = solve(c, 1.5, 40e3, false, n), b = solve(c, 1.5, 40e3, true, n);
    CHECK(a.Fx == b.Fx);
    CHECK(a.Fy == b.Fy);
    CHECK(a.Mz == b.Mz);
    CHECK(a.adhesion_fraction == b.adhesion_fraction);
    CHECK(std::isnan(a.dFx_dN));
    CHECK(std::isfinite(b.dFx_dN));
  }
}
