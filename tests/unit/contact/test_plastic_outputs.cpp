// Plastic outputs say what they mean: the elastic peak at the same load, the
// actual maximum, the elastic and plastic patches side by side. References are independent: an
// elastic law (p_lim = INFINITY) loaded with the same N.
#include <catch2/catch.hpp>
#include <cmath>

#include "contact/ellipse/ellipse_law.hpp"
#include "output/case_tables.hpp"

using namespace mh;

TEST_CASE("plastic state: p0_el, p_max and the elastic patch are those of the elastic law at the same N",
          "[plastic]") {
  Material el;
  Material pl;
  pl.p_lim = 900e6;
  const double A = 1.0875, B = 38.0;  // a flange-like ellipse [1/m]
  const EllipseLaw Le = make_ellipse_law(A, B, el, true), Lp = make_ellipse_law(A, B, pl, true);
  for (double N : {5e3, 50e3, 200e3}) {
    const EllipseState sp = ellipse_state_for_force(Lp, N), se = ellipse_state_for_force(Le, N);
    CAPTURE(N, sp.p0, se.p0);
    REQUIRE(sp.N == Approx(N).epsilon(1e-12));
    REQUIRE(sp.p0_el == Approx(se.p0).epsilon(1e-12));        // elastic peak at the same load
    REQUIRE(se.p0_el == Approx(se.p0).epsilon(1e-12));
    REQUIRE(sp.a_el == Approx(se.a).epsilon(1e-12));
    REQUIRE(sp.b_el == Approx(se.b).epsilon(1e-12));
    REQUIRE(sp.p_max == Approx(std::min(sp.p0, pl.p_lim)).epsilon(1e-15));
    if (se.p0 > pl.p_lim) {
      REQUIRE(sp.plastic);
      REQUIRE(sp.p0 > sp.p0_el);         // the uncapped peak of the enlarged patch exceeds it
      REQUIRE(sp.p_max == pl.p_lim);
      REQUIRE(sp.a * sp.b > se.a * se.b);
    } else {
      REQUIRE(sp.p0 == Approx(se.p0).epsilon(1e-12));
    }
  }
}

TEST_CASE("plastic ellipses table appends p0_el_MPa, pmax_MPa, area_mm2, area_el_mm2", "[plastic]") {
  const std::string h = ellipses_csv_header(true);
  REQUIRE(h.find(",area_ratio,hertz_valid,b_over_R,gap_error,gap_mean_error,p0_el_MPa,pmax_MPa,area_mm2,area_el_mm2\n") !=
          std::string::npos);
  REQUIRE(ellipses_csv_header(false).find("p0_el_MPa") == std::string::npos);
}
