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

#include "contact/options.hpp"
#include "geometry/contact_geometry.hpp"

namespace mh {


/// The outcome of the test for one ellipse: both measured ratios and which limits failed.
struct HertzValidity {
  bool valid = true;              ///< both ratios within their limits
  double b_over_R = 0;            ///< [-] b / min(|R_rxx|, |R_wxx|)
  double gap_error = 0;    ///< [-] max over u = ±b of |g(u) − B u²| / (B b²)
  double gap_mean_error = 0;  ///< [-] |(g(−b) + g(b))/2 − B b²| / (B b²)
  bool b_over_R_failed = false;
  bool gap_error_failed = false;
  bool gap_mean_error_failed = false;
  /// "b_over_R=22.31>0.3", "gap_error=3.1>0.5", "gap_mean_error=0.12>0.1", those that failed,
  /// joined by ':'; empty when valid.
  std::string describe(const HertzValidityOptions& opt) const;
};

/// The test from its ingredients: lateral semi-axis b [m], curvatures at the contact point
/// k_rxx = 1/R_rxx, k_wxx = 1/R_wxx [1/m], and the gap_error and gap_mean_error [-] measured on
/// the profiles.
HertzValidity hertz_validity(double b, double k_rxx, double k_wxx, double gap_error, double gap_mean_error,
                             const HertzValidityOptions& opt = {});

/// The test for a candidate g of the geometry G with lateral semi-axis b [m]: the curvature
/// gap error is measured on G's curvature samples of both profiles (ContactGeometry::rail_k,
/// wheel_k), integrated exactly over [−b, b] in O(1) (CurvatureSamples::edge_gap).
HertzValidity hertz_validity(const ContactGeometry& G, const CandidateGeom& g, double b,
                             const HertzValidityOptions& opt = {});

}  // namespace mh
