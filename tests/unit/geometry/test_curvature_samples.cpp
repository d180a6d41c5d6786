// Curvature samples and the gap they give along a patch (geometry/curvature_samples.hpp):
// edge_gap(y, b, ±1) = ∫_0^b (b − w) k(y ± w) dw against closed forms and against quadrature of
// the interpolated curvature (independent of the prefix-integral algebra).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "geometry/curvature_samples.hpp"

using namespace mh;

namespace {
// Composite Simpson on 200000 intervals of the interpolated k: the reference for any k.
double quadrature(const CurvatureSamples& c, double y, double b, int side) {
  const int n = 200000;
  const double h = b / n;
  double s = 0;
  for (int i = 0; i <= n; ++i) {
    const double w = h * i, f = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    s += f * (b - w) * c.at(y + side * w);
  }
  return s * h / 3;
}
}  // namespace

TEST_CASE("edge_gap: constant curvature gives the Hertz quadratic k b^2/2", "[geometry][curvature]") {
  // A circle of radius 13 mm sampled every 0.05 mm over 20 mm: g(b) = b²/(2R) exactly.
  const double R = 13e-3;
  const CurvatureSamples c(-10e-3, 0.05e-3, std::vector<double>(401, 1 / R));
  for (double b : {0.01e-3, 0.3e-3, 2e-3, 9e-3})
    for (int side : {-1, 1}) REQUIRE(c.edge_gap(0.37e-3, b, side) == Approx(b * b / (2 * R)).epsilon(1e-12));
  // Beyond the ends the curvature is held: still the quadratic.
  REQUIRE(c.edge_gap(9e-3, 5e-3, 1) == Approx(25e-6 / (2 * R)).epsilon(1e-12));
  REQUIRE(c.edge_gap(-9e-3, 5e-3, -1) == Approx(25e-6 / (2 * R)).epsilon(1e-12));
  REQUIRE(c.edge_gap(0, 0, 1) == 0.0);
}

TEST_CASE("edge_gap: linear curvature, closed form k0 b^2/2 ± k' b^3/6", "[geometry][curvature]") {
  // k(y) = k0 + k'·y on the samples: ∫_0^b (b − w)(k0 ± k' w) dw = k0 b²/2 ± k' b³/6.
  const double y0 = -20e-3, dy = 0.05e-3, k0 = 50.0, kp = 4000.0;  // 1/m, 1/m²
  std::vector<double> k;
  for (int i = 0; i <= 800; ++i) k.push_back(k0 + kp * (y0 + i * dy));
  const CurvatureSamples c(y0, dy, k);
  for (double y : {0.0, 1.234e-3, -7.77e-3})
    for (double b : {0.02e-3, 1e-3, 6e-3}) {
      const double ky = k0 + kp * y;
      REQUIRE(c.edge_gap(y, b, 1) == Approx(ky * b * b / 2 + kp * b * b * b / 6).epsilon(1e-10));
      REQUIRE(c.edge_gap(y, b, -1) == Approx(ky * b * b / 2 - kp * b * b * b / 6).epsilon(1e-10));
    }
}

TEST_CASE("edge_gap: a curvature jump (flange root) agrees with quadrature", "[geometry][curvature]") {
  // A tread radius of 300 mm meeting a 13 mm root between two samples, 3000 samples (a whole
  // profile): the prefix differences keep their digits far from the origin.
  const double y0 = -70e-3, dy = 0.05e-3;
  std::vector<double> k;
  for (int i = 0; i <= 3000; ++i) k.push_back(y0 + i * dy < 40.02e-3 ? 1 / 0.3 : -1 / 13e-3);
  const CurvatureSamples c(y0, dy, k);
  for (double y : {-69e-3, -68.8e-3, 38e-3, 40e-3, 40.013e-3, 41e-3, 79e-3})  // and across both ends
    for (double b : {0.04e-3, 0.15e-3, 0.5e-3, 3e-3, 4.5e-3})  // up to 3 samples: piece by piece; wider: prefix
      for (int side : {-1, 1}) {
        const double ref = quadrature(c, y, b, side);
        INFO("y=" << y << " b=" << b << " side=" << side << " got " << c.edge_gap(y, b, side) << " ref " << ref);
        // 1e-9 of the gap the larger curvature alone gives (the two parts cancel near the jump),
        // far below anything the validity test resolves.
        REQUIRE(std::fabs(c.edge_gap(y, b, side) - ref) <= 1e-9 * b * b / (2 * 13e-3));
      }
}
