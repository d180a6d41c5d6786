#pragma once
// The inputs of a contact solve that are not geometry: the material, the method and every
// method's options, each with its documented defaults and a Ceres-style valid(why) that names the
// field, the value and the rule. A light header: the case-file reader includes it without
// pulling in a solver. SI throughout (lengths m, pressures Pa).
#include <algorithm>
#include <cmath>
#include <string>

#include "core/units.hpp"
#include "contact/tangential/tangential_options.hpp"

namespace mh {

/// Identical elastic materials for wheel and rail, plus the limit pressure of the plastic law.
struct Material {
  double E = 210e9;          ///< [Pa] Young's modulus of the wheel, and of the rail unless E_rail is set (default 210 GPa, steel)
  double nu = 0.28;          ///< [-] Poisson's ratio of the wheel, and of the rail unless nu_rail is set, in (0, 0.5) (default 0.28)
  double E_rail = NAN;       ///< [Pa] the rail's Young's modulus when it differs (NaN: same as E)
  double nu_rail = NAN;      ///< [-] the rail's Poisson's ratio when it differs (NaN: same as nu)
  double p_lim = INFINITY;   ///< [Pa] limit pressure of the plastic law (method.md §5); INFINITY = elastic
  /// [Pa] uniaxial yield stress σ_y of the wheel, and of the rail unless yield_rail is set (NaN: not
  /// given). Input (case file "material.yield_MPa", hertz --yield); the case file derives p_lim from
  /// it when p_lim_MPa is not given (docs/method.md §5). Also the basis of k = σ_y/√3 (RCF indicators).
  double yield = NAN;
  double yield_rail = NAN;   ///< [Pa] the rail's yield stress when it differs (NaN: same as yield)
  /// The plastic ellipse law of the multi-Hertzian method (method.md §5.1): false = the Hertz
  /// pressure capped at p_lim (Thornton's law for a sphere; the law of a user's own p_lim_MPa);
  /// true = the yield law, Hertz up to first yield p_y = kFirstYieldPerYield σ_y (softer body),
  /// slope kYieldLawSlope above it. Set when p_lim is derived from the yield stress; needs a
  /// yield stress and a finite p_lim (which the grid methods keep as their cap).
  bool yield_law = false;
  double yield_r() const { return std::isnan(yield_rail) ? yield : yield_rail; }
  /// [Pa] the yield stress of the softer body (NaN when none is given): the one that yields first
  /// in a frictionless contact of bodies of equal elasticity.
  double yield_min() const {
    if (std::isnan(yield)) return yield_rail;
    if (std::isnan(yield_rail)) return yield;
    return std::min(yield, yield_rail);
  }
  double Er() const { return std::isnan(E_rail) ? E : E_rail; }
  double nur() const { return std::isnan(nu_rail) ? nu : nu_rail; }
  /// [Pa] the paper's E/(1−ν²) of eqs. 2–3, 8 for identical bodies; for two materials the value
  /// that gives the same pair compliance: 2 / ((1−ν_w²)/E_w + (1−ν_r²)/E_r). Johnson's composite
  /// modulus of the pair is half of it: E*_J = 1 / ((1−ν_w²)/E_w + (1−ν_r²)/E_r).
  double E_star() const {
    if (std::isnan(E_rail) && std::isnan(nu_rail)) return E / (1 - nu * nu);  // identical bodies
    return 2.0 / ((1 - nu * nu) / E + (1 - nur() * nur()) / Er());
  }
  /// [1/Pa] combined compliance of the half-space solvers (docs/method.md §8):
  /// (1−ν_w²)/(π E_w) + (1−ν_r²)/(π E_r) = 2 / (π E_star).
  double compliance() const { return 2.0 / (units::pi * E_star()); }
  /// Ceres-style check: true when valid; otherwise false and *why names the field, the value and
  /// the rule (E > 0 and finite, 0 < ν < 0.5, p_lim > 0 or INFINITY; the same for the rail's).
  bool valid(std::string* why = nullptr) const;
};

/// [-] p_lim / σ_y when only the yield stress is given: the cap of the grid methods (half-space,
/// strips) (docs/method.md §5.1). It is the saturated peak pressure of the project's
/// elastic–perfectly-plastic FE (2.1–2.3 σ_y, tests/data/fe). The capped half-space with it, against
/// those FE rows (tests/unit/contact/test_grid_plastic_fe.cpp): within 5 % in area and approach
/// while p0_el/σ_y ≤ 2.1; above, approach within 2 %, area 6–12 % smaller (the FE pressure is
/// flattened from first yield on, a cap only truncates; p0_el/σ_y 1.5 … 3.9, a/b 1.3 … 9). The
/// multi-Hertzian ellipse uses the yield law instead (Material::yield_law).
inline constexpr double kPlimPerYield = 2.1;
/// [Pa] p_lim derived from a yield stress σ_y [Pa] (kPlimPerYield σ_y).
inline double p_lim_from_yield(double sigma_y) { return kPlimPerYield * sigma_y; }
/// The plastic law of a material from what was given (docs/method.md §5.1), the one home of the
/// rule that the case file, `hertz --yield` and the C interface share:
/// - a finite p_lim (the user's own limit pressure) takes precedence: the law capped at p_lim
///   (§5); a yield stress given with it is kept for k = σ_y/√3;
/// - otherwise, with a yield stress, p_lim = kPlimPerYield σ_y of the softer body (the grid
///   methods' cap) and yield_law = true (the multi-Hertzian ellipse's law);
/// - otherwise the material stays elastic (p_lim = INFINITY).
/// Call it only when the plastic model is wanted. Returns whether the material is plastic
/// (p_lim finite).
bool derive_plastic_law(Material& m);
/// [-] p_y / σ_y of the yield law: the Hertz peak at first yield below the surface (Johnson,
/// Contact Mechanics (1985) §6.2: p0 ≈ 1.6 σ_y for a circular contact, ν = 0.3; not fitted).
inline constexpr double kFirstYieldPerYield = 1.6;
/// [-] slope β of the yield law above first yield, p = p_y + β (p_H − p_y) (docs/method.md §5.1):
/// the one calibration, against the FE table tests/data/fe/ellip3d_R460x300_sy{350,500}.csv
/// (area and approach within 5 % for p0_el/σ_y ≤ 3.9, both yield stresses).
inline constexpr double kYieldLawSlope = 0.3;

/// The solution method of a case (case file "method"). Auto chooses per case (docs/method.md).
enum class Method { MultiHertzian, HalfSpace, Strips, Auto };
const char* to_string(Method m);
/// "multi-hertzian", "half-space", "strips", "auto"; throws std::invalid_argument otherwise.
Method parse_method(const std::string& s);

struct HertzValidityOptions {
  /// Largest b / min(|R_rxx|, |R_wxx|) (default 0.3: the half-space approximation needs the patch
  /// small against the radii; the conformal flange-root contacts of the Manchester reference
  /// reach 0.24).
  double max_b_over_R = 0.3;
  /// Largest relative error of the Hertz quadratic gap B b² at the patch edges y ± b, from the
  /// curvature of both profiles along the patch (default 0.5: the gap at the edge is off by half).
  double max_gap_error = 0.5;
  /// Largest relative error of the mean of the two edge gaps (default 0.1: a curvature sum off
  /// by 10 % on average over the patch moves the peak pressure by about 5 %, the accuracy the
  /// strip method is held to on single patches). On the Manchester sweep at 50 kN the cases
  /// whose multi-Hertzian peak or area is 15–50 % off CONTACT's reach 0.11–0.40; the others
  /// stay below 0.05 (docs/method.md §4).
  double max_gap_mean_error = 0.1;
  bool valid(std::string* why = nullptr) const;
};

struct MultiHertzOptions {
  double rtol = 1e-12;     ///< converged when |Σ N_i cos γ_i − Q| ≤ rtol·Q (default 1e-12)
  int max_iterations = 60; ///< Newton iterations (evaluations of eq. 10) before `not_converged` (default 60)
  bool exact_coefficients = false;  ///< Hertz m, n, ρ by the exact solve instead of the fast table (default: table)
  HertzValidityOptions validity;    ///< limits of the per-ellipse Hertz validity test (hertz_validity.hpp)
  /// [rad] The case's relative roll δ of the wheel against the rail (about x, pair frame, positive
  /// raising the wheel's field side; method.md §3.8): the candidates are those of the rolled
  /// wheel (ContactGeometry::candidates_at(t, δ)). Per case, set by the caller (the wheelset
  /// call, the C interface's roll_rad); default 0, the wheel upright. solve_contact hands it to
  /// the grid methods too (HalfSpaceOptions::roll, StripMethodOptions::roll). |δ| ≤ 50 mrad.
  double roll = 0;
  bool valid(std::string* why) const;
};

/// Options of solve_normal_approach / solve_normal_load (documented defaults).
struct NormalCGOptions {
  /// Tolerance on the convergence measure ε (NormalCGResult::error), stop when ε ≤ tol.
  ///   ε = max( √(Σ_{e∈F} h_e² / |F|),  max_{p_e=0} max(−h_e, 0),  max_{p_e=p_lim} max(h_e, 0) )
  ///       / (δ − min_e g_e)
  /// i.e. the RMS gap residual on the free contact set F = {0 < p < p_lim} together with the worst
  /// complementarity violation outside it, both relative to the rigid interference δ − min g
  /// (the approach beyond first touch; shift-invariant in g and δ). Default 1e-9: the gap residual
  /// is then 1e-9 of the interference, far below the O(dx/a) discretisation error.
  double tol = 1e-9;
  /// Upper bound on CG steps (each costs two FFT convolutions). Default 2000: Hertz on 60 × 50
  /// needs ~40–100; more than ~n^(1/2)·20 indicates trouble.
  int max_iterations = 2000;
  /// Ceres-style check: true when valid; otherwise false and *why names the field, its value and
  /// the rule (tol > 0 and finite, max_iterations ≥ 1).
  bool valid(std::string* why = nullptr) const;
};

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
  /// A patch with fewer elements across than kMinAcrossHalfSpace (grid_checks.hpp) is solved again
  /// on its own, at the load the case gave it, with dx and ds halved, until it has that many and
  /// its peak moves less than kPeakRtolHalfSpace; at most this many halvings (default 3: elements
  /// down to 1/8 of dx, ds). 0: no refinement (the patch is then under_resolved).
  int max_refinements = 3;
  NormalCGOptions cg{1e-8, 2000};  ///< per-patch solver: ε ≤ 1e-8 of the interference (default)
  bool keep_pressure = false;  ///< keep each patch's element pressures in PatchResult::p (for --pressure-grid)
  /// [rad] The wheel's roll δ against the rail (method.md §3.8): the gap is the rolled wheel's
  /// (WheelRailGap with a roll), the start the rolled multi-Hertzian solution. Set per case by
  /// solve_contact from MultiHertzOptions::roll; default 0, upright (the same bits). |δ| ≤ 50 mrad.
  double roll = 0;
  bool valid(std::string* why) const;
};

struct StripOptions {
  /// Gauss–Legendre points along x per strip for the influence matrix K_ij.
  /// The x-range of a strip is split at the collocation abscissa (where the
  /// kernel is singular/peaked), each side gets gauss_points/2 points in the
  /// variable theta (x = c + a sin theta), after subtracting the closed-form
  /// integral of the constant part. 16 (8 per side) keeps the influence
  /// coefficients within 1.4e-4 relative of a brute-force 2-D quadrature
  /// (self term, neighbours, strips 4 to 40 widths long; test "strip influence
  /// matches brute-force"), which is far below the discretisation error of
  /// the strips themselves; a 49-strip load-controlled solve then takes
  /// ~1.5 ms (4 approach iterations, -O2). Must be even and >= 2.
  int gauss_points = 16;
  double load_rtol = 1e-8;   ///< load control: stop when |N - N_target| <= load_rtol * N_target
  int max_iterations = 60;   ///< maximum approach (delta) iterations in load control
  int max_active_set = 50;   ///< maximum active-set passes (q >= 0) and plastic-set passes each
  /// A strip whose amplitude exceeds every neighbour's (within its band) by
  /// more than this factor is flagged as an outlier (not capped). 3: in an
  /// elliptic patch adjacent amplitudes ~ sqrt(1 - y^2/b^2) differ by far less
  /// than 3x unless a strip centre lies (within round-off) on the tip y = b,
  /// where the extent is ~0 while delta - g > 0 — the failure mode to flag.
  double outlier_factor = 3.0;
  /// Elastic coupling between strips. false keeps only the diagonal of K
  /// (each strip sees only its own pressure) — for diagnostics and tests.
  bool coupling = true;
  /// The strip extents: first estimated from the rigid gap (KPEC- and ANALYN-type rules, widened
  /// tails), then checked against the contact condition at the strip ends — the deformed gap
  /// must close there (docs/method.md §9 item 3). When the estimate's end-gap error (the
  /// load-weighted mean relative error of a² it implies, StripResult::end_gap_error) exceeds
  /// end_gap_tol, the extents are refined until the gap closes at every end. Default 0.05: an
  /// extent error of about 2.5 % is kept (half of the ±5 % peak-pressure budget of a single
  /// patch); 0 refines every patch (the most accurate, several times the cost); a large value
  /// (1e9) keeps every estimate. The decision is taken once per patch (StripWarmStart).
  double end_gap_tol = 0.05;

  /// Ceres-style check: false and a message naming field, value and rule.
  bool valid(std::string* why) const;
};

struct StripMethodOptions {
  double ds = 0.2e-3;          ///< [m] strip width (default 0.2 mm)
  double d_comb = 8e-3;        ///< [m] regions closer than this are one patch (as the half-space method)
  double margin = 1.25;        ///< strips cover the interpenetration at margin × the approach
  double ref_rtol = 0.02;      ///< planes re-placed when the approach moved by more than this
  double force_rtol = 1e-7;    ///< vertical force balance across patches
  int max_outer = 60;
  int max_passes = 12;         ///< placements of the patches (default 12: a strongly capped flange patch, Manchester t_Y = 8.5 mm, 100 kN, p_lim 900 MPa, needs 8; each costs about a millisecond)
  double x_curvature_step = 1e-3;  ///< [m] x of the second point of the gap's parabola along x (default 1 mm)
  /// As HalfSpaceOptions::max_refinements, with ds and kMinAcrossStrips, kPeakRtolStrips (default 3).
  int max_refinements = 3;
  StripOptions strips;         ///< the per-patch solver (quadrature, tolerances, outlier factor)
  bool keep_strips = false;    ///< keep every strip in PatchResult::strips (for --strips)
  double roll = 0;             ///< [rad] the wheel's roll against the rail, as HalfSpaceOptions::roll
  bool valid(std::string* why) const;
};

/// The options of every method, as the case file sets them.
struct MethodOptions {
  Method method = Method::MultiHertzian;
  MultiHertzOptions multi_hertzian;   ///< case file "solver"
  HalfSpaceOptions half_space;    ///< case file "half_space"
  StripMethodOptions strips;      ///< case file "strips"
  TangentialOptions tangential;   ///< case file "friction", "kinematics" | "creepages" (docs/tangential.md)
};

}  // namespace mh
