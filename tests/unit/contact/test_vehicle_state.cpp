// The judge's vehicle-state warnings (contact/judge/judge.hpp, docs/status.md): the Nadal ratio
// Y/Q with its `nadal_limit` warning, and the `derailed` status of a wheel riding on its flange tip.
// Breaks guarded (each seen to fail):
//  - drop the nadal_limit test from add_vehicle_state_warnings(): "a Y/Q above 0.8 carries
//    nadal_limit" fails;
//  - drop the derailed test (or the status it sets in decide_status()): the t_Y 30-60 mm rows are
//    `ok` (multi-Hertzian) or `outside_validity` and "S1002 on 60E1 beyond its flange" fails;
//  - derail on flange_climb alone (no rolling-radius test): the flange-climbing rows at
//    t_Y 8.5-10 mm of the same sweep become `derailed` and the same test fails.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "contact/judge/judge.hpp"
#include "contact/solve.hpp"
#include "input/case_file.hpp"
#include "jobs/run.hpp"

TEST_CASE("judge: Y/Q is Fy/Fz and a Y/Q above 0.8 carries nadal_limit", "[judge][nadal]") {
  const mh::ContactGeometry G;  // no flange: no derailment test
  struct Row { double Fz_N, Fy_N; bool warned; };
  // Y/Q = Fy/Fz; EN 14363's flange-climbing limit 0.8 (judge.hpp).
  const Row rows[] = {{60e3, 282e3, true}, {60e3, 49.2e3, true}, {60e3, 47.4e3, false}, {60e3, -60e3, false}};
  for (const Row& t : rows) {
    mh::CaseResult r;
    r.Fz = t.Fz_N;
    r.Fy = t.Fy_N;
    CAPTURE(t.Fy_N);
    CHECK(mh::y_over_q(r) == Approx(t.Fy_N / t.Fz_N).epsilon(1e-12));
    mh::add_vehicle_state_warnings(r, G);
    mh::decide_status(r);
    CHECK(mh::has_class(r.warnings, mh::WarningClass::NadalLimit) == t.warned);
    CHECK(r.status == mh::CaseStatus::Ok);  // informational: a state of the vehicle
    if (t.warned) CHECK(mh::warning_text(r.warnings.back()).rfind("nadal_limit:Y_over_Q=", 0) == 0);
  }
  mh::CaseResult none;  // no force: no ratio
  CHECK(std::isnan(mh::y_over_q(none)));
}

TEST_CASE("judge: S1002 on 60E1 beyond its flange is derailed, flange climbing is not", "[judge][derailed]") {
  nlohmann::json j = {
      {"wheel", {{"profile", {{"standard", "S1002"}}}, {"nominal_radius_mm", 460}}},
      {"rail", {{"profile", {{"standard", "60E1"}}}, {"inclination", "1:40"}}},
      {"material", {{"E_GPa", 210}, {"nu", 0.28}}},
      {"model", "elastic"},
      {"sweep", {{"tY_mm", {{"from", 0}, {"to", 60}, {"step", 0.5}}}, {"Q_kN", {80}}}}};
  const mh::CaseFile cf = mh::parse_case_json(j, "derail.json", true);
  const mh::PairGeometry pg = mh::build_pair_geometry(cf);
  REQUIRE(pg.geo.has_flange);
  for (const mh::Method m : {mh::Method::MultiHertzian, mh::Method::Auto}) {
    mh::MethodOptions mo = cf.method_options();
    mo.method = m;
    // The finding: the wheel rides on its flange tip at these t_Y.
    for (const double tY_mm : {30.0, 40.0, 50.0, 60.0}) {
      const mh::CaseResult r = mh::solve_contact(pg.geo, cf.material, tY_mm * 1e-3, 80e3, mo);
      CAPTURE(mh::to_string(m), tY_mm, mh::warning_texts(r.warnings));
      CHECK(r.status == mh::CaseStatus::Derailed);
      CHECK(mh::has_class(r.warnings, mh::WarningClass::Derailed));
      CHECK_FALSE(mh::is_failure(r.status));  // an answer: its numbers are kept
      CHECK(r.Fz == Approx(80e3).epsilon(1e-3));
    }
    // Tread and flange climbing up to 10 mm (docs/status.md: valid answers) are not derailed.
    for (double tY_mm = 0; tY_mm <= 10.0; tY_mm += 0.5) {
      const mh::CaseResult r = mh::solve_contact(pg.geo, cf.material, tY_mm * 1e-3, 80e3, mo);
      CAPTURE(mh::to_string(m), tY_mm, mh::warning_texts(r.warnings));
      CHECK(r.status != mh::CaseStatus::Derailed);
      CHECK_FALSE(mh::has_class(r.warnings, mh::WarningClass::Derailed));
    }
  }
}
