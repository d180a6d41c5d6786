// The tangential problem of a solved case (tangential_solve.hpp).
#include "contact/tangential/tangential_solve.hpp"

#include <cmath>

#include "contact/tangential/fastsim.hpp"

namespace mh {

void combined_elastic(const Material& mat, double& G, double& nu) {
  const double G1 = mat.E / (2.0 * (1.0 + mat.nu));
  const double nu2 = std::isnan(mat.nu_rail) ? mat.nu : mat.nu_rail;
  const double G2 = mat.Er() / (2.0 * (1.0 + nu2));
  G = 2.0 / (1.0 / G1 + 1.0 / G2);
  nu = 0.5 * G * (mat.nu / G1 + nu2 / G2);
}

namespace {

// The creepages of a contact at (r_roll, γ, y_w) of the case (tangential_options.hpp).
Creepages creepages_of(const TangentialOptions& o, double tY, double r_roll, double gamma, double y_w) {
  if (o.source == TangentialOptions::Source::Creepages) return o.creep;
  Kinematics k = o.kin;
  k.yaw += o.yaw_per_tY * tY;
  // The contact's distance from the wheelset's centre plane: the wheel profile's origin lies at
  // l_origin + t_Y (t_Y moves the wheel towards the field side, method.md §1), the contact at y_w
  // on the wheel profile.
  return creepages_from_kinematics(k, {r_roll, gamma, o.l_origin + tY + y_w}, o.r0);
}

}  // namespace

void solve_tangential(CaseResult& r, const Material& mat, double tY, const TangentialOptions& opt) {
  r.tangential = TangentialSums{};
  if (!opt.enabled()) return;
  r.tangential.asked = true;
  double G = 0, nu = 0;
  combined_elastic(mat, G, nu);
  // The cells of each ellipse only when asked (run --pressure-grid): otherwise nothing is kept.
  if (opt.keep_traction) r.ellipse_traction.resize(r.loaded.size());
  else r.ellipse_traction.clear();
  for (std::size_t i = 0; i < r.loaded.size(); ++i) {
    LoadedEllipse& L = r.loaded[i];
    L.t = TangentialResult{};
    L.t.c = creepages_of(opt, tY, L.g.r_roll, L.g.gamma, L.g.y_w);
    L.t.mu = opt.mu;
    EllipseTraction* keep = opt.keep_traction ? &r.ellipse_traction[i] : nullptr;
    if (keep) {
      keep->cells.nx = keep->cells.ny = 0;
      keep->bound = opt.fastsim.bound;
    }
    if (!(L.s.N > 0 && L.s.a > 0 && L.s.b > 0)) continue;
    // FASTSIM on the patch the normal law carries (the plastic patch when plastic; its traction
    // bound the elliptical one of that patch: docs/tangential.md, limits).
    // The load slope (fastsim.hpp) only where the creep force has a vertical share worth aiming
    // the equilibrium with: |sin γ| ≥ kLoadSlopeSinGamma (the flange and its root; the tread's
    // share is aimed from its saturation: contact/solve.cpp, equilibrium_slope).
    FastsimGrid* cells = keep ? &keep->cells : nullptr;
    if (opt.fastsim.load_slope && !(std::fabs(L.sin_gamma) >= kLoadSlopeSinGamma)) {
      FastsimOptions o = opt.fastsim;
      o.load_slope = false;
      L.t = fastsim(L.t.c, L.s.a, L.s.b, L.s.N, opt.mu, G, nu, o, cells);
    } else {
      L.t = fastsim(L.t.c, L.s.a, L.s.b, L.s.N, opt.mu, G, nu, opt.fastsim, cells);
    }
  }
  for (PatchResult& P : r.patches) {
    P.t = TangentialResult{};
    P.t.c = creepages_of(opt, tY, P.r_roll, P.gamma, P.y_w);
    P.t.mu = opt.mu;
  }
  sum_tangential(r, opt.mu);
}

void CreepAnchors::take(const CaseResult& r) {
  n = -1;
  if (!r.patches.empty() || r.loaded.empty() || r.loaded.size() > static_cast<std::size_t>(kMax) || !r.tangential.solved)
    return;
  for (std::size_t i = 0; i < r.loaded.size(); ++i) {
    const LoadedEllipse& L = r.loaded[i];
    if (!(L.s.N > 0) || !L.t.solved) return;
    ellipse[i] = L.ellipse;
    N[i] = L.s.N;
    t[i] = L.t;
  }
  n = static_cast<int>(r.loaded.size());
}

bool extrapolate_tangential(CaseResult& r, const CreepAnchors& a0, const CreepAnchors& a1, double mu, double tol) {
  const int n = static_cast<int>(r.loaded.size());
  if (a0.n < 1 || a1.n != a0.n || n != a1.n || !r.patches.empty()) return false;
  for (int i = 0; i < n; ++i) {
    const LoadedEllipse& L = r.loaded[static_cast<std::size_t>(i)];
    if (L.ellipse != a1.ellipse[i] || L.ellipse != a0.ellipse[i]) return false;
    if (!(L.s.N > 0 && L.s.a > 0 && L.s.b > 0)) return false;
    const double N0 = a0.N[i], N1 = a1.N[i], dN = std::fabs(N1 - N0), step = std::fabs(L.s.N - N1);
    if (step == 0) continue;  // the same load: a1's forces
    // The secant's error ½ |F''| |N − N1| |N − N0| with |F''| ≤ kCreepCurvature μ/N (header).
    if (!(dN > 0) || !(0.5 * kCreepCurvature * step * dN <= tol * N1 * N1)) return false;
  }
  for (int i = 0; i < n; ++i) {
    LoadedEllipse& L = r.loaded[static_cast<std::size_t>(i)];
    const TangentialResult& t0 = a0.t[i];
    const TangentialResult& t1 = a1.t[i];
    L.t = t1;
    const double N1 = a1.N[i];
    if (L.s.N != N1) {
      const double s = (L.s.N - N1) / (N1 - a0.N[i]);
      L.t.Fx = t1.Fx + s * (t1.Fx - t0.Fx);
      L.t.Fy = t1.Fy + s * (t1.Fy - t0.Fy);
      L.t.Mz = t1.Mz + s * (t1.Mz - t0.Mz);
      L.t.Tgamma = -(L.t.Fx * L.t.c.xi + L.t.Fy * L.t.c.eta);
      L.t.Tgamma_spin = -L.t.Mz * L.t.c.phi;
      L.t.dFx_dN = L.t.dFy_dN = NAN;
    }
  }
  r.tangential = TangentialSums{};
  r.tangential.asked = true;
  r.ellipse_traction.clear();
  sum_tangential(r, mu);
  return true;
}

void sum_tangential(CaseResult& r, double mu) {
  double Fx = 0, Fy = 0, Mz = 0, F = 0, N = 0, Fz = 0;
  bool all = !r.loaded.empty() || !r.patches.empty();
  auto add = [&](const TangentialResult& t, double Nc, double cos_gamma, double sin_gamma) {
    if (!t.solved) {
      all = all && !(Nc > 0);  // an unloaded ellipse has nothing to solve
      return;
    }
    Fx -= t.Fx;  // on the rail
    Fy -= t.Fy * cos_gamma;
    Fz += t.Fy * sin_gamma;  // −(on the rail along ŝ) · ŝ_z: downwards on the rail
    Mz -= t.Mz;
    F += std::hypot(t.Fx, t.Fy);
    N += Nc;
  };
  for (const LoadedEllipse& L : r.loaded) add(L.t, L.s.N > 0 && L.s.a > 0 && L.s.b > 0 ? L.s.N : 0, L.cos_gamma, L.sin_gamma);
  for (const PatchResult& P : r.patches) add(P.t, P.N, std::cos(P.gamma), std::sin(P.gamma));
  r.tangential.solved = false;
  if (!all || !(N > 0)) return;
  r.tangential.solved = true;
  r.tangential.Fx = Fx;
  r.tangential.Fy_creep = Fy;
  r.tangential.Mz = Mz;
  r.tangential.F_over_muN = mu > 0 ? F / (mu * N) : NAN;
  r.tangential.Fz_creep = Fz;
}

}  // namespace mh
