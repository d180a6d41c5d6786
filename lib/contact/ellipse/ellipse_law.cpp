// The force law of one ellipse, elastic (eq. 8) and plastic (method.md §5), and its outputs.
#include "contact/ellipse/ellipse_law.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/numfmt.hpp"
#include "core/roots.hpp"
#include "core/units.hpp"

namespace mh {

namespace {
void check_curvature_sums(double A, double B) {
  if (!(B > 0) || !std::isfinite(B))
    throw std::invalid_argument("B = " + format_number(B) +
                                " 1/m: the lateral curvature sum B = (1/R_wxx + 1/R_rxx)/2 must be > 0 and finite "
                                "for a Hertzian ellipse (B <= 0: conformal or diverging profiles across the contact)");
  if (!(A > 0) || !std::isfinite(A))
    throw std::invalid_argument("A = " + format_number(A) +
                                " 1/m: the rolling-direction curvature sum A = 1/(2 R_wyy) must be > 0 and finite "
                                "(A = 0 is a line contact, A < 0 a concave wheel in the rolling direction)");
}
}  // namespace

LawMaterial law_material(const Material& mat) {
  std::string why;
  if (!mat.valid(&why)) throw std::invalid_argument(why);
  LawMaterial lm;
  lm.E_star = mat.E_star();
  // The yield law (method.md §5.1) leaves Hertz at first yield p_y = 1.6 σ_y with slope β; the
  // capped law (method.md §5) at p_lim. An elastic material (p_lim = INFINITY) stays elastic.
  const bool yield_law = mat.yield_law && std::isfinite(mat.p_lim);
  lm.p_lim = yield_law ? kFirstYieldPerYield * mat.yield_min() : mat.p_lim;
  lm.beta = yield_law ? kYieldLawSlope : 0.0;
  return lm;
}

EllipseLaw make_ellipse_law(double A, double B, const Material& mat, bool exact) {
  check_curvature_sums(A, B);  // before the material, as its errors always were
  return make_ellipse_law(A, B, law_material(mat), exact);
}

EllipseLaw make_ellipse_law(double A, double B, const LawMaterial& mat, bool exact) {
  check_curvature_sums(A, B);
  const double lambda = A / B;
  EllipseLaw L;
  L.A = A;
  L.B = B;
  L.c = exact ? hertz_coefficients_exact(lambda) : hertz_coefficients(lambda);
  L.E_star = mat.E_star;
  const double n3 = L.c.n * L.c.n * L.c.n;
  L.k_e = (2.0 / 3.0) * (1.0 + lambda) / n3 * L.E_star / std::sqrt(B);  // (eq. 8)
  L.p_lim = mat.p_lim;
  L.beta = mat.beta;
  const PlasticBranch p = plastic_branch(L.c.m, L.c.n, B, L.k_e, L.p_lim);  // method.md §5
  L.h_y = p.h_y;
  L.k_p = p.k_p;
  L.N_y = p.N_y;
  return L;
}

EllipseState ellipse_state(const EllipseLaw& L, double h0) {
  using units::pi;
  if (std::isnan(h0) || std::isinf(h0))
    throw std::invalid_argument("ellipse_state: h0 = " + format_number(h0) + " m must be finite");
  EllipseState s;
  if (!(h0 > 0)) return s;
  s.h0 = h0;
  double dN = 0;  // the law's slope, kept for the yield law's plastic branch
  s.N = L.force(h0, &dN);
  // The patch is the intersection ellipse A x² + B y² = h0 of the interpenetrated surfaces,
  // scaled to the Hertz shape: b = √(h0/B) (eq. 6), a = (m/n) b (eq. 4). Elastic: exactly Hertz.
  s.b = std::sqrt(h0 / L.B);
  s.a = (L.c.m / L.c.n) * s.b;
  const double area = pi * s.a * s.b;
  const double N_hertz = L.k_e * h0 * std::sqrt(h0);  // Hertz load of this patch (eq. 8)
  s.p0 = 1.5 * N_hertz / area;                        // p0 = 3N/(2πab)
  s.p_mean = s.N / area;
  const double C = s.b / L.c.n;                       // b = n C (eq. 3)
  s.approach = L.c.rho * C * C * (L.A + L.B);         // δ = ρ C² (A+B) (method.md §2)
  s.plastic = h0 > L.h_y;
  s.p_knee = L.p_lim;
  s.beta = L.beta;
  s.p_max = s.pressure_at(s.p0);
  if (s.plastic) {
    const double q = plateau_fraction(s.p0, L.p_lim);  // √(1 − s²) (method.md §5)
    s.plateau_a = s.a * q;
    s.plateau_b = s.b * q;
    // Elastic Hertz ellipse at the same load: h0_el = (N/k_e)^(2/3) (eq. 8), then eq. 6.
    const double q_el = s.N / L.k_e;
    const double h0_el = std::cbrt(q_el * q_el);
    s.b_el = std::sqrt(h0_el / L.B);
    s.a_el = (L.c.m / L.c.n) * s.b_el;
    s.area_ratio = (s.a * s.b) / (s.a_el * s.b_el);
    // Approach and shape held by the overlap (method.md §5, "approach and overlap").
    s.dN_dh0 = L.beta == 0 ? s.N / (h0 - L.h_y / 3.0) : dN;  // capped: N = k_p (h0 − h_y/3)
    const PlasticPatch h = plastic_patch_in_overlap(s.a, s.b, L.A, L.B, s.approach, s.N / N_hertz);
    s.approach = h.approach;
    s.plateau_a *= h.a / s.a;
    s.plateau_b *= h.b / s.b;
    s.a = h.a;
    s.b = h.b;
  } else {
    s.a_el = s.a;
    s.b_el = s.b;
    s.area_ratio = 1.0;
    s.dN_dh0 = 1.5 * s.N / h0;  // eq. 8: N = k_e h0^(3/2)
  }
  s.p0_el = 1.5 * s.N / (pi * s.a_el * s.b_el);
  return s;
}

double EllipseLaw::h0_for_force_yield_law(double N) const {
  // g(u) = β k_e u³ + (1 − β) k_p (u² − h_y/3) − N, u = √h0 ≥ u_y = √h_y (method.md §5.1),
  // increasing and convex in u. In v = u/u_y and ν = N/N_y (N_y = k_e u_y³ = (2/3) k_p h_y) it is
  // the same cubic for every ellipse:  β v³ + (3/2)(1 − β) v² − (1 − β)/2 = ν,  v ≥ 1, ν ≥ 1.
  // With t = v + s, s = (1 − β)/(2β), it loses its square term, t³ − 3 s² t = ν/β + s − 2 s³,
  // and with t = 2 s τ it is Chebyshev's T₃(τ) = 4τ³ − 3τ = x,  x = (ν/β + s − 2 s³)/(2 s³).
  const double u_y = std::sqrt(h_y);
  const double nu = N / N_y;
  const double s = (1.0 - beta) / (2.0 * beta);
  const double s3 = s * s * s;
  const double x = (nu / beta + s - 2.0 * s3) / (2.0 * s3);
  double tau;
  if (x >= 1) {
    // Cardano: τ = (w + 1/w)/2, w = ∛(x + √(x² − 1)); accurate to a few ulps (near x = 1 the
    // error of √(x² − 1) cancels to first order in w + 1/w). This is v ≥ s.
    const double w = std::cbrt(x + std::sqrt((x - 1.0) * (x + 1.0)));
    tau = 0.5 * (w + 1.0 / w);
  } else {
    // 1 ≤ v < s (x from T₃((1 + s)/(2s)) to 1; β = 0.3: x ≥ 0.417, τ ≥ 0.929): T₃(1 + e) =
    // 1 + 9e + 12e² + 4e³, its quadratic part solved for e: v within 5e-4 (relative) of the root.
    const double d = x - 1.0;
    tau = 1.0 + 2.0 * d / (9.0 + std::sqrt(81.0 + 48.0 * d));
  }
  const double v = s * (2.0 * tau - 1.0);
  // Newton on g itself from that guess (core/roots.hpp): one step from Cardano's root, three or
  // four from the quadratic, to a step of 4 ε. Clamped at u_y (the branch starts there).
  auto g = [&](double u) {
    const double u2 = u * u;
    return std::pair<double, double>(beta * k_e * u2 * u + (1.0 - beta) * k_p * (u2 - h_y / 3.0) - N,
                                     3.0 * beta * k_e * u2 + 2.0 * (1.0 - beta) * k_p * u);
  };
  RootTolerance tol;
  tol.max_iterations = 8;
  const RootResult r = newton_polish(g, v * u_y, u_y, INFINITY, tol);
  return r.x * r.x;
}

EllipseState ellipse_state_for_force(const EllipseLaw& law, double N) {
  return ellipse_state(law, law.h0_for_force(N));
}

}  // namespace mh
