#include "geometry/gap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mh {

namespace {
constexpr double kSampleStep = 0.01e-3;  // [m] sampling of g(y) for its minimum (then refined)
constexpr int kNewtonIterations = 8;     // normal-line intersections converge in 2–4
constexpr double kNewtonTol = 1e-13;     // [m]
}  // namespace

WheelRailGap::WheelRailGap(const ContactGeometry& G, double tY) : WheelRailGap(G, tY, std::nan("")) {}

WheelRailGap::WheelRailGap(const ContactGeometry& G, double tY, double y_near)
    : W_(G.wheel_gap_curve ? G.wheel_gap_curve.get() : G.wheel_curve.get()),
      R_(G.rail_gap_curve ? G.rail_gap_curve.get() : G.rail_curve.get()), shift_(G.y_offset + tY),
      R0_(G.nominal_radius), z0_(G.wheel_z0), face_foot_(G.rail_face_foot) {
  y0_ = std::max(R_->y_min(), W_->y_min() + shift_);
  y1_ = std::min(R_->y_max(), W_->y_max() + shift_);
  const int n = std::max(3, static_cast<int>((y1_ - y0_) / kSampleStep));
  if (std::isnan(y_near)) {
    find_minimum(0, n, n);
    return;
  }
  // The same sample points as the whole-profile search, only those near y_near.
  const double h = (y1_ - y0_) / n;
  const int c = static_cast<int>(std::lround((std::clamp(y_near, y0_, y1_) - y0_) / h));
  find_minimum(std::max(0, c - kLocalSamples), std::min(n, c + kLocalSamples), n);
}

void WheelRailGap::find_minimum(int i0, int i1, int n) {
  // Minimum of the raw gap: sampled on y0 + i h, i = i0 … i1, then refined by a parabola through
  // the best sample.
  const double h = (y1_ - y0_) / n;
  auto raw = [&](double y) { return W_->z(y - shift_) - R_->z(y); };
  int best = i0;
  double gb = std::numeric_limits<double>::infinity();
  for (int i = i0; i <= i1; ++i) {
    const double v = raw(y0_ + h * i);
    if (v < gb) { gb = v; best = i; }
  }
  y_contact_ = y0_ + h * best;
  if (best > 0 && best < n) {
    const double gl = raw(y_contact_ - h), gr = raw(y_contact_ + h);
    const double den = gl - 2 * gb + gr;
    if (den > 0) {
      const double t = std::clamp(0.5 * (gl - gr) / den, -1.0, 1.0);
      y_contact_ += t * h;
      gb = std::min(gb, raw(y_contact_));
    }
  }
  gmin_ = gb;
}

double WheelRailGap::g(double y) const { return W_->z(y - shift_) - R_->z(y) - gmin_; }

double WheelRailGap::z_rail(double y, double* slope) const { return R_->z(y, slope); }

double WheelRailGap::rolling_radius(double y) const { return R0_ - (W_->z(y - shift_) - z0_); }

double WheelRailGap::z_wheel(double y, double x, double* slope) const {
  double dw = 0;
  const double zw = W_->z(y - shift_, &dw) - gmin_;
  const double r = R0_ - (zw + gmin_ - z0_);
  const double root = std::sqrt(std::max(r * r - x * x, 0.0));
  if (slope) *slope = root > 0 ? dw * r / root : dw;  // d/dy [z_w + r − √(r² − x²)], dr/dy = −z_w'
  return zw + r - root;
}

ProjectedInterpenetration::ProjectedInterpenetration(const WheelRailGap& gap, double step) { reset(gap, step); }

void ProjectedInterpenetration::reset(const WheelRailGap& gap, double step) {
  gap_ = &gap;
  const double y0 = gap.y_min(), y1 = gap.y_max();
  const int n = std::max(2, static_cast<int>(std::ceil((y1 - y0) / step)));
  h_ = (y1 - y0) / n;
  y_.resize(static_cast<std::size_t>(n));
  g_.resize(static_cast<std::size_t>(n));
  r_.assign(static_cast<std::size_t>(n), std::numeric_limits<double>::quiet_NaN());
  for (int i = 0; i < n; ++i) {
    y_[i] = y0 + h_ * (i + 0.5);
    g_[i] = gap.g(y_[i]);
  }
}

double ProjectedInterpenetration::area(double dz) const {
  double A = 0;
  for (std::size_t i = 0; i < g_.size(); ++i) {
    const double e = dz - g_[i];
    if (!(e > 0)) continue;
    if (std::isnan(r_[i])) r_[i] = gap_->rolling_radius(y_[i]);
    A += 2 * std::sqrt(2 * r_[i] * e) * h_;
  }
  return A;
}

std::vector<std::pair<double, double>> WheelRailGap::interpenetration(double dz, double step) const {
  std::vector<std::pair<double, double>> out;
  interpenetration(dz, step, out);
  return out;
}

void WheelRailGap::interpenetration(double dz, double step, std::vector<std::pair<double, double>>& out) const {
  out.clear();
  const int n = std::max(2, static_cast<int>(std::ceil((y1_ - y0_) / step)));
  const double h = (y1_ - y0_) / n;
  bool in = false;
  double a = 0, prev_y = y0_, prev_v = g(y0_) - dz;
  if (prev_v < 0) { in = true; a = y0_; }
  for (int i = 1; i <= n; ++i) {
    const double y = y0_ + h * i, v = g(y) - dz;
    if (!in && v < 0) {  // entering: interpolate the crossing
      a = prev_y + h * prev_v / (prev_v - v);
      in = true;
    } else if (in && v >= 0) {
      out.emplace_back(a, prev_y + h * prev_v / (prev_v - v));
      in = false;
    }
    prev_y = y;
    prev_v = v;
  }
  if (in) out.emplace_back(a, y1_);
}

PatchPlane plane_at(const WheelRailGap& gap, double y_ref) {
  PatchPlane P;
  double slope = 0;
  P.y_ref = y_ref;
  P.z_ref = gap.z_rail(y_ref, &slope);
  P.gamma = std::atan(slope);
  return P;
}

double normal_gap(const WheelRailGap& gap, const PatchPlane& P, double x, double s, double dz, double* y_rail) {
  const double c = std::cos(P.gamma), sn = std::sin(P.gamma);
  const double qy = P.y_ref + s * c, qz = P.z_ref + s * sn;
  // Distance h along n = (−sin γ, cos γ) from the plane point to a surface z = f(y):
  // F(h) = qz + h cos γ − f(qy − h sin γ) = 0, Newton (F' = cos γ + f' sin γ > 0 near contact).
  auto intersect = [&](auto&& f) {
    double h = 0;
    for (int it = 0; it < kNewtonIterations; ++it) {
      double d = 0;
      const double F = qz + h * c - f(qy - h * sn, &d);
      const double dF = c + d * sn;
      if (!(std::fabs(dF) > 1e-12)) break;
      const double step = F / dF;
      h -= step;
      if (std::fabs(step) < kNewtonTol) break;
    }
    return h;
  };
  double h_r = 0;
  // The rail's vertical gauge face at y_f: a normal line (towards −y as it rises, sin γ > 0) that
  // crosses y = y_f below the top of the face runs under z(y) on its rail side, so the face is
  // where it meets the rail: h = (qy − y_f)/sin γ, exactly.
  const bool on_face = gap.has_rail_face() && sn > 0 &&
                       qz + (qy - gap.rail_face_y()) / sn * c < gap.z_rail(gap.rail_face_y());
  if (on_face) h_r = (qy - gap.rail_face_y()) / sn;
  else h_r = intersect([&](double y, double* d) { return gap.z_rail(y, d); });
  const double h_w = intersect([&](double y, double* d) { return gap.z_wheel(y, x, d) - dz; });
  if (y_rail) *y_rail = qy - h_r * sn;
  return h_w - h_r;
}

}  // namespace mh
