#pragma once
// The exact elastic half-space method (docs/method.md §8): per case, the contact patches are the
// separate interpenetration regions of the undeformed profiles at the rigid vertical approach δz
// (regions closer than d_comb are one patch); each patch gets its own tangent plane at its
// reference point (CONTACT's planar contact approach), a grid of dx × ds elements of uniform
// pressure, the half-space influence of Love's rectangle (contact/half_space/influence.hpp) and the
// constrained conjugate-gradient solver (contact/half_space/normal_cg.hpp), with the pressure capped at
// p_lim in the plastic model. All patches share δz, and Σ_k N_k cos γ_k = Q (eq. 10) closes the
// problem. Frictionless; no conformal correction beyond the per-patch plane.
#include <string>

#include "contact/options.hpp"
#include "contact/case_result.hpp"
#include "contact/ellipse/hertz.hpp"
#include "contact/half_space/normal_cg.hpp"
#include "geometry/contact_geometry.hpp"

namespace mh {


/// Solve one case. `material.p_lim` finite caps the pressure (plastic model). Never throws for a
/// numerical reason: the status says what happened (`not_converged` with a message).
/// `elastic_mh`: the elastic multi-Hertzian solution of the same case, the start (GridStart in
/// contact/grid/patch_driver.hpp), when the caller has it; null: solved here.
CaseResult solve_half_space(const ContactGeometry& G, const Material& material, double tY, double Q,
                            const HalfSpaceOptions& opt, const CaseResult* elastic_mh = nullptr);

}  // namespace mh
