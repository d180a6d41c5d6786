#include "profile/smoothing_spline.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "core/units.hpp"

namespace mh {

double CubicSpline1::eval(double s, double* d1, double* d2) const {
  const std::size_t n = s_.size();
  if (s <= s_.front() || s >= s_.back()) {  // linear beyond the ends (f'' = 0 there)
    const bool lo = s <= s_.front();
    const std::size_t k = lo ? 0 : n - 2;
    const double h = s_[k + 1] - s_[k];
    // f' at the end knot of the end interval (Numerical Recipes eq. 3.3.5 with A or B = 0).
    const double slope = (f_[k + 1] - f_[k]) / h + (lo ? -(h / 3) * f2_[k] - (h / 6) * f2_[k + 1]
                                                      : (h / 6) * f2_[k] + (h / 3) * f2_[k + 1]);
    if (d1) *d1 = slope;
    if (d2) *d2 = 0;
    return lo ? f_.front() + slope * (s - s_.front()) : f_.back() + slope * (s - s_.back());
  }
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(s_.begin(), s_.end(), s) - s_.begin()) - 1;
  const double h = s_[i + 1] - s_[i];
  const double A = (s_[i + 1] - s) / h, B = 1 - A;
  // Press et al., Numerical Recipes §3.3 (eqs 3.3.3, 3.3.5).
  if (d1) *d1 = (f_[i + 1] - f_[i]) / h - (3 * A * A - 1) / 6 * h * f2_[i] + (3 * B * B - 1) / 6 * h * f2_[i + 1];
  if (d2) *d2 = A * f2_[i] + B * f2_[i + 1];
  return A * f_[i] + B * f_[i + 1] + ((A * A * A - A) * f2_[i] + (B * B * B - B) * f2_[i + 1]) * h * h / 6;
}

CubicSpline1 smoothing_spline(const std::vector<double>& s, const std::vector<double>& d,
                              const std::vector<double>& w, double lambda, double* trace) {
  const std::size_t n = s.size();
  if (n < 3 || d.size() != n || w.size() != n || !(lambda >= 0))
    throw std::invalid_argument("smoothing_spline: needs n >= 3 knots, matching data and weights, lambda >= 0");
  std::vector<double> h(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    h[i] = s[i + 1] - s[i];
    if (!(h[i] > 0)) throw std::invalid_argument("smoothing_spline: knots must increase strictly");
  }
  const std::size_t m = n - 2;  // interior knots: unknowns gamma_1 .. gamma_{n-2}
  // Q (n × m): column a (knot a+1) has 1/h_a, −1/h_a − 1/h_{a+1}, 1/h_{a+1} in rows a, a+1, a+2.
  auto Q = [&](std::size_t row, std::size_t a) -> double {
    if (row == a) return 1 / h[a];
    if (row == a + 1) return -1 / h[a] - 1 / h[a + 1];
    if (row == a + 2) return 1 / h[a + 1];
    return 0;
  };
  // Band of the symmetric matrix R + lambda Qᵀ W⁻¹ Q: B[a][k] = entry (a, a+k), k = 0, 1, 2.
  std::vector<std::array<double, 3>> B(m, {0, 0, 0});
  for (std::size_t a = 0; a < m; ++a) {
    B[a][0] = (h[a] + h[a + 1]) / 3;
    if (a + 1 < m) B[a][1] = h[a + 1] / 6;
  }
  for (std::size_t row = 0; row < n; ++row) {
    const std::size_t a0 = row >= 2 ? row - 2 : 0, a1 = std::min(row, m - 1);
    for (std::size_t a = a0; a <= a1; ++a)
      for (std::size_t b = a; b <= a1; ++b) B[a][b - a] += lambda * Q(row, a) * Q(row, b) / w[row];
  }
  std::vector<double> rhs(m);
  for (std::size_t a = 0; a < m; ++a) rhs[a] = Q(a, a) * d[a] + Q(a + 1, a) * d[a + 1] + Q(a + 2, a) * d[a + 2];
  // Banded Cholesky L Lᵀ (bandwidth 2), then the two triangular solves.
  std::vector<std::array<double, 3>> L(m, {0, 0, 0});  // L[a][k] = entry (a, a−k)
  for (std::size_t a = 0; a < m; ++a) {
    for (std::size_t k = 2; k >= 1; --k) {
      if (a < k) continue;
      const std::size_t b = a - k;  // entry (a, b), b < a
      double v = B[b][k];
      for (std::size_t j = 1; j <= 2; ++j)  // Σ_c L(a,c) L(b,c), c < b
        if (b >= j && k + j <= 2) v -= L[a][k + j] * L[b][j];
      L[a][k] = v / L[b][0];
    }
    double v = B[a][0];
    for (std::size_t k = 1; k <= 2; ++k)
      if (a >= k) v -= L[a][k] * L[a][k];
    L[a][0] = std::sqrt(v);
  }
  std::vector<double> g(m);
  for (std::size_t a = 0; a < m; ++a) {
    double v = rhs[a];
    for (std::size_t k = 1; k <= 2; ++k)
      if (a >= k) v -= L[a][k] * g[a - k];
    g[a] = v / L[a][0];
  }
  for (std::size_t a = m; a-- > 0;) {
    double v = g[a];
    for (std::size_t k = 1; k <= 2; ++k)
      if (a + k < m) v -= L[a + k][k] * g[a + k];
    g[a] = v / L[a][0];
  }
  if (trace) {
    // tr A = n − lambda tr(W⁻¹ Q Σ Qᵀ), Σ = (R + lambda Qᵀ W⁻¹ Q)⁻¹, of which only the band
    // |a − b| ≤ 2 is needed (Q has three diagonals): Hutchinson & de Hoog (1985, Numer. Math.
    // 47, 99) from the factor, with L = L̃ D^(1/2), l(k, a) = L[k][k−a] / L[a][0], D_a = L[a][0]²:
    // Σ(a, b) = δ_ab / D_a − Σ_{k = a+1, a+2} l(k, a) Σ(k, b) for b ≥ a, a from the last down.
    std::vector<std::array<double, 3>> S(m, {0, 0, 0});  // S[a][k] = Σ(a, a+k)
    auto sig = [&](std::size_t a, std::size_t b) {
      const std::size_t lo = std::min(a, b), k = std::max(a, b) - lo;
      return k <= 2 ? S[lo][k] : 0.0;
    };
    for (std::size_t a = m; a-- > 0;) {
      double l[3] = {0, 0, 0};
      for (std::size_t k = 1; k <= 2; ++k)
        if (a + k < m) l[k] = L[a + k][k] / L[a][0];
      for (std::size_t j = 2; j >= 1; --j) {
        if (a + j >= m) continue;
        double v = 0;
        for (std::size_t k = 1; k <= 2; ++k)
          if (a + k < m) v -= l[k] * sig(a + k, a + j);
        S[a][j] = v;
      }
      double v = 1 / (L[a][0] * L[a][0]);
      for (std::size_t k = 1; k <= 2; ++k)
        if (a + k < m) v -= l[k] * S[a][k];
      S[a][0] = v;
    }
    double t = 0;
    for (std::size_t row = 0; row < n; ++row) {
      const std::size_t a0 = row >= 2 ? row - 2 : 0, a1 = std::min(row, m - 1);
      double q = 0;
      for (std::size_t a = a0; a <= a1; ++a)
        for (std::size_t b = a0; b <= a1; ++b) q += Q(row, a) * sig(a, b) * Q(row, b);
      t += q / w[row];
    }
    *trace = static_cast<double>(n) - lambda * t;
  }
  std::vector<double> f(d), f2(n, 0.0);
  for (std::size_t a = 0; a < m; ++a) f2[a + 1] = g[a];
  for (std::size_t row = 0; row < n; ++row) {
    double qg = 0;
    const std::size_t a0 = row >= 2 ? row - 2 : 0, a1 = std::min(row, m - 1);
    for (std::size_t a = a0; a <= a1; ++a) qg += Q(row, a) * g[a];
    f[row] -= lambda * qg / w[row];
  }
  return CubicSpline1(s, std::move(f), std::move(f2));
}

namespace {

/// The smoothed profile with the weights w_i × c_i (c: local factors, 1 everywhere for one length),
/// and the normal residuals e_i of the points (sign: along the normal (−z', y')).
SmoothedProfile smooth_weighted(const Profile& p, double L, const std::vector<double>& c, std::vector<double>* e_n = nullptr,
                                std::vector<double>* s_out = nullptr) {
  const std::size_t n = p.size();
  std::vector<double> s(n, 0.0), w(n, 0.0);
  for (std::size_t i = 1; i < n; ++i) s[i] = s[i - 1] + std::hypot(p.y[i] - p.y[i - 1], p.z[i] - p.z[i - 1]);
  for (std::size_t i = 0; i < n; ++i)
    w[i] = c[i] * 0.5 * ((i + 1 < n ? s[i + 1] : s[i]) - (i > 0 ? s[i - 1] : s[i]));
  const double lambda = std::pow(L / (2 * units::pi), 4);
  SmoothedProfile sp;
  sp.L = L;
  sp.L_local_min = L;
  sp.y = smoothing_spline(s, p.y, w, lambda, &sp.dof);
  sp.z = smoothing_spline(s, p.z, w, lambda);
  double ss = 0, sn = 0;
  if (e_n) e_n->assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double dy = p.y[i] - sp.y.values()[i], dz = p.z[i] - sp.z.values()[i];
    const double e = std::hypot(dy, dz);
    ss += e * e;
    sp.max_change = std::max(sp.max_change, e);
    double ty = 0, tz = 0;
    sp.y.eval(s[i], &ty);
    sp.z.eval(s[i], &tz);
    const double t = std::hypot(ty, tz);
    const double en = t > 0 ? (-dy * tz + dz * ty) / t : 0.0;
    sn += en * en;
    if (e_n) (*e_n)[i] = en;
  }
  sp.rms_change = std::sqrt(ss / static_cast<double>(n));
  sp.rms_normal_change = std::sqrt(sn / static_cast<double>(n));
  if (s_out) *s_out = std::move(s);
  return sp;
}

}  // namespace

namespace {
/// The local weight factor of a kept point: the local length L c^(−1/4) = kKeepLength.
double keep_factor(double L) { return std::max(1.0, std::pow(L / kKeepLength, 4)); }
}  // namespace

SmoothedProfile smooth_profile(const Profile& p, double L) {
  return smooth_weighted(p, L, std::vector<double>(p.size(), 1.0));
}

SmoothedProfile smooth_profile(const Profile& p, double L, const std::vector<char>& keep) {
  std::vector<double> c(p.size(), 1.0);
  for (std::size_t i = 0; i < keep.size() && i < c.size(); ++i)
    if (keep[i]) c[i] = keep_factor(L);
  return smooth_weighted(p, L, c);
}

SmoothedProfile smooth_profile_to_noise(const Profile& p, double sigma, const NoiseSmoothingOptions& opt,
                                        const std::vector<char>& keep) {
  const std::size_t n = p.size();
  if (!(sigma > 0) || !(opt.length_scale > 0) || !(opt.L_min > 0) || !(opt.L_max >= opt.L_min) || !(opt.sigma_ref > 0) || !(opt.spacing_ref > 0) || n < 3)
    throw std::invalid_argument("smooth_profile_to_noise: needs sigma > 0, 0 < L_min <= L_max, positive references, 3 points");
  // 1. The length from the noise and the point spacing (header).
  const auto kept = [&](std::size_t i) { return i < keep.size() && keep[i] != 0; };
  std::vector<double> d;
  for (std::size_t i = 1; i < n; ++i)
    if (!kept(i) && !kept(i - 1)) d.push_back(std::hypot(p.y[i] - p.y[i - 1], p.z[i] - p.z[i - 1]));
  if (d.empty())
    throw std::invalid_argument("smooth_profile_to_noise: every point is kept (nothing to smooth)");
  std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
  const double spacing = d[d.size() / 2];
  const double L0 = opt.L_ref * std::pow(sigma / opt.sigma_ref, 2.0 / 3.0) * std::cbrt(spacing / opt.spacing_ref);
  const double L = std::clamp(L0, opt.L_min, opt.L_max);
  // 2. ... and no more: the local discrepancy guard (header).
  std::vector<double> c(n, 1.0), e, s;
  for (std::size_t i = 0; i < n; ++i)
    if (kept(i)) c[i] = keep_factor(L);
  SmoothedProfile sp = smooth_weighted(p, L, c, &e, &s);
  const double c_max = std::pow(L / opt.L_min, 4);  // the local length L c^(−1/4) stays ≥ L_min
  double from = 0, to = 0;
  bool shortened = false;
  for (int step = 0; step < opt.local_steps; ++step) {
    const double limit = opt.local_factor * sigma;
    std::vector<double> c_new = c;
    bool any = false;
    std::size_t a = 0, b = 0;
    double ss = 0;
    for (std::size_t i = 0; i < n; ++i) {
      while (b < n && s[b] <= s[i] + L / 2) { ss += e[b] * e[b]; ++b; }
      while (s[a] < s[i] - L / 2) { ss -= e[a] * e[a]; ++a; }
      const double r = std::sqrt(std::max(0.0, ss) / static_cast<double>(b - a));
      if (!(r > limit) || c[i] >= c_max) continue;
      // Halve the length over the window around i.
      const double ci = std::min(16 * c[i], c_max);
      for (std::size_t j = a; j < b; ++j) c_new[j] = std::max(c_new[j], ci);
      if (!shortened || p.y[a] < from) from = p.y[a];
      if (!shortened || p.y[b - 1] > to) to = p.y[b - 1];
      shortened = any = true;
    }
    if (!any) break;
    c = std::move(c_new);
    sp = smooth_weighted(p, L, c, &e, &s);
  }
  // 3. The uncertainty band's lengths: every length scaled, the same regions shortened.
  const double Ls = L * opt.length_scale;
  if (opt.length_scale != 1.0) sp = smooth_weighted(p, Ls, c);
  sp.sigma = sigma;
  sp.at_bound = L != L0;
  double c_max_local = 1;  // the guard's shortest local length (kept points aside)
  for (std::size_t i = 0; i < n; ++i)
    if (!kept(i)) c_max_local = std::max(c_max_local, c[i]);
  sp.L_local_min = Ls * std::pow(c_max_local, -0.25);
  sp.local_from = shortened ? from : 0;
  sp.local_to = shortened ? to : 0;
  return sp;
}

}  // namespace mh
