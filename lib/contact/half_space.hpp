#pragma once
// The exact elastic half-space method (docs/method.md §8): per case, the contact patches are the
// separate interpenetration regions of the undeformed profiles at the rigid vertical approach δz
// (regions closer than d_comb are one patch); each patch gets its own tangent plane at its
// reference point (CONTACT's planar contact approach), a grid of dx × ds elements of uniform
// pressure, the half-space influence of Love's rectangle (contact/influence.hpp) and the
// constrained conjugate-gradient solver (contact/normal_cg.hpp), with the pressure capped at
// p_lim in the plastic model. All patches share δz, and Σ_k N_k cos γ_k = Q (eq. 10) closes the
// problem. Frictionless; no conformal correction beyond the per-patch plane.
#include <string>

#include "contact/case_result.hpp"
#include "contact/hertz.hpp"
#include "contact/normal_cg.hpp"
#include "geometry/contact_geometry.hpp"

namespace mh {

struct HalfSpaceOptions {
  double dx = 0.2e-3;          ///< [m] element length along x (default 0.2 mm, CONTACT's benchmark value)
  double ds = 0.2e-3;          ///< [m] element width along s, in the patch plane (default 0.2 mm)
  /// [m] interpenetration regions whose lateral distance (in rail y) is below this form one patch
  /// with one plane (CONTACT's D_COMB idea); farther ones are separate patches. Default 8 mm: with
  /// it the tread and gauge-corner regions of the Manchester pair at t_Y = 5 mm are one patch, as in
  /// CONTACT with D_SEP = 8 mm, D_COMB = 4 mm.
  double d_comb = 8e-3;
  /// The potential contact region of a patch is its interpenetration region at `margin` × the
  /// approach expected (default 1.25; the Hertz contact area is the interpenetration region at
  /// half the approach, so the grid holds the contact with room). A grid whose boundary carries
  /// pressure is rebuilt larger.
  double margin = 1.25;
  /// The patch planes are placed from the interpenetration at the approach of the solution: a
  /// solution whose approach differs from the one the planes were placed for by more than this
  /// (relative) is solved again with planes placed at its approach (default 0.02).
  double ref_rtol = 0.02;
  double force_rtol = 1e-7;    ///< |Σ N_k cos γ_k − Q| ≤ force_rtol·Q (default 1e-7)
  int max_outer = 60;          ///< iterations on δz with several patches (default 60)
  int max_rebuilds = 6;        ///< rebuilds of the patches (grid edge reached, planes placed anew) (default 6)
  NormalCGOptions cg{1e-8, 2000};  ///< per-patch solver: ε ≤ 1e-8 of the interference (default)
  bool keep_pressure = false;  ///< keep each patch's element pressures in PatchResult::p (for --pressure-grid)
  bool valid(std::string* why) const;
};

/// Solve one case. `material.p_lim` finite caps the pressure (plastic model). Never throws for a
/// numerical reason: the status says what happened (`not_converged` with a message).
CaseResult solve_half_space(const ContactGeometry& G, const Material& material, double tY, double Q,
                            const HalfSpaceOptions& opt);

}  // namespace mh
