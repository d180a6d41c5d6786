#pragma once
// Multi-Hertzian normal contact (paper eqs. 10–11, method.md §4): at a lateral position t_Y and a
// vertical load Q, find the vertical virtual penetration δz with
//     Σ_i N_i cos γ_i = Q                                   (10)
//     h0_i = (δz − (z_wi − z_ri)) cos γ_i                    (11)
// N_i = 0 for h0_i ≤ 0, else N(h0_i) of ellipse i (eq. 8, or the plastic law of method.md §5).
// Every case returns a status; a failing case never throws.
#include <string>
#include <vector>

#include "geometry/contact_geometry.hpp"
#include "contact/options.hpp"
#include "contact/case_result.hpp"
#include "contact/ellipse/ellipse_law.hpp"
#include "contact/ellipse/hertz_validity.hpp"

namespace mh {


/// Solve one case. Candidates whose curvature sum B ≤ 0 (conformal: a concave wheel root on a rail
/// corner of nearly the same radius) have no Hertz ellipse: they are excluded, and when such a
/// candidate would have been loaded (h0 > 0 at the solution) the case carries a warning
/// "non_hertzian_excluded:ellipse=K". Every loaded ellipse is checked against the Hertz
/// assumptions (hertz_validity.hpp); one that fails keeps its result, has validity.valid = false
/// and adds the warning "non_hertzian:ellipse=K:<limit>=<value>><max>" (never a silent ok). Q ≤ 0
/// or not finite gives `no_contact` with a message. Precondition: mat.valid() (an invalid
/// material is a bug of the caller: std::invalid_argument).
CaseResult solve_multi_hertz(const ContactGeometry& G, const Material& mat, double tY, double Q,
                             const MultiHertzOptions& opt = {});

/// One potential ellipse as a candidate at one t_Y: everything about it that does not depend on
/// the load Q (geometry.csv). The values are those solve_multi_hertz() uses and copies
/// into a LoadedEllipse (same code, same bits).
struct CandidateEllipse {
  int ellipse = 0;         ///< 1-based index of the potential ellipse
  CandidateGeom g;         ///< its strip, interpolated at t_Y
  double A = 0, B = 0;     ///< [1/m] (eq. 1)
  bool hertzian = false;   ///< it has a Hertz ellipse (B > 0 and λ in the Hertz range); else c is unset
  HertzCoefficients c;     ///< λ, m, n of its law (only when hertzian)
  double z_r = 0, z_w = 0; ///< [m] profile heights at y_r (rail) and y_w (wheel), as in LoadedEllipse
};

/// Every potential ellipse of G as a candidate at t_Y (precondition: G.covers(tY)), in
/// increasing ellipse index, into `out` (resized to G.n_ellipses()).
void candidate_ellipses(const ContactGeometry& G, const Material& mat, double tY, const MultiHertzOptions& opt,
                        std::vector<CandidateEllipse>& out);

}  // namespace mh
