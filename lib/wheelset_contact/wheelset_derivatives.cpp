// The wheelset step's derivatives (WheelsetStepOptions::derivatives): dF/dy and dF/droll by central
// differences, dF/dZ or dF/dQ analytic where the method gives it (vertical_slope), else by
// differences too. docs/c-api.md "Derivatives".
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "contact/multi_hertz/approach_given.hpp"
#include "contact/tangential/fastsim.hpp"
#include "contact/tangential/tangential_solve.hpp"
#include "wheelset_contact/contact_force.hpp"
#include "wheelset_contact/wheelset_contact.hpp"

namespace mh {

namespace {

/// dF/dδz of a wheel's answer r (side σ), δz its vertical approach (eq. 11), the geometry held
/// (t_Y, the roll): each loaded ellipse's dN_i/dδz = (dN/dh0)_i cos γ_i (approach_given.hpp,
/// normal_stiffness) and, with friction, its creep forces' dF/dN at fixed creepages by FASTSIM's
/// load slope (fastsim.hpp: exact for the discrete march of an ellipse loaded as Hertz's), mapped
/// by contact_force. *dQ: the wheel's vertical load's derivative, Σ dN_i/dδz (cos γ_i +
/// dFs_i/dN_i sin γ_i) with the creep forces' share where the loads mode balances it
/// (contact/solve.cpp, creep_equilibrium), Σ dN_i/dδz cos γ_i otherwise. False where the method
/// does not give it: a failed or grid row, no loaded ellipse, a plastic ellipse with friction (its
/// patch does not grow as Hertz's), the blended flexibilities (they move with the creepages).
bool vertical_slope(const CaseResult& r, int sigma, const Material& mat, const MethodOptions& m,
                    std::array<double, 3>& dF, double& dQ) {
  dF = {0, 0, 0};
  dQ = 0;
  if (is_failure(r.status) || r.method != Method::MultiHertzian || !r.patches.empty()) return false;
  const TangentialOptions& t = m.tangential;
  const bool friction = t.enabled();
  if (friction && (t.fastsim.blend || !r.tangential.solved)) return false;
  double G = 0, nu = 0;
  if (friction) combined_elastic(mat, G, nu);
  FastsimOptions fo = t.fastsim;
  fo.load_slope = true;
  int loaded = 0;
  for (const LoadedEllipse& L : r.loaded) {
    if (!(L.s.N > 0)) continue;
    const double k = normal_stiffness(L) * L.cos_gamma;
    if (!(k > 0) || !std::isfinite(k)) return false;
    double dFx = 0, dFs = 0;
    if (friction) {
      if (L.s.plastic || !L.t.solved) return false;
      const TangentialResult ts = fastsim(L.t.c, L.s.a, L.s.b, L.s.N, t.mu, G, nu, fo);
      if (!std::isfinite(ts.dFx_dN) || !std::isfinite(ts.dFy_dN)) return false;
      dFx = ts.dFx_dN * k;
      dFs = ts.dFy_dN * k;
    }
    const std::array<double, 3> f = contact_force(sigma, std::sin(L.g.gamma), std::cos(L.g.gamma), k, dFx, dFs);
    for (int j = 0; j < 3; ++j) dF[j] += f[j];
    dQ += k * L.cos_gamma + (friction && t.vertical_equilibrium ? dFs * L.sin_gamma : 0.0);
    ++loaded;
  }
  return loaded > 0;
}

}  // namespace

void WheelsetContact::add_derivatives(const WheelsetPose& pose, const WheelsetStepOptions& opt, WheelsetResult& out,
                                      WheelsetWorkspace& ws) const {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const bool position = pose.vertical == WheelsetVertical::Position;
  for (auto* d : {&out.dF_dy, &out.dF_droll, &out.dF_dvertical, &out.left.dF_dy, &out.left.dF_droll,
                  &out.left.dF_dvertical, &out.right.dF_dy, &out.right.dF_droll, &out.right.dF_dvertical})
    d->fill(kNaN);
  out.left.dF_dvertical_analytic = out.right.dF_dvertical_analytic = false;
  if (!opt.derivatives) return;

  // In y and φ central differences, each wheel alone (the other inputs held; the roll at its
  // value): the geometry's own derivatives in them are not the method's (the contact point moves
  // over sampled profiles; the rolled minimum can jump, docs/c-api.md). In the vertical input the
  // geometry is held and the answer is a function of the approach alone: analytic where
  // vertical_slope gives it, else central differences too.
  WheelResult& wp = ws.plus;
  WheelResult& wm = ws.minus;
  auto diff = [&](const Side& S, const WheelsetPose& p_plus, double roll_plus, const WheelsetPose& p_minus,
                  double roll_minus, double h, std::array<double, 3>& d) {
    solve_wheel(S, p_plus, roll_plus, wp, ws);
    solve_wheel(S, p_minus, roll_minus, wm, ws);
    for (int k = 0; k < 3; ++k) d[k] = (wp.on_wheelset.F[k] - wm.on_wheelset.F[k]) / (2 * h);
  };
  WheelsetPose fixed = pose;
  if (position) fixed.solve_roll = false, fixed.roll = out.roll;
  const double roll = out.roll;
  for (const Side* S : {&left_, &right_}) {
    WheelResult& w = S->sigma > 0 ? out.left : out.right;
    WheelsetPose a = fixed, b = fixed;
    a.y += opt.fd_y, b.y -= opt.fd_y;
    diff(*S, a, roll, b, roll, opt.fd_y, w.dF_dy);
    std::array<double, 3> slope{};
    double dQ = 0;
    const bool analytic = opt.analytic_vertical &&
                          vertical_slope(w.r, S->sigma, setup_.material, setup_.method, slope, dQ) && (position || dQ > 0);
    w.dF_dvertical_analytic = analytic;
    if (position) {
      diff(*S, fixed, roll + opt.fd_roll, fixed, roll - opt.fd_roll, opt.fd_roll, w.dF_droll);
      if (analytic) {
        for (int k = 0; k < 3; ++k) w.dF_dvertical[k] = -slope[k];  // δz = h − Z: dδz/dZ = −1
        continue;
      }
      a = fixed, b = fixed;
      a.Z += opt.fd_Z, b.Z -= opt.fd_Z;
      diff(*S, a, roll, b, roll, opt.fd_Z, w.dF_dvertical);
    } else if (analytic) {
      for (int k = 0; k < 3; ++k) w.dF_dvertical[k] = slope[k] / dQ;  // dF/dQ = (dF/dδz) / (dQ/dδz)
    } else {
      a = fixed, b = fixed;
      double& qa = S->sigma > 0 ? a.Q_left : a.Q_right;
      double& qb = S->sigma > 0 ? b.Q_left : b.Q_right;
      const double h = std::max(qa, 1.0) * opt.fd_Q;
      qa += h;
      qb = std::max(0.0, qb - h);
      const double span = qa - qb;
      solve_wheel(*S, a, roll, wp, ws);
      solve_wheel(*S, b, roll, wm, ws);
      for (int k = 0; k < 3; ++k) w.dF_dvertical[k] = (wp.on_wheelset.F[k] - wm.on_wheelset.F[k]) / span;
    }
  }
  for (int k = 0; k < 3; ++k) {
    out.dF_dy[k] = out.left.dF_dy[k] + out.right.dF_dy[k];
    out.dF_droll[k] = out.left.dF_droll[k] + out.right.dF_droll[k];
    out.dF_dvertical[k] = out.left.dF_dvertical[k] + out.right.dF_dvertical[k];
  }
}


}  // namespace mh
