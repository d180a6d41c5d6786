#pragma once
// The force law of one Hertzian ellipse of the multi-Hertzian solver (eqs. 6–8, method.md §2) and
// its plastic variant (method.md §5), plus the outputs of one loaded ellipse. SI throughout.
//
// Convention: h0 is the virtual interpenetration of eq. 6 (h0 = b² B), NOT the true Hertz approach
// δ = ρ C² (A+B) (for a circular contact h0 = δ/2). Both are reported, under different names.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "contact/ellipse/hertz.hpp"
#include "contact/ellipse/plastic.hpp"

namespace mh {

/// Everything about one ellipse that does not depend on the load.
struct EllipseLaw {
  double A = 0, B = 0;        ///< [1/m] curvature sums along x and y (eq. 1)
  HertzCoefficients c;        ///< m, n, ρ of λ = A/B
  double E_star = 0;          ///< [Pa] E/(1−ν²)
  double k_e = 0;             ///< [N/m^1.5] elastic stiffness (eq. 8)
  /// [Pa] the pressure where the law leaves Hertz: p_lim (capped law) or p_y = 1.6 σ_y (yield law,
  /// method.md §5.1); INFINITY = elastic
  double p_lim = INFINITY;
  /// [-] slope β of the pressure above p_lim: 0 = capped (method.md §5), kYieldLawSlope = yield law
  /// p = p_lim + β (p_H − p_lim) (method.md §5.1)
  double beta = 0;
  double h_y = INFINITY;      ///< [m] h0 at which the Hertz peak reaches p_lim (method.md §5)
  double k_p = 0;             ///< [N/m] slope dN/dh0 of the capped load above h_y (method.md §5)
  double N_y = INFINITY;      ///< [N] load at h_y, (2/3) k_p h_y

  /// N(h0) [N] and, if dN_dh0 is given, dN/dh0 [N/m] at virtual penetration h0 [m]; both 0 for
  /// h0 ≤ 0 (and NaN h0). N = k_e h0^(3/2) (eq. 8) up to h_y, above it the capped load
  /// N_c = k_p (h0 − h_y/3) (method.md §5) or, for the yield law, β k_e h0^(3/2) + (1 − β) N_c
  /// (method.md §5.1). C¹ at h_y. Inline, allocation-free: the solver's inner loop.
  double force(double h0, double* dN_dh0 = nullptr) const {
    if (!(h0 > 0)) {
      if (dN_dh0) *dN_dh0 = 0;
      return 0;
    }
    if (h0 <= h_y) {
      const double r = std::sqrt(h0);
      if (dN_dh0) *dN_dh0 = 1.5 * k_e * r;
      return k_e * h0 * r;
    }
    if (beta == 0) {
      if (dN_dh0) *dN_dh0 = k_p;
      return k_p * (h0 - h_y / 3.0);
    }
    const double r = std::sqrt(h0);
    if (dN_dh0) *dN_dh0 = 1.5 * beta * k_e * r + (1.0 - beta) * k_p;
    return beta * k_e * h0 * r + (1.0 - beta) * k_p * (h0 - h_y / 3.0);
  }

  /// The h0 [m] that carries the load N [N] (inverse of force()): (N/k_e)^(2/3) up to N_y,
  /// N/k_p + h_y/3 above for the capped law, for the yield law an explicit root polished by
  /// Newton (h0_for_force_yield_law). 0 for N = 0. Throws std::invalid_argument for N < 0 or NaN.
  double h0_for_force(double N) const {
    if (!(N >= 0)) throw std::invalid_argument("h0_for_force: the normal load N must be >= 0 N");
    if (N == 0) return 0;
    if (N <= N_y) {
      const double q = N / k_e;
      return std::cbrt(q * q);
    }
    if (beta == 0) return N / k_p + h_y / 3.0;
    return h0_for_force_yield_law(N);
  }
  /// h0 above h_y for the yield law: the root u = √h0 of β k_e u³ + (1 − β) k_p (u² − h_y/3) = N,
  /// increasing and convex in u. Cardano's root of the cubic (or, just above h_y, a quadratic
  /// approximation of it), then Newton steps (core/roots.hpp newton_polish) to machine precision.
  double h0_for_force_yield_law(double N) const;

  bool is_plastic_law() const { return std::isfinite(p_lim); }
};

/// The part of every ellipse's law that depends only on the material, for a solver that builds
/// many laws of one material (the multi-Hertzian solver: one per potential ellipse and t_Y).
struct LawMaterial {
  double E_star = 0;          ///< [Pa] Material::E_star()
  double p_lim = INFINITY;    ///< [Pa] EllipseLaw::p_lim: p_lim (capped law), p_y = 1.6 σ_y (yield law) or INFINITY
  double beta = 0;            ///< [-] EllipseLaw::beta: 0 (capped or elastic) or kYieldLawSlope (yield law)
};
/// `mat` checked (Material::valid; throws std::invalid_argument with its message) and reduced to
/// what an ellipse law needs (method.md §5, §5.1).
LawMaterial law_material(const Material& mat);

/// Build the law of an ellipse with curvature sums A, B [1/m] (eq. 1) for `mat`: λ = A/B, m, n, ρ
/// (fast path, or the exact path when `exact`), k_e (eq. 8), and with a finite mat.p_lim the
/// plastic branch (method.md §5). Throws std::invalid_argument with the rule for a
/// non-Hertzian or invalid input: B ≤ 0 (conformal or diverging profiles across the contact),
/// A ≤ 0 (A < 0 is a concave rolling direction, A = 0 a line contact), A/B outside
/// [kLambdaMinExact, kLambdaMaxExact], non-finite A or B, and an invalid material
/// (Material::is_valid).
EllipseLaw make_ellipse_law(double A, double B, const Material& mat, bool exact = false);
/// The same from the material's part, law_material(mat), computed once for many ellipses.
EllipseLaw make_ellipse_law(double A, double B, const LawMaterial& mat, bool exact = false);

/// One loaded ellipse at virtual penetration h0 (all SI). For h0 ≤ 0 everything is 0 (area_ratio 1).
struct EllipseState {
  double h0 = 0;          ///< [m] virtual penetration (eq. 6), not the true approach
  double N = 0;           ///< [N] normal force, force(h0)
  double a = 0, b = 0;    ///< [m] semi-axes along x (rolling) and y (lateral): b = √(h0/B),
                          ///<     a = (m/n) b; in the plastic regime this is the plastic patch
  double p0 = 0;          ///< [Pa] Hertz peak pressure of this patch, 3 k_e h0^(3/2) / (2π a b)
                          ///<     (uncapped: above p_lim in the plastic regime)
  double p_mean = 0;      ///< [Pa] N / (π a b)
  double approach = 0;    ///< [m] true Hertz approach δ = ρ C² (A+B) with C = b/n (= 2 h0 for a
                          ///<     sphere); in the plastic regime that of the patch (Thornton's δ)
  bool plastic = false;   ///< h0 > h_y (p0 > p_lim)
  double p_max = 0;       ///< [Pa] the largest pressure carried: min(p0, p_lim) (capped law),
                          ///<     p_y + β (p0 − p_y) above p_y (yield law)
  double plateau_a = 0, plateau_b = 0;  ///< [m] semi-axes a√(1−s²), b√(1−s²) where the Hertz pressure of
                                        ///<     the patch exceeds p_lim (capped: p = p_lim there); 0 if elastic
  double dN_dh0 = 0;      ///< [N/m] slope of the force law at h0 (the normal stiffness in h0)
  double p_knee = INFINITY;  ///< [Pa] the law's p_lim (p_y for the yield law), for pressure_at
  double beta = 0;           ///< [-] the law's slope above p_knee, for pressure_at
  /// [Pa] the pressure the law carries where the Hertz pressure of the patch is p_H [Pa].
  double pressure_at(double p_H) const {
    if (beta == 0) return std::min(p_H, p_knee);
    return p_H <= p_knee ? p_H : p_knee + beta * (p_H - p_knee);
  }
  double a_el = 0, b_el = 0;            ///< [m] elastic Hertz semi-axes at the same load N
  double area_ratio = 1;                ///< [-] a b / (a_el b_el); 1 if elastic
  double p0_el = 0;                     ///< [Pa] elastic Hertz peak at the same load N, 3N/(2π a_el b_el)
                                        ///<     (= p0 if elastic; below p0 in the plastic regime)
};

/// The state of the ellipse of `law` at virtual penetration h0 [m]. Throws std::invalid_argument
/// for NaN or infinite h0.
EllipseState ellipse_state(const EllipseLaw& law, double h0);

/// The state at load N [N] (ellipse_state(law, law.h0_for_force(N))).
EllipseState ellipse_state_for_force(const EllipseLaw& law, double N);

}  // namespace mh
