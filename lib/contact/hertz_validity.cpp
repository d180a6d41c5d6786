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
    // g(±b) = ∫_0^b (b − w) S(±w) dw by the trapezoidal rule on n intervals of each half.
    const int n = static_cast<int>(std::clamp(std::ceil(b / G.kappa_dy), 2.0, 200.0));
    const double h = b / n, quad = 0.5 * S0 * b * b;
    for (int side : {-1, 1}) {
      double gsum = 0;
      for (int i = 0; i <= n; ++i) {
        const double w = side * h * i;
        const double S = G.k_rxx_at(g.y_r + w) + G.k_wxx_at(g.y_w + w);
        gsum += (i == 0 || i == n ? 0.5 : 1.0) * (b - h * i) * S;
      }
      gsum *= h;
      err = std::max(err, S0 > 0 ? std::fabs(gsum - quad) / quad : INFINITY);
    }
  }
  return hertz_validity(b, g.k_rxx, g.k_wxx, err, opt);
}

}  // namespace mh
