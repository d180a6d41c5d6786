#pragma once
// The elastic Hertz ellipse of each grid patch's load, for the indicators defined with the
// elastic Hertzian pressure of the load (contact/rcf/shakedown.hpp; docs/outputs.md "RCF columns"): a patch's normal
// force N on the curvatures A, B (eq. 1) of the elastic multi-Hertzian ellipse whose contact point
// lies inside the patch, by the project's Hertz solution (hertz.hpp: a = m C, b = n C, eqs. 2–4).
// It does not depend on the law or the grid (a capped patch's area is the plastic one).
#include "contact/case_result.hpp"
#include "contact/options.hpp"

namespace mh {

/// Sets PatchResult::a_el, b_el of every patch of `r` from the elastic multi-Hertzian solution
/// `mh` of the same case (null: left NaN): the loaded ellipse whose rail contact point lies
/// within the patch's lateral extent (nearest its reference point when several do); NaN when
/// none does (a patch the multi-Hertzian method does not load: no ellipse to stand for it).
void set_patch_elastic_hertz(const Material& mat, const CaseResult* mh, CaseResult& r);

}  // namespace mh
