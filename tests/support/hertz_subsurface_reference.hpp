#pragma once
// Closed-form stresses below Hertzian contacts, written once for the tests and independent of the
// library's quadrature (lib/contact/rcf/subsurface.*). Tension positive, z the depth into the body,
// the surface loads acting on the body (σ_zz = −p, σ_xz = −q at the surface). Stresses in units
// of p0, lengths in units of the half-width a.
//
// 1. Circular contact, frictionless, on the axis r = 0 (Johnson, Contact Mechanics, 1985, §3.4,
//    eq. 3.45): σ_z = −p0 /(1 + z²/a²); σ_r = σ_θ = p0 [−(1 + ν)(1 − (z/a) atan(a/z)) + ½/(1 + z²/a²)].
// 2. Line contact (plane strain), pressure p0 √(1 − x²/a²) and full-slip traction q = f p along
//    +x (McEwen, Phil. Mag. 40 (1949) 454–459; Johnson 1985 §7.1–7.2, with
//    m² = ½[√((a² − x² + z²)² + 4x²z²) + (a² − x² + z²)], n² = ½[√(…) − (a² − x² + z²)], m ≥ 0 and
//    n of the sign of x). The signs below are those that satisfy equilibrium, compatibility
//    (∇²(σ_x + σ_z) = 0) and the surface conditions in this convention, checked numerically when
//    this file was written (a transcription of the textbook's signs in another convention failed
//    equilibrium); the classic values follow: max (σ1 − σ3)/2 = 0.300 p0 at z = 0.786 a, max |σ_xz|
//    = 0.250 p0 at x = ±0.87 a, z = 0.50 a.
#include <cmath>

namespace mh::testing {

struct AxisStress { double r, z; };  ///< σ_r = σ_θ and σ_z on the axis, [p0]
inline AxisStress hertz_circle_axis(double z_over_a, double nu) {
  const double t = z_over_a, s = 1 / (1 + t * t);
  return {-(1 + nu) * (1 - t * std::atan(1 / t)) + 0.5 * s, -s};
}

struct PlaneStress { double xx, zz, xz, yy; };  ///< [p0]; σ_yy = ν(σ_xx + σ_zz) (plane strain)
inline PlaneStress mcewen(double x, double z, double f, double nu) {
  const double A = 1 - x * x + z * z, S = std::sqrt(A * A + 4 * x * x * z * z);
  const double m = std::sqrt(0.5 * (S + A)), n = std::copysign(std::sqrt(std::fmax(0.0, 0.5 * (S - A))), x);
  const double D = m * m + n * n;
  PlaneStress s;
  s.xx = -(m * (1 + (z * z + n * n) / D) - 2 * z) + f * (n * (2 - (z * z - m * m) / D) - 2 * x);
  s.zz = -m * (1 - (z * z + n * n) / D) - f * n * (m * m - z * z) / D;
  s.xz = -n * (m * m - z * z) / D - f * (m * (1 + (z * z + n * n) / D) - 2 * z);
  s.yy = nu * (s.xx + s.zz);
  return s;
}

}  // namespace mh::testing
