#include "wheelset_contact/wheelset_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "contact/judge/judge.hpp"
#include "contact/multi_hertz/approach_given.hpp"
#include "contact/tangential/tangential_solve.hpp"
#include "core/roots.hpp"
#include "core/numfmt.hpp"
#include "geometry/rolled_candidates.hpp"
#include "geometry/rolled_gap.hpp"
#include "wheelset_contact/contact_force.hpp"

namespace mh {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void check_finite(double v, const char* field, const char* unit) {
  if (!std::isfinite(v))
    throw std::invalid_argument(std::string("pose.") + field + " = " + format_number(v) + " " + unit +
                                ": must be finite");
}

/// A contact's point and its force and moment on the wheelset (contact_force).
void add_contact(ContactPoint& c, int sigma, double a_tl, double y_r, double z_r, double y_w, double c_rail,
                 const TangentialResult& t) {
  const double sg = std::sin(c.gamma), cg = std::cos(c.gamma);
  c.Fx = t.solved ? t.Fx : 0.0;
  c.Fs = t.solved ? t.Fy : 0.0;
  c.Mn = t.solved ? t.Mz : 0.0;
  c.Y = sigma * (c_rail + y_r);
  c.Z = z_r;
  c.Y_ws = sigma * (a_tl + y_w);
  c.Z_ws = -c.r_roll;
  std::array<double, 3>& F = c.on_wheelset.F;
  F = contact_force(sigma, sg, cg, c.N, c.Fx, c.Fs);
  // Moments about the axle centre: the contact at (0, Y_ws, Z_ws) (the lead of the contact point
  // is not modelled), plus the spin moment about the normal, n_track = (0, −σ sin γ, cos γ), whose
  // scalar changes sign with the mirror (docs/tangential.md): σ Mn n_track.
  const double py = c.Y_ws, pz = c.Z_ws;
  std::array<double, 3>& M = c.on_wheelset.M;
  M = {py * F[2] - pz * F[1], pz * F[0], -py * F[0]};
  M[1] += -c.Mn * sg;
  M[2] += sigma * c.Mn * cg;
}

void add_wrench(Wrench& to, const Wrench& w) {
  for (int k = 0; k < 3; ++k) to.F[k] += w.F[k], to.M[k] += w.M[k];
}

/// v rounded to 0.001, as written in a warning (the shortest text of the rounded value).
std::string thousandths(double v) { return format_number(std::round(v * 1e3) / 1e3); }

/// Worse status: a failure before an answer, an answer not ok before ok.
CaseStatus worse(CaseStatus a, CaseStatus b) {
  auto rank = [](CaseStatus s) { return is_failure(s) ? 2 : s == CaseStatus::Ok ? 0 : 1; };
  return rank(b) > rank(a) ? b : a;
}

}  // namespace

std::string to_string(const WheelsetWarning& w) {
  switch (w.kind) {
    case WheelsetWarning::Kind::RollInGeometryNeglected:
      return "roll_in_geometry_neglected:roll_mrad=" + thousandths(w.value * 1e3) + ">" +
             thousandths(w.limit * 1e3);
    case WheelsetWarning::Kind::RollNearFlange:
      return std::string("roll_near_flange:wheel=") + (w.side > 0 ? "left" : "right") +
             ":gamma_deg=" + thousandths(w.value * 180 / 3.14159265358979323846) + ">" +
             thousandths(w.limit * 180 / 3.14159265358979323846);
    case WheelsetWarning::Kind::YawLeadNotModelled:
      return std::string("yaw_lead_not_modelled:wheel=") + (w.side > 0 ? "left" : "right") +
             ":lead_mm=" + thousandths(w.value * 1e3) + ">" + thousandths(w.limit * 1e3);
  }
  return "unknown";
}

void WheelsetContact::place(Side& S, int sigma) {
  S.sigma = sigma;
  S.R0 = S.geo.nominal_radius;
  // The taping line lies a = flange_back_distance/2 − flange_back_position from the wheelset
  // centre; at t_Y = 0 it faces rail y = y_offset, so the rail origin lies c = a − y_offset
  // from the track centre (geometry/wheelset.hpp: the same placement).
  S.a = setup_.track.flange_back_distance / 2 - setup_.track.flange_back_position;
  S.c = S.a - S.geo.y_offset;
}

WheelsetContact::WheelsetContact(const WheelsetSetup& setup) : setup_(setup) {
  std::string why;
  if (!setup.material.valid(&why)) throw std::invalid_argument("material: " + why);
  auto build = [&](Side& S, int sigma, const Profile& wheel, const Profile& rail, double R0) {
    TrackSetup t = setup.track;
    t.nominal_radius = R0;
    S.geo = build_geometry(wheel, rail, t, setup.geometry);
    place(S, sigma);
    for (const auto& w : S.geo.warnings) warnings_.push_back(wheel.source + ": " + w);
    for (const Profile* p : {&wheel, &rail})
      for (const auto& w : p->warnings) warnings_.push_back(p->source + ": " + w);
  };
  build(left_, +1, setup.wheel_left, setup.rail_left, setup.nominal_radius_left);
  build(right_, -1, setup.wheel_right, setup.rail_right, setup.nominal_radius_right);
  tabulate_rolled_minima();
}

void WheelsetContact::tabulate_rolled_minima() {
  if (!roll_in_geometry()) return;
  // The rolled candidates of every step from the envelopes (geometry/rolled_candidates.hpp), built
  // by the first rolled step (a wheelset made and stepped upright never builds them); the two
  // sides' are shared when they are copies of one pair's.
  tabulate_rolled_minima_on_demand(left_.geo, kRolledMinimaRollMax);
  if (right_.geo.build_id == left_.geo.build_id && right_.geo.build_id != 0) {
    if (!right_.geo.rolled_minima) {
      right_.geo.rolled_minima = left_.geo.rolled_minima;
      right_.geo.rolled_minima_on_demand = left_.geo.rolled_minima_on_demand;
    }
  } else {
    tabulate_rolled_minima_on_demand(right_.geo, kRolledMinimaRollMax);
  }
}

WheelsetContact::WheelsetContact(const ContactGeometry& left, const ContactGeometry& right, const TrackSetup& track,
                                 const Material& material, const MethodOptions& method,
                                 std::vector<std::string> warnings, bool roll_in_geometry)
    : warnings_(std::move(warnings)) {
  setup_.roll_in_geometry = roll_in_geometry;
  setup_.track = track;
  setup_.material = material;
  setup_.method = method;
  setup_.nominal_radius_left = left.nominal_radius;
  setup_.nominal_radius_right = right.nominal_radius;
  left_.geo = left;
  right_.geo = right;
  place(left_, +1);
  place(right_, -1);
  tabulate_rolled_minima();
}

namespace {

/// The table row k and weight f of t_Y in G's grid (covers(tY) assumed).
void table_at(const ContactGeometry& G, double tY, std::size_t& k, double& f) {
  const std::size_t n = G.tY.size();
  const double step = (G.tY.back() - G.tY.front()) / static_cast<double>(n - 1);
  k = static_cast<std::size_t>(std::clamp((tY - G.tY.front()) / step, 0.0, static_cast<double>(n - 2)));
  k = std::min(k, n - 2);
  f = (tY - G.tY[k]) / (G.tY[k + 1] - G.tY[k]);
}

}  // namespace

double WheelsetContact::first_contact_height(int side, double tY) const {
  const ContactGeometry& G = (side > 0 ? left_ : right_).geo;
  if (!G.covers(tY)) return kNaN;
  std::size_t k = 0;
  double f = 0;
  table_at(G, tY, k, f);
  const double gmin = G.z_contact[k] + f * (G.z_contact[k + 1] - G.z_contact[k]);
  // z_contact: the smallest z_w − z_r with the wheel at its datum (wheel frame on the rail frame);
  // lowered by it, the wheel touches, and its axle (R0 above the taping line's z0) stands at:
  return G.wheel_z0 + G.nominal_radius - gmin;
}

void WheelsetContact::pair_pose(int side, double y, double roll, double* tY, double* delta) const {
  const Side& S = side > 0 ? left_ : right_;
  const double d = roll_in_geometry() ? S.sigma * roll : 0.0;
  *delta = d;
  *tY = rolled_wheel_tY(S.sigma * y, d, S.a, S.geo.wheel_z0 + S.geo.nominal_radius);
}

double WheelsetContact::first_contact_height(int side, double y, double roll, WheelsetWorkspace& ws) const {
  const Side& S = side > 0 ? left_ : right_;
  double tY = 0, d = 0;
  pair_pose(side, y, roll, &tY, &d);
  if (d == 0) {
    const double h = first_contact_height(side, S.sigma * y);
    return roll == 0 ? h : h - S.sigma * roll * roll_lever(side, S.sigma * y);
  }
  const ContactGeometry& G = S.geo;
  if (!G.covers(tY)) return kNaN;
  ws.cand.resize(G.n_ellipses());
  int m = 0;
  if (!G.candidates_at(tY, d, ws.cand.data(), &m)) return kNaN;
  // The rolled wheel's origin lowered by its smallest separation touches; the axle centre stands
  // (z0 + R0) cos δ − a sin δ above that origin (eq. 3.8.2).
  return -ws.cand[static_cast<std::size_t>(m)].sep + (G.wheel_z0 + G.nominal_radius) * std::cos(d) - S.a * std::sin(d);
}

double WheelsetContact::roll_lever(int side, double tY) const {
  const Side& S = side > 0 ? left_ : right_;
  const ContactGeometry& G = S.geo;
  if (!G.covers(tY)) return S.a;
  std::size_t k = 0;
  double f = 0;
  table_at(G, tY, k, f);
  // The main contact point at t_Y: interpolated within one potential ellipse, else the nearer row's.
  const CandidateGeom &c0 = G.main_at(k), &c1 = G.main_at(k + 1);
  auto lever = [&](const CandidateGeom& c) { return S.a + c.y_w - c.r_roll * std::tan(c.gamma); };
  if (G.main_ellipse[k] != G.main_ellipse[k + 1]) return lever(f < 0.5 ? c0 : c1);
  return lever(c0) + f * (lever(c1) - lever(c0));
}

double WheelsetContact::roll_lever(int side, double y, double roll, WheelsetWorkspace& ws) const {
  const Side& S = side > 0 ? left_ : right_;
  double tY = 0, d = 0;
  pair_pose(side, y, roll, &tY, &d);
  const ContactGeometry& G = S.geo;
  if (d == 0 || !G.covers(tY)) return roll_lever(side, S.sigma * y);
  ws.cand.resize(G.n_ellipses());
  int m = 0;
  if (!G.candidates_at(tY, d, ws.cand.data(), &m)) return roll_lever(side, S.sigma * y);
  // dh/dδ of eq. 3.8.2 at the rolled minimum (the minimum's own motion drops out): the rotation
  // moves the wheel surface at rail point y_r by (y_r − s) + tan γ z̃_w (z̃_w its height there, the
  // rail's slope tan γ that of the wheel at the minimum), the shift of t_Y by dt/dδ lowers the
  // separation by tan γ dt/dδ, and the axle above the origin turns: −((z0 + R0) sin δ + a cos δ).
  // δ = 0: L = a + y_w − r tan γ, the upright lever.
  const CandidateGeom& c = ws.cand[static_cast<std::size_t>(m)];
  const double H = G.wheel_z0 + G.nominal_radius, sn = std::sin(d), cs = std::cos(d), tg = std::tan(c.gamma);
  const double s = G.y_offset + tY, zw = c.sep + G.rail_curve->z(c.y_r);
  return S.a * cs + (c.y_r - s) + H * sn + tg * (zw - H * cs + S.a * sn);
}

MethodOptions WheelsetContact::wheel_options(const Side& S, const WheelsetPose& pose, const WheelResult& w) const {
  const int s = S.sigma;
  MethodOptions opt = setup_.method;
  opt.multi_hertzian.roll = w.delta;
  TangentialOptions& tg = opt.tangential;
  if (tg.enabled()) {
    // The pair's frame: lateral and yaw quantities with the track's signs times σ.
    tg.source = TangentialOptions::Source::Kinematics;
    tg.kin.V = pose.V;
    tg.kin.yaw = s * pose.yaw;
    tg.kin.lateral_velocity = s * pose.lateral_velocity;
    tg.kin.yaw_rate = s * pose.yaw_rate;
    tg.kin.pitch_rate = pose.pitch_rate;
    tg.kin.roll = w.delta;
    tg.yaw_per_tY = 0;
    tg.l_origin = S.a;
    tg.r0 = S.R0;
  }
  return opt;
}

void WheelsetContact::judge_wheel(const Side& S, const WheelsetPose& pose, WheelResult& w) const {
  if (w.judged) return;
  judge_case(w.r, S.geo, setup_.material, w.tY, wheel_options(S, pose, w));
  w.judged = true;
}

void WheelsetContact::solve_wheel(const Side& S, const WheelsetPose& pose, double roll, WheelResult& w,
                                  WheelsetWorkspace& ws) const {
  const int s = S.sigma;
  w.side = s;
  pair_pose(s, pose.y, roll, &w.tY, &w.delta);
  // h: the axle height of first contact at this roll (the rolled wheel's, or the first-order rule).
  w.h = first_contact_height(s, pose.y, roll, ws);
  const MethodOptions opt = wheel_options(S, pose, w);
  const Material& mat = setup_.material;
  if (pose.vertical == WheelsetVertical::Loads) {
    const double Q = s > 0 ? pose.Q_left : pose.Q_right;
    w.judged = solve_contact_unjudged(S.geo, mat, w.tY, Q, opt, w.r, &ws.grid);
  } else {
    // δz_s = h_s(φ) − Z (h_s at the roll: first_contact_height); outside the table h is NaN and
    // the solve says out_of_range.
    const double dz = std::isfinite(w.h) ? w.h - pose.Z : 0.0;
    solve_multi_hertz_approach(S.geo, mat, w.tY, dz, opt.multi_hertzian, ws.approach, w.r);
    solve_tangential(w.r, mat, w.tY, opt.tangential);
    w.judged = false;
  }
  w.contacts.clear();
  w.on_wheelset = Wrench{};
  const bool answer = !is_failure(w.r.status);
  if (!answer) return;
  for (const LoadedEllipse& L : w.r.loaded) {
    if (!(L.s.N > 0)) continue;
    ContactPoint c;
    c.index = L.ellipse;
    c.gamma = L.g.gamma;
    c.r_roll = L.g.r_roll;
    c.N = L.s.N;
    c.a = L.s.a, c.b = L.s.b;
    add_contact(c, s, S.a, L.g.y_r, L.z_r, L.g.y_w, S.c, L.t);
    add_wrench(w.on_wheelset, c.on_wheelset);
    w.contacts.push_back(c);
  }
  for (const PatchResult& P : w.r.patches) {
    if (!(P.N > 0)) continue;
    ContactPoint c;
    c.index = P.patch;
    c.gamma = P.gamma;
    c.r_roll = P.r_roll;
    c.N = P.N;
    c.a = P.length_x / 2, c.b = P.width_s / 2;
    add_contact(c, s, S.a, P.y_r, P.z_r, P.y_w, S.c, P.t);
    add_wrench(w.on_wheelset, c.on_wheelset);
    w.contacts.push_back(c);
  }
}

namespace {

/// The roll φ where f(φ) = 0 (a height difference of the two wheels, decreasing in φ), from φ0
/// with f0 = f(φ0): secant steps, the first with the slope −L (the two levers; steps at most
/// 2 mrad), then TOMS 748 once a step crosses the root. To 1e-9 rad or |f| ≤ f_tol [m]; the point
/// of smallest |f| if neither. f is evaluated last at the returned φ when `last` is asked.
template <class F>
double roll_root(F&& f, double phi0, double f0, double L, bool last, double kFTol = 1e-10) {
  constexpr double kMaxStep = 2e-3, kTol = 1e-9;
  double best = phi0, fbest = f0, slope = L > 1e-3 ? -L : -1.0;
  double at = phi0;  // where f was evaluated last
  for (int it = 0; it < 12 && std::isfinite(f0) && std::fabs(f0) > kFTol; ++it) {
    const double step = std::clamp(-f0 / slope, -kMaxStep, kMaxStep);
    const double phi1 = phi0 + step, f1 = f(phi1);
    at = phi1;
    if (!std::isfinite(f1)) break;
    if (std::fabs(f1) < std::fabs(fbest)) best = phi1, fbest = f1;
    if (std::fabs(step) < kTol || std::fabs(f1) <= kFTol) break;
    if ((f1 < 0) != (f0 < 0)) {
      RootTolerance tol;
      tol.abs = kTol;
      tol.rel = 0;
      tol.f_abs = kFTol;
      tol.max_iterations = 40;
      const bool up = phi0 < phi1;
      const RootResult rr = bracketed_root([&](double x) { at = x; return f(x); }, up ? phi0 : phi1, up ? phi1 : phi0,
                                           up ? f0 : f1, up ? f1 : f0, tol);
      if (std::isfinite(rr.f) && std::fabs(rr.f) < std::fabs(fbest)) best = rr.x, fbest = rr.f;
      break;
    }
    const double s = (f1 - f0) / (phi1 - phi0);
    slope = s < 0 ? s : (L > 1e-3 ? -L : -1.0);
    phi0 = phi1;
    f0 = f1;
  }
  if (last && at != best) f(best);
  return best;
}

}  // namespace

namespace {

/// [m] The loads mode's tolerance on the two wheels' axle-height difference: what their load
/// balances' own tolerance leaves of each height (at least 0.1 nm).
double height_tolerance(const MethodOptions& m, const WheelsetResult& r) {
  // Each wheel's load is balanced to rtol Q (the creep equilibrium's tolerance with friction, the
  // normal solve's without): its axle height is known to rtol Q / k, k = Σ dN/dh0 cos² γ its
  // vertical stiffness (approach_given.hpp); a difference of the two below the sum is noise.
  const double rtol = m.tangential.enabled() ? m.tangential.equilibrium_tolerance : m.multi_hertzian.rtol;
  double tol = 0;
  for (const WheelResult* w : {&r.left, &r.right}) {
    double k = 0, Q = 0;
    for (const LoadedEllipse& L : w->r.loaded) {
      const double c = std::cos(L.g.gamma);
      k += normal_stiffness(L) * c * c;
      Q += L.s.N * c;
    }
    if (k > 0) tol += rtol * Q / k;
  }
  return std::max(tol, 1e-10);
}

}  // namespace

void WheelsetContact::solve_both(const WheelsetPose& pose, const WheelsetStepOptions& opt, WheelsetResult& out,
                                 WheelsetWorkspace& ws) const {
  const bool geo = roll_in_geometry();
  const double Ll = roll_lever(+1, pose.y), Lr = roll_lever(-1, -pose.y);
  double roll = pose.solve_roll ? 0.0 : pose.roll;
  auto solve_at = [&](double phi) {
    solve_wheel(left_, pose, phi, out.left, ws);
    solve_wheel(right_, pose, phi, out.right, ws);
  };
  if (pose.vertical == WheelsetVertical::Position) {
    if (pose.solve_roll) {
      // Both wheels touch at one height, h_L(φ) = h_R(φ): the first-order rule
      // h_L − φ L_L = h_R + φ L_R, then (roll in the geometry) Newton steps on the rolled heights
      // with the levers as the slope.
      const double hl = first_contact_height(+1, pose.y), hr = first_contact_height(-1, -pose.y);
      const double L = Ll + Lr;
      roll = std::isfinite(hl) && std::isfinite(hr) && L > 0 ? (hl - hr) / L : 0.0;
      if (geo) {
        auto f = [&](double phi) { return first_contact_height(+1, pose.y, phi, ws) - first_contact_height(-1, pose.y, phi, ws); };
        const double f0 = f(roll);
        roll = roll_root(f, roll, f0, roll_lever(+1, pose.y, roll, ws) + roll_lever(-1, pose.y, roll, ws), false);
      }
    }
    solve_at(roll);
    out.roll = roll;
    out.Z = pose.Z;
  } else {
    // Each wheel's axle end stands its descent below first contact: the virtual penetration δz
    // of eq. 11 (multi-Hertzian, as Position prescribes it), the rigid approach otherwise; w.h is
    // the first-contact height at the roll solved at.
    auto end_height = [](const WheelResult& w) {
      if (is_failure(w.r.status)) return kNaN;
      const double d = std::isfinite(w.r.dz) ? w.r.dz : w.r.approach;
      return w.h - d;
    };
    if (pose.solve_roll && geo) {
      // Start from the first-order roll of the upright tables' heights and levers: the two
      // wheels' first-contact heights h_L − φ L_L = h_R + φ L_R (equal loads on equal contacts
      // descend alike).
      const double hl = first_contact_height(+1, pose.y), hr = first_contact_height(-1, -pose.y);
      if (std::isfinite(hl) && std::isfinite(hr) && Ll + Lr > 0) roll = (hl - hr) / (Ll + Lr);
    }
    solve_at(roll);
    double zl = end_height(out.left), zr = end_height(out.right);
    if (pose.solve_roll && geo && roll != 0 && !(std::isfinite(zl) && std::isfinite(zr))) {
      // The first-order roll can be far off in flange contact (the upright lever short) and put a
      // wheel outside its table: start from the upright wheelset then.
      roll = 0;
      solve_at(roll);
      zl = end_height(out.left), zr = end_height(out.right);
    }
    if (pose.solve_roll) {
      // One rigid axle: Z + σ φ L_s = h_s − δ_s on both wheels, the roll from the difference. With
      // the roll in the geometry both wheels are solved again at each roll of a root search on
      // Z_L(φ) − Z_R(φ) (roll_root: the levers give its first slope).
      if (!geo) {
        const double d = (zl - zr) / (Ll + Lr);
        roll += d;
        zl -= d * Ll;  // Z = z_L − φ L_L
        zr = zl;
      } else {
        auto f = [&](double phi) {
          solve_at(phi);
          zl = end_height(out.left), zr = end_height(out.right);
          return zl - zr;
        };
        // The first slope: the rolled levers at this roll (each wheel's dh/dφ; its descent's
        // change with the roll is of higher order).
        roll = roll_root(f, roll, zl - zr, roll_lever(+1, pose.y, roll, ws) + roll_lever(-1, pose.y, roll, ws), true,
                         height_tolerance(setup_.method, out));
      }
    }
    out.roll = roll;
    out.Z = 0.5 * (zl + zr);
  }
  // The judge on the answers kept (the search's other solves are not judged: their warnings
  // were never read).
  judge_wheel(left_, pose, out.left);
  judge_wheel(right_, pose, out.right);
  out.status = worse(out.left.r.status, out.right.r.status);
  out.total = Wrench{};
  add_wrench(out.total, out.left.on_wheelset);
  add_wrench(out.total, out.right.on_wheelset);
  out.warnings.clear();
  if (!geo && std::fabs(out.roll) > opt.roll_limit)
    out.warnings.push_back({WheelsetWarning::Kind::RollInGeometryNeglected, 0, std::fabs(out.roll), opt.roll_limit});
  if (!geo && std::fabs(out.roll) > 1e-4) {
    for (const WheelResult* w : {&out.left, &out.right}) {
      double g = 0;
      for (const ContactPoint& c : w->contacts) g = std::max(g, c.gamma);
      if (g > opt.roll_flange_gamma)
        out.warnings.push_back({WheelsetWarning::Kind::RollNearFlange, w->side, g, opt.roll_flange_gamma});
    }
  }
  if (pose.yaw != 0) {
    for (const WheelResult* w : {&out.left, &out.right}) {
      // The lead of the contact point of a cone of angle γ at radius r yawed by ψ: r tan γ tan ψ.
      double worst = 0, limit = 0;
      bool over = false;
      for (const ContactPoint& c : w->contacts) {
        const double lead = std::fabs(c.r_roll * std::tan(c.gamma) * std::tan(pose.yaw));
        const double lim = opt.lead_fraction * c.a;
        if (lead > lim && (!over || lead - lim > worst - limit)) worst = lead, limit = lim, over = true;
      }
      if (over) out.warnings.push_back({WheelsetWarning::Kind::YawLeadNotModelled, w->side, worst, limit});
    }
  }
}

void WheelsetContact::step(const WheelsetPose& pose, const WheelsetStepOptions& opt, WheelsetResult& out,
                           WheelsetWorkspace& ws) const {
  check_finite(pose.y, "y", "m");
  check_finite(pose.yaw, "yaw", "rad");
  const bool position = pose.vertical == WheelsetVertical::Position;
  if (position) {
    check_finite(pose.Z, "Z", "m");
    if (!pose.solve_roll) check_finite(pose.roll, "roll", "rad");
    if (setup_.method.method != Method::MultiHertzian)
      throw std::invalid_argument(std::string("pose.vertical = position needs the multi-hertzian method, not ") +
                                  to_string(setup_.method.method) + " (give the loads instead)");
  } else {
    for (const auto& [f, q] : {std::pair<const char*, double>{"Q_left", pose.Q_left}, {"Q_right", pose.Q_right}})
      if (!(q >= 0) || !std::isfinite(q))
        throw std::invalid_argument(std::string("pose.") + f + " = " + format_number(q) +
                                    " N: a vertical load must be >= 0 and finite");
  }
  if (setup_.method.tangential.enabled()) {
    if (!(pose.V > 0) || !std::isfinite(pose.V))
      throw std::invalid_argument("pose.V = " + format_number(pose.V) +
                                  " m/s: the forward speed must be > 0 and finite with friction (the creepages divide by it)");
    check_finite(pose.lateral_velocity, "lateral_velocity", "m/s");
    check_finite(pose.yaw_rate, "yaw_rate", "rad/s");
  }
  solve_both(pose, opt, out, ws);
  add_derivatives(pose, opt, out, ws);
}

}  // namespace mh
