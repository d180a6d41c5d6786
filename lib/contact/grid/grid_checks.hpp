#pragma once
// The physical checks of a solved grid result (half-space §8 and strips §9 of docs/method.md),
// in one place for both grid methods (docs/status.md, "Physical checks of a grid result"). A grid
// solver's `ok` says its iteration stopped; these say whether what it stopped on is a contact
// solution that can be trusted. Each failed check adds a warning of a validity class, so the row
// becomes `outside_validity` (the judge, contact/judge/judge.hpp):
//
//   force_balance   Σ_k N_k cos γ_k, re-summed from the reported patches, differs from Q by more
//                   than kForceBalanceRtol·Q (eq. 10).
//   complementarity an element's pressure is negative or above p_lim, or the deformed gap
//                   h = g + u − δ violates the contact condition (h = 0 where 0 < p < p_lim,
//                   h ≥ 0 where p = 0, h ≤ 0 where p = p_lim) by more than kGapRtol times the
//                   patch's approach (half-space; Johnson, Contact Mechanics §5.9, the conditions
//                   of normal contact); for the strips, the estimated strip extents leave an
//                   end-gap error above StripOptions::end_gap_tol without being refined.
//   pressure_spike  (half-space) the patch's peak stands on a single element (pressure_spike.hpp).
//                   The strip method's isolated peak is its own strip_outlier (strips.hpp).
//   under_resolved  a patch with fewer elements (strips) across its narrow direction than the
//                   method needs for its stated peak accuracy (elements_across below; the minimum
//                   from the convergence study on Hertz patches, tests/unit/contact/
//                   test_grid_resolution.cpp, docs/half_space.md "Elements across a patch").
//   contact_hole    an element (strip) that carries no pressure although the undeformed bodies
//                   overlap there by more than kGapRtol times the patch's approach, and that is
//                   enclosed by loaded elements: along its row (x) on both sides AND along its
//                   column (s) on both sides. Elastic
//                   displacement is smooth on the scale of the patch, so such an element can
//                   only be free when the gap has a feature narrower than the patch there (a
//                   ridge of a measured profile, a kink); the pressure next to it is then set by
//                   the feature's sharpness, that is by the profile's sampling, not by the
//                   contact. Half-space only: enclosure along s alone is not a hole. The strip
//                   method sees a row only at its centre, and a free strip between loaded ones is
//                   a lateral separation, which is physical: Manchester pair, t_Y = 5 mm, 50 kN,
//                   the tread and gauge-shoulder contacts in one patch are 5.4 mm apart where the
//                   undeformed bodies overlap by up to 32.6 µm (0.58 of the approach); the
//                   half-space solution has the same free band, with no element loaded across it.
// A peak pressure that a steel contact "cannot have" is deliberately NOT a check: the elastic
// answer has no such bound, and a spike or a hole is what makes a peak meaningless.
#include <cmath>
#include <cstddef>
#include <vector>

#include "contact/case_result.hpp"

namespace mh {

/// |Σ N_k cos γ_k − Q| ≤ kForceBalanceRtol·Q. The solvers close the balance to 1e-7 (half-space,
/// HalfSpaceOptions::force_rtol) or better; 1e-5 is the strip method's own acceptance.
constexpr double kForceBalanceRtol = 1e-5;
/// Gap tolerance of the complementarity and hole checks, relative to the patch's approach (its
/// largest rigid interpenetration). A 1 % error of the gap moves a Hertz-like peak by about
/// 0.5 % (p0 ∝ δ^1/2), well inside the methods' accuracy; a converged CG solve
/// (NormalCGOptions::tol = 1e-9) violates the conditions by orders of magnitude less.
constexpr double kGapRtol = 1e-2;

/// The accuracy each grid method states: the half-space's peak pressure 2 % (its targets against
/// CONTACT, docs/half_space.md), the strips' peak 5 % and area 10 % (their single-region
/// tolerances, docs/strips.md).
constexpr double kPeakRtolHalfSpace = 0.02, kPeakRtolStrips = 0.05, kAreaRtolStrips = 0.10;
/// The fewest elements (strips) across a patch's narrow direction (elements_across) that reach
/// that accuracy on Hertz patches resolved by 2 … 24 elements, the grid shifted by 0, 1/4 and 1/2
/// element against the patch (tests/unit/contact/test_grid_resolution.cpp, which asserts that
/// these counts reach it and the next smaller count of the study does not). Half-space: 8 (peak
/// 1.5 %; 6 gives 2.6 %); its area, counted in whole elements, is still 11 % off at 8 and needs 16
/// for 4 %, a limit of the element count that this minimum does not cover. Strips: 4 (peak 2.7 %,
/// area 5.5 %; 3 gives an area 10.6 % off).
constexpr int kMinAcrossHalfSpace = 8;
constexpr int kMinAcrossStrips = 4;

/// What a grid method hands to the checks for one reported patch (the k-th of CaseResult::patches).
struct PatchCheckInput {
  int nx = 0, ns = 0;            ///< elements along x and s (strips: nx = 1, ns strips)
  std::vector<double> p;         ///< [Pa] pressure per element, index i + nx j (strips: the strip's peak, 0 unloaded)
  std::vector<double> overlap;   ///< [m] rigid interpenetration δ − g per element (> 0: the undeformed bodies overlap)
  double approach = 0;           ///< [m] the patch's approach (its largest overlap): the scale of the gap tolerance
  double p_lim = INFINITY;       ///< [Pa] the pressure cap (INFINITY: elastic)
  /// [m] the largest violation of the contact condition by the deformed gap (half-space); NaN:
  /// not measured (strips).
  double gap_violation = NAN;
  double end_gap_error = NAN;    ///< strips: the estimate's end-gap error; NaN for the half-space method
  double end_gap_tol = NAN;      ///< strips: StripOptions::end_gap_tol
  bool refined = false;          ///< strips: the extents were refined (the end gap closed at every end)
  int min_across = 0;            ///< fewest elements across the patch (kMinAcross*); 0: not checked
  double element = 0;            ///< [m] the element size across (ds), named in the under_resolved warning
  /// After a local refinement: |Δpmax| / pmax between the last two grids (NaN: not refined), and
  /// the method's peak tolerance it must settle within (kPeakRtol*).
  double peak_change = NAN;
  double peak_rtol = NAN;
  bool spike_check = false;      ///< look for a single-element peak (half-space; strips have strip_outlier)
  bool hole_check = false;       ///< look for a contact hole (half-space: rows and columns of elements)
  double y_ref = 0, gamma = 0;   ///< [m], [rad] the patch plane (to name rail y in warnings)
  double s0 = 0, ds = 0;         ///< [m] s of the first element row and the row spacing
};

/// A zero-pressure element enclosed by loaded ones where the bodies overlap (the rule above).
/// The number of elements across a patch in its narrow direction: the longest run of loaded
/// elements along s in any column, and (half-space, nx > 1) along x in any row; the smaller of the
/// two. Strips (nx = 1) are exact along x (a semi-ellipse per strip), so only s counts. A run, not
/// the extent: a patch made of two narrow bands is as narrow as its widest band.
int elements_across(const std::vector<double>& p, int nx, int ns);

struct ContactHole {
  int elements = 0;  ///< hole elements
  int i = -1, j = -1;  ///< the one with the largest overlap
  double overlap = 0;  ///< [m] its overlap
};
ContactHole find_contact_hole(const PatchCheckInput& in);

/// The checks above on a solved grid result r (status Ok; other statuses are left alone), with
/// in[k] describing r.patches[k]. Adds the warnings; does not change the status (judge_validity
/// does, once, for every method).
void check_grid_result(const std::vector<PatchCheckInput>& in, double Q, CaseResult& r);
/// The same on in[0 … n).
void check_grid_result(const PatchCheckInput* in, std::size_t n, double Q, CaseResult& r);

/// The end of a grid method's case body, once for both methods: the reported patches numbered
/// 1 … n in their order, n_contacts, the residual (Fz − Q)/Q, and the method's convergence rule on
/// it: an ok row whose |residual| exceeds `residual_tol` did not settle the load (not_converged,
/// "force balance residual R", the warning not_converged_load:residual=R>tol); then check_grid_result, whose force_balance check holds the rows
/// left ok to kForceBalanceRtol. `residual_tol`: the half-space method 10 force_rtol across
/// several patches (one patch carries the load by its own solve) and no bound on one patch, so
/// that force_balance judges it; the strip method kForceBalanceRtol.
void close_grid_case(const std::vector<PatchCheckInput>& in, double Q, double residual_tol, CaseResult& r);
/// The same on in[0 … n) (a workspace's inputs, grid/patch_driver.hpp GridCaseWorkspace).
void close_grid_case(const PatchCheckInput* in, std::size_t n, double Q, double residual_tol, CaseResult& r);

/// A grid result whose status is not_converged carries no pressures that look like an answer
/// (docs/outputs.md, "Failed rows"): its last iterate's approach, forces and residual stay (they
/// say how far it is from equilibrium), its peak pressure and area become NaN (empty cells, null)
/// and its patches are dropped (no patches.csv, pressure.csv or strips.csv rows); n_contacts stays.
void withhold_unconverged_pressures(CaseResult& r);

}  // namespace mh
