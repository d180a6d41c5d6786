#pragma once
// Stresses below a Hertzian ellipse with full-slip traction (docs/methods.md "Subsurface
// stresses"): the pressure p = p0 √(1 − x²/a² − y²/b²) and the traction (q_x, q_y) = (f_x, f_y) p
// on the surface z = 0 of an elastic half-space (z the depth), integrated over the ellipse against
// the point-force solutions of Boussinesq (normal force) and Cerruti (tangential force) (Johnson,
// Contact Mechanics, 1985, §3.2, eqs. 3.20 and 3.22–3.23). The quadrature is polar about the
// field point's projection, so the kernel's 1/r² is cancelled by the Jacobian r dr; the radial
// maps take the near field (r ≲ z) and the square-root edge of the pressure exactly.
//
// Elastic only: a plastic patch's stresses are not these (its pressure is not Hertzian and the
// material has yielded). The callers compute them for the ELASTIC Hertz ellipse of the contact's
// load (the RCF indicators' ellipse, shakedown.hpp) and say so (docs/outputs.md).
//
// Sign convention: tension positive; z into the body; the surface loads act ON the body (σ_zz =
// −p, σ_xz = −q_x at the surface). SI throughout.
#include <cmath>
#include <functional>
#include <utility>
#include <vector>

namespace mh {

/// A stress tensor [Pa] in the contact frame (x rolling, y lateral, z depth).
struct Stress {
  double xx = 0, yy = 0, zz = 0, xy = 0, xz = 0, yz = 0;
};

/// The point-force solutions [Pa per N] at (x, y, z) relative to the force's point on the surface,
/// z > 0: Boussinesq's for a unit normal force pressing on the body (Johnson 1985 eq. 3.20),
/// Cerruti's for a unit tangential force along +x and along +y acting on the body (eqs. 3.22–3.23).
Stress boussinesq(double x, double y, double z, double nu);
Stress cerruti_x(double x, double y, double z, double nu);
Stress cerruti_y(double x, double y, double z, double nu);

/// [Pa] von Mises equivalent stress √(3 J2).
double von_mises(const Stress& s);

/// [Pa] the largest principal shear stress (σ1 − σ3)/2 (Tresca).
double max_shear(const Stress& s);

/// The stresses below a line contact (plane strain) with full-slip traction, in closed form
/// (McEwen, Phil. Mag. 40 (1949) 454–459; Johnson 1985 §7.1–7.2), in units of p0 at (x, z) in units
/// of the half-width a: pressure p0 √(1 − x²/a²) and traction q = f p along +x on the body,
/// σ_yy = ν(σ_xx + σ_zz), with m² = ½[√((a² − x² + z²)² + 4x²z²) + (a² − x² + z²)],
/// n² = ½[√(…) − (a² − x² + z²)], m ≥ 0 and n of the sign of x. The signs satisfy equilibrium,
/// compatibility and the surface conditions of this file's convention; test_subsurface.cpp holds
/// them against the quadrature below and the classic values (max (σ1 − σ3)/2 = 0.300 p0 at
/// 0.786 a; max |σ_xz| = 0.250 p0 at x = ±0.87 a, z = 0.50 a). The shakedown map's line-contact
/// limits with traction are derived on it (shakedown.hpp).
inline Stress mcewen_stress(double x, double z, double f, double nu) {
  const double A = 1 - x * x + z * z, S = std::sqrt(A * A + 4 * x * x * z * z);
  const double m = std::sqrt(0.5 * (S + A)), n = std::copysign(std::sqrt(std::fmax(0.0, 0.5 * (S - A))), x);
  const double D = m * m + n * n;
  Stress s;
  s.xx = -(m * (1 + (z * z + n * n) / D) - 2 * z) + f * (n * (2 - (z * z - m * m) / D) - 2 * x);
  s.zz = -m * (1 - (z * z + n * n) / D) - f * n * (m * m - z * z) / D;
  s.xz = -n * (m * m - z * z) / D - f * (m * (1 + (z * z + n * n) / D) - 2 * z);
  s.yy = nu * (s.xx + s.zz);
  return s;
}

/// The Hertzian load: semi-axes a (along x, rolling) and b (along y) [m], peak pressure p0 [Pa],
/// full-slip traction coefficients f_x, f_y (q = f p, acting on the body), Poisson's ratio ν.
struct HertzLoad {
  double a = 0, b = 0, p0 = 0;
  double fx = 0, fy = 0;
  double nu = 0.3;
};

/// Quadrature and search settings (defaults: the stresses to about 1e-3 p0 against the closed
/// forms of tests/unit/contact/test_subsurface.cpp).
struct SubsurfaceOptions {
  int n_theta = 8;       ///< angular Gauss–Legendre points per panel (8 panels of 45°)
  int n_near = 16;       ///< radial points on the near panel r < 8z (asinh map)
  int n_far = 24;        ///< radial points on the far panel up to the edge (square-root map)
  int nx = 25;           ///< search grid along x over the ellipse (the rolling pass)
  int ny = 5;            ///< search grid along y (one row, y = 0, when f_y = 0: the symmetry plane)
  int nz = 24;           ///< search grid in depth, z from z_min to z_max (× min(a, b))
  double z_min = 0.02;   ///< [-] shallowest depth searched, × min(a, b) (the surface itself is not)
  double z_max = 1.5;    ///< [-] deepest, × min(a, b)
  double y_tol = 0.01;   ///< [-] the lateral refinement's tolerance, × min(a, b)
};

/// [Pa] The stress at (x, y, z), z > 0, inside the ellipse's projection or outside it.
Stress hertz_stress(const HertzLoad& L, double x, double y, double z, const SubsurfaceOptions& o = {});

/// The peaks of the field below one contact (searched on the grid of SubsurfaceOptions, then
/// refined by a local search): positions [m] in the contact frame, depth z.
struct SubsurfacePeaks {
  double vm_max = NAN;                   ///< [Pa] largest von Mises stress
  double vm_x = NAN, vm_y = NAN, vm_z = NAN;
  double tau_max = NAN;                  ///< [Pa] largest principal shear stress (σ1 − σ3)/2
  double tau_z = NAN;                    ///< [m] its depth
  /// [Pa] Orthogonal shear amplitude: over a pass of the load along x at fixed (y, z), half the
  /// range of σ_xz (the unloaded state, 0, included), maximised over (y, z).
  double tau_orth_amp = NAN;
  double tau_orth_z = NAN;               ///< [m] its depth
  /// [Pa] Equivalent shear stress amplitude of the pass, √(J2) of the amplitude tensor (each
  /// component's half range over the pass, 0 included), maximised over (y, z), and the
  /// hydrostatic stress σ_h = tr σ/3 [Pa] at the same (y, z) at the instant of the largest
  /// von Mises stress of the pass (docs/methods.md "FI_sub").
  double tau_eq_amp = NAN, sigma_h = NAN;
  double tau_eq_z = NAN;                 ///< [m] its depth
  bool surface = false;                  ///< the von Mises peak lies on the shallowest depth searched
};
SubsurfacePeaks subsurface_peaks(const HertzLoad& L, const SubsurfaceOptions& o = {});

/// A stress field below a surface load, for the peak search: the stress at (x, y, z); the loaded
/// chord [x_lo, x_hi] at y (the pass of the load along x runs over 0.98 of it); the rows of the
/// coarse scan, ny values of y evenly over [y_lo, y_hi] (one row at their mean when ny = 1); the
/// bounds of the lateral refinement [y_min, y_max] (NaN: y_lo, y_hi); the length that scales the
/// depths searched (SubsurfaceOptions::z_min, z_max).
struct StressField {
  std::function<Stress(double x, double y, double z)> stress;
  std::function<std::pair<double, double>(double y)> chord;
  double depth_scale = 0;
  int ny = 1;
  double y_lo = 0, y_hi = 0;
  double y_min = NAN, y_max = NAN;
};
/// The peaks of a field (as subsurface_peaks, which is this search on the Hertz field): a coarse
/// scan of passes over the rows × the depths of SubsurfaceOptions, then each quantity refined from
/// its best point of each of its two best lateral maxima, in depth, across (between the
/// neighbouring rows) and in depth again; the von Mises and principal shear peaks along x too.
SubsurfacePeaks field_peaks(const StressField& F, const SubsurfaceOptions& o = {});

/// [Pa] Subsurface fatigue index in the Dang Van form of Ekberg, Kabo & Andersson (2002):
/// FI_sub = τ_eq,a + c σ_h, subsurface initiation predicted where it exceeds the material's shear
/// fatigue limit τ_e (docs/methods.md "FI_sub"); c [-] is the material's Dang Van parameter.
inline double fi_sub(const SubsurfacePeaks& s, double c) { return s.tau_eq_amp + c * s.sigma_h; }

}  // namespace mh
