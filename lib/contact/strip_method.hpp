#pragma once
// The semi-Hertzian strip method with elastic coupling (docs/method.md §9) as a method of `run`:
// the patches, planes and vertical force balance of the grid methods (contact/patch_driver.hpp),
// and in each patch lateral strips of width ds with a semi-elliptic pressure along x whose
// amplitudes are coupled through the half-space (contact/strips.hpp).
#include "contact/case_result.hpp"
#include "contact/hertz.hpp"
#include "contact/strips.hpp"
#include "geometry/contact_geometry.hpp"

namespace mh {

struct StripMethodOptions {
  double ds = 0.2e-3;          ///< [m] strip width (default 0.2 mm)
  double d_comb = 8e-3;        ///< [m] regions closer than this are one patch (as the half-space method)
  double margin = 1.25;        ///< strips cover the interpenetration at margin × the approach
  double ref_rtol = 0.02;      ///< planes re-placed when the approach moved by more than this
  double force_rtol = 1e-7;    ///< vertical force balance across patches
  int max_outer = 60;
  int max_passes = 12;         ///< placements of the patches (default 12: a strongly capped flange patch, Manchester t_Y = 8.5 mm, 100 kN, p_lim 900 MPa, needs 8; each costs about a millisecond)
  double x_curvature_step = 1e-3;  ///< [m] x of the second point of the gap's parabola along x (default 1 mm)
  StripOptions strips;         ///< the per-patch solver (quadrature, tolerances, outlier factor)
  bool keep_strips = false;    ///< keep every strip in PatchResult::strips (for --strips)
  bool valid(std::string* why) const;
};

/// Solve one case. `material.p_lim` finite caps the strips (plastic model, §9.6). Never throws for
/// a numerical reason.
CaseResult solve_strip_method(const ContactGeometry& G, const Material& material, double tY, double Q,
                              const StripMethodOptions& opt);

}  // namespace mh
