#pragma once
// Damage and wear of every contact of a solved case, and their sums (docs/methods.md "Damage and
// wear functions"): computed once per case from its tangential results (damage.hpp's functions)
// and carried in the CaseResult (LoadedEllipse::damage, PatchResult::damage, CaseResult::damage),
// which the output tables only write.
#include "contact/case_result.hpp"
#include "contact/rcf/damage.hpp"
#include "core/units.hpp"

namespace mh {

/// [m²] The contact area A of a loaded ellipse in the USFD wear function: π a b of the patch its
/// normal law carries. Under a plastic law that is the plastic patch (a, b larger than the elastic
/// a_el, b_el at the same N): the area in contact as solved, on which FASTSIM solved the creep
/// forces and Tγ is dissipated (docs/methods.md "Damage and wear functions", the area A).
inline double wear_area(const LoadedEllipse& L) { return units::pi * L.s.a * L.s.b; }

/// The damage and wear of one contact carrying N [N] over the area A [m²] with tangential result
/// t; NaN fields where t is not solved.
ContactDamage contact_damage(const TangentialResult& t, double N, double A, const BurstowOptions& b = {},
                             const UsfdWearOptions& u = {});

/// Fills every contact's `damage` of a solved case (ellipses over wear_area, patches over their
/// area as solved) and the case sums r.damage (NaN unless r.tangential.solved). Nothing when the
/// tangential problem was not asked.
void damage_step(CaseResult& r, const BurstowOptions& b = {}, const UsfdWearOptions& u = {});

}  // namespace mh
