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

/// The same into `out`, reset first (every field as a fresh CaseResult) with its vectors keeping
/// their capacity: a caller that reuses `out` (the C interface's workspace) allocates nothing for
/// a case without warnings once the vectors have grown. Same bits as the form above.
void solve_multi_hertz(const ContactGeometry& G, const Material& mat, double tY, double Q,
                       const MultiHertzOptions& opt, CaseResult& out);

/// A candidate's curvature sums A, B [1/m] (eq. 1) and whether it has a Hertz ellipse (both
/// positive and finite, λ = A/B within the range of the Hertz coefficients); one code for the
/// load-given and the approach-given solvers.
bool candidate_sums(const CandidateGeom& g, double* A, double* B);

/// Adds candidate `g` (1-based index `ellipse`) at h0 = h > 0 to `r`, one code for both solvers:
/// the warning off_profile when it lies off a profile end; non_hertzian_excluded when it has no
/// law (`law` null); else its LoadedEllipse (state, Hertz validity and its warning, profile
/// heights) and its share of Fz, Fy (cos γ = cg, sin γ = sg), pmax, area and approach.
void add_loaded_candidate(const ContactGeometry& G, int ellipse, const CandidateGeom& g, double A, double B,
                          const EllipseLaw* law, double h, double cg, double sg, const MultiHertzOptions& opt,
                          CaseResult& r);

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
