// The strip method's tangential problem (docs/tangential.md, "Strips"): each strip patch's
// pressure laid on a grid of its strip width and solved by the exact steady-rolling solver.
// Closed form: in full sliding every element slips at μ p, so |F| = μ N on every patch. Against
// the half-space method on the same cases (Manchester pair, CONTACT's tread creepages
// of tests/data/contact_tangential/mbench_a22_right.csv, in our signs, and one in partial slip):
// the two methods' normal pressures differ (strips: a semi-ellipse per strip), so the forces are
// held to the target for a method against the exact one, 2 % of μN (measured 0.67 %),
// Mz to 2 % of μ N c (0.22 %), the adhesion fraction to 0.05.
// Break seen to fail: a uniform pressure along each strip instead of its semi-ellipse (Fy 4.2 %
// of μN and Mz 4.6 % of μ N c off in partial slip). (Dropping the raster's scaling to N was not
// seen: the raster carries N within 0.1 % already.)
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/solve.hpp"
#include "manchester_fixture.hpp"

using namespace mh;

TEST_CASE("strips: full sliding on a wheel-rail patch gives |F| = mu N", "[tangential][strips]") {
  const ContactGeometry& G = testing::manchester_geometry();
  MethodOptions mo;
  mo.method = Method::Strips;
  mo.tangential.mu = 0.3;
  mo.tangential.source = TangentialOptions::Source::Creepages;
  mo.tangential.creep = {0.05, 0.0, 0.0};
  for (double tY : {0.0, 3e-3}) {
    INFO("t_Y = " << tY);
    const CaseResult r = solve_contact(G, testing::steel(), tY, 80e3, mo);
    REQUIRE(!r.patches.empty());
    REQUIRE(r.tangential.solved);
    for (const Warning& w : r.warnings) CHECK(w.cls != WarningClass::TangentialUnsupported);
    for (const PatchResult& P : r.patches) {
      REQUIRE(P.t.solved);
      CHECK(std::hypot(P.t.Fx, P.t.Fy) == Approx(0.3 * P.N).epsilon(1e-3));
      CHECK(P.t.Fx < 0);
      CHECK(P.t.adhesion_fraction == Approx(0).margin(1e-12));
    }
  }
}

TEST_CASE("strips against the half-space method: creep forces of the A-2.2 tread cases", "[tangential][strips][half_space]") {
  const ContactGeometry& G = testing::manchester_geometry();
  const double Q = 10e3, mu = 0.3;
  // t_Y [m], ξ, η, φ [1/m]: cases 1, 2, 5 and 9 (CONTACT's creepages negated; case 1 in
  // partial slip, 73 % adhesion, the others near or in full slip), and case 5 with ξ and η a
  // tenth (partial slip: there the pressure's shape matters).
  const double cases[][4] = {{0.0, 5.665e-5, 0.0, -0.06302},
                             {0.5e-3, -4.948e-4, -1.202e-3, -0.1233},
                             {2.0e-3, -8.752e-4, -4.818e-3, -0.1746},
                             {2.0e-3, -8.752e-5, -4.818e-4, -0.1746},
                             {4.0e-3, -1.276e-3, -9.662e-3, -0.2330}};
  double worst_F = 0, worst_M = 0;
  for (const auto& c : cases) {
    INFO("t_Y " << c[0]);
    MethodOptions mo;
    mo.tangential.mu = mu;
    mo.tangential.source = TangentialOptions::Source::Creepages;
    mo.tangential.creep = {c[1], c[2], c[3]};
    mo.method = Method::Strips;
    const CaseResult s = solve_contact(G, testing::steel(), c[0], Q, mo);
    mo.method = Method::HalfSpace;
    const CaseResult h = solve_contact(G, testing::steel(), c[0], Q, mo);
    REQUIRE(s.patches.size() == 1);
    REQUIRE(h.patches.size() == 1);
    const PatchResult &S = s.patches[0], &H = h.patches[0];
    REQUIRE(S.t.solved);
    REQUIRE(H.t.solved);
    const double muN = mu * H.N, cc = 0.5 * std::sqrt(H.length_x * H.width_s);
    INFO("adhesion " << S.t.adhesion_fraction << " vs " << H.t.adhesion_fraction << " Fx " << S.t.Fx << " vs " << H.t.Fx << " Fy " << S.t.Fy << " vs " << H.t.Fy << " Mz " << S.t.Mz << " vs " << H.t.Mz);
    CHECK(std::abs(S.t.Fx - H.t.Fx) < 0.02 * muN);
    CHECK(std::abs(S.t.Fy - H.t.Fy) < 0.02 * muN);
    CHECK(std::abs(S.t.Mz - H.t.Mz) < 0.02 * muN * cc);
    CHECK(std::abs(S.t.adhesion_fraction - H.t.adhesion_fraction) < 0.05);
    // The vertical equilibrium holds for the strips too.
    CHECK(s.Fz == Approx(Q).epsilon(1e-6));
    worst_F = std::max({worst_F, std::abs(S.t.Fx - H.t.Fx) / muN, std::abs(S.t.Fy - H.t.Fy) / muN});
    worst_M = std::max(worst_M, std::abs(S.t.Mz - H.t.Mz) / (muN * cc));
  }
  WARN("strips vs half-space: |dF|/muN " << worst_F << ", |dMz|/(muN c) " << worst_M);
}
