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
