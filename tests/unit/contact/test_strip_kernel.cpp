// The strip kernel g(r) = ∫_{-1}^{1} sqrt(1 − t²) asinh(r/|t|) dt (contact/strip_kernel.hpp)
// against adaptive quadrature of its definition (GSL QAGS, independent of the elliptic-integral
// derivative and of the table), and its derivative against the integral it stands for.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include <gsl/gsl_integration.h>

#include "contact/strip_kernel.hpp"

namespace {
double qags(double (*f)(double, void*), double r) {
  gsl_integration_workspace* w = gsl_integration_workspace_alloc(1000);
  gsl_function F{f, &r};
  double res = 0, err = 0;
  gsl_integration_qags(&F, 0.0, 1.0, 0.0, 1e-13, 1000, w, &res, &err);
  gsl_integration_workspace_free(w);
  return 2.0 * res;  // the integrands are even in t
}
double g_def(double t, void* p) { return std::sqrt(1 - t * t) * std::asinh(*static_cast<double*>(p) / t); }
double dg_def(double t, void* p) {
  const double r = *static_cast<double*>(p);
  return std::sqrt(1 - t * t) / std::sqrt(t * t + r * r);
}
}  // namespace

TEST_CASE("strip kernel g(r) equals quadrature of its definition", "[strips][kernel]") {
  // Random r over 1e-7 … 1e7 (log-uniform): inside the table, below it (series) and above it.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> lg(-7, 7);
  double worst = 0;
  for (int i = 0; i < 400; ++i) {
    const double r = std::pow(10.0, lg(rng));
    const double ref = qags(g_def, r), got = mh::strip_kernel_g(r);
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
    REQUIRE(mh::strip_kernel_dg(r) == Approx(qags(dg_def, r)).epsilon(1e-11));
  }
  // Limits: 2 (ln(4/r) − 1) for small r, π/(2r) for large r.
  REQUIRE(mh::strip_kernel_dg(1e-9) == Approx(2 * (std::log(4e9) - 1)).epsilon(1e-12));
  REQUIRE(mh::strip_kernel_dg(1e8) == Approx(M_PI / 2e8).epsilon(1e-12));
}
