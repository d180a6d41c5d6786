#pragma once
// Damage and wear over a sweep of the lateral displacement t_Y, weighted by a normal distribution of
// t_Y that the user gives ("rcf": {"tY_distribution": {"mean_mm", "sd_mm"}}; docs/methods.md
// "Damage and wear functions", docs/outputs.md "Damage and wear over t_Y"). The sweep's t_Y values
// t_1 < … < t_n are the nodes of a trapezoid rule over [t_1, t_n]: node i stands for the interval
// from the midpoint with its left neighbour to the midpoint with its right one (the ends for the
// first and last), its weight is the normal density at t_i times that interval's width, and the
// weights are normalised to sum 1 over the sweep (the distribution's mass outside the sweep is not
// counted: the result is the expectation conditional on t_Y within the sweep). Light header, no state.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace mh {

/// The normalised weights of the sorted, distinct nodes t (any unit, the same as mean and sd > 0).
/// One node: weight 1. Empty when t is empty or every density underflows.
inline std::vector<double> normal_trapezoid_weights(const std::vector<double>& t, double mean, double sd) {
  const std::size_t n = t.size();
  std::vector<double> w(n);
  if (n == 1) w[0] = 1;
  if (n <= 1) return w;
  double s = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double lo = i > 0 ? 0.5 * (t[i - 1] + t[i]) : t[i];
    const double hi = i + 1 < n ? 0.5 * (t[i] + t[i + 1]) : t[i];
    const double u = (t[i] - mean) / sd;
    w[i] = std::exp(-0.5 * u * u) * (hi - lo);
    s += w[i];
  }
  if (!(s > 0)) return {};
  for (double& x : w) x /= s;
  return w;
}

/// One sweep's (t_Y, value) pairs → Σ w_i v_i with the weights above over the distinct t_Y (values
/// at the same t_Y averaged first); NaN when there is none.
inline double ty_weighted(std::vector<std::pair<double, double>> tv, double mean, double sd) {
  std::sort(tv.begin(), tv.end());
  std::vector<double> t, v;
  std::vector<int> k;
  for (const auto& [ti, vi] : tv) {
    if (!t.empty() && t.back() == ti) {
      v.back() += vi, ++k.back();
    } else {
      t.push_back(ti), v.push_back(vi), k.push_back(1);
    }
  }
  const std::vector<double> w = normal_trapezoid_weights(t, mean, sd);
  if (w.empty()) return NAN;
  double s = 0;
  for (std::size_t i = 0; i < w.size(); ++i) s += w[i] * v[i] / k[i];
  return s;
}

}  // namespace mh
