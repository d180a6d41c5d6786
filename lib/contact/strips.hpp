// Semi-Hertzian strip solver with elastic coupling between strips, for one
// contact patch (no yaw).
//
// Method: every lateral strip carries a semi-elliptic pressure along x,
//   p_i(x) = q_i sqrt(1 - ((x - c_i)/a_i)^2),  uniform across the strip width ds.
// Strip extents are the union of a KPEC-type estimate (equivalent ellipse per
// lateral band; Kik & Piotrowski 1996, Piotrowski & Kik 2008) and an
// ANALYN-type estimate (local Hertz solution per strip; Sichani et al. 2014).
// Amplitudes follow from collocation at the strip centres with the full
// Boussinesq influence matrix (Johnson, Contact Mechanics §3.2), an active set
// for q >= 0, an optional plastic cap p_lim, and load control on the approach;
// strips too short for the interpenetration the others leave at their centres are
// widened (docs/method.md §9 item 7).
//
// Interpretation used for the extent estimates: within a lateral band the
// approach is measured from the band's deepest gap g0 (delta_b = delta - g0,
// gaps g - g0). For a band touching g = 0 this is the specification verbatim;
// for a shallower band it keeps both estimates exact for an elliptic patch.
// The collocation right-hand side is always the absolute delta - h(c_i, s_i).
//
// Units: SI throughout (m, Pa, N). Never throws on numerical trouble; the
// result carries a status.
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace mh {

/// Undeformed gap of one contact patch, sampled on lateral strips.
/// Row i: h(x, s_i) = g_i + A_i (x - xc_i)^2; interpenetration at approach
/// delta is delta - h(x, s).
struct StripGeometry {
  double ds = 0.0;         ///< [m] strip width (lateral, in the contact plane)
  std::vector<double> s;   ///< [m] lateral coordinate of each strip centre, increasing, uniform spacing ds
  std::vector<double> g;   ///< [m] minimum undeformed normal gap of the row at s_i, before approach
  std::vector<double> A;   ///< [1/m] gap curvature along x (A_i > 0)
  std::vector<double> xc;  ///< [m] x of the row's minimum (0 without yaw)
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

enum class StripStatus { Ok, NoContact, NotConverged, InvalidInput };

/// One loaded strip.
struct StripState {
  double s = 0.0;        ///< [m] lateral coordinate of the strip centre
  double c = 0.0;        ///< [m] x of the pressure centre
  double a = 0.0;        ///< [m] half-length (for plastic strips: lengthened a', at most to the overlap)
  double a_elastic = 0.0;  ///< [m] half-length before the plastic lengthening (= a for an elastic strip)
  double q = 0.0;        ///< [Pa] amplitude of the semi-ellipse (plastic: elastic amplitude, flat top at p_lim)
  bool plastic = false;  ///< capped at p_lim
  int band = 0;          ///< lateral band index (0-based, increasing s)
  int index = 0;         ///< index of the strip in StripGeometry
  double load = 0.0;     ///< [N] load carried by the strip
};

struct StripResult {
  StripStatus status = StripStatus::NoContact;
  std::string message;
  int iterations = 0;     ///< delta iterations (load control), 0 for approach given
  double delta = 0.0;     ///< [m] approach
  double N = 0.0;         ///< [N] normal load
  double pmax = 0.0;      ///< [Pa] min(max q, p_lim)
  double area = 0.0;      ///< [m^2] sum 2 a_i ds over loaded strips (with plastic lengthening)
  int n_bands = 0;        ///< lateral bands found at the final delta
  double end_gap_error = NAN;  ///< the estimate's end-gap error (StripOptions::end_gap_tol), NaN if not checked
  bool refined = false;   ///< the extents close the end gap (refined), else the estimate
  int n_outliers = 0;     ///< strips flagged by outlier_factor
  int worst_outlier = -1; ///< index into `strips` of the worst outlier, -1 if none
  std::vector<StripState> strips;  ///< loaded strips only, in increasing s
};

/// What one solve of a geometry hands to the next solve of the same geometry (another approach,
/// another load, or the same patch on the next plane): its loaded strips as the first active
/// set, and whether this patch's extents are refined, with the last refined solution as the
/// start of the next refinement. The decision to refine is taken once, at the first solve, so
/// that N(δ) stays one smooth function along an approach iteration.
struct StripWarmStart {
  std::vector<int> loaded;  ///< geometry indices (increasing) of the strips that carried load
  int end_gap = -1;         ///< -1 not decided yet, 0 the estimate is kept, 1 refined extents
  double end_gap_error = NAN;  ///< the estimate's end-gap error the decision was taken on
  StripResult previous;     ///< the last refined solution (end_gap == 1), in this geometry's indices
};

/// Approach given. `warm`: geometry indices (increasing) of the strips expected to carry load,
/// e.g. those of a solve at a nearby approach, as the starting active set. The active set
/// method ends where no strip has q < 0 and no unloaded strip is penetrated, whatever it
/// started from: a warm start changes the cost (fewer factorisations), not the answer. Null or
/// empty: every strip with a positive extent.
StripResult solve_strips_approach(const StripGeometry& geo, double H, double delta, double p_lim,
                                  const StripOptions& opt = {}, const std::vector<int>* warm = nullptr);
/// Load given. `warm`: as for solve_strips_approach, for the first approach; each later one
/// starts from the strips of the one before.
StripResult solve_strips_load(const StripGeometry& geo, double H, double N, double p_lim,
                              const StripOptions& opt = {}, const std::vector<int>* warm = nullptr);

namespace strips_detail { struct Solver; }

/// A strip solver bound to one geometry, H and p_lim: the input is checked once and what
/// depends on the geometry only (the ANALYN shape per strip, the deepest row) computed once, for
/// the many solves of one patch; solve_strips_approach and solve_strips_load are this for one
/// call. `geo` must outlive the solver. Invalid input: every solve returns InvalidInput.
class StripSolver {
 public:
  StripSolver(const StripGeometry& geo, double H, double p_lim, const StripOptions& opt = {});
  ~StripSolver();
  StripSolver(const StripSolver&) = delete;
  StripSolver& operator=(const StripSolver&) = delete;
  StripResult at_approach(double delta, StripWarmStart* warm = nullptr) const;
  /// `delta_start`: the first approach tried (e.g. a previous solve's), if above the minimum gap;
  /// else the Hertz approach of the deepest row.
  StripResult at_load(double N, StripWarmStart* warm = nullptr, double delta_start = NAN) const;

 private:
  /// Load control with the estimated extents (a safeguarded secant on the approach).
  StripResult estimate_at_load(double N, const std::vector<int>* warm, double delta_start) const;
  std::unique_ptr<strips_detail::Solver> s_;  ///< null: invalid input (why_)
  std::string why_;
  double p_lim_;
};

/// The geometry indices of a result's loaded strips (increasing): a warm start's active set.
std::vector<int> loaded_strips(const StripResult& r);

/// A solution's strips carried onto another strip geometry of the same patch (the patch on a
/// new placement of its plane): the start of the next refinement of the extents
/// (StripWarmStart::previous). New strip j has its centre at `s_new[j]`, which is `s_old[j]` in
/// the old geometry's coordinate (the same rail y). Its half-length and amplitude are
/// interpolated linearly between the two old loaded strips around it, never across a gap
/// between bands (non-adjacent old indices); a new strip beyond the end of a band by less than
/// `ds_old` takes its end strip's values, so that a tail strip is not lost (the refinement keeps
/// a strip only if it starts with an extent). `old` in increasing s; the
/// result in increasing new index, index and s of the new geometry.
std::vector<StripState> map_strips(const std::vector<StripState>& old, double ds_old,
                                   const std::vector<double>& s_old, const std::vector<double>& s_new);

namespace strips_detail {
/// Integral over one strip of f(t)/r, f(t) = min(sqrt(1 - t^2), r_cap),
/// t = (xi - c_j)/a_j, for a point at x-offset X0 = x_i - c_j and lateral
/// offsets eta1 < eta2 of the strip edges from the point (eta = s_j +- ds/2 - s_i).
/// r_cap >= 1: plain semi-ellipse. Unit [m] (multiply by H q_j for the displacement).
double strip_influence(double X0, double a, double eta1, double eta2, double r_cap, int gauss_points);

/// Hertz contact ellipse for h = A x^2 + B y^2 at approach delta (Johnson §4.2):
/// semi-axes a (along x), b (along y). Independent of elastic constants.
/// Returns false for non-positive input.
bool hertz_axes(double A, double B, double delta, double* a, double* b);
}  // namespace strips_detail

}  // namespace mh
