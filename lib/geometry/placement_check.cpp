#include "geometry/placement_check.hpp"

#include <cmath>

#include "core/numfmt.hpp"
#include "core/units.hpp"

namespace mh {

namespace {
std::string r3(double v) { return format_number(std::round(v * 1e3) / 1e3 + 0.0); }
std::string mm(double v) { return r3(v * units::per_mm); }
}  // namespace

std::string PlacementCheck::explicit_placement() const {
  // 1e-6 mm: the offset the gauge rule computed, to well below the strip width.
  return "\"positioning\": \"explicit\", \"lateral_offset_mm\": " +
         format_number(std::round(lateral_offset * units::per_mm * 1e6) / 1e6 + 0.0);
}

PlacementCheck check_placement(const ContactGeometry& G, double rail_gauge_z, double flange_min_height) {
  PlacementCheck c;
  c.nominal_radius = G.nominal_radius;
  c.lateral_offset = G.y_offset;
  const ProfileCurve& W = *G.wheel_curve;
  const ProfileCurve& R = *G.rail_curve;
  const ContactGeometry::MainPoint M = G.locate_main(0.0);
  if (!M.found) {
    c.why = "the wheel and rail profiles do not overlap laterally at t_Y = 0";
    return c;
  }
  c.found = true;
  G.fill_candidate(0.0, M.y_r, true, M.gmin, c.main);
  const CandidateGeom& m = c.main;
  c.numbers = "contact at rail y " + mm(m.y_r) + " mm, wheel y " + mm(m.y_w) + " mm (from its taping line), contact angle " +
              r3(m.gamma / units::deg) + " deg, rolling radius " + mm(m.r_roll) + " mm (nominal " +
              mm(G.nominal_radius) + " mm)";
  // The wheel's lowest point on each side of its taping line (the flange tip on the gauge side).
  std::size_t i_gauge = W.nodes(), i_field = W.nodes();
  for (std::size_t i = 0; i < W.nodes(); ++i) {
    std::size_t& k = W.node_y(i) < 0 ? i_gauge : i_field;
    if (k == W.nodes() || W.z(W.node_y(i)) < W.z(W.node_y(k))) k = i;
  }
  if (!W.contains(0.0)) {
    c.why = "the wheel's origin y = 0, its taping line, lies outside its profile (y " + mm(W.y_min()) + " … " +
            mm(W.y_max()) + " mm): the taping line was not found, and the wheel is placed and its rolling radius "
            "measured from a point it does not have";
    return c;
  }
  const double z0 = W.z(0.0);
  const bool flange_gauge = i_gauge < W.nodes() && z0 - W.z(W.node_y(i_gauge)) >= flange_min_height;
  const bool flange_field = i_field < W.nodes() && z0 - W.z(W.node_y(i_field)) >= flange_min_height;
  if (flange_field && !flange_gauge) {
    c.why = "its flange (lowest point at wheel y " + mm(W.node_y(i_field)) + " mm, " + mm(z0 - W.z(W.node_y(i_field))) +
            " mm below the taping line) lies on the field side of the taping line: a mirrored profile (the canonical "
            "frame has the flange at negative y)";
    return c;
  }
  if (flange_gauge) {
    // The wheel as it stands at t_Y = 0: wheel point y_w at rail y_w + y_offset, its height
    // z_w(y_w) − z_w(contact) + z_r(contact). The rail's gauge point (gauge_height below its top).
    const double dz = R.z(m.y_r) - W.z(m.y_w);
    const double y_tip = W.node_y(i_gauge), z_tip = W.z(y_tip) + dz;
    const double level = rail_gauge_z - dz;  // the gauge point's height in the wheel's frame
    c.numbers += "; flange tip at rail y " + mm(y_tip + G.y_offset) + " mm, " + mm(std::fabs(z_tip - rail_gauge_z)) +
                 (z_tip < rail_gauge_z ? " mm below" : " mm above") + " the rail's gauge point (rail y " +
                 mm(G.rail_gauge_y) + " mm)";
    if (!(z_tip < rail_gauge_z)) {
      c.why = "its flange does not reach down to the rail's gauge point: the flange stands on the rail head, not "
              "inside the track";
      return c;
    }
    // The flange flank facing the rail: from the tip towards the taping line, where the wheel
    // rises through the gauge point's height.
    std::size_t i = i_gauge;
    while (i + 1 < W.nodes() && W.node_y(i + 1) <= 0 && W.z(W.node_y(i + 1)) < level) ++i;
    const double ya = W.node_y(i), yb = W.node_y(i + 1 < W.nodes() ? i + 1 : i);
    const double za = W.z(ya), zb = W.z(yb);
    const double y_flank = zb > za ? ya + (level - za) / (zb - za) * (yb - ya) : ya;
    c.flange_measured = true;
    c.flange_clearance = G.rail_gauge_y - (y_flank + G.y_offset);
    c.numbers += ", flange clearance " + mm(c.flange_clearance) + " mm there";
    if (c.flange_clearance * units::per_mm > PlacementLimits::kMaxFlangeClearance_mm) {
      c.why = "its flange stands " + mm(c.flange_clearance) + " mm inside the rail's gauge point, more than " +
              r3(PlacementLimits::kMaxFlangeClearance_mm) + " mm (a thin flange in a widened gauge: about 35 mm)";
      return c;
    }
  }
  if (m.off_profile)
    c.why = "its contact lies at the end of a profile's measured range (wheel y " + mm(W.y_min()) + " … " + mm(W.y_max()) +
            " mm, rail y " + mm(R.y_min()) + " … " + mm(R.y_max()) + " mm)";
  c.ok = c.why.empty();
  return c;
}

}  // namespace mh
