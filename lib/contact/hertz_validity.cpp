#include "contact/hertz_validity.hpp"

#include <algorithm>
#include <cmath>

#include "core/numfmt.hpp"

namespace mh {

bool HertzValidityOptions::valid(std::string* why) const {
  if (!(max_b_over_R > 0) || !std::isfinite(max_b_over_R)) {
    if (why) *why = "max_b_over_R must be > 0 and finite";
    return false;
  }
  if (!(max_gap_error > 0) || !std::isfinite(max_gap_error)) {
    if (why) *why = "max_gap_error must be > 0 and finite";
    return false;
  }
  return true;
}

std::string HertzValidity::describe(const HertzValidityOptions& opt) const {
  auto r = [](double v) { return format_number(std::round(v * 1e3) / 1e3); };
  std::string s;
  if (b_over_R_failed) s += "b_over_R=" + r(b_over_R) + ">" + format_number(opt.max_b_over_R);
  if (gap_error_failed) {
    if (!s.empty()) s += ':';
    s += "gap_error=" + r(gap_error) + ">" + format_number(opt.max_gap_error);
  }
  return s;
}

HertzValidity hertz_validity(double b, double k_rxx, double k_wxx, double gap_error,
                             const HertzValidityOptions& opt) {
  HertzValidity v;
  const double kmax = std::max(std::fabs(k_rxx), std::fabs(k_wxx));  // 1 / min(|R|)
  v.b_over_R = std::fabs(b) * kmax;
  v.gap_error = gap_error;
  // NaN ratios fail (a comparison with NaN is false).
  v.b_over_R_failed = !(v.b_over_R <= opt.max_b_over_R);
  v.gap_error_failed = !(v.gap_error <= opt.max_gap_error);
  v.valid = !v.b_over_R_failed && !v.gap_error_failed;
  return v;
}

HertzValidity hertz_validity(const ContactGeometry& G, const CandidateGeom& g, double b,
                             const HertzValidityOptions& opt) {
  const double S0 = g.k_rxx + g.k_wxx;  // 2B at the contact point
  double err = 0;
  if (b > 0 && G.has_curvature_samples()) {
    // g(±b) = ∫_0^b (b − w) S(±w) dw, S = k_rxx + k_wxx along both profiles from the contact
    // point, exact for the sampled (piecewise linear) curvatures.
    const double quad = 0.5 * S0 * b * b;
    for (int side : {-1, 1}) {
      const double gb = G.rail_k.edge_gap(g.y_r, b, side) + G.wheel_k.edge_gap(g.y_w, b, side);
      err = std::max(err, S0 > 0 ? std::fabs(gb - quad) / quad : INFINITY);
    }
  }
  return hertz_validity(b, g.k_rxx, g.k_wxx, err, opt);
}

}  // namespace mh
