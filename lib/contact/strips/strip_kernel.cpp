#include "contact/strips/strip_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include <boost/math/special_functions/ellint_rd.hpp>

#include "core/units.hpp"

namespace mh {

namespace {

constexpr int kEmin = -20, kEmax = 20;  // binades [2^E, 2^(E+1)), E = kEmin … kEmax − 1
constexpr int kPerBinade = 128;         // Hermite intervals per binade (a power of 2: the top mantissa bits)
static_assert((kPerBinade & (kPerBinade - 1)) == 0, "kPerBinade must be a power of 2");

// Small r: g(r) = 2r ln(4/r) + O(r³ ln r) (from g'(r) = 2 (ln(4/r) − 1) + O(r² ln r)).
double g_small(double r) { return 2.0 * r * std::log(4.0 / r); }

// 8-point Gauss–Legendre on [−1, 1] (the positive half): the 1-D table's integral of g' and the
// panels of the off-centre quadrature.
constexpr double kGx[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
constexpr double kGw[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

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
    double r0 = std::ldexp(1.0, kEmin), g0 = g_small(r0), dg0 = strip_kernel_dg(r0);
    for (int i = 0; i < n; ++i) {
      const int E = kEmin + i / kPerBinade;
      const double h = std::ldexp(1.0, E) / kPerBinade, r1 = r0 + h, mid = r0 + 0.5 * h;
      double acc = 0;
      for (int k = 0; k < 4; ++k)
        acc += kGw[k] * (strip_kernel_dg(mid - 0.5 * h * kGx[k]) + strip_kernel_dg(mid + 0.5 * h * kGx[k]));
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
  return 2.0 * boost::math::ellint_rd(0.0, r * r / s2, 1.0) / (3.0 * std::sqrt(s2));
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


// ---- Off the centre line: G(t, r) and the drop E(t, r) = g(r) − G(t, r). ----

namespace {

constexpr double kPi = units::pi;

/// L(t) = ∫_{-1}^{1} sqrt(1 − τ²) ln|τ − t| dτ (t ≥ 0) and L'(t): the logarithmic potential of
/// the semicircle density, (π/2)(t² − ½ − ln 2) on the strip and
/// (π/2)(t² − ½ − ln 2 − t sqrt(t² − 1) + ln(t + sqrt(t² − 1))) beyond it (→ (π/2) ln t).
void log_potential(double t, double* L, double* dL) {
  const double c = 0.5 * kPi;
  if (t <= 1) {
    *L = c * (t * t - 0.5 - std::log(2.0));
    *dL = c * 2 * t;
    return;
  }
  const double s = std::sqrt(t * t - 1);
  *L = c * (t * t - 0.5 - std::log(2.0) - t * s + std::log(t + s));
  *dL = c * (2 * t - s - t * t / s + 1 / s);
}

// The table of E(t, r) (header): t nodes graded towards t = 1, r nodes uniform in ln r.
constexpr int kPt = 4;               // cells per binade of |1 − t|
constexpr int kDmin = -22;           // |1 − t| binades from 2^kDmin …
constexpr int kDmaxOut = 7;          // … to 1 inside the strip and to 2^kDmaxOut beyond it (t ≤ 129)
constexpr int kPr = 4;               // cells per binade of r
constexpr int kRmin = -16, kRmax = 12;  // r from 2^kRmin to 2^kRmax
constexpr double kTmax = 1.0 + (1 << kDmaxOut);
constexpr double kDminValue = 1.0 / (1 << -kDmin);  // 2^kDmin

struct DropTable {
  std::vector<double> tn;            // t nodes, increasing: 0 … 1 … kTmax
  int nt = 0, nr = 0;
  std::vector<StripKernelValue> v;   // E and its derivatives at (tn[i], r_j): v[i * nr + j]
  DropTable() {
    tn.push_back(0.0);
    for (int k = -1; k >= kDmin; --k)
      for (int s = kPt - 1; s >= 0; --s) tn.push_back(1 - std::ldexp(1.0 + double(s) / kPt, k));
    tn.push_back(1.0);
    for (int k = kDmin; k < kDmaxOut; ++k)
      for (int s = 0; s < kPt; ++s) tn.push_back(1 + std::ldexp(1.0 + double(s) / kPt, k));
    tn.push_back(kTmax);
    nt = static_cast<int>(tn.size());
    nr = (kRmax - kRmin) * kPr + 1;
    v.resize(static_cast<std::size_t>(nt) * nr);
    for (int j = 0; j < nr; ++j) {
      const double r = std::exp2(kRmin + double(j) / kPr);
      const StripKernelValue c = strip_kernel_G_quadrature(0.0, r);
      for (int i = 0; i < nt; ++i) {
        const StripKernelValue a = strip_kernel_G_quadrature(tn[i], r);
        // E = g − G; in v = ln r the r-derivatives carry a factor r.
        v[static_cast<std::size_t>(i) * nr + j] = {c.G - a.G, r * (c.G_r - a.G_r), -a.G_t, -r * a.G_tr};
      }
    }
  }
  /// The t cell holding t in [0, kTmax]: index of its lower node.
  int t_cell(double t) const {
    // The binade and the top log2(kPt) mantissa bits of d = |1 − t| give the cell.
    static_assert(kPt == 4, "t_cell reads 2 mantissa bits");
    auto binade = [](double d, int* k, int* s) {
      std::uint64_t bits;
      std::memcpy(&bits, &d, sizeof bits);
      *k = static_cast<int>(bits >> 52) - 1023;
      *s = static_cast<int>((bits >> 50) & 3);
    };
    int k, s;
    if (t < 1) {
      const double d = 1 - t;
      if (d >= 1) return 0;
      if (d < kDminValue) return -kDmin * kPt;  // [1 − 2^kDmin, 1]
      binade(d, &k, &s);  // d = 2^k (1 + s/kPt + …)
      return (-1 - k) * kPt + (kPt - s) - 1;
    }
    const double d = t - 1;
    if (d < kDminValue) return -kDmin * kPt + 1;  // [1, 1 + 2^kDmin]
    binade(d, &k, &s);
    return std::min(-kDmin * kPt + 2 + (k - kDmin) * kPt + s, nt - 2);
  }
  static void hermite(double x, double* b) {
    const double x2 = x * x, x3 = x2 * x;
    b[0] = 2 * x3 - 3 * x2 + 1;
    b[1] = x3 - 2 * x2 + x;
    b[2] = -2 * x3 + 3 * x2;
    b[3] = x3 - x2;
  }
  /// The r part of the interpolation: the r cell and its Hermite basis in v = ln r (slopes scaled),
  /// from log2 r.
  void r_basis(double log2r, int* j, double* bw) const {
    const double vr = (log2r - kRmin) * kPr;
    *j = std::min(std::max(static_cast<int>(vr), 0), nr - 2);
    hermite(vr - *j, bw);
    const double hv = std::log(2.0) / kPr;
    bw[1] *= hv;
    bw[3] *= hv;
  }
  /// The t part: the t cell and its Hermite basis (slopes scaled).
  void t_basis(double t, int* i, double* bu) const {
    *i = t_cell(t);
    const double ht = tn[*i + 1] - tn[*i];
    hermite((t - tn[*i]) / ht, bu);
    bu[1] *= ht;
    bu[3] *= ht;
  }
  double eval(int i, const double* bu, int j, const double* bw) const {
    const StripKernelValue* p0 = &v[static_cast<std::size_t>(i) * nr + j];
    const StripKernelValue* p1 = p0 + nr;
    auto row = [&](const StripKernelValue* p, double b0, double b1) {
      return b0 * (bw[0] * p[0].G + bw[1] * p[0].G_r + bw[2] * p[1].G + bw[3] * p[1].G_r) +
             b1 * (bw[0] * p[0].G_t + bw[1] * p[0].G_tr + bw[2] * p[1].G_t + bw[3] * p[1].G_tr);
    };
    return row(p0, bu[0], bu[1]) + row(p1, bu[2], bu[3]);
  }
};

const DropTable& drop_table() {
  static const DropTable t;
  return t;
}

}  // namespace

StripKernelValue strip_kernel_G_quadrature(double t, double r) {
  StripKernelValue A;
  t = std::fabs(t);
  if (!(r > 0)) return A;
  const double tt = std::min(t, 1.0), th0 = std::asin(tt), half_pi = 0.5 * kPi;
  double S = 0, S_t = 0;
  auto f = [&](double th, double w) {
    const double c = std::cos(th), s = std::sin(th);
    // x = sin θ − t without cancellation near θ0
    double x;
    if (t <= 1) {
      x = 2 * std::cos(0.5 * (th + th0)) * std::sin(0.5 * (th - th0));
    } else {
      const double h = std::sin(0.5 * (half_pi - th));
      x = -2 * h * h - (t - 1);
    }
    const double R = std::sqrt(x * x + r * r), wc2 = w * c * c;
    S += wc2 * std::log(r + R);            // asinh(r/|x|) = ln(r + R) − ln|x|
    S_t -= wc2 * x / (R * (r + R));       // ∂t ln(r + R), ∂x/∂t = −1
    A.G_r += wc2 / R;
    A.G_tr -= w * s / R;                  // ∂r of G_t = ∫ f'(τ) asinh(r/|τ − t|) dτ, f' dτ = −sin θ dθ
  };
  auto panel = [&](double lo, double hi) {
    const double mid = 0.5 * (lo + hi), h = 0.5 * (hi - lo);
    for (int k = 0; k < 4; ++k) {
      f(mid - h * kGx[k], kGw[k] * h);
      f(mid + h * kGx[k], kGw[k] * h);
    }
  };
  constexpr double kRatio = 0.3;  // geometric grading of the panels towards θ0
  // A twentieth of the width of the kernel's peak in θ: r / cos θ0, or sqrt(r) at the end t = 1.
  const double finest = 0.05 * r / std::max(std::sqrt(std::max(1 - tt * tt, 0.0)), std::sqrt(r));
  for (int side = -1; side <= 1; side += 2) {
    const double len = side < 0 ? th0 + half_pi : half_pi - th0;
    if (!(len > 0)) continue;
    double d0 = len;
    while (d0 > finest) {
      const double d1 = d0 * kRatio;
      if (side < 0) panel(th0 - d0, th0 - d1); else panel(th0 + d1, th0 + d0);
      d0 = d1;
    }
    if (side < 0) panel(th0 - d0, th0); else panel(th0, th0 + d0);
  }
  double L, dL;
  log_potential(t, &L, &dL);
  A.G = S - L;
  A.G_t = S_t - dL;
  return A;
}

namespace {

constexpr double kDropRmin = 1.0 / (1 << -kRmin), kDropRmax = static_cast<double>(1 << kRmax);

/// E(t, r) beyond the table in t (t > kTmax): the strip is far (|τ − t| ≥ 128), Gauss–Chebyshev
/// (second kind, 3 nodes) on the analytic integrand, error below 1e-14 relative (Bernstein
/// ellipse ρ ≈ 2t, error ∝ ρ^-6). r > 0.
double drop_far(double t, double r) {
  constexpr int n = 3;
  double G = 0;
  for (int k = 1; k <= n; ++k) {
    const double th = k * kPi / (n + 1), s = std::sin(th);
    G += s * s * std::asinh(r / (t - std::cos(th)));
  }
  return strip_kernel_g(r) - G * kPi / (n + 1);
}

/// E(t, r) for large r: the limit L(t) − L(0), error below t²/r² (header).
double drop_large_r(double t) {
  double L, L0, d;
  log_potential(t, &L, &d);
  log_potential(0, &L0, &d);
  return L - L0;
}

}  // namespace

StripDropR strip_kernel_drop_prepare(double r) {
  return strip_kernel_drop_prepare(r, std::log2(std::fabs(r)));
}

StripDropR strip_kernel_drop_prepare(double r, double log2_abs_r) {
  StripDropR R;
  R.sign = r < 0 ? -1.0 : 1.0;
  R.r = std::fabs(r);
  if (R.r == 0 || std::isnan(r)) {
    R.kind = std::isnan(r) ? StripDropR::Nan : StripDropR::Zero;
  } else if (R.r >= kDropRmax) {
    R.kind = StripDropR::LargeR;
  } else if (R.r < kDropRmin) {
    R.kind = StripDropR::SmallR;
  } else {
    R.kind = StripDropR::Table;
    drop_table().r_basis(log2_abs_r, &R.j, R.bw);
  }
  return R;
}

namespace {

/// E(t, R.r) without the sign, t >= 0, with the t basis (ti, bu) of the table when t <= kTmax.
double drop_unsigned(const StripDropR& R, double t, int ti, const double* bu) {
  if (t == 0) return 0.0;
  switch (R.kind) {
    case StripDropR::Zero: return 0.0;
    case StripDropR::Nan: return NAN;
    case StripDropR::LargeR: return drop_large_r(t);
    case StripDropR::SmallR: return t > kTmax ? drop_far(t, R.r) : strip_kernel_g(R.r) - strip_kernel_G_quadrature(t, R.r).G;
    case StripDropR::Table: break;
  }
  if (t > kTmax) return drop_far(t, R.r);
  return drop_table().eval(ti, bu, R.j, R.bw);
}

}  // namespace

double strip_kernel_drop(const StripDropR& R, double t) {
  t = std::fabs(t);
  if (std::isnan(t)) return NAN;
  int ti = 0;
  double bu[4] = {0, 0, 0, 0};
  if (t <= kTmax) drop_table().t_basis(t, &ti, bu);
  return R.sign * drop_unsigned(R, t, ti, bu);
}

namespace {

/// E(t, R2.r) − E(t, R1.r) with the table T, the t half of the interpolation shared.
double drop_diff(const DropTable& T, const StripDropR& R2, const StripDropR& R1, double t) {
  t = std::fabs(t);
  if (std::isnan(t)) return NAN;
  int ti = 0;
  double bu[4] = {0, 0, 0, 0};
  if (t <= kTmax) {
    T.t_basis(t, &ti, bu);
    if (R2.kind == StripDropR::Table && R1.kind == StripDropR::Table && t > 0)  // the common case
      return R2.sign * T.eval(ti, bu, R2.j, R2.bw) - R1.sign * T.eval(ti, bu, R1.j, R1.bw);
  }
  return R2.sign * drop_unsigned(R2, t, ti, bu) - R1.sign * drop_unsigned(R1, t, ti, bu);
}

}  // namespace

double strip_kernel_drop_diff(const StripDropR& R2, const StripDropR& R1, double t) {
  return drop_diff(drop_table(), R2, R1, t);
}

void strip_kernel_drop_diffs(const StripDropR* R, const int* k, const double* t, int n, double f, double* out) {
  const DropTable& T = drop_table();  // once, not per point
  for (int i = 0; i < n; ++i) out[i] += f * drop_diff(T, R[k[i] + 1], R[k[i]], t[i]);
}

double strip_kernel_drop(double t, double r) {
  return strip_kernel_drop(strip_kernel_drop_prepare(r), t);
}

}  // namespace mh
