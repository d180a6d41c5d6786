#pragma once
// The tangential problem of a solved case (docs/tangential.md): the creepages of each contact
// (from the kinematics or as given) and FASTSIM on each loaded multi-Hertzian ellipse. The grid
// methods (half-space, strips) do not solve it yet: their contacts keep TangentialResult::solved
// false (NaN columns) and the case carries the warning `tangential_unsupported`.
#include "contact/case_result.hpp"
#include "contact/options.hpp"

namespace mh {

/// Kalker's combined shear modulus G and Poisson's ratio ν of the two bodies (Kalker 1990 §1.6:
/// 1/G = (1/G1 + 1/G2)/2, ν/G = (ν1/G1 + ν2/G2)/2).
void combined_elastic(const Material& mat, double& G, double& nu);

/// Fill r's tangential results when opt.enabled() (nothing otherwise). t_Y [m]: the case's.
void solve_tangential(CaseResult& r, const Material& mat, double tY, const TangentialOptions& opt);

}  // namespace mh
