#pragma once
// Tangential rolling contact: the creepages of one contact and the result every method fills
// (multi-Hertzian per ellipse, strips and half-space per patch). SI throughout.
//
// Frame of one contact (docs/method.md §10): x along the rolling direction, y lateral in the
// contact plane (the patch plane's s axis, towards the field side), z = x × y the normal out of the
// rail into the wheel (Kalker's, into body 1): right-handed for a left wheel, the mirror image for
// a right wheel, as the pair's frame (docs/tangential.md, left and right wheel). Sign convention (Kalker's, fixed against CONTACT by the tests): the
// creepages are the rigid slip velocity of the WHEEL relative to the rail divided by the rolling
// speed V, and the forces and moment are those the RAIL exerts ON THE WHEEL, so that linear theory
// reads Fx = −G c² C11 ξ, Fy = −G c² C22 η − G c³ C23 φ, Mz = G c³ C23 η − G c⁴ C33 φ (c = √(ab)).
#include <cmath>

namespace mh {

struct Creepages {
  double xi = 0;   ///< [-] longitudinal creepage ξ
  double eta = 0;  ///< [-] lateral creepage η (in the contact plane)
  double phi = 0;  ///< [1/m] spin creepage φ (about the contact normal)
};

/// Result of the tangential problem on one contact (ellipse or patch).
struct TangentialResult {
  Creepages c;                      ///< the creepages it was solved with
  double mu = NAN;                  ///< [-] Coulomb friction coefficient used
  double Fx = 0, Fy = 0;            ///< [N] tangential force on the wheel, contact frame
  double Mz = 0;                    ///< [N m] spin moment on the wheel about the contact's reference point
  double adhesion_fraction = NAN;   ///< [-] adhesion area / contact area (NaN: not solved)
  /// [N] = [J/m] Tγ = Fx ξ + Fy η, forces ON THE RAIL (≥ 0 without spin): the frictional work per
  /// unit rolled distance of the two force components (wear/RCF indices); the spin term is apart.
  double Tgamma = 0;
  double Tgamma_spin = 0;           ///< [N] the spin term Mz φ (forces on the rail), reported apart
  int iterations = 0;               ///< solver iterations (0 for closed forms)
  /// [-] dFx/dN, dFy/dN at fixed creepages, Hertz-loaded (FASTSIM with FastsimOptions::load_slope;
  /// else NaN)
  double dFx_dN = NAN, dFy_dN = NAN;
  bool solved = false;              ///< false: not asked (no friction given) or failed (see status)
};

}  // namespace mh
