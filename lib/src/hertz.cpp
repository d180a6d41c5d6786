#include "mhcontact/hertz.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_ellint.h>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "mhcontact/numfmt.hpp"
#include "mhcontact/units.hpp"

namespace mh {
namespace {

using units::pi;

struct KE { double K, E; };

KE ellint(double g) {
  // Complete elliptic integrals of modulus k = sqrt(1 − g²) (GSL takes the modulus).
  const double k = std::sqrt(std::max(0.0, 1.0 - g * g));
  gsl_sf_result rk, re;
  const int s1 = gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &rk);
  const int s2 = gsl_sf_ellint_Ecomp_e(k, GSL_PREC_DOUBLE, &re);
  if (s1 != GSL_SUCCESS || s2 != GSL_SUCCESS)
    throw std::runtime_error(std::string("GSL elliptic integral failed: ") + gsl_strerror(s1 ? s1 : s2));
  return {rk.val, re.val};
}

// B/A as a function of g (A ≤ B): (E/g² − K)/(K − E). Decreasing from ∞ (g → 0) to 1 (g → 1).
double ratio_of_g(double g) {
  const KE ke = ellint(g);
  return (ke.E / (g * g) - ke.K) / (ke.K - ke.E);
}

HertzCoefficients coefficients_le1(double lambda) {
  // λ = A/B ≤ 1: solve ratio_of_g(g) = 1/λ by bisection in ln g.
  HertzCoefficients c;
  c.lambda = lambda;
  if (lambda == 1.0) return c;
  const double target = 1.0 / lambda;
  double lo = std::log(1e-12), hi = 0.0;  // ln g
  for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
    const double mid = 0.5 * (lo + hi);
    const double g = std::exp(mid);
    if (g >= 1.0) { hi = mid; continue; }
    if (ratio_of_g(g) > target) lo = mid; else hi = mid;
  }
  const double g = std::exp(0.5 * (lo + hi));
  if (g >= 1.0) return c;
  const KE ke = ellint(g);
  c.m = std::cbrt(2.0 * ke.E / (pi * g * g));
  c.n = c.m * g;
  c.rho = 2.0 * ke.K / (pi * c.m);
  return c;
}

// Fast-path table: ln m, ln n, ln ρ against x = ln λ.
constexpr double kXmin = -11.512925464970229;  // ln 1e-5
constexpr double kXmax = 11.512925464970229;   // ln 1e5
constexpr double kStep = 0.005;

struct Table {
  std::vector<std::array<double, 3>> v;
  Table() {
    gsl_set_error_handler_off();
    const int n = static_cast<int>(std::ceil((kXmax - kXmin) / kStep)) + 1;
    v.resize(static_cast<std::size_t>(n) + 2);  // one guard node at each end
    for (int i = -1; i <= n; ++i) {
      const HertzCoefficients c = hertz_coefficients_exact(std::exp(kXmin + kStep * i));
      v[static_cast<std::size_t>(i + 1)] = {std::log(c.m), std::log(c.n), std::log(c.rho)};
    }
  }
};

const Table& table() {
  static const Table t;
  return t;
}

}  // namespace

HertzCoefficients hertz_coefficients_exact(double lambda) {
  if (!(lambda > 0) || !std::isfinite(lambda))
    throw std::invalid_argument("lambda = A/B must be positive and finite, got " + format_number(lambda));
  gsl_set_error_handler_off();
  if (lambda <= 1.0) return coefficients_le1(lambda);
  const HertzCoefficients s = coefficients_le1(1.0 / lambda);
  HertzCoefficients c;
  c.lambda = lambda;
  c.m = s.n;
  c.n = s.m;
  c.rho = s.rho;
  return c;
}

HertzCoefficients hertz_coefficients(double lambda) {
  if (!(lambda > 0) || !std::isfinite(lambda))
    throw std::invalid_argument("lambda = A/B must be positive and finite, got " + format_number(lambda));
  const double x = std::log(lambda);
  if (x <= kXmin || x >= kXmax) return hertz_coefficients_exact(lambda);
  const Table& T = table();
  const double s = (x - kXmin) / kStep;
  const std::size_t i = static_cast<std::size_t>(s);  // nodes i-1, i, i+1, i+2 → v[i .. i+3]
  const double t = s - static_cast<double>(i);
  // Cubic Lagrange weights on nodes −1, 0, 1, 2.
  const double w0 = -t * (t - 1) * (t - 2) / 6, w1 = (t + 1) * (t - 1) * (t - 2) / 2,
               w2 = -(t + 1) * t * (t - 2) / 2, w3 = (t + 1) * t * (t - 1) / 6;
  HertzCoefficients c;
  c.lambda = lambda;
  double r[3];
  for (int q = 0; q < 3; ++q)
    r[q] = w0 * T.v[i][q] + w1 * T.v[i + 1][q] + w2 * T.v[i + 2][q] + w3 * T.v[i + 3][q];
  c.m = std::exp(r[0]);
  c.n = std::exp(r[1]);
  c.rho = std::exp(r[2]);
  return c;
}

double hertz_C(double N, double A, double B, double E_star) {
  return std::cbrt(1.5 * N / E_star / (A + B));  // (eqs. 2–3)
}

EllipseLaw make_ellipse_law(double A, double B, const Material& mat, bool exact) {
  if (!(B > 0)) throw std::invalid_argument("B = " + format_number(B) + " 1/m: the curvature sum across the contact must be > 0 for a Hertzian ellipse (conformal contact)");
  if (!(A >= 0) || !std::isfinite(A)) throw std::invalid_argument("A = " + format_number(A) + " 1/m must be >= 0");
  if (!(mat.E > 0)) throw std::invalid_argument("E must be > 0");
  if (!(mat.nu > 0 && mat.nu < 0.5)) throw std::invalid_argument("nu must be in (0, 0.5)");
  if (!(mat.p_lim > 0)) throw std::invalid_argument("p_lim must be > 0");
  EllipseLaw L;
  L.A = A;
  L.B = B;
  // A = 0 (an infinite rolling radius) is a line contact: keep λ tiny but positive.
  const double lambda = std::max(A / B, 1e-12);
  L.c = exact ? hertz_coefficients_exact(lambda) : hertz_coefficients(lambda);
  L.E_star = mat.E_star();
  const double n3 = L.c.n * L.c.n * L.c.n;
  L.k_e = (2.0 / 3.0) * (1.0 + lambda) / n3 * L.E_star / std::sqrt(B);  // (eq. 8)
  L.p_lim = mat.p_lim;
  if (std::isfinite(mat.p_lim)) {
    // method.md §5: p0 = 3 k_e n B √h0 / (2π m) reaches p_lim at h_y.
    const double r = 2.0 * pi * L.c.m * mat.p_lim / (3.0 * L.k_e * L.c.n * B);
    L.h_y = r * r;
    L.k_p = pi * mat.p_lim * L.c.m / (L.c.n * B);
    L.N_y = (2.0 / 3.0) * L.k_p * L.h_y;
  }
  return L;
}

EllipseState ellipse_state(const EllipseLaw& L, double h0) {
  EllipseState s;
  if (!(h0 > 0)) return s;
  s.h0 = h0;
  s.N = L.force(h0);
  // The patch keeps the elastic geometry at h0 (eq. 6 and 7; method.md §5).
  s.b = std::sqrt(h0 / L.B);
  s.a = (L.c.m / L.c.n) * s.b;
  const double area = pi * s.a * s.b;
  const double N_el = L.k_e * h0 * std::sqrt(h0);  // Hertz load of this patch
  s.p0 = 1.5 * N_el / area;                         // p0 = 3N/(2πab)
  s.p_mean = s.N / area;
  const double C = s.b / L.c.n;
  s.approach = L.c.rho * C * C * (L.A + L.B);
  s.plastic = h0 > L.h_y;
  s.p_max = std::min(s.p0, L.p_lim);
  if (s.plastic) {
    const double sr = L.p_lim / s.p0;
    const double q = std::sqrt(std::max(0.0, 1.0 - sr * sr));
    s.plateau_a = s.a * q;
    s.plateau_b = s.b * q;
  }
  const double Cel = hertz_C(s.N, L.A, L.B, L.E_star);
  s.a_el = L.c.m * Cel;
  s.b_el = L.c.n * Cel;
  s.area_ratio = (s.a * s.b) / (s.a_el * s.b_el);
  return s;
}

}  // namespace mh
