#pragma once
// The tangential problem of a solved case (docs/tangential.md): the creepages of each contact
// (from the kinematics or as given) and FASTSIM on each loaded multi-Hertzian ellipse. A grid
// patch gets its creepages here; the half-space method solves its patches exactly afterwards
// (contact/half_space/tangential_patch.hpp, solve_tangential_patches), the strip method its
// patches on their strips' pressure (contact/solve.cpp); a patch whose solve fails keeps
// TangentialResult::solved false (NaN columns) and the case carries `tangential_unsupported`.
#include "contact/case_result.hpp"
#include "contact/options.hpp"

namespace mh {

/// Kalker's combined shear modulus G and Poisson's ratio ν of the two bodies (Kalker 1990 §1.6:
/// 1/G = (1/G1 + 1/G2)/2, ν/G = (ν1/G1 + ν2/G2)/2).
void combined_elastic(const Material& mat, double& G, double& nu);

/// [-] |sin γ| from which an ellipse's FASTSIM marches its load slope when opt.fastsim.load_slope
/// asks for it (γ ≥ 5.7°): below, its creep force's vertical share Fy sin γ is small enough to
/// be aimed from its saturation (contact/solve.cpp, equilibrium_slope).
constexpr double kLoadSlopeSinGamma = 0.1;

/// Fill r's tangential results when opt.enabled() (nothing otherwise). t_Y [m]: the case's.
void solve_tangential(CaseResult& r, const Material& mat, double tY, const TangentialOptions& opt);

/// The case sums of r.tangential from its contacts' results (forces on the rail): solved when
/// every loaded ellipse and patch is. mu: the friction coefficient.
void sum_tangential(CaseResult& r, double mu);

}  // namespace mh
