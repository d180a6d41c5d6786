// Flange climb and contact off the end of a profile (contact_geometry.hpp CandidateGeom flags,
// method.md §3.7), on S1002 / 60E1 1:40 (standard gauge, EN 13715 / EN 13674-1 definitions).
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "contact/solve.hpp"
#include "geometry/contact_geometry.hpp"
#include "profile/standard_profiles.hpp"

using namespace mh;

namespace {
ContactGeometry build(const Profile& w) {
  const Profile r = make_standard_profile("60E1", Inclination::In40);
  GeometryOptions g;
  g.tY_step = 0.1e-3;
  return build_geometry(w, r, TrackSetup{}, g);
}
const CandidateGeom& main_at(const ContactGeometry& G, double tY) {
  const std::size_t k = static_cast<std::size_t>(std::lround((tY - G.tY.front()) / (G.tY[1] - G.tY[0])));
  return G.main_at(k);
}
bool warned(const CaseResult& r, const std::string& kind) {
  for (const auto& w : r.warnings) if (mh::warning_text(w).rfind(kind, 0) == 0) return true;
  return false;
}
}  // namespace

TEST_CASE("flange climb is flagged once the contact passes the steepest flange point", "[geometry][flange_climb]") {
  const ContactGeometry G = build(make_standard_profile("S1002"));
  // S1002: the straight flange section is at 70° (EN 13715 section E, tan⁻¹ 2.7475); the smoothed
  // largest angle is within 1° of it, and the steepest section ends (towards the tip) at the
  // section's end S = −39.76 mm within 0.2 mm (1° of the R20 arc F is 0.35 mm).
  REQUIRE(G.has_flange);
  REQUIRE(std::fabs(G.flange_gamma_max * 180 / 3.14159265358979323846 - 70.0) < 1.0);
  REQUIRE(std::fabs(G.flange_y_steepest * 1e3 - (-39.764)) < 0.4);
  // Tread and flange-root contact: no climb; t_Y = 12 mm, contact well down the flange face
  // (contact angle below 60°): climb.
  for (double tY_mm : {-5.0, 0.0, 5.0, 6.0}) {
    CAPTURE(tY_mm);
    REQUIRE_FALSE(main_at(G, tY_mm * 1e-3).flange_climb);
  }
  const CandidateGeom& c = main_at(G, 12e-3);
  REQUIRE(c.gamma < G.flange_gamma_max - 5 * 3.14159265358979323846 / 180);
  REQUIRE(c.flange_climb);
  // The case says so, whatever the method.
  MethodOptions mo;
  REQUIRE(warned(solve_contact(G, Material{}, 12e-3, 50e3, mo), "flange_climb"));
  REQUIRE_FALSE(warned(solve_contact(G, Material{}, 0.0, 50e3, mo), "flange_climb"));
}

TEST_CASE("a contact at the cut end of a wheel profile is flagged off_profile", "[geometry][off_profile]") {
  // S1002 cut at y = +5 mm on the field side: at t_Y = −10 mm the contact on the whole S1002 lies
  // at y_w ≈ +17 mm, beyond the cut; on the cut wheel it sits on the cut edge.
  const Profile full = make_standard_profile("S1002");
  Profile cut = full;
  cut.y.clear(); cut.z.clear();
  for (std::size_t i = 0; i < full.size(); ++i)
    if (full.y[i] <= 5e-3) { cut.y.push_back(full.y[i]); cut.z.push_back(full.z[i]); }
  const ContactGeometry Gf = build(full), Gc = build(cut);
  REQUIRE(main_at(Gf, -10e-3).y_w > 10e-3);
  REQUIRE_FALSE(main_at(Gf, -10e-3).off_profile);
  REQUIRE(main_at(Gc, -10e-3).off_profile);
  MethodOptions mo;
  REQUIRE(warned(solve_contact(Gc, Material{}, -10e-3, 50e3, mo), "off_profile"));
  REQUIRE_FALSE(warned(solve_contact(Gf, Material{}, -10e-3, 50e3, mo), "off_profile"));
  REQUIRE_FALSE(warned(solve_contact(Gf, Material{}, 0.0, 50e3, mo), "off_profile"));
  // The grid methods check their patches' lateral extent against the profiles' ends.
  for (Method m : {Method::Strips, Method::HalfSpace}) {
    CAPTURE(to_string(m));
    MethodOptions g;
    g.method = m;
    const CaseResult rc = solve_contact(Gc, Material{}, -10e-3, 50e3, g);
    // The patch runs into the cut edge: the grid solvers report not_converged ("edge reached"),
    // and the row now also says why the geometry there cannot be trusted (a not_converged grid
    // row keeps no patches: grid_checks.hpp, withhold_unconverged_pressures).
    INFO(rc.message);
    REQUIRE(rc.patches.size() == (rc.status == CaseStatus::NotConverged ? 0u : 1u));
    REQUIRE(warned(rc, "off_profile:patch=1"));
    REQUIRE_FALSE(warned(solve_contact(Gf, Material{}, -10e-3, 50e3, g), "off_profile"));
    REQUIRE_FALSE(warned(solve_contact(Gf, Material{}, 0.0, 50e3, g), "off_profile"));
  }
}
