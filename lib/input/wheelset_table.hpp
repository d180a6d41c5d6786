#pragma once
// A wheelset table (docs/tables.md "A wheelset table"): the contact tables of a wheelset's two
// wheel–rail pairs in one file, with where each pair sits in the wheelset, and the lookup that
// places both wheels from the wheelset's lateral displacement y and roll φ, as the wheelset call
// does (wheelset_contact/wheelset_contact.hpp), and sums their forces in the track frame.
//
// File (schema mhcontact.wheelset-table/1): a header line `# {...}` of its own (schema, what,
// units, the two pairs' placements), then the left pair's table, then the right pair's, each a
// table file of mhcontact.table/2 as `mhcontact table` wrote it (header line, column line, rows),
// copied byte for byte by `mhcontact table-wheelset`.
//
// Placement (method.md §3.8; wheelset_contact.cpp pair_pose): side s (σ = +1 left, −1 right) at
// δ_s = σ φ and t_Y,s = σ y + a_s (cos δ_s − 1) + H_s sin δ_s, a_s the taping line's distance from
// the wheelset centre, H_s = z0_s + R0_s the axle centre above the wheel profile's origin. The
// normal forces on the wheelset in the track frame (x forward, y towards the left rail, z up):
// F_y,s = −σ Σ N sin γ, F_z,s = Σ N cos γ, and the moment about x about the axle centre of
// each contact at (Y_ws, Z_ws) = (σ (a_s + y_w), −r_roll): M_x = Y_ws F_z − Z_ws F_y (the
// wheelset call's convention). The tables hold normal contact only: no creep forces.
#include <array>
#include <string>

#include <nlohmann/json.hpp>

#include "input/contact_table.hpp"

namespace mh {

/// Where a pair sits in its wheelset (the `wheelset_placement` of its table's header) [m].
struct WheelsetPlacement {
  double a = 0.75;           ///< taping line from the wheelset centre
  double H = 0.46;           ///< axle centre above the wheel profile's origin: z0 + R0
  double rail_offset = 0.0;  ///< rail origin from the track centre
};

/// The placement recorded in a table's header; throws InputError (naming `where`) when the table
/// has none (made before it was recorded: remake it).
WheelsetPlacement table_placement(const nlohmann::json& header, const std::string& where);

/// A wheelset table in memory: 0 left, 1 right.
struct WheelsetTableData {
  nlohmann::json header;
  std::array<ContactTableData, 2> pair;
  std::array<WheelsetPlacement, 2> place;
};

/// Read a wheelset table file. Throws InputError naming the file and line.
WheelsetTableData read_wheelset_table(const std::string& path);

/// The wheelset's pose for a lookup (SI, track frame): as WheelsetPose in loads mode with the
/// roll given.
struct WheelsetTablePose {
  double y = 0;                    ///< [m] lateral displacement (towards the left rail)
  double roll = 0;                 ///< [rad] φ about x, positive raising the left wheel
  double Q_left = 0, Q_right = 0;  ///< [N] vertical loads
};

/// One wheel's answer.
struct WheelsetTableWheel {
  double tY = 0;     ///< [m] its pair's t_Y as placed
  double delta = 0;  ///< [rad] its roll against the rail, σ φ
  TableAnswer pair;  ///< the pair table's answer at (tY, Q_s, delta), pair frame
  /// [N], [N m] on the wheelset, track frame (about the axle centre). Mx sums the contacts held in
  /// pair.c (the first kTableMaxContacts; more are rare) beside a Fz of them all.
  double Fy = 0, Fz = 0, Mx = 0;
  /// ∂F_y/∂y [N/m], ∂F_y/∂φ [N/rad], ∂F_y/∂Q_s [-] by the chain rule through the placement.
  double dFy_dy = 0, dFy_droll = 0, dFy_dQ = 0;
};

struct WheelsetTableAnswer {
  CaseStatus status = CaseStatus::OutOfRange;  ///< the worse of the two wheels' (status_severity)
  std::array<WheelsetTableWheel, 2> wheel;     ///< 0 left, 1 right
  double Fy = 0, Fz = 0, Mx = 0;               ///< both wheels
  double dFy_dy = 0, dFy_droll = 0;            ///< of Fy; ∂Fy/∂Q_s is wheel[s].dFy_dQ
};

/// The two pairs' interpolants and their placements; lookups allocate nothing and may run on
/// any number of threads at once.
class WheelsetTableLookup {
 public:
  explicit WheelsetTableLookup(WheelsetTableData d);
  const nlohmann::json& header() const { return header_; }
  const ContactTableLookup& pair(int s) const { return pair_[static_cast<std::size_t>(s)]; }
  const WheelsetPlacement& placement(int s) const { return place_[static_cast<std::size_t>(s)]; }
  /// Side s's (0 left, 1 right) t_Y and δ at the wheelset's y and φ.
  void place(int s, double y, double roll, double& tY, double& delta) const;
  void lookup(const WheelsetTablePose& p, WheelsetTableAnswer& out) const;

 private:
  nlohmann::json header_;
  std::array<ContactTableLookup, 2> pair_;
  std::array<WheelsetPlacement, 2> place_;
};

}  // namespace mh
