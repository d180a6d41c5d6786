#include "geometry/placement_check.hpp"

#include <cmath>

#include "core/numfmt.hpp"
#include "core/units.hpp"

namespace mh {

namespace {
std::string r3(double v) { return format_number(std::round(v * 1e3) / 1e3 + 0.0); }
}  // namespace

PlacementCheck check_placement(const ContactGeometry& G) {
  PlacementCheck c;
  c.nominal_radius = G.nominal_radius;
  const ContactGeometry::MainPoint M = G.locate_main(0.0);
  if (!M.found) {
    c.why = "the wheel and rail profiles do not overlap laterally at t_Y = 0";
    return c;
  }
  c.found = true;
  G.fill_candidate(0.0, M.y_r, true, M.gmin, c.main);
  const CandidateGeom& m = c.main;
  const double gamma_deg = m.gamma / units::deg;
  const double dr_mm = (m.r_roll - G.nominal_radius) * units::per_mm;
  c.numbers = "contact at rail y " + r3(m.y_r * units::per_mm) + " mm, wheel y " + r3(m.y_w * units::per_mm) +
              " mm (from its taping line), contact angle " + r3(gamma_deg) + " deg, rolling radius " +
              r3(m.r_roll * units::per_mm) + " mm (nominal " + r3(G.nominal_radius * units::per_mm) + " mm)";
  const ProfileCurve& W = *G.wheel_curve;
  if (!W.contains(0.0))
    c.why = "the wheel's origin y = 0, its taping line, lies outside its profile (y " + r3(W.y_min() * units::per_mm) +
            " … " + r3(W.y_max() * units::per_mm) + " mm): the taping line was not found, and the wheel is placed "
            "and its rolling radius measured from a point it does not have";
  else if (std::fabs(gamma_deg) > PlacementLimits::kMaxContactAngle_deg)
    c.why = "its contact angle is " + r3(gamma_deg) + " deg, beyond ±" + r3(PlacementLimits::kMaxContactAngle_deg) +
            " deg (a flange or a flank, not the tread)";
  else if (std::fabs(dr_mm) > PlacementLimits::kMaxRadiusDeviation_mm)
    c.why = "its rolling radius differs from the nominal one by " + r3(dr_mm) + " mm, more than " +
            r3(PlacementLimits::kMaxRadiusDeviation_mm) + " mm (the flange tip or the rim, not the tread)";
  else if (m.off_profile)
    c.why = "it lies at the end of a profile's measured range (wheel y " + r3(G.wheel_curve->y_min() * units::per_mm) +
            " … " + r3(G.wheel_curve->y_max() * units::per_mm) + " mm, rail y " +
            r3(G.rail_curve->y_min() * units::per_mm) + " … " + r3(G.rail_curve->y_max() * units::per_mm) + " mm)";
  c.ok = c.why.empty();
  return c;
}

}  // namespace mh
