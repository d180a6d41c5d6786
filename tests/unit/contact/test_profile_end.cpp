// A grid patch that reaches the end of a profile is never `ok`: the gap beyond the
// end is extrapolated, not measured, so the row is flagged off_profile and judged
// outside_validity (docs/status.md). Reference: S1002 on 60E1 1:40 (generated), flange contact
// t_Y = 9 mm, Q = 50 kN, solved on the whole rail (ok, one patch), then on the same rail cut at
// the patch's reference point, so that half of the patch lies beyond the rail's end.
#include <catch2/catch.hpp>

#include <string>

#include "contact/solve.hpp"
#include "input/case_file.hpp"
#include "jobs/run.hpp"

TEST_CASE("a grid patch reaching a profile's end is outside validity, never ok", "[status][off_profile]") {
  mh::CaseFile cf = mh::load_case_file(std::string(MHCONTACT_SOURCE_DIR) + "/cases/s1002-60e1.json", true);
  const mh::PairGeometry pg = mh::build_pair_geometry(cf);
  const double tY = 9e-3, Q = 50e3;
  mh::MethodOptions hs_opt = cf.method_options();
  hs_opt.method = mh::Method::HalfSpace;
  const mh::CaseResult whole = mh::solve_contact(pg.geo, cf.material, tY, Q, hs_opt);
  REQUIRE(whole.status == mh::CaseStatus::Ok);
  REQUIRE(whole.patches.size() == 1);
  // The rail cut at the patch's reference point (its gauge-side half removed).
  const double y_cut = whole.patches[0].y_r;
  mh::Profile kept = pg.rail;
  kept.y.clear();
  kept.z.clear();
  for (std::size_t i = 0; i < pg.rail.y.size(); ++i)
    if (pg.rail.y[i] >= y_cut) { kept.y.push_back(pg.rail.y[i]); kept.z.push_back(pg.rail.z[i]); }
  // The cut rail has no gauge point: the wheel is placed where it was on the whole rail.
  mh::TrackSetup track = cf.track;
  track.positioning = mh::TrackSetup::Positioning::Explicit;
  track.lateral_offset = pg.geo.y_offset;
  const mh::ContactGeometry G = mh::build_geometry(pg.wheel, kept, track, cf.geometry);
  for (mh::Method m : {mh::Method::HalfSpace, mh::Method::Strips, mh::Method::Auto}) {
    INFO("method " << mh::to_string(m));
    mh::MethodOptions opt = cf.method_options();
    opt.method = m;
    const mh::CaseResult r = mh::solve_contact(G, cf.material, tY, Q, opt);
    INFO("status " << mh::to_string(r.status) << ": " << r.message);
    CHECK(r.status != mh::CaseStatus::Ok);
    if (r.status == mh::CaseStatus::OutsideValidity) {
      bool flagged = false;
      for (const auto& w : r.warnings) flagged = flagged || w.cls == mh::WarningClass::OffProfile;
      CHECK(flagged);
    }
  }
}
