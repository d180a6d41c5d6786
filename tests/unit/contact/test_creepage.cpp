// Creepages from the wheelset's motion (contact/tangential/creepage.hpp, docs/method.md §10)
// against the closed forms of rigid-body kinematics, and the whole chain on the Manchester pair:
// a centred wheelset rolling at its nominal radius has the spin of its contact angle alone, which
// gives a lateral creep force; a yawed wheelset has η ≈ −ψ.
// Breaks seen to fail: the spin's sign flipped in creepages_from_kinematics() ("pure rolling"
// fails); the cos γ of η dropped ("lateral velocity on a slope" fails); Y without the creep
// forces in y_over_q() ("Y includes the creep forces" fails).
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/judge/judge.hpp"
#include "contact/solve.hpp"
#include "contact/tangential/creepage.hpp"
#include "contact/tangential/kalker.hpp"
#include "contact/tangential/tangential_solve.hpp"
#include "manchester_fixture.hpp"

using namespace mh;

TEST_CASE("creepages: closed forms of rigid-body kinematics", "[tangential][creepage]") {
  const double r0 = 0.46, V = 30;
  Kinematics k;
  k.V = V;
  SECTION("pure rolling at the nominal radius: spin of the contact angle alone") {
    for (double g : {0.0, 0.05, 0.6, 1.1}) {
      const Creepages c = creepages_from_kinematics(k, {r0, g, 0.75}, r0);
      CHECK(std::abs(c.xi) < 1e-15);  // 1 − (V/r0) r0 / V: rounding only
      CHECK(c.eta == 0);
      CHECK(c.phi == Approx(-std::sin(g) / r0).margin(1e-15));
    }
  }
  SECTION("a rolling radius 1e-3 larger than the nominal: xi = -1e-3 to 1e-12") {
    const Creepages c = creepages_from_kinematics(k, {r0 * 1.001, 0.0, 0.75}, r0);
    CHECK(std::abs(c.xi + 1e-3) < 1e-12);
  }
  SECTION("yaw: eta = -psi (flat contact), yaw rate: xi = -psi_dot l / V") {
    k.yaw = 2e-3;
    CHECK(creepages_from_kinematics(k, {r0, 0.0, 0.75}, r0).eta == Approx(-2e-3).epsilon(1e-12));
    k.yaw = 0;
    k.yaw_rate = 0.1;
    const Creepages c = creepages_from_kinematics(k, {r0, 0.3, 0.75}, r0);
    CHECK(c.xi == Approx(-0.1 * 0.75 / V).epsilon(1e-12));
    CHECK(c.phi == Approx((0.1 * std::cos(0.3) - V / r0 * std::sin(0.3)) / V).epsilon(1e-12));
  }
  SECTION("lateral velocity on a slope: eta = y_dot / (V cos gamma)") {
    k.lateral_velocity = 0.03;
    CHECK(creepages_from_kinematics(k, {r0, 0.5, 0.75}, r0).eta == Approx(1e-3 / std::cos(0.5)).epsilon(1e-12));
  }
  SECTION("pitch rate given") {
    k.pitch_rate = V / r0 * (1 + 2e-3);
    CHECK(creepages_from_kinematics(k, {r0, 0.0, 0.75}, r0).xi == Approx(-2e-3).epsilon(1e-9));
  }
}

TEST_CASE("centred wheelset on the Manchester pair: spin alone gives a lateral creep force", "[tangential][creepage]") {
  const ContactGeometry& G = testing::manchester_geometry();
  MethodOptions mo;
  // Rolling at the main contact's own radius (pitch rate V / r): no longitudinal creepage there,
  // so the lateral force comes from the spin alone.
  // t_Y = −3 mm: one contact on the tread (t_Y = 0 has two, near a jump of the contact angle).
  const double tY = -3e-3;
  const CaseResult n = solve_contact(G, testing::steel(), tY, 80e3, mo);
  REQUIRE(n.loaded.size() == 1);
  const double r0 = n.loaded[0].g.r_roll;
  mo.tangential.mu = 0.3;
  mo.tangential.kin.V = 30;
  mo.tangential.r0 = r0;
  const CaseResult r = solve_contact(G, testing::steel(), tY, 80e3, mo);
  REQUIRE(r.status == CaseStatus::Ok);
  REQUIRE(r.tangential.solved);
  double Gc = 0, nu = 0;
  combined_elastic(testing::steel(), Gc, nu);
  for (const LoadedEllipse& L : r.loaded) {
    const double gam = L.g.gamma, rr = L.g.r_roll;
    INFO("gamma " << gam << " r_roll " << rr);
    CHECK(L.t.c.phi == Approx(-std::sin(gam) / r0).epsilon(1e-12));
    CHECK(std::abs(L.t.c.xi) < 1e-15);
    CHECK(rr == r0);
    CHECK(L.t.c.eta == 0);
    // Small spin (about a tenth of the saturating one): the lateral force is linear theory's
    // −G c³ C23 φ (FASTSIM's linear limit) up to partial slip: within 5 % here.
    const double c = std::sqrt(L.s.a * L.s.b);
    const KalkerCoefficients k = kalker_coefficients(L.s.a / L.s.b, nu);
    const double Fy_lin = -Gc * c * c * c * k.C23 * L.t.c.phi;
    CHECK(L.t.Fy == Approx(Fy_lin).epsilon(0.05));
    CHECK(L.t.Fy * gam > 0);  // towards the field side for a contact angle towards the gauge side
  }
  // Y includes the creep forces' lateral component (on the rail: −Fy cos γ).
  CHECK(y_over_q(r) == Approx((r.Fy + r.tangential.Fy_creep) / r.Fz).epsilon(1e-14));
  CHECK(r.tangential.Fy_creep != 0);
}

TEST_CASE("yawed wheelset on the Manchester pair: eta = -psi / cos gamma", "[tangential][creepage]") {
  const ContactGeometry& G = testing::manchester_geometry();
  MethodOptions mo;
  mo.tangential.mu = 0.3;
  mo.tangential.kin.V = 30;
  mo.tangential.kin.yaw = 3e-3;
  mo.tangential.r0 = 0.46;
  const CaseResult r = solve_contact(G, testing::steel(), 0.0, 80e3, mo);
  REQUIRE(!r.loaded.empty());
  for (const LoadedEllipse& L : r.loaded) {
    CHECK(L.t.c.eta == Approx(-3e-3 * L.g.r_roll / 0.46 / std::cos(L.g.gamma)).epsilon(1e-12));
    CHECK(L.t.c.eta == Approx(-3e-3).epsilon(0.01));
    CHECK(L.t.Fy > 0);  // η < 0: the force on the wheel along +s
  }
}

TEST_CASE("grid methods: creepages given, forces not solved, tangential_unsupported", "[tangential][judge]") {
  // The exact tangential solver of the grid methods needs bodies of equal elastic constants: a
  // rail of another modulus leaves the forces unsolved, and the row says so.
  const ContactGeometry& G = testing::manchester_geometry();
  MethodOptions mo;
  mo.method = Method::Strips;
  mo.tangential.mu = 0.3;
  mo.tangential.kin.V = 30;
  Material two = testing::steel();
  two.E_rail = 180e9;
  const CaseResult r = solve_contact(G, two, 0.0, 80e3, mo);
  REQUIRE(!r.patches.empty());
  CHECK_FALSE(r.tangential.solved);
  CHECK(r.status != CaseStatus::Ok);
  bool found = false;
  for (const Warning& w : r.warnings) found = found || w.cls == WarningClass::TangentialUnsupported;
  CHECK(found);
  for (const PatchResult& P : r.patches) CHECK_FALSE(P.t.solved);
  // Without friction nothing of this: the row as before.
  mo.tangential.mu = NAN;
  const CaseResult r0 = solve_contact(G, two, 0.0, 80e3, mo);
  for (const Warning& w : r0.warnings) CHECK(w.cls != WarningClass::TangentialUnsupported);
}

TEST_CASE("half-space rows: each patch solved exactly, full sliding on a wheel-rail patch gives |F| = mu N", "[tangential][half_space]") {
  // Closed form (issue 33 §4): at a creepage far beyond saturation every element slips at the
  // bound μ p, so |F| = μ N on every patch, whatever its shape. Manchester pair, t_Y 0 and 3 mm.
  const ContactGeometry& G = testing::manchester_geometry();
  MethodOptions mo;
  mo.method = Method::HalfSpace;
  mo.tangential.mu = 0.3;
  mo.tangential.source = TangentialOptions::Source::Creepages;
  mo.tangential.creep = {0.05, 0.0, 0.0};
  for (double tY : {0.0, 3e-3}) {
    INFO("t_Y = " << tY);
    const CaseResult r = solve_contact(G, testing::steel(), tY, 80e3, mo);
    REQUIRE(!r.patches.empty());
    REQUIRE(r.tangential.solved);
    for (const Warning& w : r.warnings) CHECK(w.cls != WarningClass::TangentialUnsupported);
    double N = 0;
    for (const PatchResult& P : r.patches) {
      REQUIRE(P.t.solved);
      CHECK(std::hypot(P.t.Fx, P.t.Fy) == Approx(0.3 * P.N).epsilon(1e-3));
      CHECK(P.t.Fx < 0);  // ξ > 0: the force on the wheel along −x (tangential_types.hpp)
      CHECK(P.t.adhesion_fraction == Approx(0).margin(1e-12));
      N += P.N;
    }
    CHECK(r.tangential.F_over_muN == Approx(1).epsilon(1e-3));
    CHECK(r.tangential.Fx == Approx(0.3 * N).epsilon(1e-3));  // the sum, on the rail: along +x
  }
  // Small creepage: partly in adhesion, |F| < μN.
  mo.tangential.creep = {2e-4, 0.0, 0.0};
  const CaseResult s = solve_contact(G, testing::steel(), 3e-3, 80e3, mo);
  REQUIRE(s.tangential.solved);
  CHECK(s.tangential.F_over_muN < 0.9);
  CHECK(s.patches.front().t.adhesion_fraction > 0.1);
}
