#include "contact/ellipse/hertz_validity.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "geometry/gap.hpp"

namespace mh {


Warning HertzValidity::warning(int ellipse, const HertzValidityOptions& opt) const {
  Warning w(WarningClass::NonHertzian, ContactKind::Ellipse, ellipse);
  if (b_over_R_failed) w.add(Quantity::BOverR, b_over_R, '>', opt.max_b_over_R);
  if (gap_error_failed) w.add(Quantity::GapError, gap_error, '>', opt.max_gap_error);
  if (gap_mean_error_failed) w.add(Quantity::GapMeanError, gap_mean_error, '>', opt.max_gap_mean_error);
  if (surface_gap_error_failed) w.add(Quantity::SurfaceGapError, surface_gap_error, '>', opt.max_gap_error);
  if (surface_gap_mean_error_failed)
    w.add(Quantity::SurfaceGapMeanError, surface_gap_mean_error, '>', opt.max_gap_mean_error);
  return w;
}

HertzValidity hertz_validity(double b, double k_rxx, double k_wxx, double gap_error, double gap_mean_error,
                             const HertzValidityOptions& opt) {
  HertzValidity v;
  const double kmax = std::max(std::fabs(k_rxx), std::fabs(k_wxx));  // 1 / min(|R|)
  v.b_over_R = std::fabs(b) * kmax;
  v.gap_error = gap_error;
  v.gap_mean_error = gap_mean_error;
  // NaN ratios fail (a comparison with NaN is false).
  v.b_over_R_failed = !(v.b_over_R <= opt.max_b_over_R);
  v.gap_error_failed = !(v.gap_error <= opt.max_gap_error);
  v.gap_mean_error_failed = !(v.gap_mean_error <= opt.max_gap_mean_error);
  v.valid = !v.b_over_R_failed && !v.gap_error_failed && !v.gap_mean_error_failed;
  return v;
}

namespace {

// The edge-gap errors of the Hertz quadratic on one pair of curvature samples (rail, wheel):
// g(±b) = ∫_0^b (b − w) S(±w) dw, S = k_rxx + k_wxx along both profiles from the contact
// point, exact for the sampled (piecewise linear) curvatures. w runs along the patch, in the
// contact plane, i.e. along the arc of the profiles, while the samples are uniform in the
// profiles' lateral y: the arc length w lies at y ± w cos γ (the tangent at the contact point
// is inclined by γ), so with v = w cos γ, g(±b) = edge_gap(y, b cos γ, ±1) / cos²γ. Without
// it a flange patch at γ = 70° would be tested 2.9 patch half-widths out.
void edge_gap_errors(const CurvatureSamples& rail, const CurvatureSamples& wheel, const CandidateGeom& g, double b,
                     double* err, double* mean_err) {
  const double S0 = g.k_rxx + g.k_wxx;  // 2B at the contact point
  const double c = std::cos(g.gamma), bc = b * c;
  const double quad = 0.5 * S0 * b * b;
  double e[2];
  for (int side : {-1, 1}) {
    const double gb = (rail.edge_gap(g.y_r, bc, side) + wheel.edge_gap(g.y_w, bc, side)) / (c * c);
    e[side > 0] = S0 > 0 ? (gb - quad) / quad : INFINITY;
  }
  *err = std::max(std::fabs(e[0]), std::fabs(e[1]));
  *mean_err = S0 > 0 ? 0.5 * std::fabs(e[0] + e[1]) : INFINITY;
}

}  // namespace

HertzValidity hertz_validity(const ContactGeometry& G, const CandidateGeom& g, double b,
                             const HertzValidityOptions& opt) {
  double err = 0, mean_err = 0;
  if (b > 0 && G.has_curvature_samples()) edge_gap_errors(G.rail_k, G.wheel_k, g, b, &err, &mean_err);
  HertzValidity v = hertz_validity(b, g.k_rxx, g.k_wxx, err, mean_err, opt);
  // The contact surface of a profile smoothed for contact, against the same B b² (header).
  if (b > 0 && G.has_contact_surface_samples()) {
    edge_gap_errors(G.rail_gap_k, G.wheel_gap_k, g, b, &v.surface_gap_error, &v.surface_gap_mean_error);
    v.surface_gap_error_failed = !(v.surface_gap_error <= opt.max_gap_error);  // NaN fails
    v.surface_gap_mean_error_failed = !(v.surface_gap_mean_error <= opt.max_gap_mean_error);
    v.valid = v.valid && !v.surface_gap_error_failed && !v.surface_gap_mean_error_failed;
  }
  return v;
}

void GapKink::add_to(Warning& w, const HertzValidityOptions& opt) const {
  if (!valid) w.add(Quantity::GapKink, kink_ratio, '>', opt.max_gap_mean_error);
}

GapKink gap_kink(const WheelRailGap& gap, const CandidateGeom& g, double B, double b, double p0, double E_pair,
                 double dz, const HertzValidityOptions& opt, bool use_bound) {
  GapKink k;
  if (!(b > 0) || !(p0 > 0)) return k;
  const PatchPlane P = plane_at(gap, g.y_r);
  const double h = b / 40;
  constexpr int n = 160;  // s = −b … b in steps of h/2
  auto ratio = [&](double dtheta) { return E_pair * dtheta / (2 * M_PI * p0); };
  const double limit = opt.max_gap_mean_error * (1 - 1e-9);
  // Bounds before the samples (geometry/gap.hpp), for the centres s = −b … b. Cheapest first:
  // gap_curvature_bound, one bound for every centre from the range of the gap's curvature over
  // the whole span (most tread patches pass it).
  if (use_bound) {
    const KinkBound qb = gap_curvature_bound(gap, P, -b, h, n + 1, B, dz);
    if (qb.found && ratio(qb.dtheta) <= limit) {
      k.dtheta = qb.dtheta;
      k.kink_ratio = ratio(qb.dtheta);
      k.bounded = true;
      return k;
    }
  }
  // Then gap_kink_bound, a bound per centre: first on the polylines spaced at most h (half the
  // kinks to sum), then at most h/2 (closer to the curves: the patches near the limit, flange
  // roots). Each centre keeps the lesser of its two bounds; the samples then visit only the
  // centres whose bound exceeds the limit (a centre within it has its Δθ_i within it too, so the
  // verdict and, when the test fails, the largest Δθ_i are those of all the samples).
  std::array<double, n + 1> cb, cb2;
  bool have = false;
  if (use_bound)
    for (const double spacing : {h, 0.5 * h}) {
      const KinkBound kb = gap_kink_bound(gap, P, -b, h, n + 1, B, dz, spacing, have ? cb2.data() : cb.data());
      if (!kb.found) continue;
      if (have)
        for (int i = 0; i <= n; ++i) cb[static_cast<std::size_t>(i)] = std::min(cb[static_cast<std::size_t>(i)], cb2[static_cast<std::size_t>(i)]);
      have = true;
      const double worst = *std::max_element(cb.begin(), cb.end());
      if (ratio(worst) <= limit) {
        k.dtheta = worst;
        k.kink_ratio = ratio(worst);
        k.bounded = true;
        return k;
      }
    }
  // The samples: G_j at s = −b − h + (h/2) j, centre i (s_i = −b + (i/2) h) from G_i, G_i+2, G_i+4;
  // every centre without a bound, else those whose bound exceeds the limit, in runs of
  // consecutive samples (each run's Newton solves start from its previous sample's hits).
  std::array<double, n + 5> G;
  std::array<bool, n + 5> need{};
  for (int i = 0; i <= n; ++i)
    if (!have || ratio(cb[static_cast<std::size_t>(i)]) > limit)
      need[static_cast<std::size_t>(i)] = need[static_cast<std::size_t>(i + 2)] = need[static_cast<std::size_t>(i + 4)] = true;
  for (int j = 0; j < n + 5;) {
    if (!need[static_cast<std::size_t>(j)]) { ++j; continue; }
    int e = j;
    while (e < n + 5 && need[static_cast<std::size_t>(e)]) ++e;
    normal_gaps(gap, P, 0, -b - h + 0.5 * h * j, 0.5 * h, e - j, dz, G.data() + j);
    j = e;
  }
  double bound_rest = 0;  // the largest bound of the centres not sampled
  for (int i = 2; i <= n + 2; ++i) {  // s_i = −b + (i − 2) h/2, neighbours two samples away
    if (have && !(ratio(cb[static_cast<std::size_t>(i - 2)]) > limit)) {
      bound_rest = std::max(bound_rest, cb[static_cast<std::size_t>(i - 2)]);
      continue;
    }
    const double D = G[static_cast<std::size_t>(i + 2)] - 2 * G[static_cast<std::size_t>(i)] + G[static_cast<std::size_t>(i - 2)];
    k.dtheta = std::max(k.dtheta, std::fabs(D - 2 * B * h * h) / h);
  }
  k.kink_ratio = ratio(k.dtheta);
  k.valid = k.kink_ratio <= opt.max_gap_mean_error;  // NaN fails
  if (k.valid && bound_rest > k.dtheta) {  // valid: the figures a bound of all the centres
    k.dtheta = bound_rest;
    k.kink_ratio = ratio(bound_rest);
    k.bounded = true;
  }
  return k;
}

}  // namespace mh
