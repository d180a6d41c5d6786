#pragma once
// The linearised wheelset (docs/wheelset-dynamics.md "Linear model"): small motions about the
// centred position, Kalker's linear creep coefficients on the Hertz ellipse at the nominal load,
// the equivalent conicity λ, and the lateral stiffness of the contact geometry:
//   m ÿ   + 2 f22 (ẏ/V − ψ) + 2 f23 ψ̇ / V + (k_s + k_y) y = 0,
//   I_z ψ̈ + 2 f11 l0 (λ y / r0 + l0 ψ̇ / V)               + k_ψ ψ = 0,
// f11 = G c² C11, f22 = G c² C22, f23 = G c³ C23 (c = √(ab), kalker.hpp), l0 the contact's |Y|
// and r0 its rolling radius, both of the centred wheelset; k_s the lateral stiffness of the
// normal forces (gravitational stiffness, 2 Q d tan γ / dy) less that of the spin creep force
// (2 f23 / r0 · d(sin γ cos γ)/dy). The derivation from the nonlinear model's forces
// (contact_adapter.cpp) is in the docs page; the same equations are Wickens' (A.H. Wickens,
// Fundamentals of Rail Vehicle Dynamics, Swets & Zeitlinger 2003, ch. 2) and Knothe & Stichel's
// (Rail Vehicle Dynamics, Springer 2017, the single wheelset) with the spin terms kept. Not in
// it (nor in the nonlinear model): the spin moment, the contact point's lead under yaw, roll.
#include <complex>
#include <vector>

#include "wheelset_model.hpp"

namespace wsdyn {

struct LinearWheelset {
  WheelsetBody body;
  double f11 = 0, f22 = 0;   ///< [N] G c² C11, G c² C22
  double f23 = 0;            ///< [N m] G c³ C23
  double lambda = 0;         ///< [-] equivalent conicity
  double k_s = 0;            ///< [N/m] lateral stiffness of the contact geometry (gravitational less spin)
  double l0 = 0.75;          ///< [m] the contact's |Y| from the centre plane
  double r0 = 0.46;          ///< [m] rolling radius of the centred wheelset
  /// The 4 × 4 matrix of ẋ = A x, x = (y, ẏ, ψ, ψ̇), at the speed V [m/s], row-major.
  std::vector<double> matrix(double V) const;
  /// Its eigenvalues [1/s] (Eigen's EigenSolver).
  std::vector<std::complex<double>> eigenvalues(double V) const;
  /// [1/s] the largest real part of the eigenvalues at V.
  double max_real_part(double V) const;
  /// [m/s] the lowest speed where an eigenvalue's real part turns positive, searched in
  /// [V_lo, V_hi] by a scan of `n` steps and bisection to tol; NaN when stable over all of it.
  double critical_speed(double V_lo, double V_hi, int n = 200, double tol = 1e-6) const;
  /// [m] wavelength of the oscillatory mode with the smallest damping at V: 2π V / ω.
  double wavelength(double V) const;
};

/// The linear model's inputs from the library (what the docs page names as its sources).
struct LinearInputs {
  double a = 0, b = 0;      ///< [m] the centred wheelset's Hertz ellipse (a along X) at Q (its most loaded one)
  int n_contacts = 0;       ///< loaded ellipses per wheel of the centred wheelset (the model assumes 1)
  double C11 = 0, C22 = 0, C23 = 0;
  double G = 0, nu = 0;     ///< [Pa], [-] Kalker's combined constants
  double lambda = 0;        ///< tan γe at `amplitude` (EN 15302, `mhcontact wheelset`'s function)
  double amplitude = 0;     ///< [m]
  double k_grav = 0;        ///< [N/m] 2 Q d tan γ / dy, describing function at the amplitude
  double k_spin = 0;        ///< [N/m] 2 f23 / r0 · d(sin γ cos γ)/dy, the same
  double l0 = 0, r0 = 0;    ///< [m] of the centred wheelset (wheelset geometry)
};

/// The wheelset geometry of a setup, by the functions of `mhcontact wheelset`
/// (geometry/wheelset.hpp, no roll, the setup's track; geometry/conicity.hpp on Δr(y) every
/// 0.01 mm over ±8 mm, its defaults): an independent path from the contact solve's geometry.
class GeometryReference {
 public:
  explicit GeometryReference(const WheelsetSetup& s);
  ~GeometryReference();
  /// tan γe at the amplitude A [m] (EN 15302; std::runtime_error unless its status is ok).
  double conicity(double A) const;
  /// First harmonics (2 / (π A)) ∫_0^π F(A sin θ) sin θ dθ [1/m] of F = Δ tan γ and of
  /// F = sin γ_R cos γ_R − sin γ_L cos γ_L (midpoint rule, 400 points).
  void describing_functions(double A, double* d_tan, double* d_sincos) const;
  double r0 = 0;  ///< [m] rolling radius of the centred wheelset
  double l0 = 0;  ///< [m] |Y| of its contact from the centre plane
 private:
  struct Impl;
  Impl* p_;
};

/// Build the inputs at the lateral amplitude A [m]: the ellipse and Kalker's coefficients from
/// the contact solve of the centred wheelset; λ, the contact angles and l0, r0 from the wheelset
/// geometry `g`, the stiffnesses as describing functions of its tan γ(y) at A.
LinearInputs linear_inputs(ContactAdapter& contact, const GeometryReference& g, double A);
LinearWheelset linear_model(const LinearInputs& in, const WheelsetBody& body);

}  // namespace wsdyn
