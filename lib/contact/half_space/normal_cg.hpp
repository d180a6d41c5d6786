#pragma once
// Normal contact of two elastic half-spaces on one grid of boundary elements: the linear
// complementarity problem solved by the constrained conjugate-gradient method of
//  [PK] I. A. Polonsky, L. M. Keer, "A new numerical method for solving rough contact problems
//       based on the multi-level multi-summation and conjugate gradient techniques", Wear 231
//       (1999) 206–219, §3 (the constrained CG algorithm),
// extended to a pressure cap 0 ≤ p ≤ p_lim as in elastic–perfectly-plastic BEM codes
//  [J6] K. L. Johnson, Contact Mechanics, CUP 1985, ch. 6 (elastic–perfectly-plastic solids: the
//       mean contact pressure saturates at a flow pressure of about 3 Y, the hardness);
//  [AS] A. Almqvist, F. Sahlin, R. Larsson, S. Glavatskih, "On the dry elasto-plastic contact of
//       nominally flat surfaces", Tribology International 40 (2007) 574–579: half-space BEM contact
//       with the pressure truncated at the hardness (the "p ≤ p_lim" complementarity used here).
//
// Problem, per element e of the grid (g, u, δ in m; p, p_lim in Pa):
//     h_e = g_e + u_e − δ,   u = C p   (C: InfluenceGrid, the half-space operator)
//     0 ≤ p_e ≤ p_lim,
//     h_e = 0  where 0 < p_e < p_lim   (elastic contact),
//     h_e ≥ 0  where p_e = 0           (separation),
//     h_e ≤ 0  where p_e = p_lim       (plastic interpenetration allowed).
// g_e is the undeformed gap at the element centre (positive = separation), δ the rigid approach.
// p_lim = INFINITY is the purely elastic problem ([PK] exactly).
//
// The CG loop works on the free set F = {e : 0 < p_e < p_lim}; the bound sets {p = 0} and
// {p = p_lim} are fixed during a step. Elements that violate their bound (p = 0 with h < 0, or
// p = p_lim with h > 0) re-enter F with p_e = −τ h_e (resp. p_lim − τ h_e), τ the step of that
// iteration, and the conjugacy is reset (β = 0) — [PK]'s re-entry rule and conjugacy flag,
// mirrored for the cap. In load control δ is the mean of g + u over F ([PK]), the search
// direction is centred over F ([PK]) and after each step the load is restored by scaling
// the free pressures ([PK]); with a cap the scaling is repeated with newly capped elements
// fixed (a water-filling pass, at most n passes, usually one).
// Cost: one convolution a step (C t) while C p can be carried as C p − τ C t (scaled with the
// load), corrected by direct sums where a step moved a few elements off that path (projected onto
// a bound, re-entering; InfluenceGrid::add_sparse); two when it moved many (C p convolved
// afresh). ε is measured on a C p convolved from the final p before a solve is accepted.
#include <string>
#include <vector>

#include "contact/options.hpp"
#include "contact/half_space/influence.hpp"

namespace mh {


enum class GridStatus {
  Ok,            ///< converged: ε ≤ tol
  NoContact,     ///< δ ≤ min g (approach control) or N ≤ 0 (load control): p = 0
  NotConverged,  ///< max_iterations reached, invalid input, infeasible load or numerical trouble
};

struct NormalCGResult {
  GridStatus status = GridStatus::NotConverged;
  int iterations = 0;  ///< CG steps taken (0 when the initial guess already satisfies tol)
  int convolutions = 0;  ///< applications of C (the cost: one or two a step, see the CG loop)
  double N = 0;        ///< [N] total force dx·dy·Σp
  double delta = 0;    ///< [m] approach (given in approach control, found in load control)
  double error = 0;    ///< final ε (NormalCGOptions::tol); NaN for invalid input
  int n_contact = 0;   ///< elements with p > 0
  int n_plastic = 0;   ///< elements with p == p_lim
};

/// The solvers' work vectors (nx·ny values each), kept by a caller that solves many grids on one
/// thread (the half-space method's workspace): a call then allocates nothing once they have grown
/// to the largest grid. The forms without it make their own per call. Contents between calls:
/// none that matters (every call sets what it reads).
struct NormalCGWorkspace {
  std::vector<double> u, h, t, Ct;       ///< the CG loop: C p, the residual gap, direction, C t
  std::vector<unsigned char> in_free;    ///< the free set F of the CG loop
  std::vector<int> moved;                ///< elements a step moved off −τ t ...
  std::vector<double> moved_dp;          ///< ... and by how much more [Pa]
  std::vector<double> guess, u0, sorted; ///< capped load control: the caller's guess, C p of it; g sorted (also the cold start)
};

/// Approach control: δ given [m], find p [Pa]. g: nx·ny undeformed gaps [m] (index ix + nx·iy).
/// p holds the initial guess on input (clipped to [0, p_lim]; all zeros allowed — then the guess
/// is the Hertzian shape of this approach, √(δ/2 − (g − min g)) on the gap stretched to Hertz's
/// aspect, scaled by least squares to the interference (normal_cg.cpp, hertz_shape); a previous
/// solution is a warm start) and the solution on output. p_lim > 0 [Pa] or INFINITY (elastic).
/// Never throws for numerical reasons: returns NotConverged (p unchanged for invalid input:
/// options invalid, p_lim ≤ 0 or NaN, δ not finite, a g not finite).
/// δ ≤ min g: NoContact, p = 0. Deterministic (same bytes every run). Allocates its work vectors
/// (5 of nx·ny values) once per call; the form with a NormalCGWorkspace takes them from it (the
/// same bytes).
NormalCGResult solve_normal_approach(const InfluenceGrid& C, const double* g, double delta,
                                     double p_lim, double* p, const NormalCGOptions& options = {});
NormalCGResult solve_normal_approach(const InfluenceGrid& C, const double* g, double delta, double p_lim, double* p,
                                     const NormalCGOptions& options, NormalCGWorkspace& ws);

/// Load control ([PK]'s original form): total force N [N] given, find p [Pa] and δ [m].
/// p as in solve_normal_approach; an all-zero guess becomes the Hertzian pressure of the load on
/// this gap, p ∝ √(δ/2 − (g − min g)) with δ from one probe of the grid's compliance (normal_cg.cpp,
/// hertz_shaped_guess; [PK] §3's uniform pressure where the probe carries nothing).
/// With a finite p_lim: first the elastic solution (returned as it is when its peak stays ≤ p_lim:
/// the same bytes as p_lim = INFINITY), else a safeguarded secant (Illinois) on δ over capped
/// solve_normal_approach solves, warm-started, from max(δ_el, δ_rp) (δ_rp: the rigid–perfectly-
/// plastic bound, p_lim·dx·dy·#{g < δ} = N), stopped at |N(δ) − N| ≤ tol·N, then [PK]'s load
/// scaling from there (exact N, the same ε). [PK]'s scaling alone does not converge when most of
/// the contact is capped (elements jump between 0 and p_lim every step). iterations counts every
/// CG step of all these solves; max_iterations bounds their total. N ≤ 0: NoContact, p = 0,
/// δ = min g. N > p_lim·nx·ny·dx·dy (the grid cannot carry it): NotConverged. On success
/// dx·dy·Σp = N to rounding.
NormalCGResult solve_normal_load(const InfluenceGrid& C, const double* g, double N, double p_lim,
                                 double* p, const NormalCGOptions& options = {});
/// The same with the work vectors of `ws` (see NormalCGWorkspace; the same bytes).
NormalCGResult solve_normal_load(const InfluenceGrid& C, const double* g, double N, double p_lim, double* p,
                                 const NormalCGOptions& options, NormalCGWorkspace& ws);

}  // namespace mh
