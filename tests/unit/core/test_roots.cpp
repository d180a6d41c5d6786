// The root finders of core/roots.hpp. Each block names its reference and tolerance.
#include <catch2/catch.hpp>

#include <cfloat>
#include <cmath>
#include <utility>

#include "core/roots.hpp"

using namespace mh;

TEST_CASE("newton_polish: Newton steps from a close guess reach the root to an ulp, clamped to the bracket", "[roots]") {
  // f(x) = x³ − 2, increasing and convex for x > 0; reference: std::cbrt(2) (correctly rounded
  // within 1 ulp by glibc). From a guess 1e-3 above or below the root Newton's error squares each
  // step (1e-3 → 1e-6 → 1e-12 → ε): converged within 5 evaluations, x within 2 ulps.
  auto f = [](double x) { return std::pair<double, double>(x * x * x - 2.0, 3.0 * x * x); };
  const double root = std::cbrt(2.0);
  for (double guess : {root * (1 + 1e-3), root * (1 - 1e-3), root}) {
    CAPTURE(guess);
    const RootResult r = newton_polish(f, guess, 1.0, 2.0);
    CHECK(r.converged);
    CHECK(r.iterations <= 5);
    CHECK(std::fabs(r.x - root) <= 2 * DBL_EPSILON * root);
  }
  // A root beyond the bracket: the iterate stays at the bracket's end, not converged.
  const RootResult r = newton_polish(f, 1.1, 1.0, 1.2);
  CHECK(r.x == 1.2);
  CHECK_FALSE(r.converged);
  // Not increasing where it starts (f' = 0 at x = 0): no step, not converged.
  CHECK_FALSE(newton_polish(f, 0.0, 0.0, 2.0).converged);
}
