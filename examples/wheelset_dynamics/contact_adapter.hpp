#pragma once
// The wheelset's two contacts for the dynamics example: the one place that calls mhcontact. It
// calls the library's wheelset call (wheelset_contact/wheelset_contact.hpp, the C++ layer of
// mhc_wheelset_step): both wheels at once, each wheel's load balanced with its creep forces'
// vertical share (docs/method.md §10 eq. 10.1), the forces and moments on the wheelset in track
// coordinates, the spin moments included.
//
// Track frame of the example (docs/wheelset.md "Placement"): X forward, Y lateral positive
// towards the RIGHT rail, Z up; the yaw ψ turns X towards +Y, and the yaw moment M_Z is taken in
// the same sense. The wheelset call's frame has y towards the LEFT rail (x forward, z up, yaw
// turning x towards +y): Y = −y, ψ = −ψ_call, F_Y = −F_y, M_Z = −M_z, and the moment about the
// axle in the sense of rolling forward is M_y.
#include <memory>

#include "contact/case_result.hpp"
#include "contact/options.hpp"
#include "profile/profile.hpp"
#include "wheelset_contact/wheelset_contact.hpp"

namespace wsdyn {

/// The wheelset's motion at one instant (track frame, SI).
struct WheelsetMotion {
  double y = 0;        ///< [m] lateral displacement, towards the right rail
  double psi = 0;      ///< [rad] yaw angle (X turned towards +Y)
  double y_dot = 0;    ///< [m/s]
  double psi_dot = 0;  ///< [rad/s]
  double V = 0;        ///< [m/s] forward speed
  double Omega = 0;    ///< [rad/s] the axle's rotation rate (rolling forward)
};

/// One wheel's contact, summed over its loaded ellipses; forces ON THE WHEELSET, track frame.
struct WheelContactForces {
  double F_X = 0;      ///< [N] longitudinal creep force
  double F_Y = 0;      ///< [N] lateral: normal forces' share N sin γ and the creep forces' Fy cos γ
  double F_Y_creep = 0;  ///< [N] the creep forces' share of F_Y alone
  double M_Z = 0;      ///< [N m] yaw moment about the wheelset centre: the longitudinal creep forces' (−Y_c F_X) and the spin moments' share
  double M_axle = 0;   ///< [N m] moment about the axle, in the sense of rolling forward: −Σ r F_X
  double N = 0;        ///< [N] Σ normal forces
  // The main (most loaded) contact: where it is, for output and the linear model.
  double gamma = 0;    ///< [rad] contact angle (pair frame: positive towards the gauge corner)
  double r = 0;        ///< [m] rolling radius
  double l = 0;        ///< [m] |Y| of the contact from the wheelset centre plane
  double a = 0, b = 0; ///< [m] its ellipse (a along X)
  double p_max = 0;    ///< [Pa] the largest contact pressure carried (plastic: capped by its law)
  bool plastic = false;  ///< an ellipse in the plastic regime (Material::p_lim finite)
  int n_contacts = 0;
  bool ok = false;     ///< the solve answered (mh::is_failure false) and solved the tangential problem
  mh::CaseStatus status = mh::CaseStatus::Ok;
};

struct WheelsetForces {
  WheelContactForces left, right;
  double F_Y = 0;   ///< [N] total lateral force on the wheelset from both contacts
  double M_Z = 0;   ///< [N m] total yaw moment
  double F_X = 0;   ///< [N] total longitudinal creep force
  double M_axle = 0;  ///< [N m] total moment about the axle (rolling sense)
  bool ok() const { return left.ok && right.ok; }
};

/// What a wheelset is made of, for the contact.
struct WheelsetSetup {
  mh::Profile wheel;            ///< the wheel profile (both wheels: one profile mirrored)
  mh::Profile rail;             ///< the rail profile WITH its inclination applied
  mh::TrackSetup track;         ///< gauge, flange back, nominal radius (method.md §7)
  mh::Material material;        ///< elastic unless p_lim is finite (method.md §5)
  double Q = 50e3;              ///< [N] vertical load per wheel
  double mu = 0.3;              ///< [-] Coulomb friction
  mh::FastsimOptions fastsim;   ///< FASTSIM's grid (defaults of the library)
};

/// The contacts of a wheelset: built once (the pair's geometry), evaluated at every right-hand
/// side. Not thread-safe (one result buffer, reused for both wheels).
class ContactAdapter {
 public:
  explicit ContactAdapter(const WheelsetSetup& s);
  /// Both wheels' contacts at the motion m: one step of the wheelset call with the vertical load
  /// Q on each wheel (Σ N cos γ + Σ Fy sin γ = Q), the tangential by FASTSIM on each loaded ellipse.
  WheelsetForces evaluate(const WheelsetMotion& m);
  /// [m] |Y| of the wheel profile's taping line from the centre plane (FBD/2 − flange-back position).
  double l_origin() const { return contact_.taping_line(+1); }
  const WheelsetSetup& setup() const { return s_; }
  long calls() const { return calls_; }

 private:
  WheelsetSetup s_;
  mh::WheelsetContact contact_;
  mh::WheelsetStepOptions step_options_;
  mh::WheelsetWorkspace ws_;
  mh::WheelsetResult res_;
  long calls_ = 0;
};

}  // namespace wsdyn
