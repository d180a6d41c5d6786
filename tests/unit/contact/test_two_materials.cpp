// Wheel and rail of different materials (case file "material": {"wheel": {...}, "rail": {...}};
// Material::E_rail, nu_rail): every method against closed-form Hertz with the two-body modulus
// E*_J = 1 / ((1−ν_w²)/E_w + (1−ν_r²)/E_r) (Johnson, Contact Mechanics, 1985, §4.2;
// tests/support/hertz_reference.hpp). The pair: the circular profiles circ_r50.prw (wheel,
// R_wxx = 50 mm) on circ_r100.prr (rail, R_rxx = 100 mm), exact to 5e−7 mm (tests/data/profiles),
// wheel radius 460 mm: one elliptic contact, a/b ≈ 5.5 at any t_Y. Steel wheel (210 GPa, 0.28) on
// an aluminium rail (70 GPa, 0.33): E*_J = 58.4 GPa against 114 GPa for steel on steel, and the
// rail's ν alone moves E*_J by 2.5 %.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "contact/half_space/half_space_method.hpp"
#include "contact/multi_hertz/multi_hertz.hpp"
#include "contact/strips/strip_method.hpp"
#include "input/case_file.hpp"
#include "jobs/run.hpp"
#include "support/hertz_reference.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kE_w = 210e9, kNu_w = 0.28, kE_r = 70e9, kNu_r = 0.33;

double rel(double x, double ref) { return std::fabs(x / ref - 1.0); }

/// The case file of the pair, materials per body, parsed in memory.
mh::CaseFile case_file() {
  const std::string data = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/profiles/";
  const nlohmann::json j = {
      {"wheel", {{"profile", data + "circ_r50.prw"}, {"nominal_radius_mm", 460}}},
      {"rail", {{"profile", data + "circ_r100.prr"}, {"inclination", "none"}}},
      {"material", {{"wheel", {{"E_GPa", kE_w / 1e9}, {"nu", kNu_w}}}, {"rail", {{"E_GPa", kE_r / 1e9}, {"nu", kNu_r}}}}},
      {"sweep", {{"tY_mm", {0}}, {"Q_kN", {50}}}}};
  return mh::parse_case_json(j, std::string(MHCONTACT_SOURCE_DIR) + "/cases/two-materials.json", true);
}

struct Fixture {
  mh::CaseFile cf;
  mh::PairGeometry pg;
};
const Fixture& pair() {
  static const Fixture f = [] {
    Fixture x;
    x.cf = case_file();
    x.pg = mh::build_pair_geometry(x.cf);
    return x;
  }();
  return f;
}

/// Closed-form Hertz of the case: A = cos γ / (2 r_roll) (R_wyy = r_roll / cos γ, Meusnier), B from
/// the profiles' radii, N = Q / cos γ (one contact), Johnson's two-body E*. γ and r_roll are the
/// geometry's at the contact point (the main candidate of the multi-Hertzian solution).
struct Reference {
  mh::testing::HertzReference h;
  double N = 0, cg = 1;
};
Reference reference(double tY, double Q) {
  const Fixture& F = pair();
  const mh::CaseResult m = mh::solve_multi_hertz(F.pg.geo, F.cf.material, tY, Q);
  REQUIRE(m.loaded.size() == 1);
  Reference r;
  r.cg = std::cos(m.loaded[0].g.gamma);
  r.N = Q / r.cg;
  const double A = r.cg / (2 * m.loaded[0].g.r_roll), B = 0.5 * (1 / 0.050 + 1 / 0.100);
  r.h = mh::testing::hertz_reference(A, B, r.N, mh::testing::johnson_modulus(kE_w, kNu_w, kE_r, kNu_r));
  return r;
}

}  // namespace

TEST_CASE("two materials: material.wheel and material.rail reach Material, E_star is twice Johnson's E*",
          "[two_materials][input]") {
  const mh::Material& m = pair().cf.material;
  CHECK(m.E == kE_w);
  CHECK(m.nu == kNu_w);
  CHECK(m.E_rail == kE_r);
  CHECK(m.nu_rail == kNu_r);
  // options.hpp: E_star() is the paper's E/(1−ν²), 2 E*_J; compliance() = 1/(π E*_J).
  const double EJ = mh::testing::johnson_modulus(kE_w, kNu_w, kE_r, kNu_r);
  CHECK(rel(m.E_star(), 2 * EJ) <= 1e-15);
  CHECK(rel(m.compliance(), 1 / (kPi * EJ)) <= 1e-15);
}

TEST_CASE("two materials, multi-Hertzian: closed-form Hertz with the two-body modulus", "[two_materials][solver]") {
  // Tolerance 1e-4 relative on a, b, p0 and the approach: measured at most 1.4e-5 (the curvatures
  // the geometry fits to the profile points, as for steel on steel).
  const Fixture& F = pair();
  for (double tY : {-5e-3, 0.0, 5e-3}) {
    for (double Q : {20e3, 100e3}) {
      CAPTURE(tY, Q);
      const mh::CaseResult r = mh::solve_multi_hertz(F.pg.geo, F.cf.material, tY, Q);
      REQUIRE(r.status == mh::CaseStatus::Ok);
      REQUIRE(r.loaded.size() == 1);
      const Reference ref = reference(tY, Q);
      const mh::EllipseState& s = r.loaded[0].s;
      CHECK(rel(s.N, ref.N) <= 1e-9);
      CHECK(rel(s.a, ref.h.a) <= 1e-4);
      CHECK(rel(s.b, ref.h.b) <= 1e-4);
      CHECK(rel(s.p0, ref.h.p0) <= 1e-4);
      CHECK(rel(s.approach, ref.h.delta) <= 1e-4);
      // The two-body modulus is symmetric: wheel and rail materials swapped give the same bytes.
      mh::Material swapped = F.cf.material;
      std::swap(swapped.E, swapped.E_rail);
      std::swap(swapped.nu, swapped.nu_rail);
      const mh::CaseResult t = mh::solve_multi_hertz(F.pg.geo, swapped, tY, Q);
      REQUIRE(t.loaded.size() == 1);
      CHECK(t.loaded[0].s.a == s.a);
      CHECK(t.loaded[0].s.p0 == s.p0);
    }
  }
}

TEST_CASE("two materials, half-space: closed-form Hertz with the two-body modulus", "[two_materials][half_space]") {
  // dx = ds = 0.2 mm (6 to 11 elements across the minor semi-axis b = 1.25 to 2.1 mm). Tolerances:
  // pmax 2e-3 relative (measured at most 4e-4), approach 1.5e-3 (measured at most 3e-4), area
  // (elements in contact) 10 % (measured +1.2 to +4.4 %: the element count of a coarse grid),
  // vertical force 1e-6. A rail ν taken as the wheel's moves pmax by 1.7 %.
  const Fixture& F = pair();
  for (double tY : {-5e-3, 0.0, 5e-3}) {
    for (double Q : {20e3, 100e3}) {
      CAPTURE(tY, Q);
      const mh::CaseResult r = mh::solve_half_space(F.pg.geo, F.cf.material, tY, Q, F.cf.half_space);
      REQUIRE(r.status == mh::CaseStatus::Ok);
      REQUIRE(r.patches.size() == 1);
      const Reference ref = reference(tY, Q);
      CHECK(rel(r.pmax, ref.h.p0) <= 2e-3);
      CHECK(rel(r.approach, ref.h.delta / ref.cg) <= 1.5e-3);  // vertical approach of a single contact: δ / cos γ
      CHECK(rel(r.area, kPi * ref.h.a * ref.h.b) <= 0.10);
      CHECK(rel(r.Fz, Q) <= 1e-6);
    }
  }
}

TEST_CASE("two materials, strips: closed-form Hertz with the two-body modulus", "[two_materials][strips]") {
  // 0.2 mm strips. Tolerances: pmax 5e-3 relative (measured at most 1.5e-3), approach 1e-3
  // (measured at most 2e-4), area 3 % (measured at most 1.0 %), vertical force 1e-6.
  const Fixture& F = pair();
  for (double tY : {-5e-3, 0.0, 5e-3}) {
    for (double Q : {20e3, 100e3}) {
      CAPTURE(tY, Q);
      const mh::CaseResult r = mh::solve_strip_method(F.pg.geo, F.cf.material, tY, Q, F.cf.strips);
      REQUIRE(r.status == mh::CaseStatus::Ok);
      REQUIRE(r.patches.size() == 1);
      const Reference ref = reference(tY, Q);
      CHECK(rel(r.pmax, ref.h.p0) <= 5e-3);
      CHECK(rel(r.approach, ref.h.delta / ref.cg) <= 1e-3);
      CHECK(rel(r.area, kPi * ref.h.a * ref.h.b) <= 0.03);
      CHECK(rel(r.Fz, Q) <= 1e-6);
    }
  }
}
