#pragma once
// Closed-form stresses below Hertzian contacts, independent of the library's quadrature
// (lib/contact/rcf/subsurface.*). Tension positive, z the depth into the body, the surface loads
// acting on the body (σ_zz = −p, σ_xz = −q at the surface). Stresses in units of p0, lengths in
// units of the half-width a.
//
// 1. Circular contact, frictionless, on the axis r = 0 (Johnson, Contact Mechanics, 1985, §3.4,
//    eq. 3.45): σ_z = −p0 /(1 + z²/a²); σ_r = σ_θ = p0 [−(1 + ν)(1 − (z/a) atan(a/z)) + ½/(1 + z²/a²)].
// 2. Line contact (plane strain) with full-slip traction (McEwen 1949): the library's closed form
//    (contact/rcf/subsurface.hpp, mcewen_stress), whose signs satisfy equilibrium, compatibility
//    (∇²(σ_x + σ_z) = 0) and the surface conditions in this convention (checked numerically when it
//    was written: a transcription of the textbook's signs in another convention failed
//    equilibrium); test_subsurface.cpp holds it against the quadrature and the classic values
//    (max (σ1 − σ3)/2 = 0.300 p0 at z = 0.786 a, max |σ_xz| = 0.250 p0 at x = ±0.87 a, z = 0.50 a).
//    The shakedown map derives its line-contact limits on it (shakedown.hpp).
#include <cmath>

#include "contact/rcf/subsurface.hpp"

namespace mh::testing {

struct AxisStress { double r, z; };  ///< σ_r = σ_θ and σ_z on the axis, [p0]
inline AxisStress hertz_circle_axis(double z_over_a, double nu) {
  const double t = z_over_a, s = 1 / (1 + t * t);
  return {-(1 + nu) * (1 - t * std::atan(1 / t)) + 0.5 * s, -s};
}

/// McEwen's closed form, the library's one home of it (contact/rcf/subsurface.hpp, mcewen_stress):
/// independent of the library's quadrature, which test_subsurface.cpp holds against it.
inline Stress mcewen(double x, double z, double f, double nu) { return mcewen_stress(x, z, f, nu); }

}  // namespace mh::testing
