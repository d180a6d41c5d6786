#pragma once
// The case loop shared by the grid methods (half-space §8, strips §9 of docs/method.md): place the
// contact patches and their planes (geometry/contact_patches.hpp), let a method-specific solver
// work on each patch, and close the vertical force balance Σ_k N_k cos γ_k = Q (eq. 10) with one
// rigid vertical approach δz shared by all patches (δ_k = δz cos γ_k, eq. 11). Patches are placed
// again when the contact outgrows what was set up, or when the solution's approach differs from
// the approach the planes were placed for by more than ref_rtol.
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "contact/case_result.hpp"
#include "contact/grid/grid_checks.hpp"
#include "contact/grid/patch_elastic.hpp"
#include "contact/ellipse/hertz.hpp"
#include "geometry/contact_patches.hpp"

namespace mh {

/// One patch's solver. Its gap is the undeformed normal gap with the wheel at the approach the
/// patch was set up for (dz_ref), shifted so that δ = dz cos γ reproduces it at dz = dz_ref.
class PatchSolver {
 public:
  virtual ~PatchSolver() = default;
  /// Approach control: solve at normal approach δ [m]; returns the patch's normal force [N].
  virtual double at_approach(double delta) = 0;
  /// Load control: solve for normal force N [N]; returns the normal approach δ [m].
  virtual double at_load(double N) = 0;
  /// The last solve did not converge (message in why(), what did not converge as data in
  /// failure(): its class and measures; the caller names the patch).
  virtual bool failed() const = 0;
  virtual std::string why() const = 0;
  virtual Warning failure() const = 0;
  /// The last solution reaches the edge of what was set up (grid or strips): set up larger.
  virtual bool outgrown() const = 0;
  /// Take the solution of `previous` (the same patch at the previous placement, possibly another
  /// plane or grid) as the initial guess of the next solve. Default: nothing (a cold start).
  virtual void warm_start_from(const PatchSolver& previous) { (void)previous; }
};

/// Builds the solver of one patch (region, plane) for the wheel at vertical approach dz_ref.
/// Returns nullptr and sets *why and *failure (class not_converged_setup, with what was measured)
/// when the patch cannot be set up (e.g. too many elements). The
/// solver belongs to the method (a pool of its workspace, reused from case to case: SolverPool)
/// and stays valid until the method's case ends.
using PatchSolverFactory =
    std::function<PatchSolver*(const PatchRegion& region, double dz_ref, std::string* why, Warning* failure)>;

/// The patch solvers of a grid method's case, kept from case to case so that their grids and
/// vectors keep their capacity: take() hands out the next one (made on first need), begin_case()
/// makes them all available again. Solvers handed out in one case stay valid until the next
/// begin_case(); one thread at a time.
template <class Solver>
class SolverPool {
 public:
  void begin_case() { used_ = 0; }
  Solver& take() {
    if (used_ == pool_.size()) pool_.push_back(std::make_unique<Solver>());
    return *pool_[used_++];
  }

 private:
  std::vector<std::unique_ptr<Solver>> pool_;
  std::size_t used_ = 0;
};

struct PatchDriverOptions {
  double d_comb = 8e-3;     ///< [m] regions closer than this are one patch
  double margin = 1.25;     ///< patches cover the interpenetration at margin × the approach
  double ref_rtol = 0.02;   ///< re-place the planes when the approach moved by more than this (relative)
  double force_rtol = 1e-7; ///< |Σ N_k cos γ_k − Q| ≤ force_rtol·Q with several patches
  int max_outer = 60;       ///< approach iterations with several patches
  int max_passes = 7;       ///< placements of the patches
};

struct PatchDriverResult {
  CaseStatus status = CaseStatus::Ok;
  std::string message;
  /// What did not converge when status is NotConverged (a not_converged_* class with its
  /// measures; docs/status.md): the case's warning.
  Warning failure;
  double dz = 0;            ///< [m] the rigid vertical approach of the solution
  int evaluations = 0;      ///< patch solves (all passes)
  int passes = 0;           ///< placements of the patches
  std::vector<PatchRegion> regions;    ///< of the final placement
  std::vector<PatchSolver*> solvers;   ///< their solvers (the method's), holding the solution at dz
  /// Scratch of drive_patches, balance_approach and rebalance_refined, kept with the result so
  /// that a reused PatchDriverResult (a grid method's workspace) allocates nothing once grown.
  struct Scratch {
    std::vector<PatchRegion> regions;                   ///< the previous placement's
    std::vector<PatchSolver*> solvers;                  ///< ... and its solvers (warm starts)
    RegionScratch intervals;                             ///< find_patch_regions
    std::vector<PatchSolver*> balanced;                 ///< the solvers of one approach balance
    std::vector<double> cos_gamma;                      ///< ... and their cos γ
  } scratch;
};

/// The driver options from a grid method's options (they share the fields d_comb, margin,
/// ref_rtol, force_rtol, max_outer), with max_passes placements of the patches.
template <class MethodOptions>
PatchDriverOptions patch_driver_options(const MethodOptions& o, int max_passes) {
  PatchDriverOptions d;
  d.d_comb = o.d_comb;
  d.margin = o.margin;
  d.ref_rtol = o.ref_rtol;
  d.force_rtol = o.force_rtol;
  d.max_outer = o.max_outer;
  d.max_passes = max_passes;
  return d;
}

/// The start of a grid method's case: the elastic multi-Hertzian solution of the same case (below
/// a microsecond; elastic even in the plastic model, whose "approach", Thornton's δ of the grown
/// ellipse, overestimates the capped approach 3–5 times in flange contact). Its approach is the
/// first estimate of the grid's, and its geometric warnings (flange_climb) are the case's.
struct GridStart {
  GridStart() = default;
  GridStart(const GridStart&) = delete;
  GridStart& operator=(const GridStart&) = delete;
  CaseResult own;                  ///< the elastic multi-Hertzian solution, when the caller gave none
  const CaseResult* mh = nullptr;  ///< the elastic multi-Hertzian solution used (the caller's or own)
  double dz = 0.05e-3;             ///< [m] first estimate of the vertical approach (0.05 mm without one)
};

/// What the case loop of a grid method keeps between the cases of one thread (the method's
/// workspace holds one): the start, the driver's result and scratch, the rigid–plastic sampling,
/// the physical checks' inputs. Nothing in it carries over as data: every case sets what it reads.
struct GridCaseWorkspace {
  GridStart start;
  PatchDriverResult driver;
  ProjectedInterpenetration projected;       ///< rigid_plastic_approach
  std::vector<PatchCheckInput> checks;       ///< of the reported patches; n_checks in use
  std::size_t n_checks = 0;
  std::vector<PatchSolver*> refined;         ///< the locally refined patches (null: not refined)
  /// The patch results of earlier cases (solve_grid_case hands them back), for the capacity of
  /// their vectors: take_patch.
  std::vector<PatchResult> spare;
  /// A new PatchResult (every field a fresh one's) whose vectors reuse a spare's capacity.
  PatchResult take_patch() {
    PatchResult pr;
    if (spare.empty()) return pr;
    PatchResult& s = spare.back();
    pr.p.swap(s.p);
    pr.strips.swap(s.strips);
    pr.traction.pn.swap(s.traction.pn);
    pr.traction.px.swap(s.traction.px);
    pr.traction.py.swap(s.traction.py);
    pr.traction.slip.swap(s.traction.slip);
    spare.pop_back();
    pr.p.clear();
    pr.strips.clear();
    pr.traction.clear();
    return pr;
  }
  /// A result's patches handed back for take_patch (their vectors' capacity); `patches` is left
  /// empty.
  void give_back(std::vector<PatchResult>& patches) {
    for (PatchResult& p : patches) spare.push_back(std::move(p));
    patches.clear();
  }
  /// The next check input (its vectors keep their capacity), after begin: checks[n_checks − 1].
  PatchCheckInput& next_check() {
    if (n_checks == checks.size()) checks.emplace_back();
    PatchCheckInput& c = checks[n_checks++];
    std::vector<double> p = std::move(c.p), overlap = std::move(c.overlap);
    c = PatchCheckInput();  // a fresh input's fields, its vectors' capacity kept
    c.p = std::move(p);
    c.overlap = std::move(overlap);
    c.p.clear();
    c.overlap.clear();
    return c;
  }
};

/// What every grid method does before solving a case: refuse Q ≤ 0 (`no_contact`) and a t_Y outside
/// the geometry (`out_of_range`), with r's status and message set (returns false); else fill *gs
/// from `elastic_mh` (the elastic multi-Hertzian solution of this case, e.g. the one `auto` already
/// has; null: solved here, with the wheel rolled by `roll` [rad] as the grid's gap) and return true.
bool begin_grid_case(const ContactGeometry& G, const Material& mat, double tY, double Q, double roll,
                     const CaseResult* elastic_mh, CaseResult& r, GridStart* gs);

/// What every grid method does after solving a case: the start's flange_climb warning, then
/// `off_profile:patch=K` for each patch whose contact reaches the end of either profile (of a rail
/// with a vertical gauge face: its foot; ContactGeometry::off_profile_at) (method.md
/// §3.7: it stands on extrapolated geometry; the wheel point that of the wheel rolled by `roll`
/// [rad]); a not_converged result then loses its pressures (withhold_unconverged_pressures,
/// grid_checks.hpp).
void finish_grid_case(const ContactGeometry& G, double tY, double roll, const GridStart& gs, CaseResult& r);

/// A grid method's entry: begin_grid_case, then body(gs, r) → the solved case, then
/// finish_grid_case. `method` is the row's method, `roll` [rad] the wheel's roll against the rail.
template <class Body>
CaseResult solve_grid_case(Method method, const ContactGeometry& G, const Material& mat, double tY, double Q,
                           double roll, const CaseResult* elastic_mh, Body&& body) {
  CaseResult r;
  r.method = method;
  GridStart gs;
  if (!begin_grid_case(G, mat, tY, Q, roll, elastic_mh, r, &gs)) return r;
  r = body(gs, std::move(r));
  finish_grid_case(G, tY, roll, gs, r);
  set_patch_elastic_hertz(mat, gs.mh, r);
  return r;
}

/// The same into `out`, reset first as a fresh CaseResult (reset_case_result) with its vectors
/// keeping their capacity, and with the start in ws.start: with a reused `out` and `ws` nothing
/// is allocated here once they have grown. body(gs, r) → r, as above. The same bytes.
template <class Body>
void solve_grid_case(Method method, const ContactGeometry& G, const Material& mat, double tY, double Q, double roll,
                     const CaseResult* elastic_mh, GridCaseWorkspace& ws, CaseResult& out, Body&& body) {
  ws.give_back(out.patches);  // their vectors for take_patch
  reset_case_result(out);
  out.method = method;
  GridStart& gs = ws.start;
  gs.mh = nullptr;
  gs.dz = GridStart().dz;
  if (!begin_grid_case(G, mat, tY, Q, roll, elastic_mh, out, &gs)) return;
  out = body(gs, std::move(out));
  finish_grid_case(G, tY, roll, gs, out);
  set_patch_elastic_hertz(mat, gs.mh, out);
  // Room for this case's patches in the spares now, not when the next case hands them back.
  if (ws.spare.capacity() < ws.spare.size() + out.patches.size()) ws.spare.reserve(ws.spare.size() + out.patches.size());
}

/// [m] the vertical approach at which p_lim [Pa] times the horizontal projection of the rigid
/// interpenetration equals Q [N]: a lower bound of the capped approach (contact needs g + u ≤ δ
/// with u ≥ 0, and the vertical force is at most p_lim times the projected contact area), found
/// by bisection to 1e-4 relative.
double rigid_plastic_approach(const WheelRailGap& gap, double Q, double p_lim);
/// The same with the sampling kept in `area` (reset here; its capacity kept).
double rigid_plastic_approach(const WheelRailGap& gap, double Q, double p_lim, ProjectedInterpenetration& area);

/// Several patches under one rigid vertical approach: the δz [m] at which
/// Σ_k N_k(δz cos γ_k) cos γ_k = Q (eqs. 10–11), each patch in approach control, within
/// opt.force_rtol·Q, bracketed from dz_start (> 0) and found by TOMS 748 in at most opt.max_outer
/// evaluations of the sum; every solver is left holding its solution at the δz returned.
struct ApproachBalance {
  double dz = 0;         ///< [m]
  bool ok = true;        ///< false: not within force_rtol (message and failure say so)
  std::string message;
  Warning failure;       ///< when !ok: not_converged_load with the residual and the iterations
  int evaluations = 0;   ///< patch solves
};
ApproachBalance balance_approach(const std::vector<PatchSolver*>& solvers, const std::vector<double>& cos_gamma,
                                 double Q, double dz_start, const PatchDriverOptions& opt);

/// After some patches of D were refined locally (grid_checks.hpp, under_resolved), the shared
/// approach found again with them (eqs. 10–11, every patch in approach control): refined[n], when
/// not null, replaces D.solvers[n]. A failed patch solve or an unbalanced load makes r
/// not_converged with the reason (message and warning); r.approach becomes the new approach.
/// Returns the balance.
ApproachBalance rebalance_refined(PatchDriverResult& D, const std::vector<PatchSolver*>& refined, double Q,
                                  double dz_start, const PatchDriverOptions& opt, CaseResult& r);

/// Solve for the load Q [N], starting from the approach estimate dz_est [m] (> 0), into R (reset
/// first; its vectors and scratch keep their capacity).
void drive_patches(const WheelRailGap& gap, double Q, double dz_est, const PatchDriverOptions& opt,
                   const PatchSolverFactory& make, PatchDriverResult& R);

}  // namespace mh
