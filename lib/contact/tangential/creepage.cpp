// Creepages from the wheelset's motion (creepage.hpp; derivation in docs/method.md §10).
#include "contact/tangential/creepage.hpp"

#include <cassert>
#include <cmath>

namespace mh {

Creepages creepages_from_kinematics(const Kinematics& k, const ContactKinematicPoint& p, double r0) {
  assert(k.V > 0 && r0 > 0);
  const double Omega = std::isnan(k.pitch_rate) ? k.V / r0 : k.pitch_rate;
  const double cg = std::cos(p.gamma), sg = std::sin(p.gamma);
  Creepages c;
  // Velocity of the wheel's material point at the contact, the rail at rest: the wheelset centre
  // (V, ẏ, 0) plus ω × r_c, ω = (−Ω ψ, Ω, ψ̇), r_c = (−l ψ, l, −r); to first order in ψ.
  // Written as 1 − Ω r/V so that the small difference of two near-equal speeds is not lost.
  c.xi = (1.0 - Omega * p.r_roll / k.V) - k.yaw_rate * p.l / k.V;
  // Lateral slip v_y = ẏ − Ω r ψ ≈ ẏ − V ψ; the wheel stays on the rail (v · n = 0), so the
  // in-plane component along ŝ is v_y / cos γ.
  c.eta = (k.lateral_velocity / k.V - k.yaw * Omega * p.r_roll / k.V) / cg;
  // Spin: ω · n / V with n = (0, −sin γ, cos γ) and the axle rolled by δ, ω = (·, Ω cos δ,
  // Ω sin δ + ψ̇): Ω's share −Ω sin(γ − δ) (method.md §10).
  const double sgw = k.roll == 0 ? sg : std::sin(p.gamma - k.roll);
  c.phi = (k.yaw_rate * cg - Omega * sgw) / k.V;
  return c;
}

}  // namespace mh
