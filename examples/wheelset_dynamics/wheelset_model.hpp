#pragma once
// A wheelset's lateral and yaw motion on straight track at constant speed (the dynamics example,
// docs/wheelset-dynamics.md): states y, ẏ, ψ, ψ̇ (track frame of contact_adapter.hpp) and the
// axle's rotation rate Ω,
//   m ÿ   = F_Y(y, ψ, ẏ, ψ̇, Ω) − k_y y,
//   I_z ψ̈ = M_Z(y, ψ, ẏ, ψ̇, Ω) − k_ψ ψ,
//   I_y Ω̇ = M_axle(y, ψ, ẏ, ψ̇, Ω)      (no traction or braking torque),
// with F_Y, M_Z, M_axle from both wheels' contacts (normal and creep forces, the library, every
// right-hand side) and the primary suspension to a frame moving at the speed V without lateral
// or yaw motion (k_y = k_ψ = 0: a free wheelset). Ω starts at V / r_c, r_c the rolling radius of
// the centred wheelset. Ω must be free: held constant, it imposes a net longitudinal creepage
// wherever the mean of the two rolling radii moves off r_c (on S1002/60E1 1:40 at y = 3 mm by
// 0.35 mm), and the two wheels, with ellipses of different size, then share the yaw moment
// unevenly: the wavelength came out 5 % longer than Klingel's.
// Integrated by SUNDIALS CVODE (BDF, dense Newton: the creep forces make the system stiff at
// low speed, eigenvalues near −2 f22 / (m V)).
#include <string>
#include <vector>

#include "contact_adapter.hpp"

namespace wsdyn {

/// Mass and suspension of the wheelset. Defaults: a free wheelset of 1500 kg, 900 kg m².
struct WheelsetBody {
  double m = 1500;       ///< [kg] mass
  double I_z = 900;      ///< [kg m²] yaw moment of inertia
  double I_y = 120;      ///< [kg m²] moment of inertia of the axle with its wheels about its own axis
  double k_y = 0;        ///< [N/m] lateral stiffness of the primary suspension (both axleboxes)
  double k_psi = 0;      ///< [N m/rad] yaw stiffness of the primary suspension
};

/// Options of one run, with their defaults.
struct RunOptions {
  double V = 2;          ///< [m/s] forward speed
  double y0 = 3e-3;      ///< [m] initial lateral displacement (released at rest, ψ = 0)
  double distance = 60;  ///< [m] distance run (t_end = distance / V)
  double sample_distance = 0.05;  ///< [m] distance between stored samples (0: none)
  double rtol = 1e-5;    ///< CVODE's relative tolerance
  double atol_y = 1e-8;  ///< [m] absolute tolerance of y (ψ: /1 m, the rates: × V / 1 m)
  long max_steps = 200000;  ///< CVODE steps at most
  /// Stop when |y| exceeds this [m] (a hunting wheelset reaches the flange; the growth is
  /// measured before).
  double y_stop = 8e-3;
};

struct Sample { double t, y, psi, y_dot, psi_dot, Omega; };  ///< [s], [m], [rad], [m/s], [rad/s], [rad/s]

/// One run: the trajectory, its zero crossings and extremes (CVODE's root finding on y and ẏ),
/// and the cost.
struct RunResult {
  std::string status = "ok";  ///< "ok"; "contact_failed" (a contact gave no answer); "cvode: <flag>"; "y_stop"
  double V = 0, Omega = 0, r_c = 0;
  std::vector<Sample> samples;
  std::vector<double> zero_times;   ///< [s] y = 0
  std::vector<double> peak_times, peak_values;  ///< [s], [m] at ẏ = 0 (signed y)
  long steps = 0, rhs_evals = 0, contact_calls = 0, jac_evals = 0;  // contact_calls: wheelset calls (both wheels)
  double p_max = 0;          ///< [Pa] the largest contact pressure of any right-hand side
  long plastic_rhs = 0;      ///< right-hand sides with a plastic ellipse on either wheel
  double cpu_seconds = 0;    ///< integration time, CPU time of the process
  double us_per_step() const { return steps > 0 ? 1e6 * cpu_seconds / static_cast<double>(steps) : 0; }
  double us_per_call() const {
    return contact_calls > 0 ? 1e6 * cpu_seconds / static_cast<double>(contact_calls) : 0;
  }
  /// [m] wavelength from the zero crossings from `skip` on: V × 2 × mean half period.
  double wavelength(std::size_t skip = 1) const;
  /// [m] mean |peak| of the peaks from `skip` on.
  double mean_amplitude(std::size_t skip = 0) const;
  /// [1/m] growth rate of |peak| per metre run (least squares of ln|peak| against distance) from
  /// peak `skip` on: > 0 grows (hunting), < 0 decays.
  double growth_per_metre(std::size_t skip = 1) const;
};

/// Integrate the wheelset from (y0, 0, 0, 0) over opt.distance at opt.V.
RunResult simulate(ContactAdapter& contact, const WheelsetBody& body, const RunOptions& opt);

/// [m] rolling radius of the centred wheelset (the right wheel's main contact at y = 0).
double centred_rolling_radius(ContactAdapter& contact);

}  // namespace wsdyn
