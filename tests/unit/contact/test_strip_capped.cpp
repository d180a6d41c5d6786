// The displacement of a capped strip (docs/method.md §9 item 6: pressure min(q sqrt(1 − t²), p_lim),
// r = p_lim / q) as the strip solver takes it, whole columns at once on the centre lines
// (strips_detail::influence_centre_line) and at the ends of other strips, on its prepared nodes
// (strips_detail::capped_source_influence), against tanh-sinh quadrature of the definition
// (Boost.Math, independent of the solver's Gauss–Legendre nodes, of its subtraction of the
// singular part and of its rectangle closed form):
//   u(X0, d) = H q ∫_{-a}^{a} min(sqrt(1 − ξ²/a²), r) [asinh(e2/|ξ − X0|) − asinh(e1/|ξ − X0|)] dξ,
// e1, e2 = (d ∓ ½) ds the strip's lateral edges seen from the point (Johnson, Contact Mechanics §3.2).
// Tolerance in physical units: 1 nm of displacement for p_lim = 900 MPa on steel (E* = 115 GPa),
// where the displacements are 1–60 µm (2e-4 of the smallest, the accuracy test_strips.cpp asks of
// the solver's quadrature). Measured: within 0.01 nm on the centre lines, 0.41 nm at a point 3 % of
// the flat top from its kink (the solver's 8-point Gauss–Legendre nodes near the logarithmic peak
// of the kernel); the prepared nodes agree with the general quadrature to 1e-6 of that.
#include <catch2/catch.hpp>

#include <boost/math/quadrature/tanh_sinh.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "contact/strips/strip_influence.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEstar = 210e9 / (2 * (1 - 0.28 * 0.28));  // steel on steel, E = 210 GPa, nu = 0.28 [Pa]
constexpr double kH = 1.0 / (kPi * kEstar);                // compliance of the strip solver [m/Pa · 1/m]
constexpr double kPlim = 900e6;                            // [Pa]
constexpr double kTol = 1e-9;                              // [m]: 1 nm
// [m]: 20 nm at points on a tail of the capped pressure or beyond the strip's end. There the
// solver's quadrature (gauss_points, influence()) is measured 17 nm off at r = 0.1 (a tail of a
// twentieth of the strip, the point within it next to the strip's end; 0.4 % of 4.4 µm) and
// within 2.5 nm elsewhere: the limit of 8 Gauss–Legendre nodes beside a logarithmic peak, the same
// in the prepared nodes as in influence() (checked below to 1e-6 nm), not a cost of preparing them.
constexpr double kTolTail = 2e-8;

/// asinh(e/|x|), also where e/|x| overflows.
double asinh_over(double e, double x) {
  const double ax = std::fabs(x);
  const double q = e / ax;
  if (std::isfinite(q)) return std::asinh(q);
  return e > 0 ? std::log(2 * e) - std::log(ax) : -(std::log(-2 * e) - std::log(ax));
}

/// The definition above (without H q) by tanh-sinh on the pieces between the kinks of the
/// capped profile (±a sqrt(1 − r²)), the strip ends and the point X0 (logarithmic singularity).
double reference(double X0, double a, double e1, double e2, double r) {
  static boost::math::quadrature::tanh_sinh<double> ts;
  const double xf = a * std::sqrt(1 - r * r);
  std::vector<double> br = {-a, -xf, xf, a};
  if (std::fabs(X0) < a) br.push_back(X0);
  std::sort(br.begin(), br.end());
  double sum = 0;
  for (std::size_t k = 0; k + 1 < br.size(); ++k) {
    const double lo = br[k], hi = br[k + 1];
    if (!(hi > lo)) continue;
    sum += ts.integrate(
        [&](double xi) {
          const double f = std::min(std::sqrt(std::max(0.0, 1 - (xi / a) * (xi / a))), r);
          return f * (asinh_over(e2, xi - X0) - asinh_over(e1, xi - X0));
        },
        lo, hi, 1e-12);
  }
  return sum;
}

}  // namespace

TEST_CASE("capped strip: displacement columns on the centre lines against tanh-sinh quadrature", "[strips][plastic]") {
  std::vector<double> gx, gw;
  mh::strips_detail::gauss_legendre(8, &gx, &gw);  // the solver's nodes: StripOptions::gauss_points / 2
  const double ds = 0.2e-3;
  double worst = 0;
  // Half-lengths of a tread and a flange strip; r from strongly capped (flange, docs/strips.md:
  // r = 0.1–0.3) to barely capped; distances from the strip's own centre to across a wide patch.
  for (double a : {3e-3, 25e-3})
    for (double r : {0.1, 0.45, 0.95}) {
      const double q = kPlim / r;
      const int dmax = 120;
      std::vector<double> col;
      mh::strips_detail::influence_centre_line(a, ds, r, dmax, gx, gw, col);
      // Only some distances, as the collocation asks for those of its elastic strips.
      std::vector<char> need(dmax + 1, 0);
      need[3] = need[60] = 1;
      std::vector<double> some;
      mh::strips_detail::influence_centre_line(a, ds, r, dmax, gx, gw, some, &need);
      for (int d : {0, 1, 2, 3, 5, 20, 60, 120}) {
        const double e1 = (d - 0.5) * ds, e2 = (d + 0.5) * ds;
        const double ref = kH * q * reference(0, a, e1, e2, r);
        const double lib = kH * q * col[static_cast<std::size_t>(d)];
        INFO("a = " << a * 1e3 << " mm, r = " << r << ", d = " << d << ": column " << lib << " m, quadrature " << ref << " m");
        CHECK(std::fabs(lib - ref) < kTol);
        worst = std::max(worst, std::fabs(lib - ref));
        if (need[static_cast<std::size_t>(d)]) CHECK(some[static_cast<std::size_t>(d)] == col[static_cast<std::size_t>(d)]);
        else CHECK(some[static_cast<std::size_t>(d)] == 0.0);
      }
    }
  std::printf("  capped strip, centre-line columns: worst deviation from tanh-sinh %.2e m\n", worst);
}

TEST_CASE("capped strip: displacement at the ends of other strips against tanh-sinh quadrature", "[strips][plastic]") {
  std::vector<double> gx, gw;
  mh::strips_detail::gauss_legendre(8, &gx, &gw);
  const double ds = 0.2e-3;
  double worst = 0, worst_tail = 0;
  for (double a : {3e-3, 25e-3})
    for (double r : {0.1, 0.45, 0.95}) {
      const double q = kPlim / r;
      mh::strips_detail::CappedSource src;
      mh::strips_detail::capped_source(a, r, gx, gw, src);
      CHECK(src.x_flat == Approx(a * std::sqrt(1 - r * r)).epsilon(1e-14));
      // The ends of elastic strips beside it: inside the flat top, from its centre to near its
      // kink; on its tail; at and beyond its end.
      for (double frac : {0.05, 0.5, 0.97, -0.3, -0.9, -1.0, -1.2, -3.0})
        for (int d : {0, 1, 4, 30}) {
          if (d == 0 && frac == -1.0) continue;  // the strip's own end: the kernel is singular there
          // frac > 0: a fraction of the flat top; frac < 0: |frac| > 1 beyond the end, else the
          // point that fraction of the way along the tail.
          const double X0 = frac > 0 ? frac * src.x_flat
                                     : (-frac >= 1 ? -frac * a : src.x_flat + (-frac) * (a - src.x_flat));
          const double e1 = (d - 0.5) * ds, e2 = (d + 0.5) * ds;
          const double ref = kH * q * reference(X0, a, e1, e2, r);
          const double lib = kH * q * mh::strips_detail::capped_source_influence(src, X0, e1, e2);
          // The general quadrature of the solver (influence) on the same point.
          const double gen = kH * q * mh::strips_detail::influence(X0, a, e1, e2, r, gx, gw);
          INFO("a = " << a * 1e3 << " mm, r = " << r << ", X0 = " << X0 * 1e3 << " mm, d = " << d << ": prepared " << lib
                      << " m, general " << gen << " m, quadrature " << ref << " m");
          CHECK(std::fabs(lib - ref) < (frac > 0 ? kTol : kTolTail));
          CHECK(std::fabs(lib - gen) < 1e-6 * kTol);  // the same nodes, summed in another order
          (frac > 0 ? worst : worst_tail) = std::max(frac > 0 ? worst : worst_tail, std::fabs(lib - ref));
        }
    }
  std::printf("  capped strip, ends of other strips: worst deviation from tanh-sinh %.2e m in the flat top, %.2e m on "
              "a tail or beyond\n", worst, worst_tail);
}

TEST_CASE("capped strip: the tabulated centre-line column against its quadrature and tanh-sinh", "[strips][plastic]") {
  // strips_detail::capped_centre_line reads the column of influence_centre_line from a table in
  // (th, log2 rho) (strip_influence.hpp). Against the quadrature it replaces, over capped strips
  // from r = 0.02 to 0.9999 (th off the table's nodes), half-lengths 0.5 … 25 mm, every distance
  // across 150 strips of 0.2 mm: within kTolTable of displacement per unit amplitude times
  // p_lim / r, the displacement of the strip's pressure (H q a · difference of F). Against
  // tanh-sinh quadrature of the definition it keeps the 1 nm of the quadrature's own test above.
  constexpr double kTolTable = 5e-13;  // [m]: 5e-4 nm
  std::vector<double> gx, gw;
  mh::strips_detail::gauss_legendre(8, &gx, &gw);
  const double ds = 0.2e-3;
  double worst = 0, worst_ts = 0;
  for (double a : {0.5e-3, 1.7e-3, 3e-3, 7.3e-3, 25e-3})
    for (double r : {0.02, 0.1, 0.2371, 0.45, 0.7, 0.913, 0.99, 0.9999}) {
      const double q = kPlim / r;
      const int dmax = 150;
      std::vector<double> tab, quad;
      mh::strips_detail::capped_centre_line(a, ds, r, dmax, gx, gw, tab);
      mh::strips_detail::influence_centre_line(a, ds, r, dmax, gx, gw, quad);
      for (int d = 0; d <= dmax; ++d) {
        const double dev = kH * q * std::fabs(tab[static_cast<std::size_t>(d)] - quad[static_cast<std::size_t>(d)]);
        INFO("a = " << a * 1e3 << " mm, r = " << r << ", d = " << d << ": table " << tab[static_cast<std::size_t>(d)]
                    << ", quadrature " << quad[static_cast<std::size_t>(d)]);
        CHECK(dev < kTolTable);
        worst = std::max(worst, dev);
      }
      for (int d : {0, 1, 7, 40, 150}) {
        const double ref = kH * q * reference(0, a, (d - 0.5) * ds, (d + 0.5) * ds, r);
        const double dev = std::fabs(kH * q * tab[static_cast<std::size_t>(d)] - ref);
        INFO("a = " << a * 1e3 << " mm, r = " << r << ", d = " << d << ": table " << kH * q * tab[static_cast<std::size_t>(d)]
                    << " m, tanh-sinh " << ref << " m");
        CHECK(dev < kTol);
        worst_ts = std::max(worst_ts, dev);
      }
      // Some distances only, as the collocation asks: the same values, zero elsewhere.
      std::vector<char> need(dmax + 1, 0);
      need[0] = need[5] = need[6] = need[90] = 1;
      std::vector<double> some;
      mh::strips_detail::capped_centre_line(a, ds, r, dmax, gx, gw, some, &need);
      for (int d = 0; d <= dmax; ++d)
        CHECK(some[static_cast<std::size_t>(d)] == (need[static_cast<std::size_t>(d)] ? tab[static_cast<std::size_t>(d)] : 0.0));
      // The edges' log2 given, as the solver keeps them: the same values.
      std::vector<double> l2;
      for (int m = 0; m <= dmax; ++m) l2.push_back(std::log2((m + 0.5) * ds));
      std::vector<double> given;
      mh::strips_detail::capped_centre_line(a, ds, r, dmax, gx, gw, given, nullptr, l2.data());
      CHECK(given == tab);
    }
  std::printf("  capped strip, tabulated centre-line columns: worst %.2e m from the quadrature, %.2e m from tanh-sinh\n",
              worst, worst_ts);
}
