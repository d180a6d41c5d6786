#pragma once
// One Hertzian ellipse (paper eqs. 1–4, 6–8; method.md §2) and the per-ellipse force law of the
// multi-Hertzian solver, elastic (eq. 8) and plastic (method.md §5). SI throughout.
#include <cmath>

namespace mh {

struct Material {
  double E = 210e9;          ///< [Pa] Young's modulus (both bodies)
  double nu = 0.28;          ///< [-] Poisson's ratio (both bodies)
  double p_lim = INFINITY;   ///< [Pa] limit pressure of the plastic model; INFINITY = elastic
  double E_star() const { return E / (1 - nu * nu); }  ///< E/(1−ν²)
};

/// Hertz coefficients of λ = A/B (method.md §2): a = m C, b = n C, approach δ = ρ C²(A+B).
struct HertzCoefficients {
  double lambda = 1, m = 1, n = 1, rho = 1;
};

/// Exact, from complete elliptic integrals (GSL, modulus convention). For A ≤ B (λ ≤ 1) with
/// g = n/m ≤ 1 the minor/major axis ratio, e² = 1 − g²: B/A = (E/g² − K)/(K − E), m = (2E/(πg²))^(1/3),
/// n = m g, ρ = 2K/(πm). For λ > 1 the roles swap: m(λ) = n(1/λ), n(λ) = m(1/λ), ρ(λ) = ρ(1/λ)
/// (the approach does not depend on which axis is called x). Exact 1, 1, 1 at λ = 1.
/// Throws std::invalid_argument for λ ≤ 0 or not finite.
HertzCoefficients hertz_coefficients_exact(double lambda);

/// Fast path: cubic interpolation of ln m, ln n, ln ρ tabulated against ln λ (step 0.005) over
/// λ ∈ [1e-5, 1e5]; the exact path outside. Worst relative error against the exact path over
/// 1e-4 … 1e4, measured by test_hertz.cpp: below 1e-8.
HertzCoefficients hertz_coefficients(double lambda);

/// Everything about one ellipse that does not depend on the load.
struct EllipseLaw {
  double A = 0, B = 0;        ///< [1/m] curvature sums (eq. 1)
  HertzCoefficients c;        ///< of λ = A/B
  double E_star = 0;          ///< [Pa]
  double k_e = 0;             ///< [N/m^1.5] elastic stiffness (eq. 8)
  double p_lim = INFINITY;    ///< [Pa]
  double h_y = INFINITY;      ///< [m] virtual penetration where p0 reaches p_lim (method.md §5)
  double k_p = 0;             ///< [N/m] plastic stiffness (method.md §5)
  double N_y = INFINITY;      ///< [N] load at h_y, (2/3) k_p h_y

  /// N(h0) [N] and dN/dh0 at virtual penetration h0 [m]; 0 for h0 ≤ 0.
  /// Elastic N = k_e h0^(3/2) (eq. 8) below h_y, N = k_p (h0 − h_y/3) above (method.md §5).
  double force(double h0, double* dN_dh0 = nullptr) const {
    if (!(h0 > 0)) { if (dN_dh0) *dN_dh0 = 0; return 0; }
    if (h0 <= h_y) {
      const double r = std::sqrt(h0);
      if (dN_dh0) *dN_dh0 = 1.5 * k_e * r;
      return k_e * h0 * r;
    }
    if (dN_dh0) *dN_dh0 = k_p;
    return k_p * (h0 - h_y / 3.0);
  }
  /// Inverse of force(): the h0 that carries N, closed form in both regimes.
  double h0_for_force(double N) const {
    if (!(N > 0)) return 0;
    if (N <= N_y) return std::cbrt((N / k_e) * (N / k_e));
    return N / k_p + h_y / 3.0;
  }
};

/// Build the law of an ellipse with curvature sums A, B [1/m]. `exact` uses the GSL path for
/// the coefficients instead of the fast path. Throws std::invalid_argument (with the rule) for
/// B ≤ 0 (not a Hertzian contact), A < 0, E ≤ 0, ν outside (0, 0.5), p_lim ≤ 0.
EllipseLaw make_ellipse_law(double A, double B, const Material& mat, bool exact = false);

/// One loaded ellipse at virtual penetration h0 (all SI).
struct EllipseState {
  double h0 = 0;        ///< [m] virtual penetration (eq. 6), not the true approach
  double N = 0;         ///< [N] normal force
  double a = 0, b = 0;  ///< [m] semi-axes along x (rolling) and y (lateral); the plastic patch in plastic mode
  double p0 = 0;        ///< [Pa] Hertz peak pressure of this patch (uncapped)
  double p_mean = 0;    ///< [Pa] N / (π a b)
  double approach = 0;  ///< [m] true Hertz approach δ = ρ C² (A+B) of the patch, C = b/n
  bool plastic = false; ///< p0 > p_lim
  double p_max = 0;     ///< [Pa] min(p0, p_lim)
  double plateau_a = 0, plateau_b = 0;  ///< [m] semi-axes of the region where p = p_lim
  double a_el = 0, b_el = 0;            ///< [m] elastic semi-axes at the same load N
  double area_ratio = 1;                ///< a b / (a_el b_el)
};
EllipseState ellipse_state(const EllipseLaw& law, double h0);

/// Elastic Hertz semi-axes for a load N (eqs. 2–3): C = [(3/2) N (1−ν²)/E / (A+B)]^(1/3).
double hertz_C(double N, double A, double B, double E_star);

}  // namespace mh
