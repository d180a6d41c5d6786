#include "profile/curve.hpp"

#include "profile/print_regions.hpp"

#include "core/roots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/errors.hpp"
#include "core/numfmt.hpp"

namespace mh {
namespace {

/// A file's print step for a person: "0.0001 mm" (not 1e-04), and a step below a picometre (a file
/// printed to 17 significant digits) as "full precision" rather than "1e-17 mm".
std::string print_step_text(double step) {
  const double mm = step * 1e3;
  if (mm < 1e-9) return "full precision";
  const int decimals = std::max(0, static_cast<int>(std::ceil(-std::log10(mm) - 1e-9)));
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f mm", std::min(decimals, 12), mm);
  return buf;
}

/// A fitted slope |dz/dy| above this (89.94°) is taken for a vertical tangent (ProfileCurve::build).
constexpr double kMaxCurveSlope = 1e3;

using curve_detail::LocalFit;

/// The direction of the window [i0, i1) (it depends on the points only, not on the node): the
/// last one computed for one kind of window, reused while consecutive nodes keep its points.
struct WindowDirection {
  std::size_t i0 = 0, i1 = 0;
  double theta = 0, c = 1, s = 0;
};

/// The least-squares circle-or-line of one window in its local frame, before the node's z, slope
/// and kappa are taken from it (finish_fit): a window that only competes by its residual (the
/// one-sided windows) needs no more.
struct WindowFit {
  bool solved = false;
  int points = 0;  // points in the window
  double rms = std::numeric_limits<double>::infinity();
  double alpha = 0, beta = 0, delta = 0, theta = 0, c = 1, s = 0, yc = 0, zc = 0;
};

// Fit points [i0, i1) around (yc, zc) in a frame rotated to the window's chord direction.
WindowFit solve_window(const std::vector<double>& y, const std::vector<double>& z, std::size_t i0,
                       std::size_t i1, double yc, double zc, WindowDirection& dir) {
  WindowFit f;
  const std::size_t n = i1 - i0;
  if (n < 3) return f;
  if (dir.i0 != i0 || dir.i1 != i1) {
    // Direction of the window: least-squares line through the points (total least squares would
    // also do; the fit below is exact whatever the rotation, this only conditions it).
    double my = 0, mz = 0;
    for (std::size_t i = i0; i < i1; ++i) { my += y[i]; mz += z[i]; }
    my /= static_cast<double>(n); mz /= static_cast<double>(n);
    double syy = 0, syz = 0, szz = 0;
    for (std::size_t i = i0; i < i1; ++i) {
      const double dy = y[i] - my, dz = z[i] - mz;
      syy += dy * dy; syz += dy * dz; szz += dz * dz;
    }
    dir.theta = 0.5 * std::atan2(2 * syz, syy - szz);  // principal direction
    dir.c = std::cos(dir.theta), dir.s = std::sin(dir.theta);
    dir.i0 = i0, dir.i1 = i1;
  }
  const double theta = dir.theta, c = dir.c, s = dir.s;
  // Normal equations for v = alpha q + beta u + delta, q = u² + v²: M = Σ x xᵀ, r = Σ x v with
  // x = (q, u, 1), its six distinct sums (M is symmetric; products with 1 are exact). The local
  // coordinates are kept for the residual below.
  thread_local std::vector<double> uv;
  uv.resize(2 * n);
  double Sqq = 0, Squ = 0, Sq = 0, Suu = 0, Su = 0, S1 = 0, Rq = 0, Ru = 0, Rv = 0;
  for (std::size_t i = i0; i < i1; ++i) {
    const double dy = y[i] - yc, dz = z[i] - zc;
    const double u = c * dy + s * dz, v = -s * dy + c * dz;
    const double q = u * u + v * v;
    uv[2 * (i - i0)] = u;
    uv[2 * (i - i0) + 1] = v;
    Rq += q * v, Sqq += q * q, Squ += q * u, Sq += q;
    Ru += u * v, Suu += u * u, Su += u;
    Rv += v, S1 += 1.0;
  }
  double M[3][3] = {{Sqq, Squ, Sq}, {Squ, Suu, Su}, {Sq, Su, S1}}, r[3] = {Rq, Ru, Rv};
  // Solve by Gaussian elimination with partial pivoting (3×3).
  int p[3] = {0, 1, 2};
  double A[3][4];
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) A[a][b] = M[a][b];
    A[a][3] = r[a];
  }
  for (int col = 0; col < 3; ++col) {
    int piv = col;
    for (int row = col + 1; row < 3; ++row)
      if (std::fabs(A[row][col]) > std::fabs(A[piv][col])) piv = row;
    if (piv != col) for (int b = 0; b < 4; ++b) std::swap(A[col][b], A[piv][b]);
    if (std::fabs(A[col][col]) < 1e-300) {
      // Degenerate (all points on a line through the centre of the window with no spread in
      // q): fall back to a straight line.
      if (col == 0) { A[0][0] = 1; A[0][1] = A[0][2] = A[0][3] = 0; continue; }
      return f;
    }
    for (int row = col + 1; row < 3; ++row) {
      const double fct = A[row][col] / A[col][col];
      for (int b = col; b < 4; ++b) A[row][b] -= fct * A[col][b];
    }
  }
  (void)p;
  double sol[3];
  for (int a = 2; a >= 0; --a) {
    double acc = A[a][3];
    for (int b = a + 1; b < 3; ++b) acc -= A[a][b] * sol[b];
    sol[a] = acc / A[a][a];
  }
  const double alpha = sol[0], beta = sol[1], delta = sol[2];
  // Residual (in v, i.e. normal to the chord).
  double ss = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double u = uv[2 * k], v = uv[2 * k + 1];
    const double e = v - (alpha * (u * u + v * v) + beta * u + delta);
    ss += e * e;
  }
  f.rms = std::sqrt(ss / static_cast<double>(n));
  f.points = static_cast<int>(n);
  f.solved = true;
  f.alpha = alpha, f.beta = beta, f.delta = delta, f.theta = theta, f.c = c, f.s = s, f.yc = yc, f.zc = zc;
  return f;
}

// The node's z, slope and kappa from its window's circle-or-line.
LocalFit finish_fit(const WindowFit& w) {
  LocalFit f;
  if (!w.solved) return f;
  f.rms = w.rms;
  f.points = w.points;
  const double alpha = w.alpha, beta = w.beta, delta = w.delta, theta = w.theta, c = w.c, s = w.s, yc = w.yc, zc = w.zc;
  // Curve point at u = 0: alpha v² − v + delta = 0, the small root (stable form).
  const double disc = 1.0 - 4.0 * alpha * delta;
  if (disc <= 0) return f;
  const double v0 = 2.0 * delta / (1.0 + std::sqrt(disc));
  // Slope in the local frame, F(u,v) = alpha(u²+v²) + beta u − v + delta: dv/du = −F_u/F_v.
  const double dvdu = beta / (1.0 - 2.0 * alpha * v0);
  const double phi = theta + std::atan(dvdu);
  // Circle curvature, signed: centre at (−beta/2alpha, 1/2alpha) in the local frame.
  f.kappa = 2.0 * alpha / std::sqrt(beta * beta + 1.0 - 4.0 * alpha * delta);
  // Back to the global frame; move the point from y(u=0) to yc along the tangent (second order
  // in v0·sin(theta), which is far below the fit's accuracy).
  const double yp = yc - s * v0, zp = zc + c * v0;
  const double slope_p = std::tan(phi);
  const double zpp = f.kappa * std::pow(1 + slope_p * slope_p, 1.5);  // z'' at the point
  f.z = zp + slope_p * (yc - yp) + 0.5 * zpp * (yc - yp) * (yc - yp);
  f.slope = slope_p + zpp * (yc - yp);
  f.ok = std::isfinite(f.z) && std::isfinite(f.slope) && std::isfinite(f.kappa);
  return f;
}

LocalFit fit_window(const std::vector<double>& y, const std::vector<double>& z, std::size_t i0, std::size_t i1,
                    double yc, double zc, WindowDirection& dir) {
  return finish_fit(solve_window(y, z, i0, i1, yc, zc, dir));
}

}  // namespace

std::optional<SmoothedProfile> smooth_for_contact(const Profile& p, const NoiseDecision& noise,
                                                  const std::optional<double>& L, const NoiseSmoothingOptions& opt) {
  if (!noise.measured) return std::nullopt;
  // A mixed profile's exact regions are kept as they are (NoiseDecision::regions).
  std::vector<char> keep;
  if (noise.mixed()) {
    keep.resize(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) keep[i] = noise.exact_at(p.y[i]);
  }
  if (L) {
    if (!(*L > 0)) return std::nullopt;
    return smooth_profile(p, *L * opt.length_scale, keep);
  }
  if (!(noise.sigma > 0)) return std::nullopt;
  return smooth_profile_to_noise(p, noise.sigma, opt, keep);
}

ProfileNoise parse_profile_noise(const std::string& s) {
  if (s == "auto") return ProfileNoise::Auto;
  if (s == "exact") return ProfileNoise::Exact;
  if (s == "measured") return ProfileNoise::Measured;
  throw std::invalid_argument("unknown profile noise '" + s + "' (expected auto, exact or measured)");
}

const char* to_string(ProfileNoise n) {
  switch (n) {
    case ProfileNoise::Auto: return "auto";
    case ProfileNoise::Exact: return "exact";
    case ProfileNoise::Measured: return "measured";
  }
  return "?";
}

namespace {
std::string um(double v_m) { return format_number(std::round(v_m * 1e9) / 1e3) + " µm"; }  // to 1 nm
}  // namespace

ProfileCurve::ProfileCurve(const Profile& p, const CurveOptions& opt) {
  // The narrow window's centred fits first: their median residual decides measured or exact, and
  // only an exact profile needs the rest of the narrow curve (a measured one is refitted wide).
  std::vector<LocalFit> centred;
  build(p, opt, opt.window_half_width, true, &centred);
  // Measured or exact (profiles.md "Measured or exact"): the residual against what rounding the
  // printed coordinates explains.
  NoiseDecision& d = noise_;
  std::string rule;
  d = classify_noise(centred, 0, centred.size(), median_rms_, p.print_step, opt, &rule);
  if (opt.noise != ProfileNoise::Auto) {
    d.forced = true;
    d.measured = opt.noise == ProfileNoise::Measured;
    d.reason = std::string(d.measured ? "measured" : "exact") + ": forced by the noise option; " + rule;
  } else {
    classify_regions(p, centred, opt);
  }
  const bool wide = opt.measured_window_half_width > opt.window_half_width;
  if (d.mixed() && wide) {
    // The narrow window's curve at the exact regions' nodes, the wide one's elsewhere.
    build(p, opt, opt.window_half_width, false, &centred);
    const std::vector<double> z = z_, dz = dz_, k = k_;
    const std::vector<signed char> side = side_;
    build(p, opt, opt.measured_window_half_width);
    for (std::size_t j = 0; j < z_.size(); ++j)
      if (d.exact_at(node_y(j))) z_[j] = z[j], dz_[j] = dz[j], k_[j] = k[j], side_[j] = side[j];
    median_rms_ = d.median_residual;
  } else if (d.measured && wide) {
    build(p, opt, opt.measured_window_half_width);
  } else {
    build(p, opt, opt.window_half_width, false, &centred);
  }
}

bool NoiseDecision::exact_at(double y) const {
  for (const NoiseRegion& r : regions)
    if (y >= r.y_from && y <= r.y_to) return !r.measured;
  return false;
}

NoiseDecision ProfileCurve::classify_noise(const std::vector<LocalFit>& centred, std::size_t j0, std::size_t j1,
                                           double median_residual, double print_step, const CurveOptions& opt,
                                           std::string* rule_out) {
  NoiseDecision d;
  d.median_residual = median_residual;
  d.print_step = print_step;
  d.rounding_rms = print_step / std::sqrt(12.0);
  // The rounding allowance is a bound on σ (quantisation_factor × q/√12), carried to the median
  // residual it corresponds to: σ = r √(k/ν / m_ν) for fits of k points (below), so the bound on r
  // is the bound on σ times √(ν m_ν / k) at the median k (k = 7: 0.69).
  double r_per_sigma = 1;
  {
    std::vector<double> v;
    std::vector<int> k;
    for (std::size_t j = j0; j < j1; ++j) {
      const LocalFit& f = centred[j];
      if (f.ok && f.points > 3 && std::isfinite(f.rms)) {
        v.push_back(f.rms * f.rms * f.points / (f.points - 3));
        k.push_back(f.points);
      }
    }
    if (!v.empty()) {
      const auto mid = static_cast<std::ptrdiff_t>(v.size() / 2);
      std::nth_element(v.begin(), v.begin() + mid, v.end());
      std::nth_element(k.begin(), k.begin() + mid, k.end());
      const double nu = k[v.size() / 2] - 3;
      const double median_chi2 = std::pow(1 - 2 / (9 * nu), 3);  // Wilson & Hilferty 1931
      d.sigma = std::sqrt(v[v.size() / 2] / median_chi2);
      r_per_sigma = std::sqrt(nu * median_chi2 / (nu + 3));
    }
  }
  d.threshold = std::max(opt.noise_threshold, opt.quantisation_factor * d.rounding_rms * r_per_sigma);
  const std::string step = print_step > 0 ? "the printed " + print_step_text(print_step) : "";
  const std::string rule =
      "median residual " + um(d.median_residual) + (d.median_residual > d.threshold ? " > " : " <= ") + um(d.threshold) +
      (d.threshold > opt.noise_threshold
           ? " (the residual of a noise sigma of " + format_number(std::round(opt.quantisation_factor * 100) / 100) + " x " + um(d.rounding_rms) +
                 ", rounding to " + step + ": scatter beyond the rounding as large as the rounding's own; sigma " + um(d.sigma) + ")"
           : " (noise threshold" + (step.empty() ? std::string() : "; rounding to " + step + " explains " + um(d.rounding_rms)) + ")");
  const bool coarse = d.rounding_rms > opt.max_exact_rounding && d.median_residual > opt.noise_threshold;
  const std::string coarse_rule = "printed to " + print_step_text(print_step) + ", whose rounding (" +
                                  um(d.rounding_rms) + " RMS) exceeds " + um(opt.max_exact_rounding) +
                                  ": noise to the narrow window; " + rule;
  d.measured = d.median_residual > (coarse ? opt.noise_threshold : d.threshold);
  d.reason = std::string(d.measured ? "measured: " : "exact: ") + (coarse ? coarse_rule : rule);
  if (rule_out) *rule_out = rule;
  return d;
}

void ProfileCurve::classify_regions(const Profile& p, const std::vector<LocalFit>& centred, const CurveOptions& opt) {
  const std::vector<PrintRegion> pr = print_regions(p);
  if (pr.size() < 2 || centred.empty()) return;
  NoiseDecision& d = noise_;
  std::vector<NoiseRegion> regions;
  std::string reason;
  double sigma = 0;
  bool any_measured = false, any_exact = false;
  for (std::size_t r = 0; r < pr.size(); ++r) {
    NoiseRegion g;
    // Boundaries halfway between the regions' outer points (the profile's ends beyond).
    g.y_from = r == 0 ? -std::numeric_limits<double>::infinity() : 0.5 * (p.y[pr[r - 1].last] + p.y[pr[r].first]);
    g.y_to = r + 1 == pr.size() ? std::numeric_limits<double>::infinity() : 0.5 * (p.y[pr[r].last] + p.y[pr[r + 1].first]);
    g.print_step = pr[r].step;
    // The narrow centred fits at its nodes (node j at node_y(j): the nodes built so far).
    std::size_t j0 = centred.size(), j1 = 0;
    for (std::size_t j = 0; j < centred.size(); ++j)
      if (node_y(j) >= g.y_from && node_y(j) <= g.y_to) j0 = std::min(j0, j), j1 = j + 1;
    if (j0 >= j1) continue;  // outside the nodes built (CurveOptions::y_from, y_to)
    std::vector<double> rms;
    for (std::size_t j = j0; j < j1; ++j) rms.push_back(centred[j].rms);
    std::nth_element(rms.begin(), rms.begin() + static_cast<std::ptrdiff_t>(rms.size() / 2), rms.end());
    const NoiseDecision c = classify_noise(centred, j0, j1, rms[rms.size() / 2], g.print_step, opt);
    g.median_residual = c.median_residual;
    g.threshold = c.threshold;
    g.sigma = c.sigma;
    g.measured = c.measured;
    (g.measured ? any_measured : any_exact) = true;
    if (g.measured) sigma = std::max(sigma, g.sigma);
    const std::string from = std::isfinite(g.y_from) ? format_number(std::round(g.y_from * 1e5) / 100) : "start";
    const std::string to = std::isfinite(g.y_to) ? format_number(std::round(g.y_to * 1e5) / 100) : "end";
    reason += (reason.empty() ? "" : "; ") + std::string("y ") + from + " … " + to + " mm " + c.reason;
    regions.push_back(g);
  }
  if (!(any_measured && any_exact)) return;  // one class: the whole profile's decision stands
  d.regions = std::move(regions);
  d.measured = true;
  d.sigma = sigma;
  d.reason = "mixed, by printed precision: " + reason;
}

void ProfileCurve::build(const Profile& p, const CurveOptions& opt, double w, bool centred_only,
                         std::vector<LocalFit>* centred) {
  window_ = w;
  std::vector<double> rms;
  const std::size_t n = p.size();
  const std::string where = p.source.empty() ? std::string("profile") : p.source;
  if (n < static_cast<std::size_t>(std::max(opt.min_points, 3)))
    throw InputError(where, std::to_string(n) + " points",
                     "a profile needs at least " + std::to_string(opt.min_points) + " points");
  for (std::size_t i = 1; i < n; ++i)
    if (!(p.y[i] > p.y[i - 1]))
      throw InputError(where, "y = " + std::to_string(p.y[i] * 1e3) + " mm",
                       "profile points must have strictly increasing y");
  h_ = opt.grid_step;
  const double y_first = p.y.front();
  const std::size_t m_all = static_cast<std::size_t>(std::floor((p.y.back() - y_first) / h_ + 1e-9)) + 1;
  // Nodes j_lo … j_lo + m − 1 of the full grid (CurveOptions::y_from, y_to), at least two.
  std::size_t j_lo = 0, j_hi = m_all - 1;
  if (opt.y_from > y_first) j_lo = std::min(m_all - 1, static_cast<std::size_t>(std::floor((opt.y_from - y_first) / h_)));
  if (opt.y_to < p.y.back()) j_hi = std::min(m_all - 1, static_cast<std::size_t>(std::ceil((opt.y_to - y_first) / h_)));
  if (j_hi < j_lo + 1) {
    j_hi = std::min(m_all - 1, j_lo + 1);
    j_lo = j_hi > 0 ? j_hi - 1 : 0;
  }
  const std::size_t m = j_hi - j_lo + 1;
  y_first_ = y_first;
  j0_ = j_lo;
  y0_ = y_first + h_ * static_cast<double>(j_lo);
  z_.resize(m); dz_.resize(m); k_.resize(m); side_.resize(m);
  const auto& Y = p.y;
  const auto& Z = p.z;
  // Windows are measured along the profile (chord length), not in y, so that steep flanks get as
  // short a window as the tread.
  std::vector<double> S(n, 0.0);
  for (std::size_t i = 1; i < n; ++i) S[i] = S[i - 1] + std::hypot(Y[i] - Y[i - 1], Z[i] - Z[i - 1]);
  // std::lower_bound / upper_bound of v, walked from where the same search stopped at the previous
  // node (`at`): the nodes advance by less than a point spacing, so a step or two instead of a
  // binary search; the same index (the walk stops where the bound's definition holds; NaN, which
  // compares false to everything, takes the binary search).
  auto lower_at = [&](const std::vector<double>& A, double v, std::size_t& at) {
    if (std::isnan(v)) return at = static_cast<std::size_t>(std::lower_bound(A.begin(), A.end(), v) - A.begin());
    while (at > 0 && A[at - 1] >= v) --at;
    while (at < A.size() && A[at] < v) ++at;
    return at;
  };
  auto upper_at = [&](const std::vector<double>& A, double v, std::size_t& at) {
    if (std::isnan(v)) return at = static_cast<std::size_t>(std::upper_bound(A.begin(), A.end(), v) - A.begin());
    while (at > 0 && A[at - 1] > v) --at;
    while (at < A.size() && A[at] <= v) ++at;
    return at;
  };
  std::size_t at_c0 = 0, at_c1 = 0, at_l0 = 0, at_r1 = 0, at_sc = 0, at_y = 0;
  // Widen [i0, i1) symmetrically (within the data) until it holds min_points.
  auto widen = [&](std::size_t& i0, std::size_t& i1, int dir) {
    const std::size_t need = static_cast<std::size_t>(opt.min_points);
    while (i1 - i0 < need && (i0 > 0 || i1 < n)) {
      if (dir <= 0 && i0 > 0) --i0;
      if (i1 - i0 >= need) break;
      if (dir >= 0 && i1 < n) ++i1;
      if (dir < 0 && i0 == 0 && i1 < n) ++i1;
      if (dir > 0 && i1 == n && i0 > 0) --i0;
    }
  };
  rms.reserve(m);
  WindowDirection dir_centred, dir_left, dir_right;
  for (std::size_t j = 0; j < m; ++j) {
    const double yc = y_first + h_ * static_cast<double>(j_lo + j);
    // Linear interpolation of the raw points as the local origin height.
    std::size_t k = std::min(std::max<std::size_t>(upper_at(Y, yc, at_y), 1), n - 1);
    const double t = (yc - Y[k - 1]) / (Y[k] - Y[k - 1]);
    const double zc = Z[k - 1] + t * (Z[k] - Z[k - 1]);
    const double sc = S[k - 1] + t * (S[k] - S[k - 1]);

    LocalFit best;
    if (centred && !centred_only) {
      best = (*centred)[j];
    } else {
      std::size_t c0 = lower_at(S, sc - w, at_c0), c1 = upper_at(S, sc + w, at_c1);
      widen(c0, c1, 0);
      best = fit_window(Y, Z, c0, c1, yc, zc, dir_centred);
    }
    rms.push_back(best.rms);
    if (centred_only) {
      centred->push_back(best);
      if (best.ok) continue;  // else the one-sided fits below, which throw if they fail too
    }
    int side = 0;
    // One-sided windows reach one data point past yc, so that a window on the wrong side of a
    // junction always holds a point of the other arc (and shows it in its residual).
    const std::size_t ihi = std::min(upper_at(S, sc, at_sc), n - 1);
    const std::size_t ilo = ihi > 0 ? ihi - 1 : 0;
    std::size_t l0 = lower_at(S, sc - 2 * w, at_l0), l1 = ihi + 1;
    std::size_t r0 = ilo, r1 = upper_at(S, sc + 2 * w, at_r1);
    widen(l0, l1, -1);
    widen(r0, r1, +1);
    const WindowFit left = solve_window(Y, Z, l0, l1, yc, zc, dir_left);
    const WindowFit right = solve_window(Y, Z, r0, r1, yc, zc, dir_right);
    const WindowFit& one = (left.rms <= right.rms) ? left : right;
    // The better one-sided fit replaces a failed centred one, or one whose residual is above the
    // floor and one_sided_factor times its own when it gives a point (only then is it finished).
    if (!best.ok || (best.rms > opt.residual_floor && best.rms > opt.one_sided_factor * one.rms)) {
      const LocalFit f = finish_fit(one);
      if (!best.ok || f.ok) {
        best = f;
        side = (&one == &left) ? -1 : +1;
      }
    }
    if (!best.ok)
      throw InputError(where, "y = " + std::to_string(yc * 1e3) + " mm",
                       "no smooth local fit possible (degenerate points)");
    z_[j] = best.z;
    dz_[j] = best.slope;
    k_[j] = best.kappa;
    side_[j] = static_cast<signed char>(side);
  }
  // A node where the profile is vertical (the first point of a 60E1 rail at 1:20, at its
  // R13/flank tangency; S1002 at S = −70) has no finite slope dz/dy: the fit's is ±1e14 or so,
  // of either sign, and the cubic Hermite cell beside it would swing by metres (and the linear
  // extrapolation beyond an end rise like a wall). Such a slope is replaced by the largest that
  // keeps the neighbouring cells monotone, 3 times their secant (Fritsch & Carlson 1980, SIAM J.
  // Numer. Anal. 17, 238), 0 between secants of opposite signs.
  for (std::size_t j = 0; j < m; ++j) {
    if (!(std::fabs(dz_[j]) > kMaxCurveSlope)) continue;
    const double dl = j > 0 ? (z_[j] - z_[j - 1]) / h_ : NAN, dr = j + 1 < m ? (z_[j + 1] - z_[j]) / h_ : NAN;
    if (std::isnan(dl) && std::isnan(dr)) continue;
    if (std::isnan(dl)) dz_[j] = 3 * dr;
    else if (std::isnan(dr)) dz_[j] = 3 * dl;
    else dz_[j] = dl * dr > 0 ? std::copysign(3 * std::min(std::fabs(dl), std::fabs(dr)), dl) : 0.0;
  }
  std::nth_element(rms.begin(), rms.begin() + static_cast<std::ptrdiff_t>(rms.size() / 2), rms.end());
  median_rms_ = rms[rms.size() / 2];
}

ProfileCurve::ProfileCurve(const SmoothedProfile& sp, double grid_step, const NoiseDecision& noise)
    : noise_(noise), smoothing_L_(sp.L), smoothing_rms_(sp.rms_change), smoothing_max_(sp.max_change),
      smoothing_sigma_(sp.sigma), smoothing_at_bound_(sp.at_bound), smoothing_local_min_(sp.L_local_min),
      smoothing_local_from_(sp.local_from), smoothing_local_to_(sp.local_to) {
  const std::vector<double>& S = sp.y.knots();
  const double s_end = S.back();
  h_ = grid_step;
  y0_ = sp.y.eval(S.front());
  y_first_ = y0_;  // the whole grid (no CurveOptions::y_from / y_to window)
  j0_ = 0;
  const double y_end = sp.y.eval(s_end);
  const std::size_t m = static_cast<std::size_t>(std::floor((y_end - y0_) / h_ + 1e-9)) + 1;
  z_.resize(m); dz_.resize(m); k_.resize(m); side_.assign(m, 0);
  double s_lo = S.front();
  for (std::size_t j = 0; j < m; ++j) {
    const double yj = y0_ + h_ * static_cast<double>(j);
    // s where y(s) = yj, from the previous node's s (y(s) increases with s): bisection
    // (core/roots.hpp).
    RootTolerance tol;
    tol.abs = 1e-15;
    tol.rel = 0;
    const double fa = sp.y.eval(s_lo) - yj, fb = sp.y.eval(s_end) - yj;
    const double s = fa >= 0 ? s_lo : fb <= 0 ? s_end
                                              : bisected_root([&](double c) { return sp.y.eval(c) - yj; }, s_lo, s_end, tol).x;
    s_lo = s;
    double y1 = 0, y2 = 0, z1 = 0, z2 = 0;
    sp.y.eval(s, &y1, &y2);
    z_[j] = sp.z.eval(s, &z1, &z2);
    dz_[j] = z1 / y1;
    // Curvature of the plane curve (y(s), z(s)): (y' z'' − z' y'') / (y'² + z'²)^(3/2); with y
    // increasing it is z''/(1+z'²)^(3/2) of z(y), the sign convention above.
    k_[j] = (y1 * z2 - z1 * y2) / std::pow(y1 * y1 + z1 * z1, 1.5);
  }
  window_ = 0;
  median_rms_ = noise.median_residual;
}

ProfileCurve ProfileCurve::from_nodes(double y_first, double h, std::vector<double> z, std::vector<double> dz,
                                      std::vector<double> kappa, const ProfileCurve& like) {
  ProfileCurve c = like;
  c.h_ = h;
  c.y0_ = c.y_first_ = y_first;
  c.j0_ = 0;
  c.side_.assign(z.size(), 0);
  c.z_ = std::move(z);
  c.dz_ = std::move(dz);
  c.k_ = std::move(kappa);
  return c;
}

void ProfileCurve::assign_nodes(double y_first, double h, const std::vector<double>& z, const std::vector<double>& dz,
                                const std::vector<double>& kappa, const ProfileCurve& like, std::size_t reserve) {
  *this = like;  // copy-assignment: the vectors keep their capacity
  if (z.size() > z_.capacity())
    for (auto* v : {&z_, &dz_, &k_}) v->reserve(std::max(reserve, z.size()));
  if (z.size() > side_.capacity()) side_.reserve(std::max(reserve, z.size()));
  h_ = h;
  y0_ = y_first_ = y_first;
  j0_ = 0;
  side_.assign(z.size(), 0);
  z_.assign(z.begin(), z.end());
  dz_.assign(dz.begin(), dz.end());
  k_.assign(kappa.begin(), kappa.end());
}

double ProfileCurve::node_z_span() const {
  if (z_.empty()) return 0;
  const auto [lo, hi] = std::minmax_element(z_.begin(), z_.end());
  return *hi - *lo;
}

double ProfileCurve::kappa(double y) const {
  const std::size_t m = k_.size();
  double s = grid_pos(y);
  if (s <= 0) return k_[0];
  if (s >= static_cast<double>(m - 1)) return k_[m - 1];
  const std::size_t i = static_cast<std::size_t>(s);
  const double t = s - static_cast<double>(i);
  return k_[i] + t * (k_[i + 1] - k_[i]);
}

int ProfileCurve::window_side(double y) const {
  double s = std::round(grid_pos(y));
  s = std::clamp(s, 0.0, static_cast<double>(side_.size() - 1));
  return side_[static_cast<std::size_t>(s)];
}

}  // namespace mh
