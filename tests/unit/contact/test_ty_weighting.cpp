// The damage and wear over t_Y weighted by a normal distribution of t_Y
// (contact/rcf/ty_weighting.hpp; docs/outputs.md "Damage and wear over t_Y"), against the
// trapezoid weights computed by hand on a 3-point sweep.
// Broken once to see it fail: the end nodes given a full interval (t_i ± half the spacing to
// their one neighbour) instead of the half one.
#include <catch2/catch.hpp>

#include <cmath>
#include <utility>
#include <vector>

#include "contact/rcf/ty_weighting.hpp"

using namespace mh;

TEST_CASE("t_Y weighting: trapezoid weights of a normal density on 3 points, by hand", "[rcf][damage]") {
  // t_Y = 0, 2, 6 mm, N(2 mm, 2 mm): node 0 stands for [0, 1] (width 1, density e^(−1/2)),
  // node 1 for [1, 4] (width 3, density 1), node 2 for [4, 6] (width 2, density e^(−2)).
  const double w0 = std::exp(-0.5), w1 = 3, w2 = 2 * std::exp(-2.0), S = w0 + w1 + w2;
  const std::vector<double> w = normal_trapezoid_weights({0, 2, 6}, 2, 2);
  REQUIRE(w.size() == 3);
  CHECK(w[0] == Approx(w0 / S).epsilon(1e-14));
  CHECK(w[1] == Approx(w1 / S).epsilon(1e-14));
  CHECK(w[2] == Approx(w2 / S).epsilon(1e-14));
  // Damage 1e-6, 4e-6, 0 per axle at those t_Y, in any order.
  const double D = ty_weighted({{6, 0.0}, {0, 1e-6}, {2, 4e-6}}, 2, 2);
  CHECK(D == Approx((w0 * 1e-6 + w1 * 4e-6) / S).epsilon(1e-14));
  // Two cases at one t_Y count as their mean; one t_Y alone has weight 1; none gives NaN.
  CHECK(ty_weighted({{0, 1.0}, {2, 3.0}, {2, 5.0}, {6, 0.0}}, 2, 2) == Approx((w0 * 1 + w1 * 4) / S).epsilon(1e-14));
  CHECK(ty_weighted({{3, 7.0}}, 0, 1) == 7.0);
  CHECK(std::isnan(ty_weighted({}, 0, 1)));
}
