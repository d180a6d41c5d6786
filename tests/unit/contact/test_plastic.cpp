// The plastic law of one ellipse (plastic.hpp, ellipse_law.hpp; method.md §5). Each block
// names its source and its tolerance.
#include <catch2/catch.hpp>

#include <boost/math/quadrature/tanh_sinh.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "contact/ellipse/ellipse_law.hpp"

using namespace mh;

namespace {
constexpr double kPi = 3.14159265358979323846;
double rel(double x, double ref) { return std::fabs(x / ref - 1.0); }
}  // namespace

TEST_CASE("plastic law of a sphere is Thornton's (1997) truncated-Hertz law", "[plastic]") {
  // (Thornton's force law in h0 and his contact radius; the approach beyond yield is the
  // overlap-held one of method.md §5, below.)
  // Thornton, C., "Coefficient of restitution for collinear collisions of elastic-perfectly
  // plastic spheres", J. Appl. Mech. 64 (1997) 383–386. Contact of radius R (composite), modulus
  // E*_J = E/(2(1−ν²)), interference δ; the Hertz pressure is truncated at p_y, contact radius
  // a = √(Rδ) throughout. Derivation (written here independently of the library):
  //   elastic:  F = (4/3) E*_J √R δ^(3/2),  p0 = 2E*_J a/(πR),  so p0 = p_y at δ_y = R (π p_y/(2E*_J))²;
  //   beyond:   F = ∫ min(p0√(1−r²/a²), p_y) dA = π a² p_y (1 − s²/3), s = p_y/p0, where
  //             π a² p_y s²/3 = π³ R² p_y³/(12 E*_J²) does not depend on δ, hence Thornton's
  //             F = F_y + π R p_y (δ − δ_y), F_y = F(δ_y).
  // Our h0 = δ/2 for a sphere (method.md §2), so force(δ/2) must equal F(δ). Tolerance 1e-12
  // relative (1e-11 for dF/dδ). Also the contact radius of the patch is √(Rδ).
  for (double nu : {0.25, 0.3}) {
    Material mat;
    mat.E = 210e9;
    mat.nu = nu;
    mat.p_lim = 900e6;
    const double EJ = mat.E / (2 * (1 - nu * nu));
    for (double R : {0.005, 0.05, 0.46}) {
      CAPTURE(nu, R);
      const EllipseLaw L = make_ellipse_law(1 / (2 * R), 1 / (2 * R), mat, true);
      const double delta_y = R * std::pow(kPi * mat.p_lim / (2 * EJ), 2);
      const double F_y = (4.0 / 3.0) * EJ * std::sqrt(R) * std::pow(delta_y, 1.5);
      CHECK(rel(L.h_y, delta_y / 2) <= 1e-12);
      CHECK(rel(L.N_y, F_y) <= 1e-12);
      for (double f : {0.2, 0.7, 1.0, 1.5, 2.0, 5.0, 20.0, 100.0}) {
        CAPTURE(f);
        const double delta = f * delta_y;
        const double F = delta <= delta_y ? (4.0 / 3.0) * EJ * std::sqrt(R) * std::pow(delta, 1.5)
                                          : F_y + kPi * R * mat.p_lim * (delta - delta_y);
        const double dF = delta <= delta_y ? 2 * EJ * std::sqrt(R * delta) : kPi * R * mat.p_lim;
        double dN_dh0 = 0;
        CHECK(rel(L.force(delta / 2, &dN_dh0), F) <= 1e-12);
        CHECK(rel(dN_dh0 / 2, dF) <= 1e-11);  // dN/dδ = (dN/dh0)/2
        const EllipseState s = ellipse_state(L, delta / 2);
        CHECK(rel(s.a, std::sqrt(R * delta)) <= 1e-12);
        // The approach (method.md §5, "approach and overlap"): Hertz up to yield; beyond,
        // δ' = δ_ov + r (δ − δ_ov) with δ_ov = a²/(2R) = δ/2 (the rigid overlap of the patch),
        // r = 1.5 s (1 − s²/3), s = p_y/p0 = √(δ_y/δ) = 1/√f; e.g. f = 5: s = 0.4472,
        // r = 0.6708 × 0.9333 = 0.6261, δ' = δ (0.5 + 0.5 × 0.6261) = 0.8130 δ.
        const double sy = std::sqrt(1 / f), r = f > 1 ? 1.5 * sy * (1 - sy * sy / 3) : 1.0;
        CHECK(rel(s.approach, 0.5 * delta * (1 + r)) <= 1e-12);
        if (f == 5.0) CHECK(rel(s.approach, 0.8130 * delta) <= 1e-4);
        CHECK(s.plastic == (f > 1));
      }
    }
  }
}

namespace {
// ∫∫ over the ellipse x²/a² + y²/b² ≤ 1 of min(p0 √(1 − x²/a² − y²/b²), p_lim), as an iterated
// integral in x then y by tanh-sinh quadrature (Boost.Math; it takes the square-root ends of each
// interval in its stride), split at the kinks of the cap (independent of the radial reduction
// used to derive the closed form). Relative tolerance 1e-13 per integral.
double capped_load_quadrature(double a, double b, double p0, double plim) {
  static boost::math::quadrature::tanh_sinh<double> outer, inner;  // one each: nested calls
  const double s = plim / p0;
  auto between = [](boost::math::quadrature::tanh_sinh<double>& q, auto&& f, double lo, double hi) {
    return hi > lo ? q.integrate(f, lo, hi, 1e-13) : 0.0;
  };
  auto line_load = [&](double y) {  // ∫ p dx at fixed y, x from −X to X
    const double u = 1 - y * y / (b * b);
    if (!(u > 0)) return 0.0;
    auto p = [&](double x) { return std::min(p0 * std::sqrt(std::max(0.0, u - x * x / (a * a))), plim); };
    const double X = a * std::sqrt(u);
    const double k = u - s * s;  // kink at x = a √(u − s²) where p0√(...) = p_lim
    if (k > 0) {
      const double xk = a * std::sqrt(k);
      return 2 * (between(inner, p, 0, xk) + between(inner, p, xk, X));
    }
    return 2 * between(inner, p, 0, X);
  };
  const double yk = b * std::sqrt(std::max(0.0, 1 - s * s));  // the plateau edge on the y axis
  return 2 * (between(outer, line_load, 0, yk) + between(outer, line_load, yk, b));
}

// Steel (E 210 GPa, ν 0.3) with σ_y = 350 MPa and the yield law (material.yield_MPa alone).
Material yield_law_steel() {
  Material mat;
  mat.E = 210e9;
  mat.nu = 0.3;
  mat.yield = 350e6;
  mat.p_lim = p_lim_from_yield(mat.yield);
  mat.yield_law = true;
  return mat;
}
}  // namespace

TEST_CASE("plastic law: closed-form N against quadrature of the capped pressure", "[plastic]") {
  // method.md §5: N = π a b p_lim (1 − s²/3), s = p_lim/p0 (capped_hertz_load), against direct
  // 2-D quadrature of min(p0√(1 − x²/a² − y²/b²), p_lim) over the ellipse (a ≠ b), s from 0.01
  // to 1. Tolerance 1e-8 relative.
  const double a = 7e-3, b = 5e-3, p0 = 1.2e9;
  for (double s : {0.01, 0.03, 0.1, 0.2, 0.35, 0.5, 0.65, 0.8, 0.9, 0.97, 0.999, 1.0}) {
    CAPTURE(s);
    CHECK(rel(capped_hertz_load(a, b, p0, s * p0), capped_load_quadrature(a, b, p0, s * p0)) <= 1e-8);
  }
  // s ≥ 1 is the Hertz load (2/3) π a b p0, exactly.
  CHECK(capped_hertz_load(a, b, p0, 2 * p0) == (2.0 / 3.0) * kPi * a * b * p0);
  CHECK(capped_hertz_load(a, b, p0, INFINITY) == (2.0 / 3.0) * kPi * a * b * p0);
}

TEST_CASE("plastic law: the stiffness law equals the capped load of its patch", "[plastic]") {
  // method.md §5: force(h0) = capped_hertz_load(a, b, p0, p_lim) on the patch b = √(h0/B),
  // a = (m/n) b, p0 its Hertz peak; p_mean ≤ p_max = p_lim. Tolerance 1e-12 relative.
  Material mat;
  mat.E = 210e9;
  mat.nu = 0.3;
  mat.p_lim = 1100e6;
  for (double l : {1e-3, 0.1, 0.652, 1.0, 7.0, 300.0}) {
    const EllipseLaw L = make_ellipse_law(l * 2.0, 2.0, mat);
    for (double f : {0.5, 1.0, 1.01, 3.0, 50.0}) {
      CAPTURE(l, f);
      const EllipseState s = ellipse_state(L, f * L.h_y);
      CHECK(rel(s.N, capped_hertz_load(s.a, s.b, s.p0, mat.p_lim)) <= 1e-12);
      CHECK(s.p_max <= mat.p_lim);
      CHECK(s.p_mean <= s.p_max * (1 + 1e-15));
      if (s.plastic) {
        const double q = std::sqrt(1 - std::pow(mat.p_lim / s.p0, 2));
        CHECK(rel(s.plateau_a, s.a * q) <= 1e-12);
        CHECK(rel(s.plateau_b, s.b * q) <= 1e-12);
      } else {
        CHECK(s.plateau_a == 0);
      }
    }
  }
}

TEST_CASE("plastic law: N and dN/dh0 continuous at h_y", "[plastic]") {
  // method.md §5: the law is C¹ at the yield point. Tolerance 1e-10 relative between h_y(1 ∓ 1e-13).
  Material mat;
  mat.E = 210e9;
  mat.nu = 0.28;
  mat.p_lim = 1000e6;
  for (double l : {1e-4, 0.05, 0.3, 1.0, 4.0, 30.0, 1e4}) {
    CAPTURE(l);
    const double B = 1 / 0.3, A = l * B;
    for (bool exact : {true, false}) {
      const EllipseLaw L = make_ellipse_law(A, B, mat, exact);
      double d1 = 0, d2 = 0;
      const double below = L.force(L.h_y * (1 - 1e-13), &d1), above = L.force(L.h_y * (1 + 1e-13), &d2);
      CHECK(rel(below, above) <= 1e-10);
      CHECK(rel(d1, d2) <= 1e-10);
      CHECK(rel(L.force(L.h_y), L.N_y) <= 1e-12);
      // N_y independently: the load at which the elastic (uncapped) law's Hertz peak reaches
      // p_lim, found through the elastic law's own inverse (no use of the N_y or k_p formula).
      Material el = mat;
      el.p_lim = INFINITY;
      const EllipseLaw Le = make_ellipse_law(A, B, el, exact);
      CHECK(rel(ellipse_state_for_force(Le, L.N_y).p0, mat.p_lim) <= 1e-10);
      CHECK(rel(Le.force(L.h_y), L.N_y) <= 1e-12);
      // The Hertz peak of the patch reaches p_lim exactly at h_y.
      CHECK(rel(ellipse_state(L, L.h_y).p0, mat.p_lim) <= 1e-12);
    }
  }
}

TEST_CASE("plastic law: p_lim → ∞ is the elastic law, and the inverse h0_for_force", "[plastic]") {
  // Tolerances: 1e-12 relative.
  Material mat;
  mat.E = 210e9;
  mat.nu = 0.28;
  for (double l : {1e-3, 0.3, 1.0, 4.0, 900.0}) {
    CAPTURE(l);
    const double B = 1 / 0.3, A = l * B;
    Material big = mat, el = mat, pl = mat;
    big.p_lim = 1e30;
    el.p_lim = INFINITY;
    pl.p_lim = 700e6;
    const EllipseLaw Lb = make_ellipse_law(A, B, big), Le = make_ellipse_law(A, B, el),
                     Lp = make_ellipse_law(A, B, pl);
    CHECK(std::isinf(Le.h_y));
    CHECK(Le.k_p == 0);
    CHECK_FALSE(Le.is_plastic_law());
    for (double h : {1e-7, 1e-6, 1e-5, 1e-4, 1e-3}) {
      CAPTURE(h);
      double db = 0, de = 0;
      CHECK(rel(Lb.force(h, &db), Le.force(h, &de)) <= 1e-12);
      CHECK(rel(db, de) <= 1e-12);
      const EllipseState sb = ellipse_state(Lb, h), se = ellipse_state(Le, h);
      CHECK(rel(sb.a, se.a) <= 1e-12);
      CHECK(rel(sb.p0, se.p0) <= 1e-12);
      CHECK_FALSE(sb.plastic);
      CHECK(rel(Le.h0_for_force(Le.force(h)), h) <= 1e-12);
      CHECK(rel(Lp.h0_for_force(Lp.force(h)), h) <= 1e-12);
      CHECK(rel(Lp.force(Lp.h0_for_force(1e3 * h * 1e6)), 1e3 * h * 1e6) <= 1e-12);
    }
  }
}

TEST_CASE("plastic law: worked example of method.md §5", "[plastic]") {
  // Source: method.md §5 (E 210 GPa, ν 0.3, R_wyy 460 mm, R_rxx 300 mm, flat wheel profile,
  // N = 100 kN). Tolerances: the printed digits (± half a unit in the last one).
  Material mat;
  mat.E = 210e9;
  mat.nu = 0.3;
  const double A = 1 / (2 * 0.460), B = 0.5 * (1 / 0.300);
  for (bool exact : {false, true}) {
    CAPTURE(exact);
    const EllipseState e = ellipse_state_for_force(make_ellipse_law(A, B, mat, exact), 100e3);
    CHECK(e.a * 1e3 == Approx(7.162).margin(5e-4));
    CHECK(e.b * 1e3 == Approx(5.387).margin(5e-4));
    CHECK(e.p0 / 1e6 == Approx(1238).margin(0.5));
    Material pm = mat;
    pm.p_lim = 800e6;
    const EllipseLaw pl = make_ellipse_law(A, B, pm, exact);
    CHECK(pl.h_y * 1e3 == Approx(0.02021).margin(5e-6));
    CHECK(pl.N_y / 1e3 == Approx(27.0).margin(0.05));
    const EllipseState p = ellipse_state_for_force(pl, 100e3);
    CHECK(p.plastic);
    CHECK(p.a * 1e3 == Approx(7.748).margin(5e-4));
    CHECK(p.b * 1e3 == Approx(5.829).margin(5e-4));
    CHECK(p.area_ratio == Approx(1.171).margin(5e-4));
    CHECK(p.p_max == 800e6);
    CHECK(rel(p.a_el, e.a) <= 1e-12);
    CHECK(rel(p.b_el, e.b) <= 1e-12);
    // The area ratio t against an independent reference: by 2-D quadrature (the helper above,
    // not the closed form), the capped Hertz pressure of the enlarged patch — semi-axes a_el √t,
    // b_el √t and Hertz peak p0_el √t (same shape, p0 ∝ size) — carries the 100 kN. Tolerance
    // 1e-8 relative. a and b scale by √t (1e-12).
    const double st = std::sqrt(p.area_ratio);
    CHECK(rel(capped_load_quadrature(e.a * st, e.b * st, e.p0 * st, 800e6), 100e3) <= 1e-8);
    CHECK(rel(p.a, e.a * std::sqrt(p.area_ratio)) <= 1e-12);
  }
}

TEST_CASE("a capped flange ellipse stays inside its overlap, area and load kept", "[plastic]") {
  // The Manchester flange ellipse at t_Y = 7 mm (geometry.csv: A = 3.614e-4 1/mm, B = 0.03846
  // 1/mm, λ = 0.0094), E = 210 GPa, ν = 0.28, p_lim = 900 MPa, N = 292 kN. Before the hold the
  // patch was a = 44.2 mm, b = 2.34 mm (88 mm long) at Thornton's δ = 0.918 mm, while the
  // overlap at that δ is only √(δ/A) = 50 mm; the overlap-held approach is
  // δ = a b √(AB) + r (δ_H − a b √(AB)) and the patch a' = √(δ/A), b' = a b / a'.
  Material mat;
  mat.E = 210e9;
  mat.nu = 0.28;
  mat.p_lim = 900e6;
  const double A = 3.614e-4 * 1e3, B = 0.03846 * 1e3;
  const EllipseLaw L = make_ellipse_law(A, B, mat, true);
  const EllipseState s = ellipse_state_for_force(L, 292e3);
  REQUIRE(s.plastic);
  CHECK(s.a <= std::sqrt(s.approach / A) * (1 + 1e-12));
  CHECK(s.b <= std::sqrt(s.approach / B) * (1 + 1e-12));
  // Area (hence the capped load π a b p_lim (1 − s²/3)) is the law's: (m/n) h0 / B.
  CHECK(rel(kPi * s.a * s.b, kPi * (L.c.m / L.c.n) * s.h0 / B) <= 1e-12);
  // The approach between the rigid–plastic overlap of the area and the Hertz approach.
  const double d_ov = s.a * s.b * std::sqrt(A * B);
  const double C = std::sqrt(s.h0 / B) / L.c.n;
  const double d_H = L.c.rho * C * C * (A + B);
  CHECK(s.approach > d_ov);
  CHECK(s.approach < 0.6 * d_H);  // Thornton's δ of the grown patch was d_H
}

TEST_CASE("yield law: the stiffness law equals the load of its flattened pressure, C¹, inverse", "[plastic][yield]") {
  // method.md §5.1: above p_y = 1.6 σ_y the pressure is p = p_y + β (p_H − p_y), β = 0.3, on the
  // patch of h0 (p_H its Hertz pressure). Reference: 2-D quadrature of that pressure, written as
  // β p_H + (1 − β) min(p_H, p_y) (the same function pointwise): β times the Hertz load
  // (2/3) π a b p0 plus (1 − β) times the quadrature of the capped pressure. Tolerance 1e-8
  // relative (the quadrature's). Also p_max = p_y + β (p0 − p_y); C¹ at h_y (1e-10 between
  // h_y (1 ∓ 1e-13)); force(h0_for_force(N)) = N to 1e-12 from just above N_y to 10⁴ N_y.
  const Material mat = yield_law_steel();
  const double p_y = kFirstYieldPerYield * mat.yield, beta = kYieldLawSlope;
  for (double l : {1e-3, 0.1, 0.652, 1.0, 7.0, 300.0}) {
    const EllipseLaw L = make_ellipse_law(l * 2.0, 2.0, mat, true);
    CAPTURE(l);
    CHECK(rel(L.p_lim, p_y) <= 1e-15);
    CHECK(rel(ellipse_state(L, L.h_y).p0, p_y) <= 1e-12);
    double d1 = 0, d2 = 0;
    CHECK(rel(L.force(L.h_y * (1 - 1e-13), &d1), L.force(L.h_y * (1 + 1e-13), &d2)) <= 1e-10);
    CHECK(rel(d1, d2) <= 1e-10);
    for (double f : {0.5, 1.0, 1.01, 3.0, 50.0}) {
      CAPTURE(f);
      const EllipseState s = ellipse_state(L, f * L.h_y);
      const double a = std::sqrt(s.h0 / 2.0) * L.c.m / L.c.n, b = std::sqrt(s.h0 / 2.0);  // patch of h0
      const double ref = beta * (2.0 / 3.0) * kPi * a * b * s.p0 + (1 - beta) * capped_load_quadrature(a, b, s.p0, p_y);
      CHECK(rel(s.N, ref) <= 1e-8);
      CHECK(rel(s.p_max, s.p0 <= p_y ? s.p0 : p_y + beta * (s.p0 - p_y)) <= 1e-12);
      CHECK(s.plastic == (f > 1.0));
    }
    for (double q : {1.0 + 1e-9, 1.001, 1.5, 10.0, 1e2, 1e4}) {
      CAPTURE(q);
      const double N = q * L.N_y;
      CHECK(rel(L.force(L.h0_for_force(N)), N) <= 1e-12);
    }
  }
  // Without a finite p_lim the material is elastic, yield law or not (the grid methods' elastic
  // starts copy the material with p_lim = INFINITY).
  Material el = mat;
  el.p_lim = INFINITY;
  CHECK_FALSE(make_ellipse_law(1.0, 2.0, el).is_plastic_law());
}

TEST_CASE("yield law: the inverse h0_for_force against a long-double bisection of its cubic", "[plastic][yield]") {
  // Reference: the root u = √h0 of β k_e u³ + (1 − β) k_p (u² − h_y/3) = N (method.md §5.1; k_e,
  // k_p, h_y, β of the law), bisected in long double over [0, u_hi], u_hi the larger of the two
  // bounds each term gives alone (the other term is ≥ 0 above h_y), 200 halvings. Loads N from
  // just above N_y to 10⁶ N_y, denser around ν = N/N_y = 1.556, where the library's first guess
  // changes from a quadratic approximation to Cardano's root. Tolerance 1e-15 relative in h0
  // (a few ulps: the library polishes its guess to a Newton step of 4 ε in u).
  const Material mat = yield_law_steel();
  std::vector<double> nus = {1.0 + 1e-13, 1.0 + 1e-9, 1.0 + 1e-6};
  for (int i = 0; i <= 600; ++i) nus.push_back(std::pow(10.0, 6.0 * i / 600.0));
  for (int i = -20; i <= 20; ++i) nus.push_back(1.5556 * (1.0 + 1e-3 * i));
  for (double l : {1e-3, 0.1, 0.652, 1.0, 7.0, 300.0}) {
    const EllipseLaw L = make_ellipse_law(l * 2.0, 2.0, mat, true);
    const long double b = L.beta, ke = L.k_e, kp = L.k_p, hy = L.h_y;
    for (double nu : nus) {
      const double N = nu * L.N_y;
      if (!(N > L.N_y)) continue;
      const long double Nl = N;
      auto g = [&](long double u) { return b * ke * u * u * u + (1 - b) * kp * (u * u - hy / 3) - Nl; };
      long double lo = 0, hi = std::max(std::cbrt(Nl / (b * ke)), std::sqrt(Nl / ((1 - b) * kp) + hy / 3)) * 1.01L;
      for (int k = 0; k < 200; ++k) {
        const long double mid = 0.5L * (lo + hi);
        (g(mid) < 0 ? lo : hi) = mid;
      }
      const double h0_ref = static_cast<double>(lo * lo);
      CAPTURE(l, nu);
      CHECK(rel(L.h0_for_force(N), h0_ref) <= 1e-15);
    }
  }
}
