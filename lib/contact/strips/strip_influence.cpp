// The elastic influence of one strip; see strip_influence.hpp.
//
// Sources:
//  - Johnson, Contact Mechanics (1985) §3.2 (Boussinesq point load, pressure on
//    a rectangle).
#include "contact/strips/strip_influence.hpp"

#include "contact/strips/strip_patch.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <utility>
#include "core/units.hpp"

namespace mh {
namespace strips_detail {

namespace {

constexpr double kPi = units::pi;

int sgn(double v) { return (v > 0.0) - (v < 0.0); }

/// Lateral integral of the Boussinesq kernel across a strip:
/// F(X) = int_{eta1}^{eta2} d eta / sqrt(X^2 + eta^2) = asinh(eta2/|X|) - asinh(eta1/|X|),
/// written with logs so that |X| cancels when eta1, eta2 have the same sign.
double lateral_kernel(double X, double e1, double e2) {
  // asinh(e/|X|) = sgn(e) [ln(|e| + sqrt(e^2 + X^2)) - ln|X|]; one log per call.
  const double X2 = X * X;
  const double n1 = std::fabs(e1) + std::sqrt(e1 * e1 + X2);
  const double n2 = std::fabs(e2) + std::sqrt(e2 * e2 + X2);
  const int s1 = sgn(e1), s2 = sgn(e2);
  if (s1 == s2) return s2 == 0 ? 0.0 : s2 * std::log(n2 / n1);
  if (s1 == 0) return std::log(n2 / std::fabs(X));     // e1 = 0 < e2
  if (s2 == 0) return std::log(n1 / std::fabs(X));     // e1 < 0 = e2
  return std::log(n1 * n2 / X2);                       // e1 < 0 < e2
}

/// P(X, eta) = int_0^X asinh(eta/|u|) du
///           = sgn(X) sgn(eta) [ |X| asinh(|eta|/|X|) + |eta| asinh(|X|/|eta|) ].
double P_rect(double X, double eta) {
  if (X == 0.0 || eta == 0.0) return 0.0;
  const double ax = std::fabs(X), ae = std::fabs(eta);
  return sgn(X) * sgn(eta) * (ax * std::asinh(ae / ax) + ae * std::asinh(ax / ae));
}

}  // namespace

/// Gauss–Legendre nodes/weights on [-1, 1] (Newton on P_n).
void gauss_legendre(int n, std::vector<double>* x, std::vector<double>* w) {
  x->assign(n, 0.0);
  w->assign(n, 0.0);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double z = std::cos(kPi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) { p1 = z; p0 = 1.0; }
      dp = n * (z * p1 - p0) / (z * z - 1.0);
      const double dz = p1 / dp;
      z -= dz;
      if (std::fabs(dz) < 1e-15) break;
    }
    double p0 = 1.0, p1 = z;
    for (int k = 2; k <= n; ++k) {
      const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    dp = n * (z * p1 - p0) / (z * z - 1.0);
    (*x)[i] = -z;
    (*x)[n - 1 - i] = z;
    (*w)[i] = (*w)[n - 1 - i] = 2.0 / ((1.0 - z * z) * dp * dp);
  }
}

/// Influence integral (see strips_detail::strip_influence) with given nodes.
/// Singularity subtraction: f = f(t0) + (f - f(t0)); the constant part is the
/// closed-form rectangle integral of 1/r (Johnson §3.2, uniform pressure on a
/// rectangle); the remainder vanishes at the singular point and is integrated
/// by Gauss–Legendre in theta (x = a sin theta) on sub-intervals split at the
/// point and at the kinks of the capped profile.
double influence(double X0, double a, double e1, double e2, double rcap,
                 const std::vector<double>& gx, const std::vector<double>& gw) {
  if (!(a > 0.0)) return 0.0;
  auto fcap = [rcap](double t) { return std::min(std::sqrt(std::max(0.0, 1.0 - t * t)), rcap); };
  const double t0 = X0 / a;
  const bool inside = std::fabs(t0) < 1.0;
  const double f0 = inside ? fcap(t0) : 0.0;

  double total = 0.0;
  if (f0 != 0.0) {
    const double X1 = -a - X0, X2 = a - X0;
    const double R = P_rect(X2, e2) - P_rect(X1, e2) - P_rect(X2, e1) + P_rect(X1, e1);
    total += f0 * R;
  }
  // X0 = 0: F depends on |X| = a |sin theta| and f is even, so the
  // integrand is even in theta: integrate [0, pi/2] and double.
  const bool even = X0 == 0.0;
  double br[5];
  int nb = 0;
  br[nb++] = even ? 0.0 : -0.5 * kPi;
  br[nb++] = 0.5 * kPi;
  if (inside && !even) br[nb++] = std::asin(t0);
  if (rcap < 1.0) {
    const double th = std::asin(std::sqrt(1.0 - rcap * rcap));
    if (!even) br[nb++] = -th;
    br[nb++] = th;
  }
  std::sort(br, br + nb);
  // A point inside the flat top (f0 = rcap) sees f − f0 = 0 on all of it, |theta| <= th: those
  // sub-intervals add nothing (the rectangle term holds the flat top) and are skipped.
  const double flat = rcap < 1.0 && f0 == rcap ? std::asin(std::sqrt(1.0 - rcap * rcap)) : -1.0;
  for (int k = 0; k + 1 < nb; ++k) {
    const double lo = br[k], hi = br[k + 1];
    if (!(hi > lo)) continue;
    if (lo >= -flat && hi <= flat) continue;
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    double acc = 0.0;
    for (std::size_t n = 0; n < gx.size(); ++n) {
      const double th = mid + half * gx[n];
      const double t = std::sin(th);
      const double X = a * t - X0;
      acc += gw[n] * (fcap(t) - f0) * lateral_kernel(X, e1, e2) * a * std::cos(th);
    }
    total += acc * half * (even ? 2.0 : 1.0);
  }
  return total;
}

void influence_centre_line(double a, double ds, double rcap, int dmax, const std::vector<double>& gx,
                           const std::vector<double>& gw, std::vector<double>& out, const std::vector<char>* need) {
  out.assign(static_cast<std::size_t>(dmax) + 1, 0.0);
  if (!(a > 0.0)) return;
  auto wanted = [need](int d) { return !need || (*need)[static_cast<std::size_t>(d)] != 0; };
  const double r = std::min(rcap, 1.0);
  // f0 = f(0) = r. The rectangle term: with X1 = −a, X2 = a and P odd in X,
  // R = 2 [P(a, e2) − P(a, e1)]; P odd in eta, so that at d = 0 (e1 = −e2) R = 4 P(a, ds/2).
  thread_local std::vector<double> Pe, nm;
  Pe.resize(static_cast<std::size_t>(dmax) + 1);
  for (int m = 0; m <= dmax; ++m)
    Pe[m] = wanted(m) || (m < dmax && wanted(m + 1)) ? P_rect(a, (m + 0.5) * ds) : 0.0;
  for (int d = 0; d <= dmax; ++d)
    if (wanted(d)) out[d] = r * 2.0 * (d == 0 ? 2.0 * Pe[0] : Pe[d] - Pe[d - 1]);
  // The remainder f − r vanishes on the flat top |theta| <= th (all of the strip's centre when
  // r = 1: th = 0) and is integrated over [th, pi/2], doubled (even in theta). The lateral kernel
  // of a node at X = a sin theta, as lateral_kernel above with the edges' n_m = e_m + sqrt(e_m² + X²),
  // e_m = (m + ½) ds, taken once: F(0) = ln(n_0² / X²), F(d) = ln(n_d / n_{d−1}).
  const double th = r < 1.0 ? std::asin(std::sqrt(1.0 - r * r)) : 0.0;
  const double mid = 0.5 * (th + 0.5 * kPi), half = 0.5 * (0.5 * kPi - th);
  if (!(half > 0.0)) return;
  nm.resize(static_cast<std::size_t>(dmax) + 1);
  // The edges a wanted distance uses (d: m = d and d − 1): a sparse `need` (the elastic rows of a
  // mostly capped patch) takes few of the dmax roots per node.
  thread_local std::vector<int> edges;
  edges.clear();
  for (int m = 0; m <= dmax; ++m)
    if (wanted(m) || (m < dmax && wanted(m + 1))) edges.push_back(m);
  for (std::size_t k = 0; k < gx.size(); ++k) {
    const double theta = mid + half * gx[k];
    const double t = std::sin(theta);
    const double f = std::min(std::sqrt(std::max(0.0, 1.0 - t * t)), r);
    const double X = a * t;
    const double w = 2.0 * half * gw[k] * (f - r) * a * std::cos(theta);
    if (w == 0.0) continue;
    const double X2 = X * X;
    for (const int m : edges) {
      const double e = (m + 0.5) * ds;
      nm[m] = e + std::sqrt(e * e + X2);
    }
    if (wanted(0)) out[0] += w * std::log(nm[0] * nm[0] / X2);
    for (int d = 1; d <= dmax; ++d)
      if (wanted(d)) out[d] += w * std::log(nm[d] / nm[d - 1]);
  }
}

namespace {

/// F(th, rho) of capped_centre_line (strip_influence.hpp) and dF/du, u = log2 rho, at the nodes of
/// a grid, for the Gauss–Legendre nodes gx, gw of influence_centre_line (one sub-interval [th, π/2]):
///  - th_i = (π/4) (1 − cos π xi_i), xi_i = i / kTh, i = 0 … kTh: graded towards th = 0 (r = 1),
///    where the first node nears the kink of the pressure, and towards th = π/2 (r = 0), where
///    F ∝ r and the displacement q F = p_lim F / r wants F to its relative precision;
///  - u_j = kULo + j / kPerBinade, j = 0 … ny − 1.
struct CappedCentreTable {
  static constexpr int kTh = 256;
  static constexpr int kPerBinade = 16;
  static constexpr int kULo = -10, kUHi = 7;
  static constexpr int ny = (kUHi - kULo) * kPerBinade + 1;
  std::vector<double> gx, gw;  ///< the nodes tabulated
  mutable std::vector<double> v;  ///< node (i, j): v[2 (i ny + j)] = F, v[2 (i ny + j) + 1] = dF/du (rows built on first use)

  CappedCentreTable() : v(static_cast<std::size_t>(2 * (kTh + 1) * ny), 0.0), once(kTh + 1) {
    gauss_legendre(8, &gx, &gw);  // StripOptions::gauss_points / 2 (options.hpp)
  }
  /// Row i, built on first use (a run touches the rows of its capped strips' r only).
  const double* row(int i) const {
    std::call_once(once[static_cast<std::size_t>(i)], [this, i] { build_row(i); });
    return v.data() + 2 * static_cast<std::size_t>(i) * ny;
  }

 private:
  mutable std::vector<std::once_flag> once;
  void build_row(int i) const {
    const std::size_t ng = gx.size();
    std::vector<double> sk(ng), Wk(ng);
    const double th = 0.25 * kPi * (1.0 - std::cos(kPi * i / kTh)), r = std::cos(th);
    // The nodes and weights of influence_centre_line on [th, π/2], without the factor a.
    const double mid = 0.5 * (th + 0.5 * kPi), half = 0.5 * (0.5 * kPi - th);
    for (std::size_t k = 0; k < ng; ++k) {
      const double theta = mid + half * gx[k];
      sk[k] = std::sin(theta);
      const double f = std::min(std::sqrt(std::max(0.0, 1.0 - sk[k] * sk[k])), r);
      Wk[k] = 2.0 * half * gw[k] * (f - r) * std::cos(theta);
    }
    double* out = v.data() + 2 * static_cast<std::size_t>(i) * ny;
    for (int j = 0; j < ny; ++j) {
      const double u = kULo + static_cast<double>(j) / kPerBinade, rho = std::exp2(u);
      // F = 2 r P(1, rho) + Σ W_k asinh(rho / s_k); dF/drho = 2 r asinh(1/rho) + Σ W_k / sqrt(rho² + s_k²).
      double F = 2.0 * r * P_rect(1.0, rho), Fr = 2.0 * r * std::asinh(1.0 / rho);
      for (std::size_t k = 0; k < ng; ++k) {
        F += Wk[k] * std::asinh(rho / sk[k]);
        Fr += Wk[k] / std::sqrt(rho * rho + sk[k] * sk[k]);
      }
      out[2 * j] = F;
      out[2 * j + 1] = Fr * rho * std::log(2.0);
    }
  }
};

const CappedCentreTable& capped_centre_table() {
  static const CappedCentreTable t;
  return t;
}

}  // namespace

void capped_centre_line(double a, double ds, double rcap, int dmax, const std::vector<double>& gx,
                        const std::vector<double>& gw, std::vector<double>& out, const std::vector<char>* need,
                        const double* log2_edge) {
  using T = CappedCentreTable;
  auto wanted = [need](int d) { return !need || (*need)[static_cast<std::size_t>(d)] != 0; };
  // The edges m = 0 … mmax the wanted distances use; the table serves when their rho lie in it.
  int mmax = -1;
  for (int d = dmax; d >= 0; --d)
    if (wanted(d)) { mmax = d; break; }
  const double r = std::min(rcap, 1.0);
  if (mmax < 0 || !(a > 0.0) || !(r > 0.0) || gx.size() != 8) {
    influence_centre_line(a, ds, rcap, dmax, gx, gw, out, need);
    return;
  }
  const T& tab = capped_centre_table();
  if (gx != tab.gx || gw != tab.gw || !(0.5 * ds / a >= std::exp2(T::kULo)) ||
      !((mmax + 0.5) * ds / a <= std::exp2(T::kUHi))) {
    influence_centre_line(a, ds, rcap, dmax, gx, gw, out, need);
    return;
  }
  out.assign(static_cast<std::size_t>(dmax) + 1, 0.0);
  // Cubic Lagrange weights in xi = acos(1 − 4 th / π) / π on the four nodes i0 … i0 + 3 around it.
  const double th = r < 1.0 ? std::asin(std::sqrt(1.0 - r * r)) : 0.0;
  const double x = std::acos(std::min(std::max(1.0 - th * (4.0 / kPi), -1.0), 1.0)) * (T::kTh / kPi);
  const int i0 = std::min(std::max(static_cast<int>(x) - 1, 0), T::kTh - 3);
  const double p = x - i0;  // in [0, 3]
  const double L[4] = {-(p - 1) * (p - 2) * (p - 3) / 6, p * (p - 2) * (p - 3) / 2, -p * (p - 1) * (p - 3) / 2,
                       p * (p - 1) * (p - 2) / 6};
  const double* row[4];
  for (int k = 0; k < 4; ++k) row[k] = tab.row(i0 + k);
  const double hu = 1.0 / T::kPerBinade, la = std::log2(a);
  auto F = [&](int m) {  // F(th, (m + ½) ds / a)
    const double pos = ((log2_edge ? log2_edge[m] : std::log2((m + 0.5) * ds)) - la - T::kULo) * T::kPerBinade;
    const int j = std::min(std::max(static_cast<int>(pos), 0), T::ny - 2);
    const double t = pos - j, t1 = 1.0 - t;
    const double h00 = (1 + 2 * t) * t1 * t1, h01 = t * t * (3 - 2 * t), h10 = hu * t * t1 * t1, h11 = -hu * t * t * t1;
    double s = 0.0;
    for (int k = 0; k < 4; ++k) {
      const double* c = row[k] + 2 * j;
      s += L[k] * (h00 * c[0] + h10 * c[1] + h01 * c[2] + h11 * c[3]);
    }
    return s;
  };
  double Fprev = 0.0;
  int mprev = -2;
  for (int d = 0; d <= mmax; ++d) {
    if (!wanted(d)) continue;
    if (d == 0) {
      Fprev = F(0);
      mprev = 0;
      out[0] = 2.0 * a * Fprev;
      continue;
    }
    const double Flo = mprev == d - 1 ? Fprev : F(d - 1);
    Fprev = F(d);
    mprev = d;
    out[d] = a * (Fprev - Flo);
  }
}

void capped_source(double a, double rcap, const std::vector<double>& gx, const std::vector<double>& gw,
                   CappedSource& out) {
  out.a = a;
  out.r = rcap;
  out.th = std::asin(std::sqrt(1.0 - rcap * rcap));
  out.x_flat = a * std::sin(out.th);
  out.gx = &gx;
  out.gw = &gw;
  // The sub-intervals of influence() that do not depend on the point: the two tails and the flat
  // top, with the same nodes (mid + half gx) and weights (gw half a cos theta), and f there.
  const double th = out.th;
  const double lo[3] = {-0.5 * kPi, th, -th}, hi[3] = {-th, 0.5 * kPi, th};
  for (int piece = 0; piece < 3; ++piece) {
    std::vector<double>& x = piece == 2 ? out.x_flat_nodes : out.x;
    std::vector<double>& f = piece == 2 ? out.f_flat_nodes : out.f;
    std::vector<double>& w = piece == 2 ? out.w_flat_nodes : out.w;
    if (piece != 1) { x.clear(); f.clear(); w.clear(); }
    const double mid = 0.5 * (lo[piece] + hi[piece]), half = 0.5 * (hi[piece] - lo[piece]);
    if (!(half > 0.0)) continue;
    for (std::size_t n = 0; n < gx.size(); ++n) {
      const double theta = mid + half * gx[n];
      const double t = std::sin(theta);
      x.push_back(a * t);
      f.push_back(std::min(std::sqrt(std::max(0.0, 1.0 - t * t)), rcap));
      w.push_back(half * gw[n] * a * std::cos(theta));
    }
  }
}

double capped_source_influence(const CappedSource& src, double X0, double e1, double e2) {
  const double a = src.a, r = src.r;
  const double t0 = X0 / a;  // >= 0
  const bool inside = t0 < 1.0;
  const double f0 = inside ? std::min(std::sqrt(std::max(0.0, 1.0 - t0 * t0)), r) : 0.0;
  double total = 0.0;
  if (f0 != 0.0) {
    const double X1 = -a - X0, X2 = a - X0;
    total += f0 * (P_rect(X2, e2) - P_rect(X1, e2) - P_rect(X2, e1) + P_rect(X1, e1));
  }
  // Both tails: prepared, except the right one when the point lies on it (split there).
  const bool on_tail = inside && f0 < r;
  const std::size_t ng = src.gx->size();
  for (std::size_t n = 0; n < src.x.size(); ++n) {
    if (on_tail && n >= ng) break;  // the right tail: below
    total += src.w[n] * (src.f[n] - f0) * lateral_kernel(src.x[n] - X0, e1, e2);
  }
  // The flat top: f − f0 = 0 when the point is on it.
  if (f0 != r)
    for (std::size_t n = 0; n < src.x_flat_nodes.size(); ++n)
      total += src.w_flat_nodes[n] * (src.f_flat_nodes[n] - f0) * lateral_kernel(src.x_flat_nodes[n] - X0, e1, e2);
  if (on_tail) {
    const double split = std::asin(t0);
    for (const auto& iv : {std::pair<double, double>{src.th, split}, std::pair<double, double>{split, 0.5 * kPi}}) {
      const double mid = 0.5 * (iv.first + iv.second), half = 0.5 * (iv.second - iv.first);
      if (!(half > 0.0)) continue;
      for (std::size_t n = 0; n < ng; ++n) {
        const double theta = mid + half * (*src.gx)[n];
        const double t = std::sin(theta);
        const double f = std::min(std::sqrt(std::max(0.0, 1.0 - t * t)), r);
        total += half * (*src.gw)[n] * a * std::cos(theta) * (f - f0) * lateral_kernel(a * t - X0, e1, e2);
      }
    }
  }
  return total;
}

double strip_influence(double X0, double a, double eta1, double eta2, double r_cap, int gauss_points) {
  std::vector<double> gx, gw;
  gauss_legendre(std::max(1, gauss_points / 2), &gx, &gw);
  return influence(X0, a, eta1, eta2, r_cap, gx, gw);
}

}  // namespace strips_detail
}  // namespace mh
