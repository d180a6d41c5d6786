#include "contact/half_space/half_space_method.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "contact/half_space/influence.hpp"
#include "contact/grid/grid_checks.hpp"
#include "contact/grid/patch_driver.hpp"
#include "contact/multi_hertz/multi_hertz.hpp"
#include "geometry/gap.hpp"

namespace mh {


namespace {

constexpr long kMaxElements = 4'000'000;  // one patch grid larger than this is refused (memory)

// The influence operators of a thread's half-space cases, kept by their grid (nx, ny, dx, dy,
// compliance: equal values give the same operator bit for bit), so that a case like the last one
// builds no kernel, plan or buffer (HalfSpaceWorkspace). Once kInfluenceGrids are kept, an
// operator of an earlier case is rebuilt in place for a new grid (InfluenceGrid::reset): the least
// recently used of those whose buffers hold the grid, else the least recently used, so that a
// run which keeps meeting more grid sizes than are kept (the wheelset's equilibrium at changing
// loads) soon allocates nothing either.
class InfluenceCache {
 public:
  /// A case begins: the operators it takes stay put until the next begin_case() (patches hold
  /// them), so only those of earlier cases are rebuilt to make room.
  void begin_case() { case_start_ = ++clock_; }
  const InfluenceGrid& get(int nx, int ny, double dx, double dy, double H) {
    ++clock_;
    for (Entry& e : grids_)
      if (e.C->nx() == nx && e.C->ny() == ny && e.C->dx() == dx && e.C->dy() == dy && e.C->compliance() == H) {
        e.used = clock_;
        return *e.C;
      }
    Entry* lru = nullptr;        // the least recently used of an earlier case
    Entry* lru_holds = nullptr;  // the same among those whose buffers hold nx × ny
    if (grids_.size() >= static_cast<std::size_t>(HalfSpaceWorkspace::kInfluenceGrids))
      for (Entry& e : grids_) {
        if (e.used >= case_start_) continue;
        if (!lru || e.used < lru->used) lru = &e;
        if ((!lru_holds || e.used < lru_holds->used) && e.C->holds(nx, ny)) lru_holds = &e;
      }
    Entry* slot = lru_holds ? lru_holds : lru;
    if (slot) {
      slot->C->reset(nx, ny, dx, dy, H);
    } else {  // room left, or every operator held by this case
      grids_.push_back({std::make_unique<InfluenceGrid>(nx, ny, dx, dy, H), 0});
      slot = &grids_.back();
    }
    slot->used = clock_;
    return *slot->C;
  }

 private:
  struct Entry {
    std::unique_ptr<InfluenceGrid> C;  // its own block: a patch's pointer survives the vector's growth
    unsigned long used;
  };
  std::vector<Entry> grids_;
  unsigned long clock_ = 0, case_start_ = 0;
};

struct HalfSpacePatch;

}  // namespace

struct HalfSpaceWorkspace::Impl {
  GridCaseWorkspace grid;
  SolverPool<HalfSpacePatch> patches;
  InfluenceCache influence;
  NormalCGWorkspace cg;
  CaseResult elastic;                  ///< the plastic model's elastic pass
  std::vector<HalfSpacePatch*> fine;   ///< the locally refined patches (null: not refined)
  std::vector<double> u;               ///< C p of check_input
};

namespace {

// One patch on the half-space: its grid in the patch plane, the undeformed normal gap, the
// influence operator and the pressures. Made empty by the workspace's pool and set up for each
// patch (setup: every field as a new patch's, the vectors keeping their capacity).
struct HalfSpacePatch : public PatchSolver {
  void setup(const WheelRailGap& gap, const PatchRegion& R, double dz_ref, const HalfSpaceOptions& opt, double H,
             double p_lim, HalfSpaceWorkspace::Impl& ws) {
    P = R.P;
    dx = opt.dx;
    ds = opt.ds;
    p_lim_ = p_lim;
    cg_ = opt.cg;
    ws_ = &ws;
    C = nullptr;
    last = NormalCGResult();
    iterations = 0;
    peak_change = NAN;
    h_min = 0;
    h.clear();
    p.clear();
    const double c = std::cos(P.gamma);
    // x symmetric about 0 (no yaw); s over the region's extent in the plane; 3 elements of room.
    const double sa = R.s_a - 3 * ds, sb = R.s_b + 3 * ds;
    nx = 2 * static_cast<int>(std::ceil((R.x_half + 3 * dx) / dx));
    ns = std::max(1, static_cast<int>(std::ceil((sb - sa) / ds)));
    x0 = -(nx / 2 - 0.5) * dx;
    s0 = 0.5 * (sa + sb) - (ns - 1) * 0.5 * ds;
    if (static_cast<long>(nx) * ns > kMaxElements) return;  // refused by the factory
    h.assign(static_cast<std::size_t>(nx) * ns, 0.0);
    h_min = INFINITY;
    for (int j = 0; j < ns; ++j) {
      const double s = s0 + j * ds;
      for (int i = nx / 2; i < nx; ++i) {  // h is even in x: compute x > 0, mirror
        // The gap with the wheel lowered vertically by dz_ref, shifted back by the normal approach
        // dz_ref cos γ: δ = dz cos γ reproduces it exactly at dz = dz_ref, to first order nearby.
        const double v = normal_gap(gap, P, x0 + i * dx, s, dz_ref) + dz_ref * c;
        h[static_cast<std::size_t>(i + nx * j)] = v;
        h[static_cast<std::size_t>(nx - 1 - i + nx * j)] = v;
        h_min = std::min(h_min, v);
      }
    }
    p.assign(h.size(), 0.0);
    C = &ws.influence.get(nx, ns, dx, ds, H);
  }
  bool ok() const { return C != nullptr; }
  double at_approach(double delta) override {
    last = solve_normal_approach(*C, h.data(), delta, p_lim_, p.data(), cg_, ws_->cg);
    iterations += last.iterations;
    return last.N;
  }
  double at_load(double N) override {
    last = solve_normal_load(*C, h.data(), N, p_lim_, p.data(), cg_, ws_->cg);
    iterations += last.iterations;
    return last.delta;
  }
  /// The previous placement's pressures at the same rail point: element (x, s) here is rail
  /// y = y_ref + s cos γ, i.e. s' = (y − y'_ref)/cos γ' there; nearest element, 0 outside its grid.
  /// Only a capped solution is carried over (the capped load control then starts from it instead
  /// of solving elastically first); an elastic one is rebuilt from a cold start, as before.
  void warm_start_from(const PatchSolver& previous) override {
    const auto* q = static_cast<const HalfSpacePatch*>(&previous);  // a half-space case has no other
    if (!q || !std::isfinite(p_lim_) || q->last.status != GridStatus::Ok || q->last.n_plastic == 0) return;
    for (int j = 0; j < ns; ++j) {
      const double y = P.y_ref + (s0 + j * ds) * std::cos(P.gamma);
      const int jq = static_cast<int>(std::lround(((y - q->P.y_ref) / std::cos(q->P.gamma) - q->s0) / q->ds));
      if (jq < 0 || jq >= q->ns) continue;
      for (int i = 0; i < nx; ++i) {
        const int iq = static_cast<int>(std::lround((x0 + i * dx - q->x0) / q->dx));
        if (iq < 0 || iq >= q->nx) continue;
        p[static_cast<std::size_t>(i + nx * j)] = q->p[static_cast<std::size_t>(iq + q->nx * jq)];
      }
    }
  }
  bool failed() const override { return last.status == GridStatus::NotConverged; }
  std::string why() const override { return "the half-space solver did not converge on a patch grid"; }
  Warning failure() const override {
    Warning w(WarningClass::NotConvergedCg);
    return w.add(Quantity::CgError, last.error, '>', cg_.tol).add(Quantity::Iterations, last.iterations);
  }
  bool outgrown() const override {  // pressure on the grid's edge
    for (int i = 0; i < nx; ++i)
      if (p[static_cast<std::size_t>(i)] > 0 || p[static_cast<std::size_t>(i + nx * (ns - 1))] > 0) return true;
    for (int j = 0; j < ns; ++j)
      if (p[static_cast<std::size_t>(nx * j)] > 0 || p[static_cast<std::size_t>(nx - 1 + nx * j)] > 0) return true;
    return false;
  }

  /// The solution as the physical checks see it (grid_checks.hpp): pressures, the rigid overlap
  /// δ − g per element, and the largest violation of the contact condition by the deformed gap
  /// h = g + C p − δ (δ of the last solve).
  void check_input(PatchCheckInput& c) const {
    c.nx = nx; c.ns = ns; c.p = p; c.p_lim = p_lim_;
    c.spike_check = c.hole_check = true;
    c.min_across = kMinAcrossHalfSpace;
    c.element = std::max(dx, ds);
    c.peak_change = peak_change;
    c.peak_rtol = kPeakRtolHalfSpace;
    c.y_ref = P.y_ref; c.gamma = P.gamma; c.s0 = s0; c.ds = ds;
    const double delta = last.delta;
    c.overlap.resize(h.size());
    std::vector<double>& u = ws_->u;
    u.assign(h.size(), 0.0);
    C->apply(p.data(), u.data());
    c.gap_violation = 0;
    for (std::size_t e = 0; e < h.size(); ++e) {
      c.overlap[e] = delta - h[e];
      c.approach = std::max(c.approach, c.overlap[e]);
      const double he = h[e] + u[e] - delta;
      double v = 0;
      if (p[e] <= 0) v = std::max(0.0, -he);                                 // free: h ≥ 0
      else if (std::isfinite(p_lim_) && p[e] >= p_lim_) v = std::max(0.0, he);  // capped: h ≤ 0
      else v = std::fabs(he);                                                // in contact: h = 0
      c.gap_violation = std::max(c.gap_violation, v);
    }
  }

  PatchPlane P;
  double dx, ds;
  int nx = 0, ns = 0;
  double x0 = 0, s0 = 0, h_min = 0;
  std::vector<double> h, p;
  const InfluenceGrid* C = nullptr;  ///< the workspace's (InfluenceCache); null: refused
  NormalCGResult last;
  int iterations = 0;
  /// After a local refinement (refine_patch): |Δpmax| / pmax of the last halving; NaN: not refined.
  double peak_change = NAN;

 private:
  double p_lim_ = INFINITY;
  NormalCGOptions cg_;
  HalfSpaceWorkspace::Impl* ws_ = nullptr;
};

// A patch with fewer elements across than kMinAcrossHalfSpace (grid_checks.hpp), solved again on
// its own at the load N the case gave it, on its region with dx and ds halved, until it has that
// many elements across and its peak moves by at most kPeakRtolHalfSpace between two grids; at
// most opt.max_refinements halvings. The gap is that of the wheel at the case's approach dz. With
// several patches the caller then finds the shared approach again with the refined ones
// (balance_approach). Returns the finest patch solved (null: none could be, the coarse one
// stays); its peak_change says whether the peak settled.
HalfSpacePatch* refine_patch(const WheelRailGap& gap, const PatchRegion& region, double dz, const HalfSpacePatch& coarse,
                             double N, const HalfSpaceOptions& opt, double H, double p_lim,
                             HalfSpaceWorkspace::Impl& ws) {
  HalfSpacePatch* best = nullptr;
  double p_prev = *std::max_element(coarse.p.begin(), coarse.p.end());
  HalfSpaceOptions o = opt;
  for (int level = 1; level <= opt.max_refinements; ++level) {
    o.dx *= 0.5;
    o.ds *= 0.5;
    HalfSpacePatch* f = &ws.patches.take();
    f->setup(gap, region, dz, o, H, p_lim, ws);
    if (!f->ok()) break;  // beyond the element budget
    f->at_load(N);
    if (f->failed() || f->outgrown()) break;
    const double p_new = *std::max_element(f->p.begin(), f->p.end());
    f->peak_change = std::fabs(p_new - p_prev) / p_new;
    f->iterations += best ? best->iterations : coarse.iterations;
    const bool settled = elements_across(f->p, f->nx, f->ns) >= kMinAcrossHalfSpace &&
                         f->peak_change <= kPeakRtolHalfSpace;
    best = f;
    p_prev = p_new;
    if (settled) break;
  }
  return best;
}

}  // namespace

namespace {

// The case after begin_grid_case (r holds its method; gs the start).
CaseResult half_space_case(const ContactGeometry& G, const Material& mat, double tY, double Q, const HalfSpaceOptions& opt,
                           const GridStart& gs, CaseResult r, HalfSpaceWorkspace::Impl& ws) {
  double dz_est = gs.dz;
  if (std::isfinite(mat.p_lim)) {
    // Plastic model: when the elastic solution stays below the cap it is the solution of the
    // capped problem too (it satisfies every condition, and the solution is unique), exactly.
    // (The elastic pass fills the workspace's result, r's copy, which keeps its capacity.)
    Material elastic = mat;
    elastic.p_lim = INFINITY;
    ws.elastic = r;
    CaseResult el = half_space_case(G, elastic, tY, Q, opt, gs, std::move(ws.elastic), ws);
    if (el.status != CaseStatus::Ok || el.pmax <= mat.p_lim) {
      // The elastic answer is the answer; r's storage kept for the next pass (both with room for
      // a usual row, reserve_row: trading places grows neither).
      reserve_row(r);
      reserve_row(el);
      std::swap(r, el);
      ws.elastic = std::move(el);
      return r;
    }
    // The capped approach is at least the elastic one (capping only softens) and at least the
    // rigid–perfectly-plastic one, where p_lim times the horizontal projection of the
    // interpenetration carries Q (contact needs g + u ≤ δ with u ≥ 0, and Σ N_k cos γ_k is p_lim
    // times the projected area of the capped elements). The multi-Hertzian estimate is not used:
    // its plastic "approach" (Thornton's δ of the grown ellipse) overestimates this approach 3–5
    // times in flange contact, where the interpenetration at that depth reaches the tread.
    const WheelRailGap gap0(G, tY, NAN, opt.roll);
    dz_est = std::max(el.approach, rigid_plastic_approach(gap0, Q, mat.p_lim, ws.grid.projected));
    // The elastic patches' vectors go back to the spares for the capped pass (the spares then
    // hold no more than at the case's start: no growth).
    ws.grid.give_back(el.patches);
    ws.elastic = std::move(el);
  }
  ws.patches.begin_case();
  ws.influence.begin_case();
  ws.grid.n_checks = 0;
  const WheelRailGap gap(G, tY, NAN, opt.roll);  // upright at roll 0 (the same bits)
  const double H = mat.compliance();
  const double p_lim = mat.p_lim;


  const PatchDriverOptions dopt = patch_driver_options(opt, opt.max_rebuilds + 1);
  // The factory's state behind one pointer: a std::function keeps a lambda of one reference in
  // place (no allocation).
  struct Make {
    const WheelRailGap& gap;
    const HalfSpaceOptions& opt;
    double H, p_lim;
    HalfSpaceWorkspace::Impl& ws;
  } make{gap, opt, H, p_lim, ws};
  PatchDriverResult& D = ws.grid.driver;
  drive_patches(gap, Q, dz_est, dopt, [&make](const PatchRegion& reg, double dz_ref, std::string* why, Warning* failure) -> PatchSolver* {
    HalfSpacePatch& k = make.ws.patches.take();
    k.setup(make.gap, reg, dz_ref, make.opt, make.H, make.p_lim, make.ws);
    if (!k.ok()) {
      *why = "a contact patch would need " + std::to_string(static_cast<long>(k.nx) * k.ns) +
             " elements (more than " + std::to_string(kMaxElements) + "): use larger dx_mm/ds_mm";
      failure->add(Quantity::Elements, static_cast<double>(k.nx) * k.ns, '>', kMaxElements);
      return nullptr;
    }
    return &k;
  }, D);
  r.status = D.status;
  r.message = D.message;
  if (D.status == CaseStatus::NotConverged) r.warnings.push_back(D.failure);
  double dz = D.dz;
  const int outer = D.evaluations;  // patch solves, all placements
  // Results per patch and for the case.
  r.approach = dz;
  r.iterations = outer;
  // Patches resolved by too few elements: refined locally (refine_patch).
  std::vector<HalfSpacePatch*>& fine = ws.fine;
  fine.assign(D.solvers.size(), nullptr);
  bool any_fine = false;
  for (std::size_t n = 0; n < D.solvers.size() && r.status == CaseStatus::Ok && n < D.regions.size(); ++n) {
    const HalfSpacePatch* coarse = static_cast<const HalfSpacePatch*>(D.solvers[n]);
    if (elements_across(coarse->p, coarse->nx, coarse->ns) >= kMinAcrossHalfSpace) continue;
    double sp = 0;
    for (double v : coarse->p) sp += v;
    if (sp > 0) fine[n] = refine_patch(gap, D.regions[n], dz, *coarse, sp * coarse->dx * coarse->ds, opt, H, p_lim, ws);
    any_fine = any_fine || fine[n];
  }
  if (any_fine && D.solvers.size() > 1) {
    // A refined patch is stiffer or softer than its coarse grid said: the shared approach again.
    std::vector<PatchSolver*>& refined = ws.grid.refined;
    refined.assign(fine.begin(), fine.end());
    const ApproachBalance b = rebalance_refined(D, refined, Q, dz, dopt, r);
    dz = b.dz;
    r.iterations += b.evaluations;
  }
  // The physical checks' inputs of the reported patches: ws.grid.checks[0 … n_checks).
  for (std::size_t n = 0; n < D.solvers.size(); ++n) {
    const HalfSpacePatch* coarse = static_cast<const HalfSpacePatch*>(D.solvers[n]);
    const HalfSpacePatch& k = fine[n] ? *fine[n] : *coarse;
    PatchResult pr = ws.grid.take_patch();  // a new one, its vectors a spare's capacity
    pr.y_r = k.P.y_ref;
    pr.z_r = gap.z_rail(k.P.y_ref);  // the reference point on the rail profile (as CONTACT reports it)
    pr.y_w = gap.y_wheel(k.P.y_ref);
    pr.r_roll = gap.rolling_radius(k.P.y_ref);
    pr.gamma = k.P.gamma;
    pr.iterations = k.iterations;
    const double da = k.dx * k.ds;
    int i0 = k.nx, i1 = -1, j0 = k.ns, j1 = -1;
    double sp = 0, spx = 0, sps = 0;
    for (int j = 0; j < k.ns; ++j)
      for (int i = 0; i < k.nx; ++i) {
        const double p = k.p[static_cast<std::size_t>(i + k.nx * j)];
        if (!(p > 0)) continue;
        ++pr.n_elements;
        pr.pmax = std::max(pr.pmax, p);
        if (std::isfinite(p_lim) && p >= p_lim) { pr.plastic_area += da; pr.capped_load += p * da; }
        sp += p; spx += p * (k.x0 + i * k.dx); sps += p * (k.s0 + j * k.ds);
        i0 = std::min(i0, i); i1 = std::max(i1, i); j0 = std::min(j0, j); j1 = std::max(j1, j);
      }
    pr.N = sp * da;
    pr.area = pr.n_elements * da;
    if (pr.n_elements > 0) {
      pr.length_x = (i1 - i0 + 1) * k.dx;
      pr.width_s = (j1 - j0 + 1) * k.ds;
      pr.s_lo = k.s0 + j0 * k.ds;
      pr.s_hi = k.s0 + j1 * k.ds;
      pr.x_centroid = spx / sp;
      pr.s_centroid = sps / sp;
    }
    // A refined patch alone in its case found its own normal approach by load control.
    pr.approach = (fine[n] && D.solvers.size() == 1 ? k.last.delta : dz * std::cos(k.P.gamma)) - k.h_min;
    if (pr.N <= 0) continue;  // a potential patch that carries nothing is not reported
    k.check_input(ws.grid.next_check());
    pr.elements_across = elements_across(k.p, k.nx, k.ns);
    pr.element = std::max(k.dx, k.ds);
    if (opt.keep_pressure) {
      pr.nx = k.nx; pr.ns = k.ns; pr.dx = k.dx; pr.ds = k.ds; pr.x0 = k.x0; pr.s0 = k.s0;
      pr.p = k.p;
    }
    r.Fz += pr.N * std::cos(pr.gamma);
    r.Fy += pr.N * std::sin(pr.gamma);
    r.pmax = std::max(r.pmax, pr.pmax);
    r.area += pr.area;
    r.patches.push_back(std::move(pr));
  }
  close_grid_case(ws.grid.checks.data(), ws.grid.n_checks, Q, D.solvers.size() > 1 ? 10 * opt.force_rtol : INFINITY, r);
  return r;
}

}  // namespace

HalfSpaceWorkspace::HalfSpaceWorkspace() = default;
HalfSpaceWorkspace::~HalfSpaceWorkspace() = default;
HalfSpaceWorkspace::HalfSpaceWorkspace(HalfSpaceWorkspace&&) noexcept = default;
HalfSpaceWorkspace& HalfSpaceWorkspace::operator=(HalfSpaceWorkspace&&) noexcept = default;
HalfSpaceWorkspace::Impl& HalfSpaceWorkspace::impl() {
  if (!impl_) impl_ = std::make_unique<Impl>();
  return *impl_;
}

void recycle_patches(HalfSpaceWorkspace& ws, CaseResult& r) { ws.impl().grid.give_back(r.patches); }

CaseResult solve_half_space(const ContactGeometry& G, const Material& mat, double tY, double Q,
                            const HalfSpaceOptions& opt, const CaseResult* elastic_mh) {
  HalfSpaceWorkspace ws;
  CaseResult r;
  solve_half_space(G, mat, tY, Q, opt, ws, r, elastic_mh);
  return r;
}

void solve_half_space(const ContactGeometry& G, const Material& mat, double tY, double Q, const HalfSpaceOptions& opt,
                      HalfSpaceWorkspace& ws, CaseResult& out, const CaseResult* elastic_mh) {
  HalfSpaceWorkspace::Impl& w = ws.impl();
  solve_grid_case(Method::HalfSpace, G, mat, tY, Q, opt.roll, elastic_mh, w.grid, out, [&](const GridStart& gs, CaseResult r) {
    return half_space_case(G, mat, tY, Q, opt, gs, std::move(r), w);
  });
}

}  // namespace mh
