#include "contact/strips/strip_method.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "contact/multi_hertz/multi_hertz.hpp"
#include "contact/grid/grid_checks.hpp"
#include "contact/grid/patch_driver.hpp"
#include "contact/strips/strip_collocation.hpp"
#include "geometry/gap.hpp"

namespace mh {


namespace {

struct StripPatch;

}  // namespace

struct StripWorkspace::Impl {
  GridCaseWorkspace grid;
  SolverPool<StripPatch> patches;
  std::vector<StripPatch*> fine;  ///< the locally refined patches (null: not refined)
};

namespace {

// One patch as strips: the minimum gap g(s) of each lateral row and its parabola along x. Made
// empty by the workspace's pool and set up for each patch (setup: every field as a new patch's,
// the vectors keeping their capacity).
struct StripPatch : public PatchSolver {
  void setup(const WheelRailGap& gap, const PatchRegion& R, double dz_ref, const StripMethodOptions& opt, double H,
             double p_lim) {
    P = R.P;
    H_ = H;
    p_lim_ = p_lim;
    opt_ = opt.strips;
    strips_detail::clear_result(last);
    evaluations = 0;
    peak_change = NAN;
    clear_warm();
    delta_start_ = NAN;
    solver_ready_ = false;
    geo.s.clear();
    geo.g.clear();
    geo.A.clear();
    geo.xc.clear();
    const double c = std::cos(P.gamma), ds = opt.ds;
    const double sa = R.s_a - 3 * ds, sb = R.s_b + 3 * ds;
    const int n = std::max(1, static_cast<int>(std::ceil((sb - sa) / ds)));
    const double s0 = 0.5 * (sa + sb) - (n - 1) * 0.5 * ds;
    const double X = opt.x_curvature_step;
    geo.ds = ds;
    for (int j = 0; j < n; ++j) {
      const double s = s0 + j * ds;
      // As for the half-space grid: the gap with the wheel at dz_ref, shifted by dz_ref cos γ.
      const double g0 = normal_gap(gap, P, 0, s, dz_ref) + dz_ref * c;
      const double gX = normal_gap(gap, P, X, s, dz_ref) + dz_ref * c;
      geo.s.push_back(s);
      geo.g.push_back(g0);
      geo.A.push_back(std::max((gX - g0) / (X * X), 1e-12));  // h(x, s) ≈ g(s) + A(s) x² (no yaw)
      geo.xc.push_back(0.0);
    }
  }
  double at_approach(double delta) override {
    solver().at_approach(delta, &warm_, last);
    evaluations += 1 + last.iterations;
    return last.status == StripStatus::Ok ? last.N : 0.0;
  }
  double at_load(double N) override {
    solver().at_load(N, &warm_, delta_start_, last);
    evaluations += 1 + last.iterations;
    return last.delta;
  }
  /// The loaded strips of the same patch at the previous placement, mapped by rail y onto this
  /// plane's strips: the first active set (strips.hpp: the cost changes, not the answer).
  void warm_start_from(const PatchSolver& previous) override {
    const auto* o = static_cast<const StripPatch*>(&previous);  // a strip case has no other
    // The same interpenetration depth below the deepest row as the previous placement's answer.
    if (o->last.status == StripStatus::Ok)
      delta_start_ = o->last.delta - *std::min_element(o->geo.g.begin(), o->geo.g.end()) +
                     *std::min_element(geo.g.begin(), geo.g.end());
    clear_warm();
    const double c = std::cos(P.gamma), n = static_cast<double>(geo.s.size());
    for (const StripState& st : o->last.strips) {
      const double y = o->P.y_ref + st.s * std::cos(o->P.gamma);
      const double j = std::round(((y - P.y_ref) / c - geo.s.front()) / geo.ds);
      if (!(j >= 0 && j < n) || (!warm_.loaded.empty() && warm_.loaded.back() >= static_cast<int>(j))) continue;
      warm_.loaded.push_back(static_cast<int>(j));
    }
    // The decision to refine the extents stays with the patch. Its last refined strips start the
    // next refinement: extents and amplitudes interpolated at this plane's strip centres (by rail
    // y), which keeps the start as close as the previous answer (nearest strips alone would put
    // tail strips a fraction of a strip off, and cost passes).
    warm_.end_gap = o->warm_.end_gap;
    warm_.end_gap_error = o->warm_.end_gap_error;
    if (warm_.end_gap == 1 && o->last.refined && !o->last.strips.empty()) {
      s_old_.resize(geo.s.size());
      for (std::size_t j = 0; j < geo.s.size(); ++j)
        s_old_[j] = (P.y_ref + geo.s[j] * c - o->P.y_ref) / std::cos(o->P.gamma);  // same rail y
      map_strips(o->last.strips, o->geo.ds, s_old_, geo.s, warm_.previous.strips);
    }
    warm_.previous.delta = delta_start_;
  }
  bool failed() const override { return last.status == StripStatus::NotConverged || last.status == StripStatus::InvalidInput; }
  std::string why() const override { return "strip solver: " + last.message; }
  Warning failure() const override {
    // An invalid input is a patch that could not be set up (its geometry refused: strip_patch.cpp).
    return last.status == StripStatus::InvalidInput ? Warning(WarningClass::NotConvergedSetup) : last.failure;
  }
  bool outgrown() const override {  // the first or last strip carries load
    for (const auto& st : last.strips)
      if (st.index == 0 || st.index + 1 == static_cast<int>(geo.s.size())) return true;
    return false;
  }

  /// The solution as the physical checks see it (grid_checks.hpp): one element per strip, its
  /// peak pressure, the rigid overlap δ − g(s) of each strip, and the end-gap error.
  void check_input(const StripOptions& o, PatchCheckInput& c) const {
    c.nx = 1;
    c.ns = static_cast<int>(geo.s.size());
    c.p.assign(geo.s.size(), 0.0);
    c.overlap.resize(geo.s.size());
    c.p_lim = p_lim_;
    for (std::size_t j = 0; j < geo.s.size(); ++j) {
      c.overlap[j] = last.delta - geo.g[j];
      c.approach = std::max(c.approach, c.overlap[j]);
    }
    for (const StripState& st : last.strips) c.p[static_cast<std::size_t>(st.index)] = std::min(st.q, p_lim_);
    c.end_gap_error = last.end_gap_error;
    c.end_gap_tol = o.end_gap_tol;
    c.refined = last.refined;
    c.y_ref = P.y_ref; c.gamma = P.gamma; c.s0 = geo.s.empty() ? 0 : geo.s.front(); c.ds = geo.ds;
    c.min_across = kMinAcrossStrips;
    c.element = geo.ds;
    c.peak_change = peak_change;
    c.peak_rtol = kPeakRtolStrips;
  }

  PatchPlane P;
  StripGeometry geo;
  StripResult last;
  int evaluations = 0;
  /// After a local refinement (refine_patch): |Δpmax| / pmax of the last halving; NaN: not refined.
  double peak_change = NAN;

 private:
  double H_ = 0, p_lim_ = INFINITY;
  StripOptions opt_;
  StripWarmStart warm_;  ///< the loaded strips of this patch's last solve, and its extents' refinement
  double delta_start_ = NAN;  ///< the first approach of load control (from the previous placement)
  std::unique_ptr<StripSolver> solver_;  ///< kept from patch to patch with its memory (reset on first use)
  bool solver_ready_ = false;            ///< solver_ set up for this patch
  std::vector<double> s_old_;            ///< warm_start_from's strip centres in the previous placement
  const StripSolver& solver() {
    if (!solver_) solver_ = std::make_unique<StripSolver>(geo, H_, p_lim_, opt_);
    else if (!solver_ready_) solver_->reset(geo, H_, p_lim_, opt_);
    solver_ready_ = true;
    return *solver_;
  }
  /// warm_ as a new StripWarmStart, its vectors kept.
  void clear_warm() {
    warm_.loaded.clear();
    warm_.end_gap = -1;
    warm_.end_gap_error = NAN;
    strips_detail::clear_result(warm_.previous);
  }
};

// The loaded strips of a solution as elements (grid_checks.hpp, elements_across).
int strips_across(const StripPatch& k) {
  thread_local std::vector<double> q;  // kept: no allocation per call once grown
  q.assign(k.geo.s.size(), 0.0);
  for (const StripState& st : k.last.strips) q[static_cast<std::size_t>(st.index)] = st.q;
  return elements_across(q, 1, static_cast<int>(q.size()));
}

// A patch with fewer strips across than kMinAcrossStrips (grid_checks.hpp), solved again on its
// own at the load N the case gave it, on its region with ds halved, until it has that many strips
// and its peak moves by at most kPeakRtolStrips between two widths; at most opt.max_refinements
// halvings (as the half-space method's refine_patch; with several patches the caller then finds the
// shared approach again). Returns the finest patch solved (null: none could be, the coarse one stays).
StripPatch* refine_patch(const WheelRailGap& gap, const PatchRegion& region, double dz, const StripPatch& coarse,
                         const StripMethodOptions& opt, double H, double p_lim, StripWorkspace::Impl& ws) {
  StripPatch* best = nullptr;
  double p_prev = coarse.last.pmax;
  StripMethodOptions o = opt;
  for (int level = 1; level <= opt.max_refinements; ++level) {
    o.ds *= 0.5;
    StripPatch* f = &ws.patches.take();
    f->setup(gap, region, dz, o, H, p_lim);
    f->at_load(coarse.last.N);
    if (f->failed() || f->outgrown() || f->last.status != StripStatus::Ok) break;
    f->peak_change = std::fabs(f->last.pmax - p_prev) / f->last.pmax;
    f->evaluations += best ? best->evaluations : coarse.evaluations;
    const bool settled = strips_across(*f) >= kMinAcrossStrips && f->peak_change <= kPeakRtolStrips;
    p_prev = f->last.pmax;
    best = f;
    if (settled) break;
  }
  return best;
}

}  // namespace

namespace {

// The case after begin_grid_case (r holds its method; gs the start).
CaseResult strip_case(const ContactGeometry& G, const Material& mat, double tY, double Q, const StripMethodOptions& opt,
                      const GridStart& gs, CaseResult r, StripWorkspace::Impl& ws) {
  ws.patches.begin_case();
  ws.grid.n_checks = 0;
  double dz_est = gs.dz;
  const WheelRailGap gap(G, tY, NAN, opt.roll);  // upright at roll 0 (the same bits)
  // Plastic model: the capped approach is at least the elastic one and at least the rigid–
  // perfectly-plastic one (as for the half-space method).
  if (std::isfinite(mat.p_lim))
    dz_est = std::max(dz_est, rigid_plastic_approach(gap, Q, mat.p_lim, ws.grid.projected));
  const double H = mat.compliance(), p_lim = mat.p_lim;
  const PatchDriverOptions dopt = patch_driver_options(opt, opt.max_passes);
  // The factory's state behind one pointer: a std::function keeps a lambda of one reference in
  // place (no allocation).
  struct Make {
    const WheelRailGap& gap;
    const StripMethodOptions& opt;
    double H, p_lim;
    StripWorkspace::Impl& ws;
  } make{gap, opt, H, p_lim, ws};
  PatchDriverResult& D = ws.grid.driver;
  drive_patches(gap, Q, dz_est, dopt, [&make](const PatchRegion& reg, double dz_ref, std::string*, Warning*) -> PatchSolver* {
    StripPatch& k = make.ws.patches.take();
    k.setup(make.gap, reg, dz_ref, make.opt, make.H, make.p_lim);
    return &k;
  }, D);
  r.status = D.status;
  r.message = D.message;
  if (D.status == CaseStatus::NotConverged) r.warnings.push_back(D.failure);
  r.approach = D.dz;
  int evaluations = 0;
  // The physical checks' inputs of the reported patches: ws.grid.checks[0 … n_checks).
  // Patches resolved by too few strips: refined locally (refine_patch).
  std::vector<StripPatch*>& fine = ws.fine;
  fine.assign(D.solvers.size(), nullptr);
  bool any_fine = false;
  for (std::size_t n = 0; n < D.solvers.size() && r.status == CaseStatus::Ok && n < D.regions.size(); ++n) {
    const StripPatch* coarse = static_cast<const StripPatch*>(D.solvers[n]);
    if (coarse->last.status != StripStatus::Ok || !(coarse->last.N > 0) || strips_across(*coarse) >= kMinAcrossStrips)
      continue;
    fine[n] = refine_patch(gap, D.regions[n], D.dz, *coarse, opt, H, p_lim, ws);
    any_fine = any_fine || fine[n];
  }
  if (any_fine && D.solvers.size() > 1) {
    // The shared approach found again with the refined patches (as the half-space method does).
    std::vector<PatchSolver*>& refined = ws.grid.refined;
    refined.assign(fine.begin(), fine.end());
    D.dz = rebalance_refined(D, refined, Q, D.dz, dopt, r).dz;
  }
  for (std::size_t n = 0; n < D.solvers.size(); ++n) {
    const StripPatch* coarse = static_cast<const StripPatch*>(D.solvers[n]);
    const StripPatch& k = fine[n] ? *fine[n] : *coarse;
    evaluations += k.evaluations;
    const StripResult& S = k.last;
    // A patch solve that did not converge keeps its last (closest) iterate, as every
    // not_converged row does (docs/outputs.md); the case's status and message say why.
    if ((S.status != StripStatus::Ok && S.status != StripStatus::NotConverged) || S.N <= 0) continue;
    PatchResult pr = ws.grid.take_patch();  // a new one, its vectors a spare's capacity
    pr.y_r = k.P.y_ref;
    pr.z_r = gap.z_rail(k.P.y_ref);
    pr.y_w = gap.y_wheel(k.P.y_ref);
    pr.r_roll = gap.rolling_radius(k.P.y_ref);
    pr.gamma = k.P.gamma;
    pr.iterations = S.iterations;
    pr.end_gap_error = S.end_gap_error;
    pr.refined = S.refined;
    pr.N = S.N;
    pr.pmax = S.pmax;
    pr.area = S.area;
    // A refined patch alone in its case found its own normal approach by load control.
    pr.approach = (fine[n] && D.solvers.size() == 1 ? S.delta : D.dz * std::cos(k.P.gamma)) -
                  *std::min_element(k.geo.g.begin(), k.geo.g.end());
    double s_lo = INFINITY, s_hi = -INFINITY, ls = 0, lc = 0;
    for (const StripState& st : S.strips) {
      pr.length_x = std::max(pr.length_x, 2 * st.a);
      s_lo = std::min(s_lo, st.s);
      s_hi = std::max(s_hi, st.s);
      ls += st.load * st.s;
      lc += st.load * st.c;
      ++pr.n_elements;
      if (st.plastic) {
        // Flat top at p_lim where q √(1 − t²) ≥ p_lim: |t| ≤ √(1 − r²), r = p_lim / q (§9.6).
        const double rr = p_lim / st.q, half = st.a * std::sqrt(std::max(0.0, 1 - rr * rr));
        pr.plastic_area += 2 * half * k.geo.ds;
        pr.capped_load += 2 * half * k.geo.ds * p_lim;
      }
      if (opt.keep_strips)
        pr.strips.push_back({st.s, k.P.y_ref + st.s * std::cos(k.P.gamma), st.c, st.a, st.q, st.plastic});
    }
    pr.width_s = S.strips.empty() ? 0 : s_hi - s_lo + k.geo.ds;
    if (!S.strips.empty()) { pr.s_lo = s_lo; pr.s_hi = s_hi; }
    pr.s_centroid = S.N > 0 ? ls / S.N : 0;
    pr.x_centroid = S.N > 0 ? lc / S.N : 0;
    r.Fz += pr.N * std::cos(pr.gamma);
    r.Fy += pr.N * std::sin(pr.gamma);
    r.pmax = std::max(r.pmax, pr.pmax);
    r.area += pr.area;
    if (S.n_outliers > 0 && S.worst_outlier >= 0) {
      // The known failure mode (§9.7): a strip whose peak pressure stands far above its
      // neighbours' (q_MPa: that peak, min(amplitude, p_lim)).
      const StripState& w = S.strips[static_cast<std::size_t>(S.worst_outlier)];
      Warning o(WarningClass::StripOutlier, ContactKind::Patch, static_cast<int>(r.patches.size()) + 1);
      o.add(Quantity::Strips, S.n_outliers)
          .add(Quantity::YRailStrip, k.P.y_ref + w.s * std::cos(k.P.gamma))
          .add(Quantity::QStrip, std::min(w.q, p_lim));
      r.warnings.push_back(o);
    }
    PatchCheckInput& check = ws.grid.next_check();
    k.check_input(opt.strips, check);
    pr.elements_across = elements_across(check.p, check.nx, check.ns);
    pr.element = k.geo.ds;
    r.patches.push_back(std::move(pr));
  }
  r.iterations = evaluations;
  close_grid_case(ws.grid.checks.data(), ws.grid.n_checks, Q, kForceBalanceRtol, r);
  return r;
}

}  // namespace

StripWorkspace::StripWorkspace() = default;
StripWorkspace::~StripWorkspace() = default;
StripWorkspace::StripWorkspace(StripWorkspace&&) noexcept = default;
StripWorkspace& StripWorkspace::operator=(StripWorkspace&&) noexcept = default;
StripWorkspace::Impl& StripWorkspace::impl() {
  if (!impl_) impl_ = std::make_unique<Impl>();
  return *impl_;
}

void recycle_patches(StripWorkspace& ws, CaseResult& r) { ws.impl().grid.give_back(r.patches); }

CaseResult solve_strip_method(const ContactGeometry& G, const Material& mat, double tY, double Q,
                              const StripMethodOptions& opt, const CaseResult* elastic_mh) {
  StripWorkspace ws;
  CaseResult r;
  solve_strip_method(G, mat, tY, Q, opt, ws, r, elastic_mh);
  return r;
}

void solve_strip_method(const ContactGeometry& G, const Material& mat, double tY, double Q,
                        const StripMethodOptions& opt, StripWorkspace& ws, CaseResult& out,
                        const CaseResult* elastic_mh) {
  StripWorkspace::Impl& w = ws.impl();
  solve_grid_case(Method::Strips, G, mat, tY, Q, opt.roll, elastic_mh, w.grid, out, [&](const GridStart& gs, CaseResult r) {
    return strip_case(G, mat, tY, Q, opt, gs, std::move(r), w);
  });
}

}  // namespace mh
