#pragma once
// The semi-Hertzian strip method with elastic coupling (docs/method.md §9) as a method of `run`:
// the patches, planes and vertical force balance of the grid methods (contact/grid/patch_driver.hpp),
// and in each patch lateral strips of width ds with a semi-elliptic pressure along x whose
// amplitudes are coupled through the half-space (contact/strips/strip_patch.hpp).
#include "contact/options.hpp"
#include "contact/case_result.hpp"
#include "contact/ellipse/hertz.hpp"
#include "contact/strips/strip_patch.hpp"
#include "geometry/contact_geometry.hpp"

namespace mh {


/// Solve one case. `material.p_lim` finite caps the strips (plastic model, §9.6). Never throws for
/// a numerical reason. `elastic_mh`: the elastic multi-Hertzian solution of the same case, the
/// start (GridStart in contact/grid/patch_driver.hpp), when the caller has it; null: solved here.
CaseResult solve_strip_method(const ContactGeometry& G, const Material& material, double tY, double Q,
                              const StripMethodOptions& opt, const CaseResult* elastic_mh = nullptr);

}  // namespace mh
