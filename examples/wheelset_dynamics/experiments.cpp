#include "experiments.hpp"

#include <cmath>
#include <stdexcept>

#include "geometry/conicity.hpp"
#include "geometry/wheelset.hpp"
#include "profile/read.hpp"
#include "profile/standard_profiles.hpp"

namespace wsdyn {

namespace {
mh::Material steel() {
  mh::Material m;
  m.E = 210e9;
  m.nu = 0.28;
  return m;
}
}  // namespace

WheelsetSetup standard_setup(const mh::Inclination& incl, double Q, double mu) {
  WheelsetSetup s;
  s.wheel = mh::make_standard_profile("S1002");
  s.rail = mh::make_standard_profile("60E1", incl);
  s.material = steel();
  s.Q = Q;
  s.mu = mu;
  return s;
}

WheelsetSetup measured_wheel_setup(const std::string& wheel_file, double Q, double mu) {
  WheelsetSetup s = standard_setup(mh::Inclination::In40, Q, mu);
  mh::ProfileReadOptions o;
  o.kind = mh::ProfileKind::Wheel;
  s.wheel = mh::read_profile(wheel_file, o);
  return s;
}

double KlingelResult::mean_error() const {
  double e = 0;
  for (const HalfCycle& h : half_cycles) e += h.error();
  return half_cycles.empty() ? NAN : e / static_cast<double>(half_cycles.size());
}

double KlingelResult::max_error() const {
  double e = half_cycles.empty() ? NAN : 0;
  for (const HalfCycle& h : half_cycles) e = std::max(e, std::abs(h.error()));
  return e;
}

KlingelResult klingel(ContactAdapter& contact, double y0, double V, double distance, const WheelsetBody& body,
                      double rtol) {
  KlingelResult K;
  RunOptions o;
  o.atol_y *= rtol / o.rtol;
  o.rtol = rtol;
  o.V = V;
  o.y0 = y0;
  o.distance = distance;
  K.run = simulate(contact, body, o);
  const RunResult& R = K.run;
  // Half cycles between consecutive zero crossings, each with the extreme inside it.
  double sum_peak = 0;
  for (std::size_t i = 0; i + 1 < R.zero_times.size(); ++i) {
    HalfCycle h;
    h.s0 = V * R.zero_times[i];
    h.s1 = V * R.zero_times[i + 1];
    for (std::size_t k = 0; k < R.peak_times.size(); ++k)
      if (V * R.peak_times[k] > h.s0 && V * R.peak_times[k] < h.s1) h.peak = std::max(h.peak, std::abs(R.peak_values[k]));
    if (h.peak == 0) continue;
    h.L_sim = 2 * (h.s1 - h.s0);
    K.half_cycles.push_back(h);
    sum_peak += h.peak;
  }
  if (K.half_cycles.empty()) return K;
  K.amplitude = sum_peak / static_cast<double>(K.half_cycles.size());
  const GeometryReference g(contact.setup());
  K.r0 = g.r0;
  K.s = g.l0;
  for (HalfCycle& h : K.half_cycles) {
    h.lambda = g.conicity(h.peak);
    h.L_klingel = 2 * M_PI * std::sqrt(K.r0 * K.s / h.lambda);
  }
  K.L_linear = linear_model(linear_inputs(contact, g, K.amplitude), WheelsetBody{}).wavelength(V);
  return K;
}

WornResult worn_pair(const std::string& wheel_file, double y0, double V, double distance, double yield) {
  WornResult W;
  W.yield = yield;
  const WheelsetSetup es = measured_wheel_setup(wheel_file);
  WheelsetSetup ps = es;
  ps.material.yield = yield;
  mh::derive_plastic_law(ps.material);
  ContactAdapter ce(es), cp(ps);
  W.elastic = klingel(ce, y0, V, distance);
  W.plastic = klingel(cp, y0, V, distance);
  return W;
}

WheelsetBody suspended_body() {
  WheelsetBody b;
  b.m = 1500;        // [kg]
  b.I_z = 900;       // [kg m²]
  b.k_y = 0.2e6;     // [N/m]
  b.k_psi = 0.2e6;   // [N m/rad]
  return b;
}

double growth_at(ContactAdapter& contact, const WheelsetBody& body, double y0, double V, double distance,
                 RunResult* run) {
  RunOptions o;
  o.V = V;
  o.y0 = y0;
  o.distance = distance;
  o.sample_distance = run ? 0.05 : 0;
  o.y_stop = 4 * y0;
  RunResult R = simulate(contact, body, o);
  if (R.status != "ok" && R.status != "y_stop") throw std::runtime_error("growth_at: " + R.status);
  const double g = R.growth_per_metre(1);
  if (run) *run = std::move(R);
  return g;
}

CriticalResult critical_speed(ContactAdapter& contact, const WheelsetBody& body, double y0, double distance,
                              double rel_tol) {
  CriticalResult C;
  const GeometryReference g(contact.setup());
  C.in = linear_inputs(contact, g, y0);
  if (C.in.n_contacts != 1)
    throw std::runtime_error("critical_speed: the centred wheelset has " + std::to_string(C.in.n_contacts) +
                             " contacts per wheel; the linear model needs one");
  C.lin = linear_model(C.in, body);
  C.V_linear = C.lin.critical_speed(1, 200);
  if (!std::isfinite(C.V_linear)) throw std::runtime_error("critical_speed: the linear model is stable up to 200 m/s");
  // Bracket around the linear value, then bisect on the sign of the growth.
  double lo = 0.8 * C.V_linear, hi = 1.25 * C.V_linear;
  if (growth_at(contact, body, y0, lo, distance) > 0) throw std::runtime_error("critical_speed: grows at 0.8 V_linear");
  if (growth_at(contact, body, y0, hi, distance) < 0) throw std::runtime_error("critical_speed: decays at 1.25 V_linear");
  C.runs = 2;
  while ((hi - lo) > rel_tol * lo) {
    const double mid = 0.5 * (lo + hi);
    (growth_at(contact, body, y0, mid, distance) > 0 ? hi : lo) = mid;
    ++C.runs;
  }
  C.V_lo = lo;
  C.V_hi = hi;
  C.V_nonlinear = 0.5 * (lo + hi);
  return C;
}

}  // namespace wsdyn
