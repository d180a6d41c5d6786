#include "contact_adapter.hpp"

#include <algorithm>
#include <cmath>

namespace wsdyn {

namespace {
/// The geometry's t_Y grid: the default (−10 … 12 mm) mirrored, so that the left wheel at −y
/// and the right at +y lie on the same grid.
mh::GeometryOptions geometry_options() {
  mh::GeometryOptions g;
  g.tY_min = -12e-3;
  g.tY_max = 12e-3;
  return g;
}
}  // namespace

ContactAdapter::ContactAdapter(const WheelsetSetup& s)
    : s_(s),
      geo_(mh::build_geometry(s.wheel, s.rail, s.track, geometry_options())),
      l_origin_(s.track.flange_back_distance / 2 - s.track.flange_back_position) {
  opt_.method = mh::Method::MultiHertzian;
  mh::TangentialOptions& t = opt_.tangential;
  t.mu = s.mu;
  t.source = mh::TangentialOptions::Source::Kinematics;
  t.l_origin = l_origin_;
  t.r0 = s.track.nominal_radius;
  t.fastsim = s.fastsim;
}

WheelContactForces ContactAdapter::wheel(int side, const WheelsetMotion& m) {
  // Pair frame (method.md §10): the right wheel's is the track frame, the left wheel's its mirror.
  const double sg = side;
  const double tY = sg * m.y;
  mh::Kinematics& k = opt_.tangential.kin;
  k.V = m.V;
  k.yaw = sg * m.psi;
  k.lateral_velocity = sg * m.y_dot;
  k.yaw_rate = sg * m.psi_dot;
  k.pitch_rate = m.Omega;
  mh::solve_contact(geo_, s_.material, tY, s_.Q, opt_, res_);
  ++calls_;
  WheelContactForces w;
  w.status = res_.status;
  w.ok = !mh::is_failure(res_.status) && res_.tangential.solved;
  double N_main = -1;
  for (const mh::LoadedEllipse& L : res_.loaded) {
    if (L.s.N <= 0) continue;
    ++w.n_contacts;
    const double cg = L.cos_gamma, sgm = L.sin_gamma;
    // On the wheel, pair frame: the normal force along n = (0, −sin γ, cos γ), the creep force Fy
    // along ŝ = (0, cos γ, sin γ), Fx along x (tangential_types.hpp).
    const double Fy_pair = -L.s.N * sgm + L.t.Fy * cg;
    w.F_Y += sg * Fy_pair;
    w.F_Y_creep += sg * L.t.Fy * cg;
    w.F_X += L.t.Fx;
    // The contact's |Y| from the centre plane: l = l_origin + t_Y + y_w (method.md §10).
    const double l = l_origin_ + tY + L.g.y_w;
    // Yaw moment (sense X → Y) of a force F_X at Y_c = side · l: −Y_c F_X.
    w.M_Z += -sg * l * L.t.Fx;
    // A forward force at the contact, r below the axle, slows the rolling wheel.
    w.M_axle += -L.g.r_roll * L.t.Fx;
    w.N += L.s.N;
    w.p_max = std::max(w.p_max, L.s.p_max);
    w.plastic = w.plastic || L.s.plastic;
    if (L.s.N > N_main) {
      N_main = L.s.N;
      w.gamma = L.g.gamma;
      w.r = L.g.r_roll;
      w.l = l;
      w.a = L.s.a;
      w.b = L.s.b;
    }
  }
  if (w.n_contacts == 0) w.ok = false;
  return w;
}

WheelsetForces ContactAdapter::evaluate(const WheelsetMotion& m) {
  WheelsetForces f;
  f.right = wheel(+1, m);
  f.left = wheel(-1, m);
  f.F_Y = f.left.F_Y + f.right.F_Y;
  f.M_Z = f.left.M_Z + f.right.M_Z;
  f.F_X = f.left.F_X + f.right.F_X;
  f.M_axle = f.left.M_axle + f.right.M_axle;
  return f;
}

}  // namespace wsdyn
