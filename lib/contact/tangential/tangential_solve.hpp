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

/// One full FASTSIM solve of a row's loaded ellipses, kept by the vertical equilibrium
/// (contact/solve.cpp) as an anchor of extrapolate_tangential (below). Fixed size: no allocation.
struct CreepAnchors {
  static constexpr int kMax = 8;  ///< ellipses kept; a row with more is not anchored
  int n = -1;                     ///< ellipses kept (-1: none)
  int ellipse[kMax] = {};         ///< the ellipse numbers (LoadedEllipse::ellipse), in r.loaded's order
  double N[kMax] = {};            ///< [N] their normal forces
  TangentialResult t[kMax];       ///< their FASTSIM results
  /// Keep r's ellipses when r is an elastic-or-plastic multi-Hertzian row without grid patches,
  /// its tangential problem solved, at most kMax ellipses; else forget (n = -1).
  void take(const CaseResult& r);
};

/// [-] The bound on the curvature of a creep force in its load at fixed creepages that
/// extrapolate_tangential (below) assumes: |d²F/dN²| ≤ kCreepCurvature μ/N. By Kalker's
/// similarity (fastsim.hpp) F = μN Φ(ξ N^(−1/3), η N^(−1/3), φ): in the linear limit F ∝ N^(2/3),
/// |F''| = (2/9) F/N² ≤ (2/9) μ/N; in full slip F = μN, F'' = 0; between them, on Johnson and
/// Vermeulen's saturation curve Φ(u) = u − u²/3 + u³/27, at most μ/(6N). Twice the largest:
/// 4/9. FASTSIM's own curvature against it: tests/unit/contact/test_creep_extrapolation.cpp.
constexpr double kCreepCurvature = 4.0 / 9.0;

/// The creep forces of r's loaded ellipses (r solved again by the normal solver at a load close
/// to a1's) without FASTSIM: each ellipse's Fx, Fy, Mz linear in its own N through the two full
/// solves a0 and a1 (the secant of F_i(N_i) extrapolated from a1), the adhesion fraction a1's;
/// then the case sums. Used only where the extrapolation's error, ½ |F''| |N − N1| |N − N0|
/// ≈ ½ kCreepCurvature μ |N − N1| |N1 − N0| / N1, is at most tol μ N_i on every ellipse: what
/// the vertical equilibrium's tolerance tol on the load already leaves open (N_i known to about
/// tol N_i, F_i to about tol μ N_i). Returns false, r's tangential results untouched, where that
/// does not hold or the ellipses differ (another ellipse loaded, or one unloaded): the caller
/// solves FASTSIM then.
bool extrapolate_tangential(CaseResult& r, const CreepAnchors& a0, const CreepAnchors& a1, double mu, double tol);

/// The case sums of r.tangential from its contacts' results (forces on the rail): solved when
/// every loaded ellipse and patch is. mu: the friction coefficient.
void sum_tangential(CaseResult& r, double mu);

}  // namespace mh
