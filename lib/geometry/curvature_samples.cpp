#include "geometry/curvature_samples.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mh {

CurvatureSamples::CurvatureSamples(double y0, double dy, std::vector<double> k)
    : y0_(y0), dy_(dy), k_(std::move(k)) {
  const std::size_t n = k_.size();
  P0_.assign(n, 0.0);
  P1_.assign(n, 0.0);
  for (std::size_t i = 0; i + 1 < n; ++i) {  // exact integrals of the linear k over cell i
    const double a = k_[i], b = k_[i + 1], s = static_cast<double>(i);
    P0_[i + 1] = P0_[i] + 0.5 * (a + b);
    P1_[i + 1] = P1_[i] + s * 0.5 * (a + b) + (a + 2 * b) / 6;
  }
}

double CurvatureSamples::at(double y) const {
  if (k_.empty()) return 0.0;
  const double s = (y - y0_) / dy_;
  if (!(s > 0)) return k_.front();
  const double last = static_cast<double>(k_.size() - 1);
  if (s >= last) return k_.back();
  const std::size_t i = static_cast<std::size_t>(s);
  const double f = s - static_cast<double>(i);
  return k_[i] + f * (k_[i + 1] - k_[i]);
}

void CurvatureSamples::prefix(double s, double& K0, double& K1) const {
  const std::size_t n = k_.size();
  const double last = static_cast<double>(n - 1);
  if (!(s > 0)) {  // constant k_0 before the first sample (also NaN: no extrapolation)
    K0 = k_.front() * s;
    K1 = k_.front() * 0.5 * s * s;
    return;
  }
  if (s >= last) {  // constant k_{n−1} after the last
    K0 = P0_.back() + k_.back() * (s - last);
    K1 = P1_.back() + k_.back() * 0.5 * (s * s - last * last);
    return;
  }
  const std::size_t i = static_cast<std::size_t>(s);
  const double f = s - static_cast<double>(i), a = k_[i], d = k_[i + 1] - k_[i];
  const double j0 = f * a + 0.5 * f * f * d;                  // ∫_0^f k(i + t) dt
  const double j1 = 0.5 * f * f * a + f * f * f * d / 3.0;    // ∫_0^f t k(i + t) dt
  K0 = P0_[i] + j0;
  K1 = P1_[i] + static_cast<double>(i) * j0 + j1;
}

double CurvatureSamples::moment(double a, double b, double c) const {
  // Spans of up to kDirectCells samples are integrated cell by cell in coordinates local to each
  // piece (no cancellation); longer spans by the prefix integrals, whose differences lose about
  // (s / span)² ulps: below 1e-10 relative for a whole profile's 3000 samples.
  constexpr double kDirectCells = 4;
  const double last = static_cast<double>(k_.size() - 1);
  if (b - a > kDirectCells) {
    double A0, A1, B0, B1;
    prefix(a, A0, A1);
    prefix(b, B0, B1);
    return c * (B0 - A0) - (B1 - A1);
  }
  double sum = 0, p = a;
  while (p < b) {
    double q, kp, d;  // piece [p, q] where k = kp + d·(s − p)
    if (p < 0) {  // before the first sample: k held
      q = std::min(b, 0.0);
      kp = k_.front();
      d = 0;
    } else if (p >= last) {  // after the last
      q = b;
      kp = k_.back();
      d = 0;
    } else {
      const std::size_t i = static_cast<std::size_t>(p);
      q = std::min(b, static_cast<double>(i) + 1);
      d = k_[i + 1] - k_[i];
      kp = k_[i] + (p - static_cast<double>(i)) * d;
    }
    const double L = q - p, e = c - p;
    sum += e * (kp * L + 0.5 * d * L * L) - (0.5 * kp * L * L + d * L * L * L / 3);
    p = q;
  }
  return sum;
}

double CurvatureSamples::edge_gap(double y, double b, int side) const {
  if (k_.empty() || !(b > 0)) return 0.0;
  const double sy = (y - y0_) / dy_, bs = b / dy_;
  if (!std::isfinite(sy) || !std::isfinite(bs)) return NAN;
  // dy² ∫_{sy}^{sy+bs} (sy + bs − s) k ds, or dy² ∫_{sy−bs}^{sy} (s − sy + bs) k ds.
  return dy_ * dy_ * (side >= 0 ? moment(sy, sy + bs, sy + bs) : -moment(sy - bs, sy, sy - bs));
}

}  // namespace mh
