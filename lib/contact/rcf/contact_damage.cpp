// Damage and wear of the contacts of a case (contact_damage.hpp).
#include "contact/rcf/contact_damage.hpp"

namespace mh {

ContactDamage contact_damage(const TangentialResult& t, double N, double A, const BurstowOptions& b,
                             const UsfdWearOptions& u) {
  ContactDamage d;
  if (!t.solved) return d;
  d.traction = N > 0 ? std::hypot(t.Fx, t.Fy) / N : NAN;
  d.damage = burstow_damage(t.Tgamma, b);
  const Wear w = usfd_wear(t.Tgamma, A, u);
  d.wear_rate = w.rate;
  d.wear_per_metre = w.per_metre;
  return d;
}

void damage_step(CaseResult& r, const BurstowOptions& b, const UsfdWearOptions& u) {
  r.damage = CaseDamage{};
  if (!r.tangential.asked) return;
  // Σ in contact order (ellipses, then patches); an unsolved contact makes a sum NaN, and the
  // sums are NaN anyway unless every contact is solved.
  double D = 0, W = 0;
  for (LoadedEllipse& L : r.loaded) {
    L.damage = contact_damage(L.t, L.s.N, wear_area(L), b, u);
    D += L.damage.damage, W += L.damage.wear_per_metre;
  }
  for (PatchResult& P : r.patches) {
    P.damage = contact_damage(P.t, P.N, P.area, b, u);
    D += P.damage.damage, W += P.damage.wear_per_metre;
  }
  if (!r.tangential.solved) return;
  r.damage.damage = D;
  r.damage.wear_per_metre = W;
}

}  // namespace mh
