// Semi-Hertzian strip solver with elastic coupling; see strips.hpp.
//
// Sources:
//  - Johnson, Contact Mechanics (1985) §3.2 (Boussinesq point load, pressure on
//    a rectangle), §3.6 / §4.2 (Hertz elliptic contact, eq. 3.69-3.71 / 4.2x).
//  - Kik & Piotrowski 1996; Piotrowski & Kik 2008 (KPEC: equivalent ellipse,
//    virtual penetration, strip extents from a reduced interpenetration).
//  - Sichani, Enblom, Berg 2014 (ANALYN: local Hertz solution per strip).
#include "contact/strips.hpp"

#include "contact/strip_kernel.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include "core/units.hpp"

namespace mh {

namespace {

constexpr double kPi = units::pi;

/// Complete elliptic integrals K(m), E(m) of parameter m = e^2 by the
/// arithmetic–geometric mean (Abramowitz & Stegun 17.6).
void ellip_KE(double m, double* K, double* E) {
  double a = 1.0, b = std::sqrt(1.0 - m), c = std::sqrt(m);
  double pw = 0.5, sum = pw * c * c;
  for (int it = 0; it < 64 && c > std::numeric_limits<double>::epsilon() * a; ++it) {
    const double an = 0.5 * (a + b);
    const double bn = std::sqrt(a * b);
    c = 0.5 * (a - b);
    a = an;
    b = bn;
    pw *= 2.0;
    sum += pw * c * c;
  }
  *K = kPi / (2.0 * a);
  *E = *K * (1.0 - sum);
}

/// Hertz shape for h = A x^2 + B y^2 with A <= B (major axis along x):
/// axis ratio k = b/a from B/A = (E/k^2 - K)/(K - E), m = 1 - k^2, and the
/// scale a^2 = delta (K - E)/(A m K) (Johnson §3.6 eq. 3.71: delta = H L,
/// A = H M, B = H N with L = pi b p0 K, M = pi b p0 (K-E)/(e^2 a^2)).
/// Returns a/sqrt(delta), b/sqrt(delta).
void hertz_shape_major_x(double A, double B, double* ka, double* kb) {
  const double ratio = B / A;
  // Below this excess over 1 the ellipse is a circle to double precision.
  constexpr double kCircleTol = 1e-12;
  if (ratio <= 1.0 + kCircleTol) {
    *ka = std::sqrt(1.0 / (2.0 * A));  // sphere: a^2 = R delta, A = 1/(2R)
    *kb = *ka;
    return;
  }
  auto f = [](double k) {
    double K, E;
    ellip_KE(1.0 - k * k, &K, &E);
    return (E / (k * k) - K) / (K - E);
  };
  // f decreases from +inf (k -> 0) to 1 (k = 1). Root of
  // phi(u) = ln f(e^u) - ln(B/A) in u = ln k by the Illinois variant of
  // regula falsi (smooth in u; ~10 evaluations instead of ~50 for bisection).
  double lo = 0.5;
  while (f(lo) < ratio && lo > 1e-300) lo *= 0.5;
  const double lr = std::log(ratio);
  double ua = std::log(lo), fa = std::log(f(lo)) - lr;  // fa >= 0
  double ub = 0.0, fb = -lr;                             // k = 1: f = 1 (limit), fb < 0
  int side = 0;
  // Stop when the bracket in ln k is this narrow (double precision).
  constexpr double kUtol = 1e-15;
  for (int it = 0; it < 200 && ub - ua > kUtol; ++it) {
    const double uc = (ua * fb - ub * fa) / (fb - fa);
    if (!(uc > ua && uc < ub)) break;
    const double fc = std::log(f(std::exp(uc))) - lr;
    if (fc == 0.0) { ua = ub = uc; break; }
    if (fc < 0.0) {
      ub = uc; fb = fc;
      if (side == -1) fa *= 0.5;
      side = -1;
    } else {
      ua = uc; fa = fc;
      if (side == 1) fb *= 0.5;
      side = 1;
    }
  }
  // the end of the bracket with the smaller residual
  const double k_root = std::exp(std::fabs(fa) < std::fabs(fb) ? ua : ub);
  lo = k_root;
  double hi = k_root;
  const double k = std::sqrt(lo * hi);
  const double m = 1.0 - k * k;
  double K, E;
  ellip_KE(m, &K, &E);
  *ka = std::sqrt((K - E) / (A * m * K));
  *kb = k * *ka;
}

/// Hertz shape for any A, B > 0: a/sqrt(delta) along x, b/sqrt(delta) along y.
void hertz_shape(double A, double B, double* ka, double* kb) {
  if (A <= B) {
    hertz_shape_major_x(A, B, ka, kb);
  } else {
    hertz_shape_major_x(B, A, kb, ka);
  }
}

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
  for (int k = 0; k + 1 < nb; ++k) {
    const double lo = br[k], hi = br[k + 1];
    if (!(hi > lo)) continue;
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

/// Phi(r) = r sqrt(1 - r^2) + asin r: load of a capped semi-ellipse
/// min(q sqrt(1-t^2), r q) over t in [-1, 1] is q a Phi(r); Phi(1) = pi/2.
double Phi(double r) {
  if (r >= 1.0) return 0.5 * kPi;
  return r * std::sqrt(1.0 - r * r) + std::asin(r);
}

/// Root of the quadratic through (s_k, g_k), k = 0..2, equal to `level` in
/// [lo, hi] (the interpolant changes sign there by construction); bisection.
double crossing(const double* sv, const double* gv, double level, double lo, double hi) {
  auto q = [&](double x) {
    double r = 0.0;
    for (int i = 0; i < 3; ++i) {
      double li = 1.0;
      for (int j = 0; j < 3; ++j)
        if (j != i) li *= (x - sv[j]) / (sv[i] - sv[j]);
      r += li * gv[i];
    }
    return r - level;
  };
  double flo = q(lo);
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    const double fm = q(mid);
    if ((fm < 0.0) == (flo < 0.0)) { lo = mid; flo = fm; } else { hi = mid; }
  }
  return 0.5 * (lo + hi);
}

struct Solver {
  const StripGeometry& geo;
  double H;
  StripOptions opt;
  int n;
  std::vector<double> gx, gw;     // Gauss nodes per sub-interval
  std::vector<double> Bloc;       // [1/m] local lateral curvature (g''/2), <= 0: none
  std::vector<double> ka, kb;     // ANALYN Hertz shape per strip (valid where Bloc > 0)
  double gmin = 0.0;
  int imin = 0;

  Solver(const StripGeometry& g, double Hc, const StripOptions& o)
      : geo(g), H(Hc), opt(o), n(static_cast<int>(g.s.size())) {
    gauss_legendre(opt.gauss_points / 2, &gx, &gw);
    Bloc.assign(n, 0.0);
    ka.assign(n, 0.0);
    kb.assign(n, 0.0);
    const double ds2 = geo.ds * geo.ds;
    for (int i = 0; i < n; ++i) {
      // ANALYN (Sichani et al. 2014): B(s) from the second difference of g;
      // end strips borrow the neighbour's difference.
      int c = std::min(std::max(i, 1), n - 2);
      if (n >= 3) Bloc[i] = (geo.g[c + 1] - 2.0 * geo.g[c] + geo.g[c - 1]) / (2.0 * ds2);
      if (Bloc[i] > 0.0) hertz_shape(geo.A[i], Bloc[i], &ka[i], &kb[i]);
    }
    imin = static_cast<int>(std::min_element(geo.g.begin(), geo.g.end()) - geo.g.begin());
    gmin = geo.g[imin];
  }

  /// Bands at approach delta: runs of g < delta split at interior local maxima.
  /// Returns band id per strip (-1 outside), sets nb.
  std::vector<int> bands(double delta, int* nb) const {
    std::vector<int> band(n, -1);
    int id = -1;
    bool in = false;
    for (int i = 0; i < n; ++i) {
      if (!(geo.g[i] < delta)) { in = false; continue; }
      if (!in) { ++id; in = true; band[i] = id; continue; }
      band[i] = id;
      // saddle at i-1 (strict local maximum, inside the run): start a new band
      // at i if i-1 is a maximum; the saddle strip stays with the side whose
      // neighbour is deeper.
      if (i >= 2 && band[i - 2] == id && geo.g[i - 1] > geo.g[i - 2] && geo.g[i - 1] > geo.g[i]) {
        ++id;
        band[i] = id;
        if (geo.g[i] < geo.g[i - 2]) band[i - 1] = id;
      }
    }
    *nb = id + 1;
    return band;
  }

  /// Strip half-lengths at approach delta: union of KPEC and ANALYN estimates.
  /// Within a band the approach is measured from the band's deepest gap g0:
  /// delta_b = delta - g0 and g - g0 (identical to the spec for g0 = 0 and
  /// exact for an elliptic patch whose minimum gap is g0).
  std::vector<double> extents(double delta, const std::vector<int>& band, int nb) const {
    std::vector<double> a(n, 0.0);
    for (int b = 0; b < nb; ++b) {
      int first = -1, last = -1;
      for (int i = 0; i < n; ++i)
        if (band[i] == b) { if (first < 0) first = i; last = i; }
      int i0 = first;
      for (int i = first; i <= last; ++i)
        if (geo.g[i] < geo.g[i0]) i0 = i;
      // deepest point: vertex of the parabola through the three rows around i0
      double s0 = geo.s[i0], g0 = geo.g[i0];
      if (i0 > 0 && i0 < n - 1) {
        const double d2 = geo.g[i0 + 1] - 2.0 * geo.g[i0] + geo.g[i0 - 1];
        if (d2 > 0.0) {
          const double d1 = 0.5 * (geo.g[i0 + 1] - geo.g[i0 - 1]);
          const double u = -d1 / d2;  // in strip widths, |u| <= 1/2
          s0 = geo.s[i0] + u * geo.ds;
          g0 = geo.g[i0] + 0.5 * d1 * u;
        }
      }
      g0 = std::min(g0, geo.g[i0]);
      const double db = delta - g0;
      if (!(db > 0.0)) continue;
      const double half = 0.5 * db;

      // ---- KPEC-type (Kik & Piotrowski 1996): equivalent ellipse of the band.
      // Lateral extent of h < delta/2 around i0 within the band.
      auto edge = [&](int dir) {
        int k = i0;
        while (true) {
          const int nx = k + dir;
          if (nx < first || nx > last) return geo.s[k] + dir * 0.5 * geo.ds;  // band ends first
          if (!(geo.g[nx] - g0 < half)) {
            // crossing between k (inside) and nx (outside); quadratic through
            // k - dir, k, nx where available
            const int o = (k - dir >= 0 && k - dir < n) ? k - dir : nx + dir;
            if (o < 0 || o >= n) {
              const double t = (half - (geo.g[k] - g0)) / (geo.g[nx] - geo.g[k]);
              return geo.s[k] + t * (geo.s[nx] - geo.s[k]);
            }
            const double sv[3] = {geo.s[o], geo.s[k], geo.s[nx]};
            const double gv[3] = {geo.g[o] - g0, geo.g[k] - g0, geo.g[nx] - g0};
            return crossing(sv, gv, half, std::min(geo.s[k], geo.s[nx]), std::max(geo.s[k], geo.s[nx]));
          }
          k = nx;
        }
      };
      const double sL = edge(-1), sR = edge(+1);
      const double w = 0.5 * (sR - sL);
      const double Ab = geo.A[i0];
      if (w > 0.0) {
        const double Bb = half / (w * w);
        double kA, kB;
        hertz_shape(Ab, Bb, &kA, &kB);
        const double ae = kA * std::sqrt(db), be = kB * std::sqrt(db);
        const double Aa2 = Ab * ae * ae, Bb2 = Bb * be * be;
        for (int i = first; i <= last; ++i) {
          const double y = (geo.s[i] - s0) / be;
          // reduced interpenetration eps(s) delta_b, clipped to [0, delta_b]
          const double ed = std::min(std::max(Aa2 - (Aa2 - Bb2) * y * y, 0.0), db);
          const double pen = ed - (geo.g[i] - g0);
          if (pen > 0.0) a[i] = std::max(a[i], std::sqrt(pen / geo.A[i]));
        }
      }
      // ---- ANALYN-type (Sichani et al. 2014): local Hertz solution per strip,
      // a_i = a* sqrt(1 - (g_i - g0)/(B b*^2)).
      for (int i = first; i <= last; ++i) {
        if (!(Bloc[i] > 0.0)) continue;
        const double as = ka[i] * std::sqrt(db), bs = kb[i] * std::sqrt(db);
        const double arg = 1.0 - (geo.g[i] - g0) / (Bloc[i] * bs * bs);
        if (arg > 0.0) a[i] = std::max(a[i], as * std::sqrt(arg));
      }
    }
    return a;
  }

  double K_elastic(int i, int j, double aj) const {
    const double e1 = geo.s[j] - 0.5 * geo.ds - geo.s[i], e2 = geo.s[j] + 0.5 * geo.ds - geo.s[i];
    if (geo.xc[i] == geo.xc[j] && aj > 0.0)  // X0 = 0, uncapped: the tabulated kernel, exact
      return H * aj * (strip_kernel_g(e2 / aj) - strip_kernel_g(e1 / aj));
    return H * influence(geo.xc[i] - geo.xc[j], aj, geo.s[j] - 0.5 * geo.ds - geo.s[i],
                         geo.s[j] + 0.5 * geo.ds - geo.s[i], 1.0, gx, gw);
  }

  /// Solve at fixed approach.
  StripResult evaluate(double delta, double p_lim) const {
    StripResult res;
    res.delta = delta;
    if (!(delta > gmin)) {
      res.status = StripStatus::NoContact;
      res.message = "approach does not exceed the minimum gap";
      return res;
    }
    int nb = 0;
    const std::vector<int> band = bands(delta, &nb);
    const std::vector<double> a = extents(delta, band, nb);
    res.n_bands = nb;

    std::vector<int> cand;
    for (int i = 0; i < n; ++i)
      if (a[i] > 0.0) cand.push_back(i);
    const int m = static_cast<int>(cand.size());
    if (m == 0) {
      res.status = StripStatus::NoContact;
      res.message = "no strip has a positive extent";
      return res;
    }
    // Elastic influence matrix among candidates (unit amplitude).
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(m, m);
    for (int jj = 0; jj < m; ++jj)
      for (int ii = 0; ii < m; ++ii)
        if (opt.coupling || ii == jj) K(ii, jj) = K_elastic(cand[ii], cand[jj], a[cand[jj]]);

    // Plastic bookkeeping. A capped strip keeps the ELASTIC amplitude q_j at
    // which it was capped and is lengthened to a'_j = a_j (pi/2)/Phi(r_j),
    // r_j = p_lim/q_j; its pressure is min(q_j sqrt(1 - ((x-c)/a'_j)^2), p_lim):
    // flat top at p_lim, load q_j a'_j Phi(r_j) ds = (pi/2) q_j a_j ds (the
    // elastic strip's load). Its displacement equation is dropped.
    std::vector<char> capped(m, 0);
    std::vector<double> q(m, 0.0), aeff(m, 0.0), rcap(m, 1.0);
    Eigen::MatrixXd Ucap = Eigen::MatrixXd::Zero(m, m);  // column j: displacement from capped strip j
    for (int ii = 0; ii < m; ++ii) aeff[ii] = a[cand[ii]];

    bool settled = false;
    bool as_ok = true;
    for (int pass = 0; pass < opt.max_active_set && !settled; ++pass) {
      std::vector<int> act;
      for (int ii = 0; ii < m; ++ii)
        if (!capped[ii]) act.push_back(ii);
      Eigen::VectorXd ucap = Eigen::VectorXd::Zero(m);
      for (int jj = 0; jj < m; ++jj)
        if (capped[jj]) ucap += Ucap.col(jj);
      // Active set for q >= 0 among elastic strips.
      as_ok = false;
      for (int it = 0; it < opt.max_active_set; ++it) {
        const int k = static_cast<int>(act.size());
        if (k == 0) { as_ok = true; break; }
        Eigen::MatrixXd Kaa(k, k);
        Eigen::VectorXd rhs(k);
        for (int r = 0; r < k; ++r) {
          rhs(r) = delta - geo.g[cand[act[r]]] - ucap(act[r]);
          for (int c = 0; c < k; ++c) Kaa(r, c) = K(act[r], act[c]);
        }
        const Eigen::VectorXd sol = Kaa.partialPivLu().solve(rhs);
        std::vector<int> keep;
        for (int r = 0; r < k; ++r) {
          q[act[r]] = sol(r);
          if (sol(r) >= 0.0) keep.push_back(act[r]);
        }
        for (int ii = 0; ii < m; ++ii)
          if (!capped[ii] && std::find(keep.begin(), keep.end(), ii) == keep.end()) q[ii] = 0.0;
        if (keep.size() == act.size()) { as_ok = true; break; }
        act.swap(keep);
      }
      if (!as_ok) break;
      // Newly capped strips.
      bool any = false;
      if (std::isfinite(p_lim)) {
        for (int ii : act) {
          if (q[ii] > p_lim) {
            capped[ii] = 1;
            any = true;
            rcap[ii] = p_lim / q[ii];
            aeff[ii] = a[cand[ii]] * (0.5 * kPi) / Phi(rcap[ii]);
            const int j = cand[ii];
            for (int r = 0; r < m; ++r) {
              if (!opt.coupling && r != ii) continue;
              const int i = cand[r];
              Ucap(r, ii) = H * q[ii] *
                            influence(geo.xc[i] - geo.xc[j], aeff[ii], geo.s[j] - 0.5 * geo.ds - geo.s[i],
                                      geo.s[j] + 0.5 * geo.ds - geo.s[i], rcap[ii], gx, gw);
            }
          }
        }
      }
      if (!any) settled = true;
    }

    res.status = StripStatus::Ok;
    if (!as_ok || !settled) {
      res.status = StripStatus::NotConverged;
      res.message = !as_ok ? "active set (q >= 0) did not settle within max_active_set passes"
                           : "plastic set did not settle within max_active_set passes";
    }
    double qmax = 0.0;
    for (int ii = 0; ii < m; ++ii) {
      if (!(q[ii] > 0.0)) continue;
      StripState st;
      st.index = cand[ii];
      st.s = geo.s[cand[ii]];
      st.c = geo.xc[cand[ii]];
      st.a = aeff[ii];
      st.q = q[ii];
      st.plastic = capped[ii] != 0;
      st.band = band[cand[ii]];
      st.load = (st.plastic ? q[ii] * aeff[ii] * Phi(rcap[ii]) : 0.5 * kPi * q[ii] * aeff[ii]) * geo.ds;
      res.N += st.load;
      res.area += 2.0 * st.a * geo.ds;
      qmax = std::max(qmax, q[ii]);
      res.strips.push_back(st);
    }
    res.pmax = std::min(qmax, p_lim);
    if (res.strips.empty() && res.status == StripStatus::Ok) {
      res.status = StripStatus::NoContact;
      res.message = "all amplitudes non-positive";
    }
    // Outliers: amplitude above every neighbour's (same band, adjacent strip)
    // by more than outlier_factor — the thin-tail failure mode of short strips.
    double worst = 0.0;
    const int L = static_cast<int>(res.strips.size());
    for (int k = 0; k < L; ++k) {
      double qn = -1.0;
      for (int d : {-1, 1}) {
        const int o = k + d;
        if (o < 0 || o >= L) continue;
        if (res.strips[o].band != res.strips[k].band || std::abs(res.strips[o].index - res.strips[k].index) != 1)
          continue;
        qn = std::max(qn, res.strips[o].q);
      }
      if (qn < 0.0) continue;
      if (res.strips[k].q > opt.outlier_factor * qn) {
        ++res.n_outliers;
        const double ratio = res.strips[k].q / std::max(qn, std::numeric_limits<double>::min());
        if (ratio > worst) { worst = ratio; res.worst_outlier = k; }
      }
    }
    return res;
  }
};

bool check_input(const StripGeometry& geo, double H, double p_lim, const StripOptions& opt, std::string* why) {
  std::ostringstream os;
  if (!opt.valid(why)) return false;
  const std::size_t n = geo.s.size();
  if (n == 0 || geo.g.size() != n || geo.A.size() != n || geo.xc.size() != n) {
    os << "geometry: s, g, A, xc must be non-empty and of equal size (sizes " << geo.s.size() << ", "
       << geo.g.size() << ", " << geo.A.size() << ", " << geo.xc.size() << ")";
    *why = os.str();
    return false;
  }
  if (!(geo.ds > 0.0) || !std::isfinite(geo.ds)) {
    os << "geometry.ds = " << geo.ds << ": must be positive and finite";
    *why = os.str();
    return false;
  }
  // Spacing tolerance: relative deviation of s_{i+1} - s_i from ds.
  constexpr double kSpacingRtol = 1e-6;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(geo.s[i]) || !std::isfinite(geo.g[i]) || !std::isfinite(geo.xc[i]) || !(geo.A[i] > 0.0) ||
        !std::isfinite(geo.A[i])) {
      os << "geometry row " << i << ": s, g, xc must be finite and A > 0 (A = " << geo.A[i] << ")";
      *why = os.str();
      return false;
    }
    if (i > 0 && std::fabs(geo.s[i] - geo.s[i - 1] - geo.ds) > kSpacingRtol * geo.ds) {
      os << "geometry.s[" << i << "] - s[" << i - 1 << "] = " << geo.s[i] - geo.s[i - 1]
         << ": must equal ds = " << geo.ds;
      *why = os.str();
      return false;
    }
  }
  if (!(H > 0.0) || !std::isfinite(H)) {
    os << "H = " << H << ": must be positive and finite";
    *why = os.str();
    return false;
  }
  if (!(p_lim > 0.0)) {
    os << "p_lim = " << p_lim << ": must be positive (INFINITY for elastic)";
    *why = os.str();
    return false;
  }
  return true;
}

}  // namespace

bool StripOptions::valid(std::string* why) const {
  std::ostringstream os;
  if (gauss_points < 2 || gauss_points % 2 != 0) {
    os << "gauss_points = " << gauss_points << ": must be even and >= 2";
  } else if (!(load_rtol > 0.0) || !std::isfinite(load_rtol)) {
    os << "load_rtol = " << load_rtol << ": must be positive and finite";
  } else if (max_iterations < 1) {
    os << "max_iterations = " << max_iterations << ": must be >= 1";
  } else if (max_active_set < 1) {
    os << "max_active_set = " << max_active_set << ": must be >= 1";
  } else if (!(outlier_factor > 1.0) || !std::isfinite(outlier_factor)) {
    os << "outlier_factor = " << outlier_factor << ": must be > 1 and finite";
  } else {
    return true;
  }
  if (why) *why = os.str();
  return false;
}

StripResult solve_strips_approach(const StripGeometry& geo, double H, double delta, double p_lim,
                                  const StripOptions& opt) {
  std::string why;
  if (!check_input(geo, H, p_lim, opt, &why) || !std::isfinite(delta)) {
    StripResult r;
    r.status = StripStatus::InvalidInput;
    r.message = why.empty() ? "delta must be finite" : why;
    return r;
  }
  Solver S(geo, H, opt);
  return S.evaluate(delta, p_lim);
}

StripResult solve_strips_load(const StripGeometry& geo, double H, double Nt, double p_lim,
                              const StripOptions& opt) {
  std::string why;
  if (!check_input(geo, H, p_lim, opt, &why) || !(Nt > 0.0) || !std::isfinite(Nt)) {
    StripResult r;
    r.status = StripStatus::InvalidInput;
    r.message = why.empty() ? "N must be positive and finite" : why;
    return r;
  }
  Solver S(geo, H, opt);
  // Start: Hertz with the equivalent sphere at the deepest row (Johnson §4.2,
  // R_e = 1/(2 sqrt(A B)), E* = 1/(pi H)): delta = (9 N^2 / (16 R_e E*^2))^(1/3).
  const int i0 = S.imin;
  const double B0 = S.Bloc[i0] > 0.0 ? S.Bloc[i0] : geo.A[i0];
  const double Re = 1.0 / (2.0 * std::sqrt(geo.A[i0] * B0));
  const double Es = 1.0 / (kPi * H);
  double d = S.gmin + std::cbrt(9.0 * Nt * Nt / (16.0 * Re * Es * Es));

  // Safeguarded secant on psi(delta) = N^(2/3) - Nt^(2/3), nearly linear in
  // delta for Hertz-like patches (N ~ (delta - gmin)^(3/2)). The bracket
  // starts at [gmin (N = 0), +inf).
  const double psi_t = std::cbrt(Nt * Nt);
  double lo = S.gmin, hi = std::numeric_limits<double>::infinity();
  double d_prev = S.gmin, psi_prev = -psi_t;
  StripResult best;
  best.status = StripStatus::NotConverged;
  for (int it = 1; it <= opt.max_iterations; ++it) {
    StripResult r = S.evaluate(d, p_lim);
    r.iterations = it;
    const double N = (r.status == StripStatus::Ok || r.status == StripStatus::NotConverged) ? r.N : 0.0;
    if (r.status == StripStatus::NotConverged) {
      r.message = "inner solve: " + r.message;
      return r;
    }
    const double psi = std::cbrt(N * N) - psi_t;
    if (std::fabs(N - Nt) <= opt.load_rtol * Nt) return r;
    if (it == 1 || std::fabs(N - Nt) < std::fabs(best.N - Nt)) best = r;  // closest so far
    if (N < Nt) lo = std::max(lo, d); else hi = std::min(hi, d);
    // Bracket collapsed to adjacent doubles: N(delta) jumps across the target
    // (e.g. the plastic set changes its capping order there).
    if (std::isfinite(hi) && hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * hi) {
      best.status = StripStatus::NotConverged;
      std::ostringstream os;
      os << "N(delta) jumps across the target at delta = " << hi << " m (closest N = " << best.N
         << " N); returned the closest iterate";
      best.message = os.str();
      best.iterations = it;
      return best;
    }
    double next = std::numeric_limits<double>::quiet_NaN();
    if (psi != psi_prev) next = d - psi * (d - d_prev) / (psi - psi_prev);
    if (!(next > lo && next < hi)) {
      next = std::isfinite(hi) ? 0.5 * (lo + hi) : S.gmin + 2.0 * (d - S.gmin);
    }
    d_prev = d;
    psi_prev = psi;
    d = next;
  }
  best.status = StripStatus::NotConverged;
  best.message = "load not reached within max_iterations; returned the closest iterate";
  best.iterations = opt.max_iterations;
  return best;
}

namespace strips_detail {
double strip_influence(double X0, double a, double eta1, double eta2, double r_cap, int gauss_points) {
  std::vector<double> gx, gw;
  gauss_legendre(std::max(1, gauss_points / 2), &gx, &gw);
  return influence(X0, a, eta1, eta2, r_cap, gx, gw);
}
bool hertz_axes(double A, double B, double delta, double* a, double* b) {
  if (!(A > 0.0) || !(B > 0.0) || !(delta > 0.0)) return false;
  double ka, kb;
  hertz_shape(A, B, &ka, &kb);
  *a = ka * std::sqrt(delta);
  *b = kb * std::sqrt(delta);
  return true;
}
}  // namespace strips_detail

}  // namespace mh
