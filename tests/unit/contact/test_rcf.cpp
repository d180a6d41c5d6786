// RCF indicators (contact/rcf/shakedown.hpp; docs/methods.md "RCF indicators"). Reference values by
// hand from the formulas, on the worked example of method.md §5 (E = 210 GPa, ν = 0.3,
// N = 100 kN: a = 7.162 mm, b = 5.387 mm):
//   p0 = 3N/(2π a b) = 1.5 × 100e3 / (π × 7.162e-3 × 5.387e-3) = 1237.54 MPa, e = b/a = 0.75216
//   first yield (ν = 0.3) 3.106727 + (2.793446 − 3.106727) e = 2.871088, elastic shakedown
//   4.0 + 0.7 e = 4.52651 (frictionless); 3.106727 and 2.793446 are √3 over the largest von Mises
//   stress of the closed forms (McEwen's line contact, Johnson eq. 3.45 on the circle's axis),
//   maximised on a grid of 1e-5 in z/a by a script independent of the library
//   (/usr/bin/python3, numpy; the values 0.5575162 at 0.7043 b and 0.6200410 at 0.4809 a)
//   f = 0.3, k = 300 MPa: p0/k = 4.12514 > 1/f = 3.3333; FI_surf = 0.3 − 300/1237.54 = +0.057584 → ratchetting
//   f = 0.2, k = 300 MPa: 2.871088 < 4.12514 ≤ min(4.52651, 5); FI_surf = −0.042416 → elastic shakedown
//   f = 0.1, k = 250 MPa: p0/k = 4.95017 > 4.52651; FI_surf = 0.1 − 250/1237.54 = −0.102013 → plastic shakedown
//   f = 0.3, k = 500 MPa: p0/k = 2.47508 < 2.871088; FI_surf = −0.104027 → elastic
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/rcf/shakedown.hpp"

using namespace mh;

TEST_CASE("RCF: shakedown map point and surface fatigue index by hand", "[rcf]") {
  const double a = 7.162e-3, b = 5.387e-3, N = 100e3;
  struct Row { double f, k, p0k, fi; ShakedownRegime reg; };
  const Row rows[] = {
      {0.3, 300e6, 4.12514, 0.057584, ShakedownRegime::Ratchetting},
      {0.2, 300e6, 4.12514, -0.042416, ShakedownRegime::ElasticShakedown},
      {0.1, 250e6, 4.95017, -0.102013, ShakedownRegime::PlasticShakedown},
      {0.3, 500e6, 2.47508, -0.104027, ShakedownRegime::Elastic},
  };
  for (const Row& w : rows) {
    CAPTURE(w.f, w.k);
    const RcfPoint p = rcf_point(w.f, w.k, N, a, b);
    CHECK(std::fabs(p.p0_el_over_k / w.p0k - 1) < 1e-5);
    CHECK(std::fabs(p.fi_surf_el - w.fi) < 1e-6);
    CHECK(p.regime == w.reg);
  }
  const RcfPoint p = rcf_point(0.2, 300e6, N, a, b);
  CHECK(std::fabs(p.elastic_limit - 2.871088) < 1e-5);
  // The two ends at ν = 0.3, and ν's effect (0.28: 3.061844 and 2.752373, the same script).
  CHECK(std::fabs(frictionless_elastic_limit(0.0) - 3.106727) < 1e-5);
  CHECK(std::fabs(frictionless_elastic_limit(1.0) - 2.793446) < 1e-5);
  CHECK(std::fabs(frictionless_elastic_limit(0.0, 0.28) - 3.061844) < 1e-5);
  CHECK(std::fabs(frictionless_elastic_limit(1.0, 0.28) - 2.752373) < 1e-5);
  CHECK(std::fabs(p.shakedown_limit - 4.52651) < 1e-5);
  // The surface limit caps both at high traction: f = 0.5 gives 1/f = 2.
  const RcfPoint q = rcf_point(0.5, 300e6, N, a, b);
  CHECK(q.shakedown_limit == 2.0);
  CHECK(q.elastic_limit == 2.0);
}

TEST_CASE("RCF: k from the user, else from the material's yield (NaN until Material has one)", "[rcf]") {
  Material m;
  RcfOptions o;
  o.f = 0.3;
  CHECK(std::isnan(rcf_shear_yield(m, o)));
  o.k = 300e6;
  CHECK(rcf_shear_yield(m, o) == 300e6);
  CHECK(std::isnan(rcf_point(0.3, NAN, 100e3, 1e-3, 1e-3).fi_surf_el));
}
