#pragma once
// The exact steady-rolling tangential solution of one solved half-space patch (docs/half_space.md,
// "Tangential steady rolling"): the patch's own grid and pressure (PatchResult of the normal
// solve), the creepages of that contact and μ, solved by HalfSpaceTangentialSolver. The
// creepages per contact come from the kinematics (lib/contact/tangential); this entry takes them
// as given, so that the caller decides where they come from.
#include "contact/case_result.hpp"
#include "contact/half_space/tangential_rolling.hpp"
#include "contact/options.hpp"
#include "contact/tangential/tangential_solve.hpp"

#include <memory>
#include <vector>

namespace mh {

/// One thread's tangential solvers for grid patches, kept from solve to solve: slot k serves the
/// k-th patch of a case, set up again for its grid in its own buffers
/// (HalfSpaceTangentialSolver::reset), so that once they have grown a solve allocates nothing
/// (the wheelset call's steps, docs/c-api.md). It carries nothing a result depends on.
struct TangentialPatchWorkspace {
  std::vector<std::unique_ptr<HalfSpaceTangentialSolver>> solvers;
  PatchResult raster;  ///< the strip method's pressure laid on a grid (solve.cpp)
  /// Slot k (made empty on first use).
  std::unique_ptr<HalfSpaceTangentialSolver>& slot(std::size_t k) {
    if (solvers.size() <= k) solvers.resize(k + 1);
    return solvers[k];
  }
};

/// Solve the tangential problem on `patch` (its nx × ns grid of dx × ds elements, element centres
/// at x0 + i dx, s0 + j ds relative to the reference point, pressure p) with the creepages `c`
/// (x rolling direction, y = the plane's s axis) and Coulomb's `mu`. Requires bodies of equal
/// elastic constants (Material without E_rail, nu_rail, or with the same values): the
/// decoupling of the normal and tangential problems holds only then; otherwise the result is
/// NotConverged with a message naming the rule. G = E / (2 (1 + ν)). Never throws for numerical
/// reasons. `keep` (optional): the tractions per element of a converged solve on the patch's grid
/// (traction_grid.hpp); cleared otherwise. `solver` (optional): a kept solver to set up for this
/// patch (made there when empty; the same bytes as a new one); null: one is built (allocates).
HalfSpaceTangentialResult solve_tangential_patch(const PatchResult& patch, const Material& material,
                                                 const Creepages& c, double mu,
                                                 const HalfSpaceTangentialOptions& options = {},
                                                 PatchTraction* keep = nullptr,
                                                 std::unique_ptr<HalfSpaceTangentialSolver>* solver = nullptr);

/// The half-space method's tangential step (docs/tangential.md, "Half-space"): every patch of a
/// half-space row whose creepages solve_tangential set (friction given) and whose pressure grid was
/// kept (HalfSpaceOptions::keep_pressure) is solved exactly; the case sums follow
/// (sum_tangential). A patch whose solve fails keeps solved = false (the row then carries
/// tangential_unsupported). No-op for other methods or without friction. keep_traction: each
/// patch's tractions per element into PatchResult::traction. `ws` (optional): the solvers kept.
void solve_tangential_patches(CaseResult& r, const Material& material, double mu, bool keep_traction = false,
                              TangentialPatchWorkspace* ws = nullptr);

}  // namespace mh
