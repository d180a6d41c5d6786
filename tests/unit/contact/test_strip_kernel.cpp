// The strip kernel g(r) = ∫_{-1}^{1} sqrt(1 − t²) asinh(r/|t|) dt (contact/strips/strip_kernel.hpp)
// against adaptive quadrature of its definition (tanh-sinh, Boost.Math; independent of the
// elliptic-integral derivative and of the table), and its derivative against the integral it
// stands for.
#include <catch2/catch.hpp>
#include <cmath>
#include <algorithm>
#include <random>
#include <vector>

#include <boost/math/quadrature/tanh_sinh.hpp>

#include "contact/strips/strip_kernel.hpp"

namespace {
/// ∫ f over [lo, hi] by tanh-sinh quadrature to 1e-13 relative; f(x, d_lo, d_hi) gets the
/// distances of x to both ends exactly (Boost's complement argument), so that an integrand
/// singular at an end (the logarithm of asinh(r/|τ − t|) at τ = t, the square root at τ = ±1)
/// is evaluated without cancellation right up to it.
template <class F>
double quad(F&& f, double lo, double hi) {
  static boost::math::quadrature::tanh_sinh<double> ts;  // not const: Boost 1.74 declares the two-argument integrate non-const
  return ts.integrate([&](double x, double xc) { return f(x, xc < 0 ? -xc : x - lo, xc > 0 ? xc : hi - x); }, lo, hi,
                      1e-13);
}
/// asinh(r/d) for d > 0, also where r/d overflows.
double asinh_ratio(double r, double d) {
  const double q = r / d;
  return std::isfinite(q) ? std::asinh(q) : std::log(2 * r) - std::log(d);
}
// The integrands are even in t: twice the integral over [0, 1].
double g_quad(double r) {
  return 2 * quad([r](double t, double d0, double d1) { return std::sqrt(d1 * (1 + t)) * asinh_ratio(r, d0); }, 0.0, 1.0);
}
double dg_quad(double r) {
  return 2 * quad([r](double t, double, double d1) { return std::sqrt(d1 * (1 + t)) / std::hypot(t, r); }, 0.0, 1.0);
}
}  // namespace

TEST_CASE("strip kernel g(r) equals quadrature of its definition", "[strips][kernel]") {
  // Random r over 1e-7 … 1e7 (log-uniform): inside the table, below it (series) and above it.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> lg(-7, 7);
  double worst = 0;
  for (int i = 0; i < 400; ++i) {
    const double r = std::pow(10.0, lg(rng));
    const double ref = g_quad(r), got = mh::strip_kernel_g(r);
    INFO("r = " << r << ": table " << got << ", quadrature " << ref);
    // 1e-9 absolute (g itself runs from ~1e-6 to ~26), and odd.
    REQUIRE(std::fabs(got - ref) <= 1e-9 + 1e-10 * std::fabs(ref));
    REQUIRE(mh::strip_kernel_g(-r) == -got);
    worst = std::max(worst, std::fabs(got - ref));
  }
  std::printf("  strip kernel: worst |g_table - g_quadrature| %.2e over 400 r in 1e-7..1e7\n", worst);
  REQUIRE(mh::strip_kernel_g(0.0) == 0.0);
  REQUIRE(std::isnan(mh::strip_kernel_g(NAN)));
}

TEST_CASE("strip kernel derivative: complete elliptic integrals against quadrature", "[strips][kernel]") {
  for (double r : {1e-6, 1e-3, 0.05, 0.5, 1.0, 3.0, 40.0, 1e4}) {
    INFO("r = " << r);
    REQUIRE(mh::strip_kernel_dg(r) == Approx(dg_quad(r)).epsilon(1e-11));
  }
  // Limits: 2 (ln(4/r) − 1) for small r, π/(2r) for large r.
  REQUIRE(mh::strip_kernel_dg(1e-9) == Approx(2 * (std::log(4e9) - 1)).epsilon(1e-12));
  REQUIRE(mh::strip_kernel_dg(1e8) == Approx(M_PI / 2e8).epsilon(1e-12));
}

// ---- Off the centre line: G(t, r) and the drop E(t, r) = g(r) − G(t, r). ----

namespace {
/// G(t, r) = ∫_{-1}^{1} √(1 − τ²) asinh(r/|τ − t|) dτ by tanh-sinh quadrature between breakpoints
/// at the kernel's peak (τ = t) and at distances r, 10 r, … from it and from the strip's end τ = 1,
/// where the integrand changes on the scale r: an independent reference (no change of variable,
/// no closed-form part). At a breakpoint τ = t the distance |τ − t| is the exact distance to the
/// end of the interval.
double G_reference(double t, double r) {
  std::vector<double> pts = {-1.0, 1.0};
  for (double c : {t, 1.0})
    for (double k : {0.0, 1.0, 10.0, 100.0, 1000.0})
      for (double sgn : {-1.0, 1.0}) {
        const double p = c + sgn * k * r;
        if (p > -1 && p < 1) pts.push_back(p);
      }
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  double G = 0;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const double lo = pts[i], hi = pts[i + 1];
    G += quad(
        [&](double tau, double d_lo, double d_hi) {
          const double d = lo == t ? d_lo : hi == t ? d_hi : std::fabs(tau - t);
          const double one_minus = hi == 1.0 ? d_hi : 1 - tau, one_plus = lo == -1.0 ? d_lo : 1 + tau;
          return std::sqrt(one_minus * one_plus) * asinh_ratio(r, d);
        },
        lo, hi);
  }
  return G;
}
}  // namespace

TEST_CASE("off-centre strip kernel G(t, r): quadrature against adaptive quadrature of its definition",
          "[strips][kernel]") {
  // On the strip (t < 1), at its end (t = 1, where G has a boundary layer of width r), just
  // beyond it and far from it; r from the narrowest strips at their own end to far strips.
  double worst = 0;
  for (double t : {0.0, 0.3, 0.9, 0.99, 0.99999, 1.0, 1.00001, 1.001, 1.3, 2.0, 9.0, 100.0})
    for (double r : {1.5e-5, 1e-3, 0.01, 0.05, 0.3, 1.0, 10.0, 1000.0}) {
      const double ref = G_reference(t, r), got = mh::strip_kernel_G_quadrature(t, r).G;
      INFO("t = " << t << ", r = " << r << ": " << got << " against " << ref);
      // The closed-form logarithmic part leaves a cancellation of O(1) terms for G ~ r.
      REQUIRE(std::fabs(got - ref) <= 1e-8 * std::fabs(ref) + 1e-9);
      worst = std::max(worst, std::fabs(got - ref) / std::fabs(ref));
    }
  std::printf("  off-centre kernel: worst relative difference from adaptive quadrature %.2e\n", worst);
  // On the centre line G is the tabulated g.
  for (double r : {1e-4, 0.02, 1.0, 300.0})
    CHECK(mh::strip_kernel_G_quadrature(0.0, r).G == Approx(mh::strip_kernel_g(r)).epsilon(1e-8).margin(1e-9));
}

TEST_CASE("off-centre strip kernel: derivatives against central differences", "[strips][kernel]") {
  // The table's Hermite slopes are these derivatives; a wrong one shows as a cubic error.
  for (double t : {0.3, 0.99, 1.01, 2.0})
    for (double r : {0.01, 0.3, 3.0}) {
      INFO("t = " << t << ", r = " << r);
      const auto v = mh::strip_kernel_G_quadrature(t, r);
      const double hr = 1e-5 * r, ht = 1e-6;
      auto G = [](double tt, double rr) { return mh::strip_kernel_G_quadrature(tt, rr); };
      CHECK(v.G_r == Approx((G(t, r + hr).G - G(t, r - hr).G) / (2 * hr)).epsilon(1e-6));
      CHECK(v.G_t == Approx((G(t + ht, r).G - G(t - ht, r).G) / (2 * ht)).epsilon(1e-5));
      CHECK(v.G_tr == Approx((G(t + ht, r).G_r - G(t - ht, r).G_r) / (2 * ht)).epsilon(1e-5));
    }
}

TEST_CASE("strip kernel drop E(t, r): table against quadrature", "[strips][kernel]") {
  // What the strip solver needs: the drop across one strip, E(t, e2/a) − E(t, e1/a), for a strip
  // of half-length a whose edges lie e1 = (k − ½) ds, e2 = (k + ½) ds from the point; measured
  // relative to the centre-line value of the same strip, g(e2/a) − g(e1/a) (header: within 3e-5).
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0, 1);
  double worst = 0;
  for (int i = 0; i < 3000; ++i) {
    const double t = i % 3 == 0 ? 12 * U(rng) : (i % 3 == 1 ? 1 + (U(rng) - 0.5) * std::pow(10, -7 * U(rng))
                                                            : std::pow(10, -4 * U(rng)));
    const double a = 0.3 + 10 * U(rng), ds = 0.2;  // [mm]
    const int k = i % 25 - 3;
    const double r1 = (k - 0.5) * ds / a, r2 = (k + 0.5) * ds / a;
    auto E_quad = [&](double r) {
      const double s = r < 0 ? -1 : 1;
      return s * (mh::strip_kernel_g(std::fabs(r)) - mh::strip_kernel_G_quadrature(t, std::fabs(r)).G);
    };
    const double got = mh::strip_kernel_drop(t, r2) - mh::strip_kernel_drop(t, r1);
    const double ref = E_quad(r2) - E_quad(r1);
    const double scale = std::fabs(mh::strip_kernel_g(r2) - mh::strip_kernel_g(r1));
    INFO("t = " << t << ", a = " << a << " mm, k = " << k);
    REQUIRE(std::fabs(got - ref) <= 5e-5 * scale);
    worst = std::max(worst, std::fabs(got - ref) / scale);
    // The prepared form is the same function.
    const auto R1 = mh::strip_kernel_drop_prepare(r1), R2 = mh::strip_kernel_drop_prepare(r2);
    REQUIRE(mh::strip_kernel_drop_diff(R2, R1, t) == Approx(got).margin(1e-15 * scale + 1e-300));
    const mh::StripDropR RR[2] = {R1, R2};
    const int k0 = 0;
    double acc = 1.0;  // accumulated into, scaled by f = 2
    mh::strip_kernel_drop_diffs(RR, &k0, &t, 1, 2.0, &acc);
    REQUIRE(acc == Approx(1.0 + 2.0 * got).margin(1e-14 * scale + 1e-300));
  }
  std::printf("  strip kernel drop: worst difference from quadrature %.2e of the centre-line value\n", worst);
}

TEST_CASE("strip kernel drop E(t, r): symmetries and limits", "[strips][kernel]") {
  for (double r : {1e-6, 0.01, 0.7, 50.0, 1e5}) {
    INFO("r = " << r);
    CHECK(mh::strip_kernel_drop(0.0, r) == 0.0);                      // on the centre line
    CHECK(mh::strip_kernel_drop(0.6, -r) == -mh::strip_kernel_drop(0.6, r));   // odd in r
    CHECK(mh::strip_kernel_drop(-0.6, r) == mh::strip_kernel_drop(0.6, r));    // even in t
  }
  CHECK(mh::strip_kernel_drop(0.5, 0.0) == 0.0);
  // Far lateral distance: E → L(t) − L(0) = (π/2) t² on the strip (the logarithmic potential of
  // the semicircle density), (π/2)(ln t − 1/(8t²) + ½ + ln 2) … beyond it, within r⁻².
  CHECK(mh::strip_kernel_drop(0.5, 1e5) == Approx(M_PI / 2 * 0.25).epsilon(1e-8));
  CHECK(mh::strip_kernel_drop(0.5, 3000.0) == Approx(M_PI / 2 * 0.25).epsilon(1e-6));
  // Far along x (t beyond the table): continuous with the table at its end, within the table's
  // interpolation error there (3e-7 of E).
  CHECK(mh::strip_kernel_drop(129.0 * (1 + 1e-12), 0.4) == Approx(mh::strip_kernel_drop(129.0 * (1 - 1e-12), 0.4)).epsilon(1e-6));
  CHECK(std::isnan(mh::strip_kernel_drop(NAN, 0.1)));
}
