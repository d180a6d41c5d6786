#include "contact/grid/patch_driver.hpp"

#include <algorithm>
#include <cmath>

#include "contact/grid/grid_checks.hpp"
#include "contact/multi_hertz/multi_hertz.hpp"
#include "core/numfmt.hpp"
#include "core/roots.hpp"

namespace mh {

namespace {
// A patch's failure as the row's warning: the solver's measures, on the patch numbered k + 1.
Warning patch_failure(Warning w, std::size_t k) {
  w.kind = ContactKind::Patch;
  w.contact = static_cast<int>(k) + 1;
  return w;
}
}  // namespace

bool begin_grid_case(const ContactGeometry& G, const Material& mat, double tY, double Q, double roll,
                     const CaseResult* elastic_mh, CaseResult& r, GridStart* gs) {
  r.dz = NAN;
  if (!(Q > 0) || !std::isfinite(Q)) {
    r.status = CaseStatus::NoContact;
    r.message = "Q must be > 0";
    return false;
  }
  if (!G.covers(tY) || !G.wheel_curve || !G.rail_curve) {
    r.status = CaseStatus::OutOfRange;
    r.message = "t_Y = " + format_number(tY * 1e3) + " mm outside the geometry table [" +
                format_number(G.tY.front() * 1e3) + ", " + format_number(G.tY.back() * 1e3) + "] mm";
    return false;
  }
  if (!elastic_mh) {
    Material elastic = mat;
    elastic.p_lim = INFINITY;
    MultiHertzOptions o;  // the default options, with the roll of the grid's gap
    o.roll = roll;
    solve_multi_hertz(G, elastic, tY, Q, o, gs->own);
    elastic_mh = &gs->own;
  }
  gs->mh = elastic_mh;
  const CaseResult& mhr = *elastic_mh;
  if (mhr.status == CaseStatus::Ok && mhr.approach > 0 && std::isfinite(mhr.approach)) gs->dz = mhr.approach;
  return true;
}

void finish_grid_case(const ContactGeometry& G, double tY, double roll, const GridStart& gs, CaseResult& r) {
  if (gs.mh)
    for (const Warning& w : gs.mh->warnings)
      if (w.cls == WarningClass::FlangeClimb) r.warnings.push_back(w);
  if (G.wheel_curve && G.rail_curve && !G.strip_y.empty())
    for (const PatchResult& P : r.patches) {
      const double c = std::cos(P.gamma), sn = std::sin(P.gamma);
      if (G.off_profile_at(tY, P.y_r + P.s_lo * c, P.z_r + P.s_lo * sn, roll) ||
          G.off_profile_at(tY, P.y_r + P.s_hi * c, P.z_r + P.s_hi * sn, roll))
        r.warnings.emplace_back(WarningClass::OffProfile, ContactKind::Patch, P.patch);
    }
  withhold_unconverged_pressures(r);
}

double rigid_plastic_approach(const WheelRailGap& gap, double Q, double p_lim) {
  ProjectedInterpenetration area;
  return rigid_plastic_approach(gap, Q, p_lim, area);
}

double rigid_plastic_approach(const WheelRailGap& gap, double Q, double p_lim, ProjectedInterpenetration& area) {
  constexpr double kStep = 0.02e-3;  // [m] as find_patch_regions samples g(y)
  area.reset(gap, kStep);  // the profiles sampled once for the whole search
  auto F = [&](double z) { return p_lim * area.area(z) - Q; };
  double lo = 0, hi = 0.05e-3, F_lo = -Q, F_hi = F(hi);
  while (F_hi < 0 && hi < 0.1) {
    lo = hi;
    F_lo = F_hi;
    hi *= 2;
    F_hi = F(hi);
  }
  if (F_hi < 0) return hi;
  RootTolerance tol;
  tol.rel = 1e-4;
  return bracketed_root(F, lo, hi, F_lo, F_hi, tol).x;
}

ApproachBalance balance_approach(const std::vector<PatchSolver*>& solvers, const std::vector<double>& cos_gamma,
                                 double Q, double dz_start, const PatchDriverOptions& opt) {
  ApproachBalance b;
  // F(δz) − Q with δ_k = δz cos γ_k (eqs. 10–11).
  auto force = [&](double z) {
    double F = 0;
    for (std::size_t k = 0; k < solvers.size(); ++k) {
      F += solvers[k]->at_approach(z * cos_gamma[k]) * cos_gamma[k];
      ++b.evaluations;
    }
    return F - Q;
  };
  // Bracket δz from the estimate, then TOMS 748 (core/roots.hpp); every patch solver holds the
  // solution at the last δz evaluated, so the root is evaluated last.
  int outer = 0;
  double lo = 0, Flo = -Q, hi = dz_start, Fhi = force(hi), last = hi;
  ++outer;
  while (Fhi < 0 && outer < opt.max_outer) {
    lo = hi; Flo = Fhi;
    hi *= 1.5;
    Fhi = force(hi);
    last = hi;
    ++outer;
  }
  RootResult root;
  root.x = hi;
  root.f = Fhi;
  if (Fhi >= 0 && std::fabs(Fhi) > opt.force_rtol * Q && outer < opt.max_outer) {
    RootTolerance tol;
    tol.abs = 1e-15;
    tol.rel = 0;
    tol.f_abs = opt.force_rtol * Q;
    tol.max_iterations = opt.max_outer - outer;
    root = bracketed_root([&](double z) { last = z; ++outer; return force(z); }, lo, hi, Flo, Fhi, tol);
    if (root.x != last) {
      root.f = force(root.x);
      ++outer;
    }
  }
  b.dz = root.x;
  if (std::fabs(root.f) > opt.force_rtol * Q) {
    b.ok = false;
    b.message = "force balance not reached in " + std::to_string(outer) + " iterations on the approach";
    b.failure = Warning(WarningClass::NotConvergedLoad)
                    .add(Quantity::Residual, root.f / Q, '>', opt.force_rtol)
                    .add(Quantity::Iterations, outer);
  }
  return b;
}

void drive_patches(const WheelRailGap& gap, double Q, double dz_est, const PatchDriverOptions& opt,
                   const PatchSolverFactory& make, PatchDriverResult& R) {
  R.status = CaseStatus::Ok;
  R.message.clear();
  R.dz = 0;
  R.evaluations = R.passes = 0;
  R.regions.clear();
  R.solvers.clear();
  PatchDriverResult::Scratch& S = R.scratch;
  // Room for the usual few patches in every vector once: the placements swap `regions` and
  // `solvers` with their scratch, so both must hold as many.
  constexpr std::size_t kPatches = 8;
  for (auto* v : {&R.regions, &S.regions}) v->reserve(kPatches);
  for (auto* v : {&R.solvers, &S.solvers, &S.balanced}) v->reserve(kPatches);
  S.cos_gamma.reserve(kPatches);
  S.intervals.grid.reserve(2 * kPatches);
  S.intervals.cores.reserve(2 * kPatches);
  S.intervals.merged.reserve(4 * kPatches);
  double dz_ref = dz_est, dz = dz_est;
  const double margin = opt.margin;  // the grid covers the interpenetration at margin × dz_ref,
  double grow = 1;                    // its extents (x, s) times this
  double prev_ref = NAN, prev_dz = NAN;  // the last placement that was not outgrown: dz_ref ↦ dz
  // The last placement's exit test, for the warning of one that did not settle.
  int n_outgrown = 0, first_outgrown = 0;
  double last_change = 0, last_tol = 0;
  bool settled = false;
  for (int pass = 0; pass < opt.max_passes && !settled; ++pass) {
    ++R.passes;
    R.status = CaseStatus::Ok;
    R.message.clear();
    R.failure = Warning();
    std::vector<PatchRegion>& old_regions = S.regions;
    std::vector<PatchSolver*>& old_solvers = S.solvers;
    old_regions.swap(R.regions);
    old_solvers.swap(R.solvers);
    find_patch_regions(gap, dz_ref, margin * dz_ref, opt.d_comb, R.regions, S.intervals);
    for (auto& reg : R.regions) {  // an outgrown grid's room: its extents × grow about the region
      const double mid = 0.5 * (reg.s_a + reg.s_b), half = 0.5 * (reg.s_b - reg.s_a) * grow;
      reg.s_a = mid - half;
      reg.s_b = mid + half;
      reg.x_half *= grow;
    }
    R.solvers.clear();
    for (const auto& reg : R.regions) {
      std::string why;
      Warning failure(WarningClass::NotConvergedSetup);
      PatchSolver* s = make(reg, dz_ref, &why, &failure);
      if (!s) {
        R.status = CaseStatus::NotConverged;
        R.message = why;
        R.failure = patch_failure(failure, R.solvers.size());
        return;
      }
      // Warm start from the previous placement's solver nearest in rail y, if any.
      std::size_t best = old_solvers.size();
      for (std::size_t k = 0; k < old_solvers.size(); ++k)
        if (best == old_solvers.size() ||
            std::fabs(old_regions[k].P.y_ref - reg.P.y_ref) < std::fabs(old_regions[best].P.y_ref - reg.P.y_ref))
          best = k;
      if (best < old_solvers.size()) s->warm_start_from(*old_solvers[best]);
      R.solvers.push_back(s);
    }
    old_solvers.clear();
    if (R.solvers.empty()) {
      R.status = CaseStatus::NotConverged;
      R.message = "no interpenetration region found";
      R.failure = Warning(WarningClass::NotConvergedSetup).add(Quantity::Patches, 0);
      return;
    }
    if (R.solvers.size() == 1) {
      const double c = std::cos(R.regions[0].P.gamma);
      dz = R.solvers[0]->at_load(Q / c) / c;  // load control inside the one patch
      ++R.evaluations;
    } else {
      std::vector<PatchSolver*>& solvers = S.balanced;
      std::vector<double>& cos_gamma = S.cos_gamma;
      solvers.clear();
      cos_gamma.clear();
      for (std::size_t k = 0; k < R.solvers.size(); ++k) {
        solvers.push_back(R.solvers[k]);
        cos_gamma.push_back(std::cos(R.regions[k].P.gamma));
      }
      const ApproachBalance b = balance_approach(solvers, cos_gamma, Q, dz_ref, opt);
      R.evaluations += b.evaluations;
      dz = b.dz;
      if (!b.ok) {
        R.status = CaseStatus::NotConverged;
        R.message = b.message;
        R.failure = b.failure;
      }
    }
    bool outgrown = false;
    n_outgrown = first_outgrown = 0;
    for (std::size_t k = 0; k < R.solvers.size(); ++k) {
      PatchSolver* s = R.solvers[k];
      if (s->failed()) {
        R.status = CaseStatus::NotConverged;
        R.message = s->why();
        R.failure = patch_failure(s->failure(), k);
      }
      if (s->outgrown()) {
        outgrown = true;
        if (n_outgrown++ == 0) first_outgrown = static_cast<int>(k) + 1;
      }
    }
    last_change = std::fabs(dz - dz_ref);
    last_tol = opt.ref_rtol * std::fabs(dz);
    if (outgrown || dz > margin * dz_ref || std::fabs(dz - dz_ref) > opt.ref_rtol * dz) {
      // The planes go where the solution is (dz). An outgrown grid that already covered the
      // interpenetration at the solution's approach gets more room (margin × 1.3); one that did
      // not is rebuilt at the new approach with the same margin. (Placing the planes at 1.3 ×
      // max(dz, dz_ref), as before, moved a conformal flange patch's plane by several degrees per
      // pass and its grid onto the tread: the capped flange cases never settled.)
      // The extent grows about the region, not through a deeper interpenetration: at 1.6 × the
      // approach the Manchester flange region spans to the tread, where the planar gap of the
      // patch is meaningless.
      if (outgrown && !(dz > margin * dz_ref * grow)) grow *= 1.3;
      if (std::isfinite(dz) && dz > 0) {
        // The placement is a fixed point dz = F(dz_ref). In conformal flange contact F' ≈ −0.6
        // (a plane placed deeper tilts and the contact then needs less approach): plain
        // substitution oscillates for 6 passes. Secant on F(x) − x from the last two placements.
        double next = dz;
        if (!outgrown && std::isfinite(prev_ref) && prev_ref != dz_ref) {
          const double slope = (dz - prev_dz) / (dz_ref - prev_ref);
          const double z = dz_ref + (dz - dz_ref) / (1 - slope);
          if (slope < 0.5 && slope > -5 && z > 0) next = z;
        }
        if (!outgrown) { prev_ref = dz_ref; prev_dz = dz; }
        dz_ref = next;
      } else if (outgrown) {
        dz_ref *= 1.3;
      } else {
        // No positive approach carries the load on these planes: they were placed far too deep
        // (a multi-Hertzian start of 4–5 mm on a noisy R3 gauge corner, where 0.3–0.6 mm settles,
        // spans 70 mm at γ 30–41° instead of the corner's 62–64°). The same planes give the same
        // answer again: place them shallower.
        dz_ref *= 0.5;
      }
      continue;
    }
    settled = true;
  }
  R.dz = dz;
  if (!settled) {
    R.status = CaseStatus::NotConverged;
    R.message = "the contact patches did not settle (edge reached or planes moving) after " +
                std::to_string(opt.max_passes) + " placements";
    // Which exit held at the last placement: patches at their grid's edge (the first named),
    // the approach still moving (dz > margin·dz_ref implies a move above ref_rtol·dz), or both.
    Warning& w = R.failure;
    w = Warning(WarningClass::NotConvergedPlacement, n_outgrown ? ContactKind::Patch : ContactKind::None,
                first_outgrown);
    w.add(Quantity::Placements, opt.max_passes);
    if (n_outgrown) w.add(Quantity::EdgeReached, n_outgrown);
    if (last_change > last_tol) w.add(Quantity::ApproachChange, last_change, '>', last_tol);
  }
}

ApproachBalance rebalance_refined(PatchDriverResult& D, const std::vector<PatchSolver*>& refined, double Q,
                                  double dz_start, const PatchDriverOptions& opt, CaseResult& r) {
  std::vector<PatchSolver*>& solvers = D.scratch.balanced;
  std::vector<double>& cos_gamma = D.scratch.cos_gamma;
  solvers.clear();
  cos_gamma.clear();
  for (std::size_t n = 0; n < D.solvers.size(); ++n) {
    solvers.push_back(refined[n] ? refined[n] : D.solvers[n]);
    cos_gamma.push_back(std::cos(D.regions[n].P.gamma));
  }
  const ApproachBalance b = balance_approach(solvers, cos_gamma, Q, dz_start, opt);
  r.approach = b.dz;
  for (std::size_t n = 0; n < solvers.size(); ++n)
    if (solvers[n]->failed()) {
      r.status = CaseStatus::NotConverged;
      r.message = solvers[n]->why();
      r.warnings.push_back(patch_failure(solvers[n]->failure(), n));
    }
  if (!b.ok) {
    r.status = CaseStatus::NotConverged;
    r.message = b.message;
    r.warnings.push_back(b.failure);
  }
  return b;
}

}  // namespace mh
