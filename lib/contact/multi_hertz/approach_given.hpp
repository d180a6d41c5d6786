#pragma once
// Multi-Hertzian contact with the vertical approach prescribed instead of the load: eq. 11 with
// δz given, each ellipse's force from its law (eq. 8, or the plastic law of method.md §5), no
// iteration. The penetration-driven force element of a multi-body code (docs/c-api.md);
// solve_multi_hertz() (multi_hertz.hpp) is the load-driven one (eq. 10). At the δz that
// solve_multi_hertz returns for a load Q, this gives back Σ N_i cos γ_i = Q to the solver's rtol.
#include <vector>

#include "contact/case_result.hpp"
#include "contact/multi_hertz/multi_hertz.hpp"
#include "contact/options.hpp"
#include "geometry/contact_geometry.hpp"

namespace mh {

/// The buffers of solve_multi_hertz_approach, kept between calls so that a call at the same
/// number of ellipses allocates nothing but the warnings' text.
struct ApproachWorkspace {
  std::vector<CandidateGeom> geo;  ///< the candidates at t_Y, one per potential ellipse
};

/// The case at lateral position tY [m] and vertical virtual penetration dz [m] (eq. 11: h0_i =
/// (δz − gap_i) cos γ_i; 0 at first contact) into `r` (cleared first; its vectors keep their
/// capacity). The fields are those of solve_multi_hertz at the same δz: loaded ellipses, Fz, Fy,
/// pmax, area, approach, the same warnings; iterations 0, residual 0. Status out_of_range for a
/// t_Y outside the table (the same message), no_contact when nothing is loaded (dz ≤ the gap of
/// every Hertzian candidate). Never throws for a numerical reason.
void solve_multi_hertz_approach(const ContactGeometry& G, const Material& mat, double tY, double dz,
                                const MultiHertzOptions& opt, ApproachWorkspace& ws, CaseResult& r);

/// dN/dh0 [N/m] of a loaded ellipse at its state: 3/2 N / h0 on the elastic branch (N = k_e h0^1.5,
/// eq. 8), k_p = N / (h0 − h_y/3) on the plastic one (method.md §5). Its derivative in the
/// vertical approach δz is dN/dh0 · cos γ (eq. 11); 0 for an unloaded ellipse.
double normal_stiffness(const LoadedEllipse& L);

}  // namespace mh
