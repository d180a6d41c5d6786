#include "contact_adapter.hpp"

#include <algorithm>
#include <cmath>

namespace wsdyn {

namespace {

/// The wheelset call's setup: the same wheel and rail on both sides (each mirrored by the call),
/// the multi-Hertzian method with FASTSIM, the tables over |y| ≤ 12 mm.
mh::WheelsetSetup wheelset_setup(const WheelsetSetup& s) {
  mh::WheelsetSetup w;
  w.wheel_left = w.wheel_right = s.wheel;
  w.rail_left = w.rail_right = s.rail;
  w.track = s.track;
  w.nominal_radius_left = w.nominal_radius_right = s.track.nominal_radius;
  w.material = s.material;
  w.method.method = mh::Method::MultiHertzian;
  mh::TangentialOptions& t = w.method.tangential;
  t.mu = s.mu;
  t.source = mh::TangentialOptions::Source::Kinematics;
  t.fastsim = s.fastsim;
  w.geometry.tY_min = -12e-3;
  w.geometry.tY_max = 12e-3;
  return w;
}

/// One wheel of the call's result in the example's frame (Y towards the right rail).
WheelContactForces wheel_forces(const mh::WheelResult& w) {
  WheelContactForces f;
  f.status = w.r.status;
  f.ok = !mh::is_failure(w.r.status) && w.r.tangential.solved;
  // The call's track frame has y to the left: F_Y = −F_y, M_Z = −M_z; M_y is the moment in the
  // sense of rolling forward (x forward, y left: a rotation about +y rolls the wheel forward).
  f.F_X = w.on_wheelset.F[0];
  f.F_Y = -w.on_wheelset.F[1];
  f.M_Z = -w.on_wheelset.M[2];
  f.M_axle = w.on_wheelset.M[1];
  double N_main = -1;
  for (const mh::ContactPoint& c : w.contacts) {
    ++f.n_contacts;
    f.N += c.N;
    // The creep force Fs along s = (0, cos γ, sin γ) of the pair; the pair's y is σ y_track.
    f.F_Y_creep += -w.side * c.Fs * std::cos(c.gamma);
    if (c.N > N_main) {
      N_main = c.N;
      f.gamma = c.gamma;
      f.r = c.r_roll;
      f.l = std::abs(c.Y_ws);
      f.a = c.a;
      f.b = c.b;
    }
  }
  for (const mh::LoadedEllipse& L : w.r.loaded) {
    if (!(L.s.N > 0)) continue;
    f.p_max = std::max(f.p_max, L.s.p_max);
    f.plastic = f.plastic || L.s.plastic;
  }
  if (f.n_contacts == 0) f.ok = false;
  return f;
}

}  // namespace

ContactAdapter::ContactAdapter(const WheelsetSetup& s) : s_(s), contact_(wheelset_setup(s)) {}

WheelsetForces ContactAdapter::evaluate(const WheelsetMotion& m) {
  mh::WheelsetPose p;
  p.y = -m.y;
  p.yaw = -m.psi;
  p.vertical = mh::WheelsetVertical::Loads;
  p.Q_left = p.Q_right = s_.Q;
  p.V = m.V;
  p.lateral_velocity = -m.y_dot;
  p.yaw_rate = -m.psi_dot;
  p.pitch_rate = m.Omega;
  contact_.step(p, step_options_, res_, ws_);
  ++calls_;
  WheelsetForces f;
  f.left = wheel_forces(res_.left);
  f.right = wheel_forces(res_.right);
  f.F_Y = f.left.F_Y + f.right.F_Y;
  f.M_Z = f.left.M_Z + f.right.M_Z;
  f.F_X = f.left.F_X + f.right.F_X;
  f.M_axle = f.left.M_axle + f.right.M_axle;
  return f;
}

}  // namespace wsdyn
