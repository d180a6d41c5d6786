#pragma once
// Validity of the Hertz assumptions for one loaded ellipse (docs/method.md §4, "Validity of an
// ellipse"). Hertz theory holds while the patch is small against the radii of both bodies and
// lies inside a zone of (nearly) constant curvature. Two limits, both dimensionless:
//   b_over_R         = b / min(|R_rxx|, |R_wxx|)                       (default limit 0.3)
//   gap_error        = max over u = ±b of |g(u) − B u²| / (B b²)      (default limit 0.5)
//   gap_mean_error   = |(g(−b) + g(b))/2 − B b²| / (B b²)             (default limit 0.1)
//                      g(u) = ∫_0^u (u − w) S(w) dw, S(w) = 1/R_rxx(y_r + w) + 1/R_wxx(y_w + w):
//                      the gap the curvatures of both profiles actually give at the patch edges,
//                      against the quadratic B u² (B = S(0)/2) Hertz assumes. It measures the
//                      curvature along [y − b, y + b] against its value at the contact point,
//                      integrated the way it acts on the patch. The mean of the two edge gaps
//                      sets the patch's width and peak (2-D Hertz: b ∝ B^−1/2, p0 ∝ B^1/2, so a
//                      mean error ε moves p0 by about ε/2); their difference, a curvature that
//                      varies linearly across the patch, mostly shifts it.
// b is the lateral semi-axis of the (possibly plastic) patch. A candidate with B ≤ 0 has no
// ellipse at all and is handled by the solver (non_hertzian_excluded).
// The multi-Hertzian solver reports the result per loaded ellipse (hertz_valid column, warning
// non_hertzian:ellipse=K:...); a method chooser ("method": "auto") can use hertz_validity() to
// send such a case to a grid solver.
#include <string>

#include "contact/judge/status.hpp"
#include "contact/options.hpp"
#include "geometry/contact_geometry.hpp"

namespace mh {


/// The outcome of the test for one ellipse: both measured ratios and which limits failed.
struct HertzValidity {
  bool valid = true;              ///< every ratio within its limit
  double b_over_R = 0;            ///< [-] b / min(|R_rxx|, |R_wxx|)
  double gap_error = 0;    ///< [-] max over u = ±b of |g(u) − B u²| / (B b²)
  double gap_mean_error = 0;  ///< [-] |(g(−b) + g(b))/2 − B b²| / (B b²)
  /// The same two errors with g(u) from the contact surface, a profile smoothed for contact
  /// (ContactGeometry::rail_gap_k, wheel_gap_k), against the same B b²; 0 when no profile is
  /// smoothed for contact (the surface is then the curves). See hertz_validity(G, g, b) below.
  double surface_gap_error = 0, surface_gap_mean_error = 0;
  bool b_over_R_failed = false;
  bool gap_error_failed = false;
  bool gap_mean_error_failed = false;
  bool surface_gap_error_failed = false;
  bool surface_gap_mean_error_failed = false;
  /// The `non_hertzian` warning of ellipse `ellipse` (1-based): one measure per failed limit
  /// (b_over_R, gap_error, gap_mean_error, surface_gap_error, surface_gap_mean_error), written
  /// "non_hertzian:ellipse=4:b_over_R=22.31>0.3:gap_error=3.1>0.5"; no measure when valid.
  Warning warning(int ellipse, const HertzValidityOptions& opt) const;
};

/// The test from its ingredients: lateral semi-axis b [m], curvatures at the contact point
/// k_rxx = 1/R_rxx, k_wxx = 1/R_wxx [1/m], and the gap_error and gap_mean_error [-] measured on
/// the profiles.
HertzValidity hertz_validity(double b, double k_rxx, double k_wxx, double gap_error, double gap_mean_error,
                             const HertzValidityOptions& opt = {});

/// The test for a candidate g of the geometry G with lateral semi-axis b [m]: the curvature
/// gap error is measured on G's curvature samples of both profiles (ContactGeometry::rail_k,
/// wheel_k), integrated exactly over [−b, b] in O(1) (CurvatureSamples::edge_gap).
/// When a profile is smoothed for contact (a measured profile, profiles.md "Smoothing for
/// contact"), the edge gaps are measured again on the contact surface (rail_gap_k, wheel_gap_k)
/// against the same B b², with the same limits. The ellipse's B comes from the curve's
/// window fit at the contact point; the smoothed surface is the project's definition of a
/// measured profile for contact, on which the grid methods (and an independent reference) solve.
/// The two agree wherever the profile's curvature varies over lengths longer than the smoothing
/// length L; where they disagree over the patch by more than the budget, the curvature there
/// changes over less than L (a sharp measured gauge corner, a corner near the profile's clipped
/// end), the measurement does not fix the curvature at the patch's scale, and the Hertz answer is
/// not the answer on the contact surface: not valid.
HertzValidity hertz_validity(const ContactGeometry& G, const CandidateGeom& g, double b,
                             const HertzValidityOptions& opt = {});

/// A corner of the gap inside the patch (used by `auto`, contact/solve.cpp). hertz_validity()
/// measures the profiles' sampled curvature (ContactGeometry::rail_k, wheel_k) at the patch
/// edges; the grid methods solve on the 3-D normal gap of the profiles themselves
/// (geometry/gap.hpp). A corner of that gap, a jump Δθ of its slope across the patch (a kink
/// of a measured profile between its points, a step, a normal ray changing branch on a steep
/// flange), is invisible in the integrated edge gaps but makes the elastic pressure singular:
/// near a corner p ≈ (E* Δθ / 2π) cosh⁻¹(c/|s − s_k|) (Johnson, Contact Mechanics §5.8, the
/// wedge: Δθ = 2 cot α), a logarithmic peak of scale E*Δθ/2π whatever the load. The Hertz peak
/// p0 is then not the peak, and a grid method's peak grows as its elements shrink.
/// The test samples the normal gap across the patch, in the patch plane at the ellipse's contact
/// point, at x = 0, s ∈ [−b, b] in steps of h/2 with h = b/40, wheel at the vertical approach dz:
///   Δθ = max over s of |g(s+h) − 2 g(s) + g(s−h) − 2 B h²| / h
/// (a corner inside [s−h, s+h] gives its slope jump; a smooth gap, curvature varying or not,
/// gives O(h) → 0), and
///   kink_ratio = E* Δθ / (2π p0)     (E* = E_star()/2, Johnson's combined modulus)
/// valid when kink_ratio ≤ HertzValidityOptions::max_gap_mean_error (0.1: the corner's pressure
/// scale within 10 % of p0, the budget of the mean-gap limit). Measured: Manchester pair ≤ 0.052
/// (t_Y −6 … 10 mm); worn measured flanges 0.38 … 10^4 (docs/methods.md, auto).
///
/// The samples cost about 330 profile evaluations per ellipse (two Newton solves each). Most
/// patches are shown valid without them: first by the range of the gap's curvature over the span
/// (geometry/gap.hpp, gap_curvature_bound: the tread patches, a few dozen blocks of nodes), then
/// by a bound of Δθ from the profiles' nodes (gap_kink_bound: the polylines through the nodes
/// spaced at most h, then at most h/2
/// when that does not pass the patch, whose second differences are
/// exact sums over their kinks, plus the largest deviation of the curves from them). When
/// E* Δθ / (2π p0) from that bound is within the limit the test passes with the bound as its
/// figures (`bounded`); otherwise (a corner, a patch too small for the deviation, a normal on the
/// rail's gauge face) the samples decide, taken only around the centres whose own bound (the
/// lesser of the two polylines') exceeds the limit (all of them when there is no bound). Either
/// way the same verdict, and a failed test's kink_ratio is always the sampled one (the largest
/// Δθ_i is at a centre the bound did not pass).
struct GapKink {
  double dtheta = 0;      ///< [rad] the largest slope jump of the gap across the patch (`bounded`: a bound of it)
  double kink_ratio = 0;  ///< [-] E* Δθ / (2π p0) (`bounded`: a bound of it)
  bool valid = true;
  bool bounded = false;   ///< valid shown by the bound, without the samples
  /// Append the measure gap_kink (written "gap_kink=0.71>0.1") to `w` when not valid.
  void add_to(Warning& w, const HertzValidityOptions& opt) const;
};
class WheelRailGap;
/// The test above for an ellipse at candidate g with lateral curvature B [1/m] (eq. 1),
/// semi-axis b [m] and peak p0 [Pa], combined modulus E_pair [Pa] (Johnson's E*), the wheel
/// lowered by dz [m] (the case's vertical approach).
/// `use_bound` false: the samples always (tests of the bound).
GapKink gap_kink(const WheelRailGap& gap, const CandidateGeom& g, double B, double b, double p0, double E_pair,
                 double dz, const HertzValidityOptions& opt = {}, bool use_bound = true);

}  // namespace mh
