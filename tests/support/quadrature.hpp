#pragma once
// Adaptive quadrature for the tests' independent references: tanh-sinh (double-exponential)
// quadrature of Boost.Math (Takahasi & Mori 1974; boost::math::quadrature::tanh_sinh), which
// converges exponentially also for integrands with algebraic or logarithmic singularities at
// the ends of the interval. Interior kinks and peaks go in as break points, so that every piece
// is smooth inside.
#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/math/quadrature/tanh_sinh.hpp>

namespace mh_test {

/// ∫_lo^hi f, relative tolerance rtol (0 when hi ≤ lo).
template <class F>
double integrate(F f, double lo, double hi, double rtol = 1e-13) {
  if (!(hi > lo)) return 0;
  static thread_local boost::math::quadrature::tanh_sinh<double> q(15);
  double err = 0, L1 = 0;
  std::size_t levels = 0;
  return q.integrate(f, lo, hi, rtol, &err, &L1, &levels);
}

/// ∫ over [pts.front(), pts.back()] of f, split at every point of pts (any order, duplicates
/// allowed).
template <class F>
double integrate_pieces(F f, std::vector<double> pts, double rtol = 1e-13) {
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  double s = 0;
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) s += integrate(f, pts[k], pts[k + 1], rtol);
  return s;
}

}  // namespace mh_test
