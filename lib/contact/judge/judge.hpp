#pragma once
// The judge (docs/status.md): takes a solved case and decides its status and its warnings, by
// one rule for every method and every entry point (the command line, batches, the C API and
// Python all reach it through solve_contact(), or call it directly for an approach given).
#include "contact/case_result.hpp"
#include "contact/options.hpp"
#include "geometry/contact_geometry.hpp"

namespace mh {

/// Two loaded ellipses close enough to interact elastically, which the multi-Hertzian method
/// solves each on its own (docs/method.md §9, the gauge-shoulder case): the lateral gap between
/// their edges on the rail is below d_comb, the distance at which the grid methods make the
/// regions one patch. `found` false when no pair is that close.
struct EllipseInteraction {
  bool found = false;
  int first = 0, second = 0;  ///< the ellipses (LoadedEllipse::ellipse) of the first such pair
  double edge_gap = 0;        ///< [m] lateral gap between their edges on the rail (negative: overlap)
};
EllipseInteraction interacting_ellipses(const CaseResult& r, double d_comb);

/// The Nadal ratio Y/Q of a case: its lateral over its vertical force of the wheel on the rail,
/// Fy / Fz (CaseResult's signs: positive towards the field side, as a flange contact pushes the
/// rail). NaN when Fz <= 0 (no force).
double y_over_q(const CaseResult& r);

/// The limits of the judge's vehicle-state warnings (docs/status.md): states of the wheelset, not
/// limits of a method, so informational (they never make a row outside_validity).
struct VehicleStateLimits {
  /// Y/Q above which a case carries `nadal_limit`: EN 14363's flange-climbing limit (Y/Q)_lim = 0.8
  /// for a wheel with 70° flange and μ = 0.36 (Nadal, as rounded there). The full Nadal limit,
  /// (tan β − μ) / (1 + μ tan β), depends on the flange angle β and the friction μ, which a
  /// normal-contact case does not know; this is the standard's fixed value.
  double nadal = 0.8;
  /// [m] The wheel rides on its flange tip when its main contact has passed the flange's steepest
  /// point (flange_climb) and its rolling radius is within this of the flange tip's (the largest
  /// of the wheel): `derailed` (docs/status.md gives the figures this margin is chosen from).
  double derail_margin = 2e-3;
};

/// [rad] How far the rail under a grid patch turns away from the patch's plane (its γ), either
/// side: at the row carrying the peak pressure (PatchResult::y_peak; a capped plateau's middle
/// row) and the larger of the first and last loaded rows (s_lo, s_hi), on the rail's contact
/// surface. The planar approach's evidence rows bound both (evidence.hpp). NaN without a peak.
struct PlanarTilt {
  double peak = NAN;
  double edge = NAN;
};
PlanarTilt planar_tilt(const PatchResult& P, const ContactGeometry& G);

/// The vehicle-state warnings of a solved case (any method): `nadal_limit` when Y/Q > lim.nadal,
/// `derailed` when the wheel rides on its flange tip (VehicleStateLimits::derail_margin). Rows
/// without an answer (is_failure) get none. judge_case() calls it; so does `auto` for the
/// multi-Hertzian rows it keeps.
void add_vehicle_state_warnings(CaseResult& r, const ContactGeometry& G, const VehicleStateLimits& lim = {});

/// The limits of the smoothing's uncertainty band (docs/status.md "smoothing_sensitive"): the
/// trust table's tolerances (docs/trust.md: 10 % in peak pressure, 15 % in area).
struct SmoothingBandLimits {
  double pmax = 0.10;  ///< [1] relative change of the peak pressure (default 10 %)
  double area = 0.15;  ///< [1] relative change of the total area (default 15 %)
};

/// The uncertainty band of a case solved on smoothed profiles (docs/profiles.md §7): r's
/// pmax_half_L … area_double_L from the same case solved with every smoothing length halved
/// (`half`) and doubled (`twice`); a solve without an answer (is_failure) leaves its two NaN.
/// When r has an answer and the peak pressure or the area of either moves by more than
/// `lim` relative to r's: the informational warning `smoothing_sensitive` with the largest
/// relative change of each (pmax_band, area_band) that crossed its limit. The status is not
/// touched (docs/status.md gives why the class is informational).
void judge_smoothing_band(CaseResult& r, const CaseResult& half, const CaseResult& twice,
                          const SmoothingBandLimits& lim = {});

/// The judge (docs/status.md): decide the status of a solved case r of the geometry G at t_Y
/// [m] with material mat and options opt, and add the warnings of its tests. Every method and
/// entry point calls it once per case (solve_contact(), and the C interface's approach-given
/// solve); `auto` judges its multi-Hertzian answer with the same tests before keeping it, so a
/// multi-Hertzian row is `ok` exactly when `auto` keeps it (or would, but for off_profile or
/// beyond_evidence: the grid methods share its evidence bound, so auto keeps the row, judged).
///  1. add_validity_warnings(): a plastic row of any method gets `beyond_evidence` for each
///     loaded ellipse or patch loaded beyond its method and law's evidence domain (evidence.hpp);
///     a multi-Hertzian row gets `interacting` for two ellipses closer
///     than d_comb and, when it passed every Hertz test (no non_hertzian, non_hertzian_excluded
///     or interacting warning) and converged, `non_hertzian:ellipse=K:gap_kink=R>0.1` for each
///     loaded ellipse with a corner of the gap inside its patch (hertz_validity.hpp, gap_kink).
///  2. add_vehicle_state_warnings(): nadal_limit and derailed (informational classes).
///  3. decide_status(): an `ok` row with a warning of a validity class becomes OutsideValidity,
///     its message naming the classes; then an `ok` or `outside_validity` row with the `derailed`
///     warning becomes Derailed (the wheel is off the rail, whatever the method's accuracy);
///     other statuses stay.
void judge_case(CaseResult& r, const ContactGeometry& G, const Material& mat, double tY, const MethodOptions& opt);

/// Step 1 of judge_case() alone: the warnings, the status untouched (auto reads them to decide
/// whether to hand the case on, and starts the grid methods from the unjudged row).
void add_validity_warnings(CaseResult& r, const ContactGeometry& G, const Material& mat, double tY,
                           const MethodOptions& opt);
/// Step 3 of judge_case() alone.
void decide_status(CaseResult& r);

/// The judge without the geometry (unit tests of the rule on hand-made results): the
/// `interacting` warning and decide_status(), no gap-corner test.
void judge_validity(CaseResult& r, double d_comb);

}  // namespace mh
