#pragma once
// The evidence domains of the plastic laws (docs/trust.md "Evidence domains"): for each method
// and plastic law, the load range over which a test of the project shows the answer within its
// tolerance, and the test that shows it. The judge (judge.hpp) compares every plastic case with
// it: a loaded ellipse or grid patch beyond its row's bound gets a `beyond_evidence` warning
// (docs/status.md), so the row is `outside_validity`. A light header: the table and the check.
#include <vector>

#include "contact/case_result.hpp"
#include "contact/judge/status.hpp"
#include "contact/options.hpp"

namespace mh {

/// Which plastic law a row of the table is about (Material: docs/method.md §5.1).
enum class PlasticLaw : std::uint8_t {
  YieldLaw,   ///< from a yield stress alone (Material::yield_law): the ellipse's yield law, the grids' cap kPlimPerYield σ_y
  UserPLim,   ///< a user's own p_lim (p_lim_MPa): the ellipse's capped law, the grids' cap p_lim
  AnyLaw,     ///< every model, elastic or plastic: a bound of the method itself
};

/// One row: a method family and law, the quantity that measures a case's load against the
/// evidence (the elastic Hertz p0 of the contact's load over σ_y or over p_lim), the largest value
/// the tests cover, and the test that establishes it.
struct EvidenceDomain {
  const char* methods;   ///< "multi-hertzian" or "half-space, strips" (as written in docs)
  PlasticLaw law;
  const char* law_name;  ///< as written in docs/trust.md
  Quantity q;            ///< Quantity::P0ElOverSigmaY, P0ElOverPLim, PlaneTilt or EdgeTilt
  double bound;          ///< the largest value the tests establish (inclusive), in q's written unit (plane_tilt_deg, edge_tilt_deg: degrees)
  const char* test;      ///< the test file that establishes it (path in the repository)
  const char* evidence;  ///< what the test shows, in one sentence
};
/// The table, one row per method family and plastic law (docs/trust.md renders it; a unit test
/// checks that the two agree).
const std::vector<EvidenceDomain>& evidence_domains();

/// The row for a method and a law; null for an elastic material (no plastic law, no bound).
const EvidenceDomain* evidence_domain(Method m, const Material& mat);

/// The grid methods' row of the planar approach (PlasticLaw::AnyLaw, Quantity::PlaneTilt): one
/// plane per patch measures the gap and the pressure along one normal; where the rail under the
/// patch's peak pressure is tilted against that plane by more than the bound, CONTACT's conformal
/// runs (a curved reference surface) put the peak lower, by up to 16 % in the cases measured
/// (docs/trust.md "Evidence domains"). The judge (judge.cpp) compares each grid patch's tilt at
/// its peak (PatchResult::y_peak) with it.
/// q = Quantity::EdgeTilt: the row of the planar approach's extent, the same tilt at the patch's
/// first and last loaded row (PatchResult::s_lo, s_hi): how far from its plane the rail under a
/// patch turns anywhere in it, in the cases that establish the row.
const EvidenceDomain& planar_evidence_domain(Quantity q = Quantity::PlaneTilt);

/// Adds a `beyond_evidence` warning to `r` for each loaded ellipse (multi-Hertzian: its state's
/// p0_el) or grid patch (1.5 N / (π a_el b_el), the elastic ellipse of its load,
/// contact/grid/patch_elastic.hpp) whose elastic Hertz p0 over σ_y (or p_lim) exceeds the
/// bound of its method and law. Elastic materials, and patches without an elastic ellipse
/// (a_el NaN), are not checked.
void add_evidence_warnings(CaseResult& r, const Material& mat);

}  // namespace mh
