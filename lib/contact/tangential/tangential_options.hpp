#pragma once
// The tangential problem's inputs of a case (case file `friction`, `kinematics` | `creepages`;
// docs/case-file.md, docs/tangential.md): light, for the case-file reader. SI.
#include <cmath>

#include "contact/tangential/creepage.hpp"
#include "contact/tangential/fastsim.hpp"
#include "contact/tangential/tangential_types.hpp"

namespace mh {

struct TangentialOptions {
  /// [-] Coulomb friction coefficient μ (case file friction.coefficient); NaN: no tangential
  /// problem is solved and no tangential column is written (the outputs are those without it).
  double mu = NAN;
  enum class Source { Kinematics, Creepages };
  Source source = Source::Kinematics;
  /// The wheelset's motion (Source::Kinematics). yaw is the yaw at t_Y = 0; yaw_per_tY [rad/m]
  /// adds yaw_per_tY · t_Y (kinematics.yaw_mrad_per_mm, as the Manchester case does).
  Kinematics kin;
  double yaw_per_tY = 0;
  /// The creepages given directly, the same for every contact of the case (Source::Creepages).
  Creepages creep;
  /// [m] lateral distance of the wheel profile's origin (taping line) from the wheelset's centre
  /// plane: half the flange-back distance minus the flange-back position (method.md §7, §10).
  /// Set by the case-file reader from the track setup.
  double l_origin = 0.75;
  /// [m] nominal rolling radius r0 (track.nominal_radius): the pitch rate's default V / r0.
  double r0 = 0.46;
  FastsimOptions fastsim;
  /// Whether the vertical load Q is balanced with the creep forces' vertical components,
  /// Q = Σ (N_i cos γ_i + Fy_i sin γ_i) (docs/tangential.md, "Vertical equilibrium"; default
  /// true, as CONTACT's module 1 does), by the methods that solve the tangential problem
  /// (multi-Hertzian, half-space). false: Σ N_i cos γ_i = Q, the creep forces computed after
  /// (a caller balancing the load itself, e.g. with the wheelset's full equilibrium).
  bool vertical_equilibrium = true;
  /// [-] The vertical equilibrium's tolerance, |Σ (N_i cos γ_i + Fy_i sin γ_i) − Q| ≤ it × Q
  /// (default 1e-7: 1 mN at 10 kN; the wheelset call's default is its own, wheelset_contact.hpp).
  double equilibrium_tolerance = 1e-7;
  /// Keep each contact's traction per element (CaseResult::ellipse_traction, PatchResult::traction;
  /// contact/tangential/traction_grid.hpp) for the traction grid of `run --pressure-grid`. Default
  /// false: nothing is kept and nothing allocated for it.
  bool keep_traction = false;
  bool enabled() const { return std::isfinite(mu); }
};

}  // namespace mh
