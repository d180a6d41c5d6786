#pragma once
// The example's three checks (docs/wheelset-dynamics.md), as functions that the command line
// (main.cpp) and the tests (test_wheelset_dynamics.cpp) call alike.
#include <string>

#include "linear_model.hpp"
#include "wheelset_model.hpp"

namespace wsdyn {

/// S1002 on 60E1 at the inclination (1:40 or 1:20), standard track (method.md §7), steel
/// (E 210 GPa, ν 0.28), Q per wheel [N], μ.
WheelsetSetup standard_setup(const mh::Inclination& incl = mh::Inclination::In40, double Q = 50e3, double mu = 0.3);
/// A measured wheel profile file (a wheel, read with the library's readers) on 60E1 at 1:40.
WheelsetSetup measured_wheel_setup(const std::string& wheel_file, double Q = 50e3, double mu = 0.3);

/// 1. Klingel: a free wheelset released at y0 with speed V. The amplitude of EN 15302 is the peak
/// of the oscillation: each half cycle (between two zero crossings of y) is compared with
/// Klingel's wavelength at the conicity of its own peak, so that the slow change of the amplitude
/// (the creep forces damp the free wheelset at low speed) does not enter the comparison.
struct HalfCycle {
  double s0 = 0, s1 = 0;     ///< [m] distance run at its zero crossings
  double peak = 0;           ///< [m] |y| at its extreme
  double lambda = NAN;       ///< tan γe at `peak`
  double L_sim = NAN;        ///< [m] 2 (s1 − s0)
  double L_klingel = NAN;    ///< [m] 2π √(r0 s / λ)
  double error() const { return L_sim / L_klingel - 1; }
};
struct KlingelResult {
  RunResult run;
  std::vector<HalfCycle> half_cycles;  ///< complete half cycles, the first (from the release) excluded
  double r0 = NAN, s = NAN;  ///< [m] rolling radius and contact |Y| of the centred wheelset (wheelset geometry)
  double amplitude = NAN;    ///< [m] mean |peak| of the half cycles
  double L_linear = NAN;     ///< [m] the linear model's wavelength at V and the mean amplitude
  double mean_error() const;  ///< mean of the half cycles' L_sim / L_klingel − 1
  double max_error() const;   ///< the largest |L_sim / L_klingel − 1| of the half cycles
};
/// `body`: the free wheelset by default (its I_y = ∞ holds the pitch rate: the trap of wheelset_model.hpp).
/// `rtol`: CVODE's relative tolerance (RunOptions::rtol; the absolute tolerances scale with it).
KlingelResult klingel(ContactAdapter& contact, double y0, double V, double distance = 60,
                      const WheelsetBody& body = WheelsetBody{}, double rtol = RunOptions{}.rtol);

/// 2. Critical speed: the suspended wheelset's linear critical speed against the speed where the
/// nonlinear simulation of a small perturbation starts to grow.
struct CriticalResult {
  LinearInputs in;
  LinearWheelset lin;
  double V_linear = NAN;     ///< [m/s] from the eigenvalues
  double V_nonlinear = NAN;  ///< [m/s] bisection on the growth of the perturbation
  double V_lo = NAN, V_hi = NAN;  ///< [m/s] the final bracket (decays at V_lo, grows at V_hi)
  int runs = 0;
  double error() const { return V_nonlinear / V_linear - 1; }
};
/// The body of the check: 1500 kg, 900 kg m², k_y 0.2 MN/m, k_ψ 0.2 MN m/rad: soft enough that
/// S1002 on 60E1 1:20 (tan γe 0.009) hunts at a running speed (84 m/s).
WheelsetBody suspended_body();
CriticalResult critical_speed(ContactAdapter& contact, const WheelsetBody& body, double y0, double distance,
                              double rel_tol = 0.005);
/// 3. A measured (worn) wheel on 60E1 1:40, elastic and plastic contact in the same program run:
/// the free wheelset released at y0, speed V, each half cycle against Klingel at the worn pair's
/// conicity, and the cost per step.
struct WornResult {
  KlingelResult elastic, plastic;
  double yield = 0;  ///< [Pa] σ_y of the plastic run (the multi-Hertzian yield law, method.md §5.1)
};
WornResult worn_pair(const std::string& wheel_file, double y0, double V, double distance, double yield = 500e6);

/// [1/m] the growth rate of the perturbation y0 at speed V (RunResult::growth_per_metre).
double growth_at(ContactAdapter& contact, const WheelsetBody& body, double y0, double V, double distance,
                 RunResult* run = nullptr);

}  // namespace wsdyn
