#pragma once
// The result of one case, shared by every method (multi-Hertzian, half-space, strips): a status,
// the case summary every method fills (forces, approach, maximum pressure, area, number of
// contacts), and the method's own detail: loaded ellipses (multi-Hertzian) or contact patches
// (grid methods). The output schema (lib/output/case_tables) is written from this struct alone.
// Its status and warnings are decided by the judge (contact/judge/judge.hpp).
#include <cmath>
#include <string>
#include <vector>

#include "contact/ellipse/ellipse_law.hpp"
#include "contact/options.hpp"
#include "contact/ellipse/hertz_validity.hpp"
#include "contact/judge/status.hpp"
#include "contact/tangential/tangential_types.hpp"
#include "contact/tangential/traction_grid.hpp"
#include "geometry/contact_geometry.hpp"

namespace mh {

/// Damage and wear of one contact (docs/outputs.md "Damage and wear columns"), filled once per
/// case by damage_step (contact/rcf/contact_damage.hpp); NaN where its tangential problem is not
/// solved.
struct ContactDamage {
  double traction = NAN;        ///< [-] the actual traction coefficient |F|/N
  double damage = NAN;          ///< [-] Burstow damage per axle passage (burstow_damage)
  double wear_rate = NAN;       ///< [kg/m³] USFD wear rate over the contact's area A (usfd_wear)
  double wear_per_metre = NAN;  ///< [kg/m] mass worn per metre rolled
};

/// The sums over a case's contacts (one wheel's passage): NaN unless every contact's tangential
/// problem is solved (TangentialSums::solved).
struct CaseDamage {
  double damage = NAN;          ///< [-] Σ Burstow damage per axle passage
  double wear_per_metre = NAN;  ///< [kg/m] Σ mass worn per metre rolled
};

/// One loaded ellipse of a multi-Hertzian solution.
struct LoadedEllipse {
  int ellipse = 0;          ///< 1-based index of the potential ellipse
  CandidateGeom g;          ///< its strip (interpolated at the case's t_Y)
  double cos_gamma = 1, sin_gamma = 0;  ///< cos γ, sin γ of g.gamma, as the solver used them (eqs. 10–11)
  double A = 0, B = 0;      ///< [1/m] (eq. 1)
  HertzCoefficients c;
  double h_y = INFINITY;    ///< [m] yield penetration of its law (docs/method.md §5); INFINITY when elastic
  EllipseState s;           ///< h0, N, a, b, p0, ... (ellipse_law.hpp)
  HertzValidity validity;   ///< Hertz assumptions checked on this patch (hertz_validity.hpp)
  double z_r = 0;           ///< [m] rail profile z at y_r (the rail's frame, as in profiles.csv)
  double z_w = 0;           ///< [m] wheel profile z at y_w (the wheel's frame, as in profiles.csv)
  TangentialResult t;       ///< the tangential problem (FASTSIM on this ellipse; solved false: not asked)
  ContactDamage damage;     ///< damage and wear from t (contact/rcf/contact_damage.hpp, damage_step)
};

/// One contact patch of a grid method (half-space, strips): its own tangent plane (docs/method.md §8).
/// One strip of a strip-method patch (docs/method.md §9).
struct StripOut {
  double s = 0;         ///< [m] lateral coordinate of the strip centre in the patch plane
  double y_r = 0;       ///< [m] rail y of the strip centre (y_ref + s cos γ)
  double c = 0;         ///< [m] x of its pressure centre
  double a = 0;         ///< [m] half-length (plastic: lengthened)
  double q = 0;         ///< [Pa] amplitude of the semi-ellipse (plastic: elastic amplitude, flat top at p_lim)
  bool plastic = false;
};

struct PatchResult {
  int patch = 0;            ///< 1-based, in increasing rail y
  double y_r = 0;           ///< [m] contact reference point on the rail (the patch plane's origin)
  double z_r = 0;           ///< [m] its height on the rail profile
  double y_w = 0;           ///< [m] the facing wheel-profile lateral coordinate
  double gamma = 0;         ///< [rad] contact angle of the patch plane
  double r_roll = 0;        ///< [m] wheel rolling radius at the reference point
  double N = 0;             ///< [N] normal force Σ p dx ds
  double pmax = 0;          ///< [Pa] largest element pressure
  double area = 0;          ///< [m²] elements in contact × dx ds
  double length_x = 0;      ///< [m] extent of the contact along x (element centres, + one element)
  double width_s = 0;       ///< [m] extent along s in the patch plane (+ one element)
  double s_lo = 0, s_hi = 0;  ///< [m] s of the first and last element row (strip) in contact
  double approach = 0;      ///< [m] normal approach of the patch, δz cos γ minus the plane's offset
  double x_centroid = 0;    ///< [m] pressure centroid relative to the reference point, along x
  double s_centroid = 0;    ///< [m] ... and along s (rail y ≈ y_r + s cos γ)
  double plastic_area = 0;  ///< [m²] elements at the pressure cap (plastic model)
  double capped_load = 0;   ///< [N] load carried by those elements
  int n_elements = 0;       ///< elements in contact
  /// [m] The elastic Hertz semi-axes of this patch's N on the curvatures of the elastic
  /// multi-Hertzian ellipse inside it (contact/grid/patch_elastic.hpp; NaN: none): the ellipse of
  /// the RCF indicators, whatever the law.
  double a_el = NAN, b_el = NAN;
  /// Elements (strips) across the patch in its narrow direction (grid_checks.hpp, elements_across);
  /// fewer than the method's minimum: the under_resolved warning.
  int elements_across = 0;
  /// [m] Rail y of the element (strip) carrying the peak pressure, a capped plateau's middle row
  /// (grid_checks.cpp; NaN: none): where the judge measures the plane's tilt against the rail
  /// (evidence.hpp).
  double y_peak = NAN;
  /// [m] the element size (strip width) across the patch: the method's dx, ds, or smaller where the
  /// patch was refined locally (grid_checks.hpp, kMinAcross*).
  double element = 0;
  int iterations = 0;       ///< solver iterations summed over the outer loop
  /// Strip method: the end-gap error of the estimated strip extents (StripOptions::end_gap_tol),
  /// and whether the extents were refined to close the gap at every strip end. NaN / false for
  /// the other methods.
  double end_gap_error = NAN;
  bool refined = false;
  // Pressure on the patch grid (for --pressure-grid): nx × ns values, x fastest, element centres
  // at x0 + i dx, s0 + j ds (plane coordinates relative to the reference point).
  int nx = 0, ns = 0;
  double dx = 0, ds = 0, x0 = 0, s0 = 0;
  std::vector<double> p;    ///< [Pa]
  std::vector<StripOut> strips;  ///< strip method: the loaded strips (kept for --strips)
  /// The tangential problem of this patch (exact steady rolling on its pressure; solved false: not asked or failed).
  TangentialResult t;
  ContactDamage damage;     ///< damage and wear from t (contact/rcf/contact_damage.hpp, damage_step)
  /// The tractions per element of t's solve (TangentialOptions::keep_traction only; empty otherwise).
  PatchTraction traction;
};

/// The tangential problem summed over a case's contacts (docs/tangential.md). Forces ON THE RAIL,
/// as the case's normal forces (docs/outputs.md, Conventions).
struct TangentialSums {
  bool asked = false;      ///< friction given: the columns are written (empty where not solved)
  bool solved = false;     ///< every contact's tangential problem solved
  double Fx = NAN;         ///< [N] Σ Fx_i on the rail, along the rolling direction
  double Fy_creep = NAN;   ///< [N] Σ Fy_i cos γ_i on the rail: the creep forces' lateral component, towards the field side
  double Mz = NAN;         ///< [N m] Σ Mz_i on the rail, each about its own contact normal
  double F_over_muN = NAN; ///< [-] Σ |F_i| / (μ Σ N_i): the friction used
  /// [N] Σ Fy_i sin γ_i with Fy_i the lateral creep force ON THE WHEEL (− that on the rail): the
  /// creep forces' share of the vertical load the rail carries, downwards (docs/tangential.md,
  /// "Vertical equilibrium"). The case's Fz is Σ N_i cos γ_i + Fz_creep.
  double Fz_creep = NAN;
};

struct CaseResult {
  CaseStatus status = CaseStatus::Ok;
  Method method = Method::MultiHertzian;  ///< the method that solved it (never Auto)
  std::string message;               ///< why, when not ok
  std::vector<Warning> warnings;     ///< as data (contact/judge/status.hpp); text only where written
  /// [m] multi-Hertzian only: the vertical VIRTUAL penetration δz of eq. 11 (h0 = δ/2 for a
  /// sphere), from the geometric contact position. NaN for the grid methods.
  double dz = 0;
  /// [m] the rigid vertical approach of the wheel from first contact (CONTACT's z_ws difference);
  /// multi-Hertzian: max over loaded ellipses of δ_i / cos γ_i + gap_i with δ_i the true Hertz approach.
  double approach = 0;
  int iterations = 0;
  double residual = 0;    ///< (Σ N_i cos γ_i − Q) / Q at the end
  double Fz = 0, Fy = 0;  ///< [N] Σ N_i cos γ_i and Σ N_i sin γ_i (lateral, towards the field side)
  double pmax = 0;        ///< [Pa] the largest contact pressure of the case (capped in plastic mode)
  double area = 0;        ///< [m²] total contact area
  int n_contacts = 0;     ///< loaded ellipses or patches
  std::vector<LoadedEllipse> loaded;  ///< multi-Hertzian: in increasing ellipse index
  std::vector<PatchResult> patches;   ///< grid methods: in increasing rail y
  /// The smoothing's uncertainty band (docs/profiles.md §7 "Uncertainty band"): the same case's
  /// peak pressure [Pa] and total area [m²] solved again with every contact smoothing length
  /// halved and doubled, both profiles together (judge.hpp, judge_smoothing_band). NaN where
  /// not computed: nothing smoothed for contact, the band turned off, a multi-Hertzian run, or
  /// that solve without an answer.
  double pmax_half_L = NAN, pmax_double_L = NAN, area_half_L = NAN, area_double_L = NAN;
  TangentialSums tangential;          ///< friction given: the creep forces (docs/tangential.md)
  CaseDamage damage;                  ///< friction given: Σ damage and wear (contact/rcf/contact_damage.hpp)
  /// FASTSIM's cells of each loaded ellipse, in the order of `loaded` (TangentialOptions::keep_traction
  /// only; empty otherwise, and an ellipse without a tangential solve has empty cells).
  std::vector<EllipseTraction> ellipse_traction;
};

/// Reset r to a fresh CaseResult's values, its message and vectors keeping their capacity (the
/// solvers' forms that fill a caller's result: no allocation once it has grown).
inline void reset_case_result(CaseResult& r) {
  r.status = CaseStatus::Ok;
  r.method = Method::MultiHertzian;
  r.message.clear();
  r.warnings.clear();
  r.dz = r.approach = r.residual = 0;
  r.iterations = 0;
  r.Fz = r.Fy = r.pmax = r.area = 0;
  r.n_contacts = 0;
  r.pmax_half_L = r.pmax_double_L = r.area_half_L = r.area_double_L = NAN;
  r.tangential = TangentialSums{};
  r.damage = CaseDamage{};
  r.loaded.clear();
  r.patches.clear();
  r.ellipse_traction.clear();
}

/// Room in r for a usual row: 16 warnings, 8 contacts (ellipses or patches), a 256-character
/// message. Results that trade places by swapping (auto's rows and the caller's, the half-space
/// method's elastic pass) are given it first, so that trading places grows nothing; a larger row
/// grows its result once.
inline void reserve_row(CaseResult& r) {
  r.warnings.reserve(16);
  r.loaded.reserve(8);
  r.patches.reserve(8);
  r.message.reserve(256);
}

}  // namespace mh
