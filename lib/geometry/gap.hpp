#pragma once
// The undeformed gap between wheel and rail at one lateral position t_Y, in three dimensions, for
// the grid methods (half-space, strips; docs/method.md §8). Built from the smooth profiles kept by
// ContactGeometry. Rail frame: y lateral towards the field side, z up, x the rolling direction.
// The wheel is a body of revolution about the axle (radius r(y) from the nominal radius and the
// profile), placed at its first-contact height, upright or rolled by δ (method.md §3.8), with no
// yaw; the rail is straight in x.
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "geometry/contact_geometry.hpp"

namespace mh {

class WheelRailGap {
 public:
  /// Precondition: G was built by build_geometry (it keeps the smooth profiles).
  WheelRailGap(const ContactGeometry& G, double tY);
  /// The same with the first contact known to lie near rail y `y_near` [m], a solved case's
  /// candidate of least gap (NaN: not known, the whole profile is searched as above): the minimum
  /// of the gap is refined on the same samples, only those within kLocalSamples of y_near,
  /// instead of across the whole profile (about 10,000 samples). Near the geometry's main contact
  /// that is the global minimum; elsewhere a local one, which lifts the wheel by the difference of
  /// the two minima (a constant: second differences of the gap, what gap_kink measures, move by
  /// that times the gap's curvature h², far below its limit).
  WheelRailGap(const ContactGeometry& G, double tY, double y_near);
  /// The same with the wheel rolled by δ = `roll` [rad] against the rail (method.md §3.8, eq.
  /// 3.8.1; positive raising the field side): the wheel profile rotated about its origin
  /// (rolled_gap.hpp, the rotation of ContactGeometry::candidates_at(t, δ)), placed by tY as
  /// upright, its surface a body of revolution about the rolled axle (z_wheel, rolling_radius), the
  /// first contact the minimum of the rolled gap. δ = 0 is the upright gap (the same path, bits).
  WheelRailGap(const ContactGeometry& G, double tY, double y_near, double roll);

  /// [m] the rail-y range where both profiles exist.
  double y_min() const { return y0_; }
  double y_max() const { return y1_; }
  /// [m] vertical gap z_w(y) − z_r(y) at rail y, x = 0; 0 at first contact, ≥ 0 elsewhere.
  double g(double y) const;
  /// [m] rail y of first contact (the minimum of g).
  double y_first_contact() const { return y_contact_; }
  /// Rail height [m] and slope dz/dy at rail y.
  double z_rail(double y, double* slope = nullptr) const;
  /// Wheel surface height [m] at rail y and rolling coordinate x (first-contact position) and its
  /// slope dz/dy: z_w(y) + r(y) − √(r(y)² − x²).
  double z_wheel(double y, double x, double* slope = nullptr) const;
  /// The rail's vertical gauge face (ContactGeometry::rail_face_foot): whether there is one,
  /// its y [m] (the rail curve's first point, from which it hangs) and its foot's height [m].
  bool has_rail_face() const { return face_foot_ == face_foot_; }
  double rail_face_y() const { return R_->y_min(); }
  double rail_face_foot() const { return face_foot_; }
  /// [m] wheel rolling radius at rail y.
  double rolling_radius(double y) const;
  /// [m] wheel-profile lateral coordinate facing rail y (rolled: of the wheel point rotated there).
  double y_wheel(double y) const { return roll_ == 0.0 ? y - shift_ : rolled_source(y, nullptr); }
  /// [rad] the wheel's roll δ against the rail (0: upright).
  double roll() const { return roll_; }
  /// Intervals [a, b] of rail y where g(y) < dz (the interpenetration of a rigid vertical approach
  /// dz), found on a sampling of step `step` [m], in increasing y.
  std::vector<std::pair<double, double>> interpenetration(double dz, double step) const;
  /// The same into `out` (cleared first; its capacity kept: no allocation once it has grown).
  void interpenetration(double dz, double step, std::vector<std::pair<double, double>>& out) const;
  /// The curves g(y) is made of (ContactGeometry's gap curves): the wheel's in its own y, and
  /// the wheel's lift [m], the raw minimum its heights are lowered by (z_wheel = W(y_wheel) − lift).
  const ProfileCurve& wheel_curve() const { return *W_; }
  const ProfileCurve& rail_curve() const { return *R_; }
  double wheel_lift() const { return gmin_; }
  /// ContactGeometry::build_id of the geometry it was made from (0: not from build_geometry, or
  /// rolled: its wheel curve is its own, not the geometry's).
  std::uint64_t build_id() const { return build_id_; }

 private:
  /// Samples each side of y_near in the second constructor: ±0.2 mm at kSampleStep.
  static constexpr int kLocalSamples = 20;
  void find_minimum(int i0, int i1, int n);
  /// Rolled: the upright wheel point (y_w, returned; *z_w its height) that the roll carries to
  /// rail y's wheel point.
  double rolled_source(double y, double* z_w) const;
  const ProfileCurve* W_;
  std::shared_ptr<const ProfileCurve> rolled_W_;  // the rolled wheel's curve (roll_ != 0)
  double roll_ = 0;
  const ProfileCurve* R_;
  double shift_ = 0;   // rail y − wheel y
  std::uint64_t build_id_ = 0;
  double gmin_ = 0;    // minimum of z_w − z_r before normalisation
  double R0_ = 0, z0_ = 0;
  double y0_ = 0, y1_ = 0, y_contact_ = 0;
  double face_foot_ = std::numeric_limits<double>::quiet_NaN();  // [m] NaN: no gauge face
};

/// The horizontal projection of the interpenetration of a rigid vertical approach dz [m²]:
/// ∫ 2 √(2 r(y) (dz − g(y))) dy over g(y) < dz (the wheel's x-extent g + x²/2r < dz, as in
/// find_patch_regions), midpoint rule on a sampling of step `step` [m] of the gap's y range.
/// g at the midpoints is sampled once (it does not depend on dz), r where first needed: a root
/// search on dz (rigid_plastic_approach) evaluates the profiles once, not once per dz.
class ProjectedInterpenetration {
 public:
  ProjectedInterpenetration() = default;
  ProjectedInterpenetration(const WheelRailGap& gap, double step);
  /// Sample `gap` again (as the constructor), keeping the vectors' capacity: a reused object
  /// allocates nothing once it has sampled a gap of as many points.
  void reset(const WheelRailGap& gap, double step);
  double area(double dz) const;

 private:
  const WheelRailGap* gap_ = nullptr;
  double h_ = 0;
  std::vector<double> y_, g_;
  mutable std::vector<double> r_;  // NaN until first needed
};

/// A contact patch's tangent plane (CONTACT's planar contact approach): tangent to the rail at
/// the reference point (y_ref, z_ref), at the contact angle γ = atan(dz_r/dy) there. Plane
/// coordinates: x (rolling), s (lateral in the plane, towards the field side); normal n =
/// (−sin γ, cos γ) in (y, z), pointing into the wheel.
struct PatchPlane {
  double y_ref = 0, z_ref = 0, gamma = 0;
};
PatchPlane plane_at(const WheelRailGap& gap, double y_ref);

/// [m] the undeformed distance between rail and wheel along the plane normal through plane point
/// (x, s), with the wheel lowered by `dz` [m] from its first-contact position (negative: the
/// surfaces interpenetrate there); `y_rail` receives the rail y hit by that normal. The rail is
/// z(y) continued by its vertical gauge face where it has one (a normal that crosses the face's y
/// below the face's top hits the face; below its foot, the face's extension). The wheel moves
/// vertically, not along the normal: in a conformal flange contact its lateral component in the
/// plane (dz sin γ) changes the shape of the interpenetration, not only its depth.
double normal_gap(const WheelRailGap& gap, const PatchPlane& P, double x, double s, double dz = 0,
                  double* y_rail = nullptr);
/// normal_gap(gap, P, x, s0 + ds i, dz) for i = 0 … n − 1 into out[i], the same numbers, with
/// the plane's cos γ and sin γ taken once (the gap-corner test's samples).
void normal_gaps(const WheelRailGap& gap, const PatchPlane& P, double x, double s0, double ds, int n, double dz,
                 double* out);

/// A bound of the gap-corner test's slope jump without its samples (contact/ellipse/
/// hertz_validity.hpp, gap_kink): Δθ_i = |G(s_i + h) − 2 G(s_i) + G(s_i − h) − 2 B h²| / h at the
/// centres s_i = s_first + (h/2) i, i = 0 … n − 1, G(s) = normal_gap(gap, P, 0, s, dz). Between
/// its nodes each curve is a cubic Hermite z(y) = L(y) + e(y), L the polyline through the nodes
/// and |e| ≤ (4/27) Δy (|z'_k − m| + |z'_k+1 − m|) on an interval of width Δy and chord slope m
/// (|h10|, |h11| ≤ 4/27). Seen from the plane (rotated by −γ) each polyline is a polyline again,
/// whose slope jumps at a node from chord slope m0 to m1 by (m1 − m0) / (D0 D1), D = cos γ + m sin γ,
/// so the gap of the polylines G_L is piecewise linear with kinks J_k at the nodes' plane
/// coordinates s_k, and exactly
///   G_L(s + h) − 2 G_L(s) + G_L(s − h) = Σ_k J_k (h − |s_k − s|)₊.
/// Each e moves a normal's hit by at most |e| / D_min, and a sampled G is within kGapError of the
/// exact one, so Δθ_i ≤ |Σ_k J_k (1 − |s_k − s_i|/h)₊ − 2 B h| + 4 (η + ε) / h with
/// η = E_w / D_min,w + E_r / D_min,r. `found` false (the samples must decide) when a normal of
/// the span meets the rail's gauge face, when the span reaches beyond a curve's nodes, or when
/// D < kMinSlopeFactor on it (the plane turned too far from a curve for it to be a graph).
struct KinkBound {
  bool found = false;
  double dtheta = 0;  ///< [rad] the bound of max_i Δθ_i
  static constexpr double kMinSlopeFactor = 0.5;
};
/// ε: the error of a sampled normal gap allowed for by the bound [m] (normal_gap's Newton solves
/// stop at steps below 1e-13 m, converging quadratically; coordinates below 1 m round at 1e-16 m).
constexpr double kGapError = 1e-12;
/// `spacing` [m]: the polylines are those through every 2^l-th node with the largest l whose
/// spacing is at most this (default h/2): a coarser one sums fewer kinks, its deviation from the
/// curve larger.
/// `centre_bound` (optional, n values): when found, each centre's own bound of Δθ_i (the same
/// terms with its own |S_i − 2Bh|), so that the samples need only visit the centres it does not pass.
KinkBound gap_kink_bound(const WheelRailGap& gap, const PatchPlane& P, double s_first, double h, int n, double B,
                         double dz, double spacing, double* centre_bound = nullptr);
inline KinkBound gap_kink_bound(const WheelRailGap& gap, const PatchPlane& P, double s_first, double h, int n, double B,
                                double dz) {
  return gap_kink_bound(gap, P, s_first, h, n, B, dz, 0.5 * h);
}
/// A coarser bound of the same Δθ_i (all centres at once), cheaper than gap_kink_bound: instead
/// of summing every kink of the polylines into every centre, the range over the span of each
/// polyline's kinks per length in the plane, c_k = J_k / δ_k (δ_k the kink's share of plane
/// length), whose second differences over h are then within h (range) of h κ̄ (trapezoid error
/// included). The kinks per length in y are tabulated per node (the plane enters through the range
/// of D only), so a call is a min/max scan of the span's nodes. It passes the patches whose gap
/// curvature varies by less than the limit across the span (tread contacts: 236 of 297 Manchester
/// patches), not those near a corner or a change of radius, which gap_kink_bound or the samples
/// then decide. `found` false as gap_kink_bound's, or for a rolled wheel (its curve has no node
/// table).
KinkBound gap_curvature_bound(const WheelRailGap& gap, const PatchPlane& P, double s_first, double h, int n, double B,
                              double dz);

}  // namespace mh
