#pragma once
// Curvature of one profile sampled on a uniform grid in y, linear between samples and held
// constant beyond the ends, with the gap that this curvature gives at a distance from a point
// (docs/method.md §4, "Validity of an ellipse"):
//   edge_gap(y, b, ±1) = ∫_0^b (b − w) k(y ± w) dw
// the height reached at y ± b by a curve leaving y with zero slope and curvature k along the way.
// For a constant k it is k b²/2, the Hertz quadratic. The integral is exact for the piecewise
// linear k and costs O(1): a patch up to 4 samples wide is integrated piece by piece, a wider
// one by two prefix integrals per sample, K0(s) = ∫ k ds and K1(s) = ∫ s k ds, in grid units
// s = (y − y0)/dy (below 1e-10 relative at a whole profile's 3000 samples; checked against
// closed forms and quadrature in tests/unit/geometry/test_curvature_samples.cpp).
#include <cstddef>
#include <vector>

namespace mh {

class CurvatureSamples {
 public:
  CurvatureSamples() = default;
  /// k[i] [1/m] at y = y0 + i·dy [m]; dy > 0.
  CurvatureSamples(double y0, double dy, std::vector<double> k);

  bool empty() const { return k_.empty(); }
  double y0() const { return y0_; }
  double dy() const { return dy_; }
  const std::vector<double>& samples() const { return k_; }

  /// k at y [1/m]: linear between samples, constant beyond the ends.
  double at(double y) const;
  /// ∫_0^b (b − w) k(y + side·w) dw [m], side = +1 or −1, b ≥ 0 [m]; exact for the linear k.
  double edge_gap(double y, double b, int side) const;

 private:
  /// K0(s) = ∫_0^s k ds' and K1(s) = ∫_0^s s' k ds' in grid units, any s (extended beyond the ends).
  void prefix(double s, double& K0, double& K1) const;
  /// ∫_a^b (c − s) k(s) ds in grid units, a ≤ b.
  double moment(double a, double b, double c) const;
  double y0_ = 0, dy_ = 1;
  std::vector<double> k_;
  std::vector<double> P0_, P1_;  ///< K0, K1 at the samples
};

}  // namespace mh
