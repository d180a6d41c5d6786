// Damage and wear of a case's contacts, computed once per case into its result
// (contact/rcf/contact_damage.hpp): each contact's values from damage.hpp's functions over its
// area as solved, a plastic ellipse's wear over its plastic patch π a b (not π a_el b_el), and the
// case sums. References by hand from the functions' published constants (docs/methods.md).
// Breaks seen to fail: wear_area() returning π a_el b_el (the plastic row), the sums left NaN.
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/rcf/contact_damage.hpp"

using namespace mh;

namespace {

TangentialResult solved(double Tgamma, double Fx, double Fy) {
  TangentialResult t;
  t.solved = true;
  t.Tgamma = Tgamma, t.Fx = Fx, t.Fy = Fy;
  return t;
}

}  // namespace

TEST_CASE("Contact damage: per contact and per case, a plastic ellipse over its plastic patch", "[rcf][damage]") {
  CaseResult r;
  r.tangential.asked = r.tangential.solved = true;
  LoadedEllipse el;  // elastic: a = a_el
  el.s.N = 60e3, el.s.a = el.s.a_el = 6e-3, el.s.b = el.s.b_el = 4e-3;
  el.t = solved(40, 3e3, 4e3);  // Tγ 40 J/m: rising branch, 1e-5 (40 − 15)/50 = 5e-6
  LoadedEllipse pl;  // plastic: the patch larger than the elastic ellipse
  pl.s.N = 100e3, pl.s.a = 5e-3, pl.s.b = 3e-3, pl.s.a_el = 4e-3, pl.s.b_el = 2.5e-3, pl.s.plastic = true;
  pl.t = solved(120, 0, 20e3);  // falling branch: 1e-5 (175 − 120)/110 = 5e-6
  r.loaded = {el, pl};
  damage_step(r);
  const double A1 = M_PI * 6e-3 * 4e-3, A2 = M_PI * 5e-3 * 3e-3;  // [m²]
  const ContactDamage& d1 = r.loaded[0].damage;
  const ContactDamage& d2 = r.loaded[1].damage;
  CHECK(d1.traction == Approx(5e3 / 60e3).epsilon(1e-14));
  CHECK(d1.damage == Approx(5e-6).epsilon(1e-12));
  CHECK(d2.damage == Approx(5e-6).epsilon(1e-12));
  // Mild wear: 5.3 µg/(m·mm²) per N/mm² of Tγ/A; the mass per metre 5.3 Tγ [µg/m] whatever A.
  const double x2 = 120 / (A2 * 1e6);  // [N/mm²] over the plastic patch
  CHECK(d2.wear_rate == Approx(5.3 * x2 * 1e-3).epsilon(1e-12));  // [kg/m³]
  CHECK(d2.wear_per_metre == Approx(5.3 * x2 * A2 * 1e6 * 1e-9).epsilon(1e-12));  // [kg/m]
  CHECK(d1.wear_per_metre == Approx(5.3 * 40 * 1e-9).epsilon(1e-12));
  CHECK(wear_area(r.loaded[0]) == Approx(A1).epsilon(1e-15));
  CHECK(r.damage.damage == Approx(1e-5).epsilon(1e-12));
  CHECK(r.damage.wear_per_metre == Approx(d1.wear_per_metre + d2.wear_per_metre).epsilon(1e-15));
  // A case whose tangential problem is not solved everywhere: contacts filled, no sums.
  r.tangential.solved = false;
  damage_step(r);
  CHECK(std::isnan(r.damage.damage));
  CHECK(r.loaded[0].damage.damage == Approx(5e-6).epsilon(1e-12));
  // Not asked (no friction): nothing.
  CaseResult none;
  damage_step(none);
  CHECK(std::isnan(none.damage.wear_per_metre));
}
