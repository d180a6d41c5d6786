#include "contact/solve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/ellipse/hertz_validity.hpp"
#include "contact/judge/judge.hpp"
#include "contact/half_space/tangential_patch.hpp"
#include "contact/tangential/tangential_solve.hpp"
#include "core/roots.hpp"
#include "geometry/gap.hpp"

namespace mh {

namespace {

// The half-space options of a solve: with friction the patch grids' pressures are kept, the
// tangential step solves on them (solve_tangential_patches); the case's roll (method.md §3.8).
HalfSpaceOptions half_space_options(const MethodOptions& opt) {
  HalfSpaceOptions o = opt.half_space;
  o.keep_pressure = o.keep_pressure || opt.tangential.enabled();
  o.roll = opt.multi_hertzian.roll;
  return o;
}

// The strip-method options of a solve: with friction every patch's strips are kept, the
// tangential step lays them on a grid (solve_tangential_strips); the case's roll.
StripMethodOptions strip_options(const MethodOptions& opt) {
  StripMethodOptions o = opt.strips;
  o.keep_strips = o.keep_strips || opt.tangential.enabled();
  o.roll = opt.multi_hertzian.roll;
  return o;
}

// The strip method's tangential problem (docs/tangential.md, "Strips"): each strip patch's
// pressure laid on a grid of its own strip width across — on strip j the semi-ellipse
// q_j √(1 − ((x − c_j)/a_j)²), flat-topped at p_lim when plastic — and square-or-finer elements
// along x, then solved there by the exact steady-rolling solver as a half-space patch
// (solve_tangential_patch). The grid's pressures are scaled to carry the patch's N exactly (the
// raster's quadrature error), so that in full sliding |F| = μN. A patch whose solve fails keeps
// solved = false (the row then carries tangential_unsupported).
void solve_tangential_strips(CaseResult& r, const Material& mat, double mu, bool keep_traction,
                             TangentialPatchWorkspace* ws) {
  if (r.method != Method::Strips || !r.tangential.asked || !(mu > 0)) return;
  PatchResult local;
  PatchResult& g = ws ? ws->raster : local;
  for (std::size_t k = 0; k < r.patches.size(); ++k) {
    PatchResult& P = r.patches[k];
    if (P.strips.empty() || !(P.N > 0) || !(P.element > 0)) continue;
    const double ds = P.element;
    double s_lo = INFINITY, s_hi = -INFINITY, x_lo = INFINITY, x_hi = -INFINITY;
    for (const StripOut& S : P.strips) {
      s_lo = std::min(s_lo, S.s);
      s_hi = std::max(s_hi, S.s);
      x_lo = std::min(x_lo, S.c - S.a);
      x_hi = std::max(x_hi, S.c + S.a);
    }
    // At least 32 elements along the patch, none longer than the strip width.
    const double dx = std::min(ds, (x_hi - x_lo) / 32);
    g.patch = P.patch;
    g.nx = static_cast<int>(std::ceil((x_hi - x_lo) / dx));
    g.ns = static_cast<int>(std::lround((s_hi - s_lo) / ds)) + 1;
    g.dx = dx;
    g.ds = ds;
    g.x0 = x_lo + 0.5 * dx;
    g.s0 = s_lo;
    g.p.assign(static_cast<std::size_t>(g.nx) * static_cast<std::size_t>(g.ns), 0.0);
    double total = 0;
    for (const StripOut& S : P.strips) {
      const long j = std::lround((S.s - s_lo) / ds);
      if (j < 0 || j >= g.ns || !(S.a > 0)) continue;
      for (int i = 0; i < g.nx; ++i) {
        const double u = (g.x0 + i * dx - S.c) / S.a;
        if (std::fabs(u) >= 1) continue;
        double p = S.q * std::sqrt(1 - u * u);
        if (S.plastic) p = std::min(p, mat.p_lim);
        g.p[static_cast<std::size_t>(j) * static_cast<std::size_t>(g.nx) + static_cast<std::size_t>(i)] = p;
        total += p * dx * ds;
      }
    }
    if (!(total > 0)) continue;
    for (double& p : g.p) p *= P.N / total;
    const Creepages c = P.t.c;
    // keep_traction: the tractions on this grid, with its pressure (traction_grid.hpp).
    const HalfSpaceTangentialResult t = solve_tangential_patch(g, mat, c, mu, {}, keep_traction ? &P.traction : nullptr,
                                                               ws ? &ws->slot(k) : nullptr);
    if (t.status != TangentialStatus::Ok) continue;
    P.t = t.forces;
    P.t.c = c;
    P.t.mu = mu;
  }
  sum_tangential(r, mu);
}

// The tangential problem of a solved row (docs/tangential.md): creepages of every contact,
// FASTSIM per ellipse, the exact solution per half-space patch and per strip patch (above), the
// case sums.
void tangential_step(CaseResult& r, const Material& mat, double tY, const MethodOptions& opt,
                     TangentialPatchWorkspace* ws = nullptr) {
  solve_tangential(r, mat, tY, opt.tangential);
  solve_tangential_patches(r, mat, opt.tangential.mu, opt.tangential.keep_traction, ws);
  solve_tangential_strips(r, mat, opt.tangential.mu, opt.tangential.keep_traction, ws);
}

// The slope df/dQ_n of the vertical equilibrium's f(Q_n) = Q_n + Fz_creep(Q_n) − Q (below) at a
// solved row r (f0 = f there). Multi-Hertzian rows whose loaded ellipses are elastic: each
// ellipse's N_i follows the rigid approach δz (h_i = (δz − g_i) cos γ_i, eq. 11:
// dN_i/dδz = (dN/dh0)_i cos γ_i, dQ_n/dδz = Σ (dN/dh0)_i cos² γ_i), its creep force's share of
// Fz_creep = Σ Fy_i sin γ_i by FASTSIM's load slope (fastsim.hpp, load_slope: Kalker's
// similarity, marched where |sin γ_i| ≥ kLoadSlopeSinGamma) or else by the scaling below; exact
// for a fixed set of loaded ellipses where the load slope is marched. Otherwise (grid patches,
// plastic ellipses) from the scaling of the creep forces with the load, Fz_creep ∝ Q_n^p: p = 1 in
// full slip (F = μN), 2/3 in the linear limit (F ∝ c² ∝ N^(2/3), Hertz), in between by the
// saturation |F|/(μN).
double equilibrium_slope(const CaseResult& r, double Q, double f0, double mu) {
  auto p_of = [](double sat) { return (2.0 + std::clamp(sat, 0.0, 1.0)) / 3.0; };
  double dQn = 0, dFz = 0;
  bool ellipses = r.patches.empty() && !r.loaded.empty();
  for (const LoadedEllipse& L : r.loaded) {
    if (!(L.s.N > 0)) continue;
    if (L.s.plastic || !(L.s.dN_dh0 > 0) || !L.t.solved) ellipses = false;
    const double dN = L.s.dN_dh0 * L.cos_gamma;  // dN_i/dδz
    const double dFy_dN = std::isfinite(L.t.dFy_dN) ? L.t.dFy_dN
                                                    : p_of(std::hypot(L.t.Fx, L.t.Fy) / (mu * L.s.N)) * L.t.Fy / L.s.N;
    dQn += dN * L.cos_gamma;
    dFz += dFy_dN * L.sin_gamma * dN;
  }
  if (ellipses && dQn > 0 && std::isfinite(dFz)) return 1.0 + dFz / dQn;
  const double sat = std::isfinite(r.tangential.F_over_muN) ? r.tangential.F_over_muN : 1.0;
  return 1.0 + p_of(sat) * f0 / Q;
}

// The vertical equilibrium with the creep forces (docs/tangential.md, "Vertical equilibrium"):
//   Q = Σ N_i cos γ_i + Σ Fy_i sin γ_i,
// Fy_i the lateral creep force ON THE WHEEL along the contact plane's ŝ = (0, cos γ, sin γ)
// (tangential_types.hpp), so that Fy_i sin γ_i is its share of the load, downwards on the rail
// (TangentialSums::Fz_creep). The normal solvers balance Q_n = Σ N_i cos γ_i; every contact's N_i
// follows from the one rigid approach, so a root in Q_n is a root in the approach — the split
// between contacts is the normal solver's at that approach, each contact's creep force recomputed
// at its own N_i. f(Q_n) = Q_n + Fz_creep(Q_n) − Q is nearly linear (|dFz_creep/dQ_n| ≤ μ tan γ):
// secant steps from Q_n = Q (below) approach the root, TOMS 748 (core/roots.hpp) closes it once
// they step across it. Where the creep forces lift the wheel faster than the load grows
// (μ tan γ ≥ 1 in full slip: Nadal's limit) f has no root and the row is not_converged with a message saying so.
// r: solved at Q with its tangential step; resolve(Q_n, r) solves the normal problem at Q_n
// into r with its tangential step. Returns true when r was solved again (at another load).
template <class Resolve>
bool creep_equilibrium(CaseResult& r, double Q, const TangentialOptions& t, Resolve&& resolve) {
  if (!t.enabled() || !t.vertical_equilibrium || is_failure(r.status) || !r.tangential.solved) return false;
  double last = Q;  // the load r holds the solution of
  bool failed = false, resolved = false;
  auto f = [&](double Qn) -> double {
    if (Qn != last) {
      resolve(Qn, r);
      last = Qn;
      resolved = true;
    }
    if (is_failure(r.status) || !r.tangential.solved) {
      failed = true;
      return NAN;
    }
    return Qn + r.tangential.Fz_creep - Q;
  };
  auto fail = [&](const std::string& why) {
    r.status = CaseStatus::NotConverged;
    r.message = "no vertical equilibrium with the creep forces (Q = sum N cos(gamma) + Fy sin(gamma)): " + why;
    return resolved;
  };
  const double f_abs = t.equilibrium_tolerance * Q;  // 1e-7: 1 mN at 10 kN; the normal solvers' residuals are below
  double x0 = Q, f0 = f(Q);
  double x1 = x0, f1 = f0;
  if (std::fabs(f0) > f_abs) {
    // Secant steps from Q: the first slope equilibrium_slope's (above), then the secant's own.
    // They stop at the first sign change short of the tolerance (TOMS 748 below closes the root).
    double slope = std::clamp(equilibrium_slope(r, Q, f0, t.mu), 0.5, 2.0);
    for (int k = 0; k < 8 && !failed && std::fabs(f1) > f_abs && (k == 0 || (f0 < 0) == (f1 < 0)); ++k) {
      if (k > 0) {
        slope = (f1 - f0) / (x1 - x0);
        x0 = x1;
        f0 = f1;
      }
      if (!(slope > 0)) return fail("the creep forces' vertical share falls faster than the normal load grows (flange climbing: mu tan(gamma) >= 1)");
      const double x = x0 - f0 / slope;
      if (!(x > 0)) return fail("the normal load would have to be negative (flange climbing: mu tan(gamma) >= 1)");
      x1 = x;
      f1 = f(x1);
    }
    if (failed) return fail(r.message.empty() ? std::string("a solve on the way failed") : r.message);
    if (std::fabs(f1) > f_abs) {
      if ((f0 < 0) == (f1 < 0)) return fail("no bracket of the root found in 8 secant steps");
      RootTolerance tol;
      tol.f_abs = f_abs;
      tol.rel = 1e-12;
      tol.max_iterations = 40;
      const bool up = x0 < x1;
      const RootResult root = bracketed_root(f, up ? x0 : x1, up ? x1 : x0, up ? f0 : f1, up ? f1 : f0, tol);
      if (failed) return fail(r.message.empty() ? std::string("a solve on the way failed") : r.message);
      if (!(std::fabs(root.f) <= std::max(1e-5, 10 * t.equilibrium_tolerance) * Q)) return fail("the root finder stopped at a residual of " + std::to_string(root.f / Q));
      f(root.x);
    }
  }
  r.Fz += r.tangential.Fz_creep;
  r.residual = (r.Fz - Q) / Q;
  return resolved;
}

// The leading `auto` warnings of a row (why it was handed on: to the strips, then to the
// half-space or its rejection; at most two), kept across a solve again, without allocating.
struct AutoWarnings {
  static constexpr int kMax = 4;
  Warning w[kMax];
  int n = 0;
};
AutoWarnings auto_warnings(const CaseResult& r) {
  AutoWarnings a;
  for (const Warning& x : r.warnings) {
    if (x.cls != WarningClass::Auto || a.n == AutoWarnings::kMax) break;
    a.w[a.n++] = x;
  }
  return a;
}

// The tangential step of a row solved by method m at Q, with the vertical equilibrium (above):
// the row's method is solved again at the loads the root asks for. ws: the caller's workspace
// (or null).
bool tangential_with_equilibrium(CaseResult& r, const ContactGeometry& G, const Material& mat, double tY, double Q,
                                 const MethodOptions& opt, GridWorkspace* ws) {
  // At Q with FASTSIM's load slope when the equilibrium will aim with it (equilibrium_slope).
  TangentialOptions first = opt.tangential;
  first.fastsim.load_slope = first.vertical_equilibrium && r.method == Method::MultiHertzian;
  solve_tangential(r, mat, tY, first);
  TangentialPatchWorkspace* tws = ws ? &ws->tangential : nullptr;
  solve_tangential_patches(r, mat, opt.tangential.mu, opt.tangential.keep_traction, tws);
  solve_tangential_strips(r, mat, opt.tangential.mu, opt.tangential.keep_traction, tws);

  const AutoWarnings handed = auto_warnings(r);
  const Method m = r.method;
  // The multi-Hertzian row's creep forces at the loads the root asks for after two full solves
  // (at Q and the first step): extrapolated from those two (tangential_solve.hpp,
  // extrapolate_tangential) where that is accurate to the equilibrium's tolerance, FASTSIM again
  // otherwise: most steps past the first are short (docs/tangential.md "Cost"), and cost a
  // normal solve only.
  const bool extrapolate = m == Method::MultiHertzian && opt.tangential.enabled() &&
                           opt.tangential.vertical_equilibrium && !opt.tangential.keep_traction;
  CreepAnchors anchor[2];  // [1] the last full solve, [0] the one before
  if (extrapolate) anchor[1].take(r);
  const bool again = creep_equilibrium(r, Q, opt.tangential, [&](double Qn, CaseResult& out) {
    if (m == Method::MultiHertzian) {
      solve_multi_hertz(G, mat, tY, Qn, opt.multi_hertzian, out);
      if (extrapolate &&
          extrapolate_tangential(out, anchor[0], anchor[1], opt.tangential.mu, opt.tangential.equilibrium_tolerance))
        return;
      tangential_step(out, mat, tY, opt, tws);
      if (extrapolate) {
        anchor[0] = anchor[1];
        anchor[1].take(out);
      }
      return;
    } else if (m == Method::Strips) {
      if (ws) solve_strip_method(G, mat, tY, Qn, strip_options(opt), ws->strips, out);
      else out = solve_strip_method(G, mat, tY, Qn, strip_options(opt));
    } else if (ws) {
      solve_half_space(G, mat, tY, Qn, half_space_options(opt), ws->half_space, out);
    } else {
      out = solve_half_space(G, mat, tY, Qn, half_space_options(opt));
    }
    tangential_step(out, mat, tY, opt, tws);
  });
  if (again && handed.n > 0) r.warnings.insert(r.warnings.begin(), handed.w, handed.w + handed.n);
  return again;
}

// "auto" (docs/method.md §9): the multi-Hertzian answer is kept when it can be trusted — it
// converged and every loaded ellipse passes the Hertz validity test, with no non-Hertzian
// candidate excluded; otherwise the case is solved by the strip method. The `method` column says
// which one solved it, and a case handed over carries the warning auto:strips:<reason>. ws (may be
// null): the grid methods' memory for the cases handed on (the same bytes).
void solve_auto(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt,
                GridWorkspace* ws, CaseResult& out) {
  // The rows in the workspace's (or, without one, these) results, the one kept swapped into out;
  // out's patches from an earlier row go back to their method's spares first.
  // Each of them is given room for a usual row (reserve_row), so that trading places grows nothing.
  GridWorkspace::AutoRows local;
  GridWorkspace::AutoRows& rows = ws ? ws->auto_rows : local;
  if (ws) {
    if (out.method == Method::Strips) recycle_patches(ws->strips, out);
    if (out.method == Method::HalfSpace) recycle_patches(ws->half_space, out);
    for (CaseResult* r : {&out, &rows.mh, &rows.mh_at_Q, &rows.elastic_mh, &rows.strips, &rows.half_space}) reserve_row(*r);
  }
  CaseResult& mhr = rows.mh;
  solve_multi_hertz(G, mat, tY, Q, opt.multi_hertzian, mhr);
  if (mhr.status == CaseStatus::OutOfRange) {
    std::swap(out, mhr);
    return;
  }
  // With friction the row is first balanced with its creep forces (tangential_with_equilibrium),
  // so that the tests below judge the row that would be kept; the grid methods still start from
  // the solution at Q (a copy kept for them).
  CaseResult& mh_at_Q = rows.mh_at_Q;
  if (opt.tangential.enabled()) mh_at_Q = mhr;
  tangential_with_equilibrium(mhr, G, mat, tY, Q, opt, nullptr);
  // The judge's tests on the multi-Hertzian answer (judge.hpp): the Hertz validity of each
  // ellipse, an excluded non-Hertzian candidate, interacting ellipses, a corner of the gap inside
  // a patch (hertz_validity.hpp, gap_kink: the edge-gap test measures the profiles' sampled
  // curvature at the patch edges, which on a measured flange misses it, and the pressure there is
  // singular; docs/methods.md, auto). The first failure, in that order, is the reason given.
  add_validity_warnings(mhr, G, mat, tY, opt);
  bool hand_on = true;
  Warning why = Warning::auto_to(Method::Strips, AutoReason::Status);
  auto first = [&](WarningClass c) {
    return std::find_if(mhr.warnings.begin(), mhr.warnings.end(), [c](const Warning& w) { return w.cls == c; });
  };
  if (mhr.status != CaseStatus::Ok) {
    why.status = mhr.status;
  } else if (auto w = first(WarningClass::NonHertzian); w != mhr.warnings.end()) {
    why.contact = w->contact;
    // The gap-corner test runs only on rows that passed the others: its warning is alone.
    if (w->n == 1 && w->m[0].q == Quantity::GapKink) {
      why.reason = AutoReason::GapKink;
      why.add(Quantity::GapKink, w->m[0].value, w->m[0].rel, w->m[0].limit);
    } else {
      why.reason = AutoReason::NotHertzian;
    }
  } else if (first(WarningClass::NonHertzianExcluded) != mhr.warnings.end()) {
    why.reason = AutoReason::CandidateExcluded;
  } else if (auto i = first(WarningClass::Interacting); i != mhr.warnings.end()) {
    // Contacts close enough to interact elastically: each ellipse is solved on its own, while the
    // strip method couples them (the gauge-shoulder case of §9; judge.hpp).
    why.reason = AutoReason::Interact;
    why.contact = i->contact;
    why.contact2 = i->contact2;
  } else {
    hand_on = false;
  }
  if (!hand_on) {
    add_vehicle_state_warnings(mhr, G);  // after the tangential step: Y includes the creep forces
    decide_status(mhr);
    std::swap(out, mhr);
    return;
  }
  // The grid methods start from the elastic multi-Hertzian solution: mhr itself when the model
  // is elastic, else one elastic solve shared by strips and the half-space fallback.
  CaseResult& elastic_mh = rows.elastic_mh;
  const CaseResult* start = opt.tangential.enabled() ? &mh_at_Q : &mhr;
  if (std::isfinite(mat.p_lim)) {
    Material elastic = mat;
    elastic.p_lim = INFINITY;
    MultiHertzOptions rolled;  // the default options, with the case's roll
    rolled.roll = opt.multi_hertzian.roll;
    solve_multi_hertz(G, elastic, tY, Q, rolled, elastic_mh);
    start = &elastic_mh;
  }
  CaseResult& sr = rows.strips;
  if (ws) solve_strip_method(G, mat, tY, Q, strip_options(opt), ws->strips, sr, start);
  else sr = solve_strip_method(G, mat, tY, Q, strip_options(opt), start);
  sr.warnings.insert(sr.warnings.begin(), why);
  // A strip answer is kept when it passes its physical checks (contact/grid/grid_checks.hpp: no
  // warning of a validity class). Otherwise (not converged, e.g. a load inside a jump of its
  // N(δ), docs/strips.md, or a strip_outlier, a hole, ...) the exact half-space method, slower
  // but robust, solves the case, and its answer is taken only if it passes the same checks; else
  // the strip row stays, with its status and warnings.
  WarningClass strip_failed;
  const bool strip_fails = first_validity_failure(sr.warnings, &strip_failed);
  if (sr.status == CaseStatus::Ok && !strip_fails) {  // judged by solve_contact
    std::swap(out, sr);
    return;
  }
  Warning to_hs = Warning::auto_to(Method::HalfSpace, AutoReason::StripsNotConverged);
  if (sr.status == CaseStatus::Ok) {
    to_hs.reason = AutoReason::StripsFailed;
    to_hs.failed = strip_failed;
  }
  CaseResult& hr = rows.half_space;
  if (ws) solve_half_space(G, mat, tY, Q, half_space_options(opt), ws->half_space, hr, start);
  else hr = solve_half_space(G, mat, tY, Q, half_space_options(opt), start);
  WarningClass hs_failed;
  const bool hs_fails = first_validity_failure(hr.warnings, &hs_failed);
  if (hr.status != CaseStatus::Ok || hs_fails) {
    Warning rejected = Warning::auto_to(Method::HalfSpace, AutoReason::HalfSpaceRejected);
    rejected.status = hr.status;
    if (hs_fails) {
      rejected.has_failed = true;
      rejected.failed = hs_failed;
    }
    sr.warnings.push_back(rejected);
    std::swap(out, sr);
    return;
  }
  hr.warnings.insert(hr.warnings.begin(), to_hs);
  hr.warnings.insert(hr.warnings.begin(), why);
  std::swap(out, hr);
}

}  // namespace

CaseResult solve_contact(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt) {
  CaseResult r;
  switch (opt.method) {
    case Method::Auto: solve_auto(G, mat, tY, Q, opt, nullptr, r); break;
    case Method::HalfSpace: r = solve_half_space(G, mat, tY, Q, half_space_options(opt)); break;
    case Method::Strips: r = solve_strip_method(G, mat, tY, Q, strip_options(opt)); break;
    case Method::MultiHertzian:
    default: r = solve_multi_hertz(G, mat, tY, Q, opt.multi_hertzian); break;
  }
  // Whether the row can be trusted, by one judge for every method (judge.hpp, docs/status.md).
  // auto's multi-Hertzian rows were judged already (their tests decided whether to keep them);
  // the grid rows it hands back are judged here like any other.
  if (opt.method != Method::Auto || r.method != Method::MultiHertzian) {
    tangential_with_equilibrium(r, G, mat, tY, Q, opt, nullptr);
    judge_case(r, G, mat, tY, opt);
  }
  return r;
}

void solve_contact(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt,
                   CaseResult& out) {
  solve_contact(G, mat, tY, Q, opt, out, nullptr);
}

void solve_contact(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt,
                   CaseResult& out, GridWorkspace* ws) {
  if (!solve_contact_unjudged(G, mat, tY, Q, opt, out, ws)) judge_case(out, G, mat, tY, opt);  // as above
}

bool solve_contact_unjudged(const ContactGeometry& G, const Material& mat, double tY, double Q,
                            const MethodOptions& opt, CaseResult& out, GridWorkspace* ws) {
  switch (opt.method) {
    case Method::MultiHertzian: solve_multi_hertz(G, mat, tY, Q, opt.multi_hertzian, out); break;
    case Method::HalfSpace:
      if (!ws) {
        out = solve_contact(G, mat, tY, Q, opt);
        return true;
      }
      solve_half_space(G, mat, tY, Q, half_space_options(opt), ws->half_space, out);
      break;
    case Method::Strips:
      if (!ws) {
        out = solve_contact(G, mat, tY, Q, opt);
        return true;
      }
      solve_strip_method(G, mat, tY, Q, strip_options(opt), ws->strips, out);
      break;
    case Method::Auto:
      if (!ws) {
        out = solve_contact(G, mat, tY, Q, opt);
        return true;
      }
      // auto with the workspace: as solve_contact above, its grid solves in ws's memory.
      solve_auto(G, mat, tY, Q, opt, ws, out);
      if (out.method != Method::MultiHertzian) {
        tangential_with_equilibrium(out, G, mat, tY, Q, opt, ws);
        judge_case(out, G, mat, tY, opt);
      }
      return true;
    default: out = solve_contact(G, mat, tY, Q, opt); return true;
  }
  tangential_with_equilibrium(out, G, mat, tY, Q, opt, ws);
  return false;
}

void set_pair_band(PairGeometry& pg, const TrackSetup& track, const GeometryOptions& geo, bool on, Method method) {
  set_band_geometries(pg, track, geo, on && method != Method::MultiHertzian,
                      on && (method == Method::MultiHertzian || method == Method::Auto));
}

void add_smoothing_band(CaseResult& r, const BandGeometries& band, const Material& mat, double tY, double Q,
                        const MethodOptions& opt) {
  const bool ellipse = r.method == Method::MultiHertzian;
  const ContactGeometry* half = (ellipse ? band.window_half : band.half).get();
  const ContactGeometry* twice = (ellipse ? band.window_twice : band.twice).get();
  if (!half || !twice || is_failure(r.status)) return;
  // Like with like: the method that solved the row (for `auto`, the L/2 surface must not hand a
  // strip row back to the ellipses, nor the ellipses' L/2 tables an ellipse row to the strips).
  MethodOptions mo = opt;
  mo.method = r.method;
  mo.half_space.keep_pressure = false;
  mo.strips.keep_strips = false;
  mo.tangential.keep_traction = false;
  judge_smoothing_band(r, solve_contact(*half, mat, tY, Q, mo), solve_contact(*twice, mat, tY, Q, mo));
}

}  // namespace mh
