#include "geometry/gap.hpp"

#include "geometry/normal_hits.hpp"
#include "geometry/rolled_gap.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

namespace mh {

namespace {
constexpr double kSampleStep = 0.01e-3;  // [m] sampling of g(y) for its minimum (then refined)

/// The rolled wheel curves of this thread's last gaps, by geometry, wheel curve and roll: a gap
/// at a roll met before takes its curve as it is, and a new roll is built in place of the least
/// recently used curve no gap holds any more (its vectors' capacity kept), so that the grid
/// methods' rolled cases allocate nothing for it once the slots have grown (docs/c-api.md). A
/// geometry without a build id (not made by build_geometry) is not kept.
std::shared_ptr<const ProfileCurve> rolled_curve(const ProfileCurve& W, std::uint64_t build_id, double roll) {
  if (build_id == 0) return std::make_shared<const ProfileCurve>(rolled_wheel_curve(W, roll));
  struct Slot {
    std::uint64_t id = 0;
    const ProfileCurve* W = nullptr;
    double roll = 0;
    std::shared_ptr<ProfileCurve> curve;
    std::uint64_t used = 0;
  };
  constexpr std::size_t kSlots = 8;
  thread_local Slot slots[kSlots];
  thread_local std::uint64_t tick = 0;
  ++tick;
  Slot* free_slot = nullptr;
  for (Slot& s : slots) {
    if (s.curve && s.id == build_id && s.W == &W && s.roll == roll) {
      s.used = tick;
      return s.curve;
    }
    if ((!s.curve || s.curve.use_count() == 1) && (!free_slot || s.used < free_slot->used)) free_slot = &s;
  }
  if (!free_slot) return std::make_shared<const ProfileCurve>(rolled_wheel_curve(W, roll));  // every slot held
  if (free_slot->curve) rolled_wheel_curve(W, roll, *free_slot->curve);  // in place
  else free_slot->curve = std::make_shared<ProfileCurve>(rolled_wheel_curve(W, roll));
  free_slot->id = build_id;
  free_slot->W = &W;
  free_slot->roll = roll;
  free_slot->used = tick;
  return free_slot->curve;
}
constexpr int kNewtonIterations = 8;     // normal-line intersections converge in 2–4
constexpr double kNewtonTol = 1e-13;     // [m]
}  // namespace

WheelRailGap::WheelRailGap(const ContactGeometry& G, double tY) : WheelRailGap(G, tY, std::nan("")) {}

WheelRailGap::WheelRailGap(const ContactGeometry& G, double tY, double y_near) : WheelRailGap(G, tY, y_near, 0.0) {}

WheelRailGap::WheelRailGap(const ContactGeometry& G, double tY, double y_near, double roll)
    : W_(G.wheel_gap_curve ? G.wheel_gap_curve.get() : G.wheel_curve.get()),
      R_(G.rail_gap_curve ? G.rail_gap_curve.get() : G.rail_curve.get()), shift_(G.y_offset + tY),
      build_id_(G.build_id), R0_(G.nominal_radius), z0_(G.wheel_z0), face_foot_(G.rail_face_foot) {
  if (roll != 0.0) {
    // The rolled wheel's own curve; no node tables of gap_kink_bound keyed by the geometry's id.
    rolled_W_ = rolled_curve(*W_, G.build_id, roll);
    W_ = rolled_W_.get();
    roll_ = roll;
    build_id_ = 0;
  }
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

double WheelRailGap::rolled_source(double y, double* z_w) const {
  // The rolled wheel's point (y_w', z_w') rotated back by −δ: the upright profile's point.
  const double yr = y - shift_, zr = W_->z(yr), c = std::cos(roll_), sn = std::sin(roll_);
  if (z_w) *z_w = zr * c - yr * sn;
  return yr * c + zr * sn;
}

double WheelRailGap::rolling_radius(double y) const {
  if (roll_ != 0.0) {
    // The radius of the upright point the roll carries there (about the rolled axle).
    double z_w;
    rolled_source(y, &z_w);
    return R0_ - (z_w - z0_);
  }
  return R0_ - (W_->z(y - shift_) - z0_);
}

double WheelRailGap::z_wheel(double y, double x, double* slope) const {
  if (roll_ != 0.0) {
    // z_w(y) + r − √(r² − x²) with r the rolled wheel's radius there (rolling_radius): the
    // drop x²/2r taken vertically, not along the rolled radius (an error of order δ z_w' x²/2r,
    // 0.4 µm at δ 25 mrad, a flange slope 1.5 and x 3 mm on r 0.46 m).
    double dw = 0;
    const double zw = W_->z(y - shift_, &dw) - gmin_;
    const double r = rolling_radius(y), dr = std::sin(roll_) - dw * std::cos(roll_);
    const double root = std::sqrt(std::max(r * r - x * x, 0.0));
    if (slope) *slope = dw + dr * (root > 0 ? 1 - r / root : 1);
    return zw + r - root;
  }
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

namespace detail {

bool on_rail_face(const WheelRailGap& gap, double qy, double qz, double c, double sn) {
  return gap.has_rail_face() && sn > 0 && qz + (qy - gap.rail_face_y()) / sn * c < gap.z_rail(gap.rail_face_y());
}

NormalHits normal_hits(const WheelRailGap& gap, const PatchPlane& P, double c, double sn, double x, double s, double dz,
                       double hr0, double hw0) {
  const double qy = P.y_ref + s * c, qz = P.z_ref + s * sn;
  // Distance h along n = (−sin γ, cos γ) from the plane point to a surface z = f(y):
  // F(h) = qz + h cos γ − f(qy − h sin γ) = 0, Newton (F' = cos γ + f' sin γ > 0 near contact).
  auto intersect = [&](double h, auto&& f) {
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
  NormalHits n;
  n.qy = qy;
  // The rail's vertical gauge face at y_f: a normal line (towards −y as it rises, sin γ > 0) that
  // crosses y = y_f below the top of the face runs under z(y) on its rail side, so the face is
  // where it meets the rail: h = (qy − y_f)/sin γ, exactly.
  n.on_face = on_rail_face(gap, qy, qz, c, sn);
  if (n.on_face) n.h_r = (qy - gap.rail_face_y()) / sn;
  else n.h_r = intersect(hr0, [&](double y, double* d) { return gap.z_rail(y, d); });
  n.h_w = intersect(hw0, [&](double y, double* d) { return gap.z_wheel(y, x, d) - dz; });
  return n;
}

}  // namespace detail

using detail::NormalHits;
using detail::normal_hits;

double normal_gap(const WheelRailGap& gap, const PatchPlane& P, double x, double s, double dz, double* y_rail) {
  const double c = std::cos(P.gamma), sn = std::sin(P.gamma);
  const NormalHits n = normal_hits(gap, P, c, sn, x, s, dz);
  if (y_rail) *y_rail = n.qy - n.h_r * sn;
  return n.h_w - n.h_r;
}

void normal_gaps(const WheelRailGap& gap, const PatchPlane& P, double x, double s0, double ds, int n, double dz,
                 double* out) {
  const double c = std::cos(P.gamma), sn = std::sin(P.gamma);
  // Each sample's Newton solves start from the previous sample's hits: on the Manchester sweep
  // of bench_judge.sh 15 % fewer instructions in the samples, the same bytes out.
  double hr0 = 0, hw0 = 0;
  for (int i = 0; i < n; ++i) {
    const NormalHits h = normal_hits(gap, P, c, sn, x, s0 + ds * i, dz, hr0, hw0);
    out[i] = h.h_w - h.h_r;
    hr0 = h.on_face ? 0 : h.h_r;
    hw0 = h.h_w;
  }
}

}  // namespace mh
