#pragma once
// The plastic law of one ellipse (method.md §5, [design]): the patch keeps the elastic geometry
// of its virtual penetration h0, the Hertz pressure on it is capped at p_lim.
//   p(x, y) = min(p0 √(1 − x²/a² − y²/b²), p_lim)
//   N = π a b p_lim (1 − s²/3),  s = p_lim / p0 < 1      (elastic, N = (2/3) π a b p0, for s ≥ 1)
// With b = √(h0/B), a = (m/n) b and p0 ∝ √h0 this gives the closed-form stiffness law
//   N = k_e h0^(3/2) for h0 ≤ h_y,   N = k_p (h0 − h_y/3) = N_y + k_p (h0 − h_y) for h0 > h_y,
//   h_y = (2π m p_lim / (3 k_e n B))²,  k_p = π p_lim m / (n B),  N_y = (2/3) k_p h_y,
// C¹ at h_y. For a sphere (m = n = 1) it is Thornton's (1997) truncated-Hertz law.
// SI throughout.
#include <cmath>
#include "core/units.hpp"

namespace mh {

/// [N] Load carried by the capped Hertz pressure on the ellipse of semi-axes a, b [m] with Hertz
/// peak p0 [Pa] and cap p_lim [Pa] (method.md §5): π a b p_lim (1 − s²/3), s = p_lim/p0, when
/// p0 > p_lim; the Hertz load (2/3) π a b p0 otherwise (p_lim = INFINITY: always elastic).
inline double capped_hertz_load(double a, double b, double p0, double p_lim) {
  constexpr double pi = units::pi;
  if (!(p0 > p_lim)) return (2.0 / 3.0) * pi * a * b * p0;
  const double s = p_lim / p0;
  return pi * a * b * p_lim * (1.0 - s * s / 3.0);
}

/// [-] Fraction √(1 − s²) of the semi-axes on which p = p_lim (the plateau), s = p_lim/p0;
/// 0 when p0 ≤ p_lim (method.md §5).
inline double plateau_fraction(double p0, double p_lim) {
  if (!(p0 > p_lim)) return 0.0;
  const double s = p_lim / p0;
  return std::sqrt(1.0 - s * s);
}

/// [-] Area ratio plastic/elastic patch at the same load, t = (2 + σ³)/(3σ), σ = p_lim / p0_el
/// with p0_el the elastic Hertz peak at that load; 1 for σ ≥ 1 (method.md §5).
inline double plastic_area_ratio(double sigma) {
  if (!(sigma < 1.0)) return 1.0;
  return (2.0 + sigma * sigma * sigma) / (3.0 * sigma);
}

/// Parameters of the plastic branch of the stiffness law of one ellipse (method.md §5).
struct PlasticBranch {
  double h_y = INFINITY;  ///< [m] virtual penetration at which the Hertz peak p0 reaches p_lim
  double k_p = 0;         ///< [N/m] slope dN/dh0 above h_y
  double N_y = INFINITY;  ///< [N] load at h_y, (2/3) k_p h_y = k_e h_y^(3/2)
};

/// h_y, k_p, N_y from the Hertz coefficients m, n, the curvature sum B [1/m], the elastic
/// stiffness k_e [N/m^1.5] (eq. 8) and p_lim [Pa]. p_lim = INFINITY gives the elastic defaults
/// (h_y = N_y = INFINITY, k_p = 0).
inline PlasticBranch plastic_branch(double m, double n, double B, double k_e, double p_lim) {
  constexpr double pi = units::pi;
  PlasticBranch p;
  if (!std::isfinite(p_lim)) return p;
  // p0 = 3 N/(2π a b) = 3 k_e n B √h0 / (2π m) on the patch b = √(h0/B), a = (m/n) b.
  const double r = 2.0 * pi * m * p_lim / (3.0 * k_e * n * B);
  p.h_y = r * r;
  p.k_p = pi * p_lim * m / (n * B);
  p.N_y = (2.0 / 3.0) * p.k_p * p.h_y;
  return p;
}

/// The approach and semi-axes of a capped ellipse, held within its overlap (method.md §5).
struct PlasticPatch {
  double approach = 0;  ///< [m] true approach δ
  double a = 0, b = 0;  ///< [m] semi-axes (a b kept: the area and the load of the law)
};

/// The approach of the capped patch of semi-axes a, b [m] (curvature sums A, B [1/m]) whose Hertz
/// approach (Thornton's δ of the grown patch) is delta_H [m] and which carries the fraction
/// r = N/N_H ≤ 1 of the Hertz load of its patch (r = 1.5 s (1 − s²/3), s = p_lim/p0):
///   δ = δ_ov + r (δ_H − δ_ov),   δ_ov = a b √(A B)
/// δ_ov is the rigid approach at which the surfaces overlap over an ellipse of the patch's area
/// (the rigid–perfectly-plastic limit, r → 0); δ_H − δ_ov is the elastic displacement at the edge
/// of the Hertz patch, scaled by the load the capped pressure actually carries (r = 1: Hertz,
/// continuous at yield). The patch is then held inside the overlap ellipse √(δ/A), √(δ/B): an
/// axis beyond it is shortened to it and the other lengthened to keep a b (always possible:
/// δ ≥ δ_ov). As a capped strip never reaches beyond its overlap (docs/strips.md).
inline PlasticPatch plastic_patch_in_overlap(double a, double b, double A, double B, double delta_H, double r) {
  PlasticPatch p;
  const double ab = a * b;
  const double d_ov = ab * std::sqrt(A * B);
  p.approach = d_ov + r * (delta_H - d_ov);
  const double a_ov = std::sqrt(p.approach / A), b_ov = std::sqrt(p.approach / B);
  p.a = a;
  p.b = b;
  if (p.a > a_ov) { p.a = a_ov; p.b = ab / a_ov; }
  if (p.b > b_ov) { p.b = b_ov; p.a = ab / b_ov; }
  return p;
}

}  // namespace mh
