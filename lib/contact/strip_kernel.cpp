#include "contact/strip_kernel.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include <gsl/gsl_sf_ellint.h>

#include "core/units.hpp"

namespace mh {

namespace {

constexpr int kEmin = -20, kEmax = 20;  // binades [2^E, 2^(E+1)), E = kEmin … kEmax − 1
constexpr int kPerBinade = 128;         // Hermite intervals per binade (a power of 2: the top mantissa bits)
static_assert((kPerBinade & (kPerBinade - 1)) == 0, "kPerBinade must be a power of 2");

// Small r: g(r) = 2r ln(4/r) + O(r³ ln r) (from g'(r) = 2 (ln(4/r) − 1) + O(r² ln r)).
double g_small(double r) { return 2.0 * r * std::log(4.0 / r); }

struct Table {
  // Per interval i (binade E = kEmin + i / kPerBinade, r from 2^E (1 + j/kPerBinade), j = i mod
  // kPerBinade): g at both ends and g' at both ends times the interval's width, for the Hermite
  // cubic in the interval's own coordinate.
  struct Interval { double g0, g1, d0, d1; };
  std::vector<Interval> iv;
  double g_max = 0;  // g(2^kEmax)
  Table() {
    const int n = (kEmax - kEmin) * kPerBinade;
    iv.resize(n);
    // 8-point Gauss–Legendre on [−1, 1].
    static const double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
    static const double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
    double r0 = std::ldexp(1.0, kEmin), g0 = g_small(r0), dg0 = strip_kernel_dg(r0);
    for (int i = 0; i < n; ++i) {
      const int E = kEmin + i / kPerBinade;
      const double h = std::ldexp(1.0, E) / kPerBinade, r1 = r0 + h, mid = r0 + 0.5 * h;
      double acc = 0;
      for (int k = 0; k < 4; ++k)
        acc += w[k] * (strip_kernel_dg(mid - 0.5 * h * x[k]) + strip_kernel_dg(mid + 0.5 * h * x[k]));
      const double g1 = g0 + 0.5 * h * acc, dg1 = strip_kernel_dg(r1);
      iv[i] = {g0, g1, dg0 * h, dg1 * h};
      r0 = r1;
      g0 = g1;
      dg0 = dg1;
    }
    g_max = g0;
  }
};

const Table& table() {
  static const Table t;
  return t;
}

}  // namespace

double strip_kernel_dg(double r) {
  // D(k) = R_D(0, k'², 1)/3 (Carlson), with the complementary modulus k'² = r²/(1 + r²) formed
  // directly: 1 − k² would lose its digits for small r, where K and D grow like ln(4/k').
  r = std::fabs(r);
  const double s2 = 1.0 + r * r;
  return 2.0 * gsl_sf_ellint_RD(0.0, r * r / s2, 1.0, GSL_PREC_DOUBLE) / (3.0 * std::sqrt(s2));
}

double strip_kernel_g(double r) {
  if (std::isnan(r)) return r;
  if (r < 0) return -strip_kernel_g(-r);
  if (r == 0) return 0.0;
  constexpr double rmin = 1.0 / (1 << -kEmin), rmax = static_cast<double>(1 << kEmax);
  const Table& T = table();
  if (r < rmin) return g_small(r);
  if (r >= rmax) return T.g_max + 0.5 * units::pi * std::log(r / rmax);
  // r = (1 + f) 2^E: the interval from the exponent and the top 7 bits of the mantissa, the
  // position in it from the remaining 45 bits.
  std::uint64_t bits;
  std::memcpy(&bits, &r, sizeof bits);
  const int E = static_cast<int>(bits >> 52) - 1023;
  const std::size_t i = static_cast<std::size_t>(E - kEmin) * kPerBinade + ((bits >> 45) & (kPerBinade - 1));
  const double t = static_cast<double>(bits & ((std::uint64_t{1} << 45) - 1)) * (1.0 / static_cast<double>(std::uint64_t{1} << 45));
  const Table::Interval& v = T.iv[i];
  const double t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * v.g0 + (t3 - 2 * t2 + t) * v.d0 + (-2 * t3 + 3 * t2) * v.g1 + (t3 - t2) * v.d1;
}

}  // namespace mh
