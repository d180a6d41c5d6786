// The status rule (contact/judge/judge.hpp judge_validity, docs/status.md): a row whose
// method is outside its validity is `outside_validity`, not `ok`, and keeps its numbers; the
// warnings say why. Applied once, in solve_contact, to every method's result.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "contact/solve.hpp"
#include "input/case_file.hpp"
#include "jobs/run.hpp"

using namespace mh;

namespace {

CaseResult ok_with(std::vector<Warning> warnings, Method m = Method::Strips) {
  CaseResult r;
  r.method = m;
  r.warnings = std::move(warnings);
  return r;
}

/// A loaded ellipse at rail y `y` [m] with lateral semi-axis b [m] on a flat contact (γ = 0).
LoadedEllipse ellipse_at(int k, double y, double b) {
  LoadedEllipse L;
  L.ellipse = k;
  L.g.y_r = y;
  L.g.gamma = 0;
  L.s.b = b;
  return L;
}

constexpr double kDcomb = 8e-3;  // [m] StripMethodOptions::d_comb's default

using C = WarningClass;
using K = ContactKind;
using Q = Quantity;
Warning auto_not_hertzian(int e) {
  Warning w = Warning::auto_to(Method::Strips, AutoReason::NotHertzian);
  w.contact = e;
  return w;
}
Warning pair_warning(int a, int b) {
  Warning w(C::Interacting, K::EllipsePair, a);
  w.contact2 = b;
  return w;
}

}  // namespace

TEST_CASE("status: every warning class but auto and flange_climb puts an ok row outside validity", "[status]") {
  // One row per class, with a warning as the solvers make it and its text as written (the text
  // the solvers built before the warnings were data: tests/ref and tests/cli compare it).
  struct Row {
    std::string cls;
    Warning w;
    std::string text;
  };
  const std::vector<Row> table = {
      {"non_hertzian", Warning(C::NonHertzian, K::Ellipse, 2).add(Q::GapError, 0.5871, '>', 0.5).add(Q::GapMeanError, 0.3139, '>', 0.1),
       "non_hertzian:ellipse=2:gap_error=0.587>0.5:gap_mean_error=0.314>0.1"},
      {"non_hertzian", Warning(C::NonHertzian, K::Ellipse, 4).add(Q::BOverR, 22.3314, '>', 0.3),
       "non_hertzian:ellipse=4:b_over_R=22.331>0.3"},
      {"non_hertzian_excluded", Warning(C::NonHertzianExcluded, K::Ellipse, 3), "non_hertzian_excluded:ellipse=3"},
      {"interacting", pair_warning(1, 2).add(Q::EdgeGap, -0.049e-3, '<', kDcomb), "interacting:ellipses=1+2:edge_gap_mm=-0.049<8"},
      {"off_profile", Warning(C::OffProfile, K::Patch, 1), "off_profile:patch=1"},
      {"pressure_spike",
       Warning(C::PressureSpike, K::Patch, 1).add(Q::YRail, -31.2e-3).add(Q::PSpike, 5123.4e6).add(Q::PNeighbours, 2100.1e6),
       "pressure_spike:patch=1:y_rail_mm=-31.2:p_MPa=5123.4:neighbours_MPa=2100.1"},
      {"strip_outlier", Warning(C::StripOutlier, K::Patch, 2).add(Q::Strips, 1).add(Q::YRailStrip, -30.4e-3).add(Q::QStrip, 4100.2e6),
       "strip_outlier:patch=2:strips=1:y_rail_mm=-30.4:q_MPa=4100.2"},
      {"force_balance", Warning(C::ForceBalance).add(Q::Residual, 0.001, '>', 1e-5), "force_balance:residual=0.001>1e-05"},
      {"complementarity", Warning(C::Complementarity, K::Patch, 1).add(Q::GapViolation, 1.2e-6, '>', 0.5e-6),
       "complementarity:patch=1:gap_um=1.2>0.5"},
      {"complementarity", Warning(C::Complementarity, K::Patch, 1).add(Q::PMin, -2.5e6, '<', 0), "complementarity:patch=1:p_min_MPa=-2.5<0"},
      {"complementarity", Warning(C::Complementarity, K::Patch, 2).add(Q::PMax, 1100.0004e6, '>', 1050e6),
       "complementarity:patch=2:p_max_MPa=1100>p_lim"},
      {"contact_hole",
       Warning(C::ContactHole, K::Patch, 1).add(Q::Elements, 20).add(Q::YRail, -43.935e-3).add(Q::Overlap, 90.1e-6, '>', 1.6e-6),
       "contact_hole:patch=1:elements=20:y_rail_mm=-43.935:overlap_um=90.1>1.6"},
  };
  for (const auto& [cls, w, text] : table) {
    CAPTURE(text);
    REQUIRE(warning_text(w) == text);
    REQUIRE(to_string(w.cls) == cls);
    CaseResult r = ok_with({auto_not_hertzian(2), w});
    judge_validity(r, kDcomb);
    REQUIRE(r.status == CaseStatus::OutsideValidity);
    REQUIRE(std::string(to_string(r.status)) == "outside_validity");
    REQUIRE(r.message == "outside the validity of the method: " + cls + " (see warnings)");
    REQUIRE(r.warnings.size() == 2);  // the detail is kept
  }
  // No warning, or auto's note alone: ok.
  CaseResult none = ok_with({});
  judge_validity(none, kDcomb);
  REQUIRE(none.status == CaseStatus::Ok);
  REQUIRE(none.message.empty());
  // A class named later by a new check (--fail-on, summaries) counts too: no row stays ok by omission.
  REQUIRE(is_validity_class("some_new_check"));
  Warning interact = Warning::auto_to(Method::Strips, AutoReason::Interact);
  interact.contact = 2;
  interact.contact2 = 3;
  REQUIRE(warning_text(interact) == "auto:strips:ellipses 2 and 3 interact");
  CaseResult note = ok_with({interact});
  judge_validity(note, kDcomb);
  REQUIRE(note.status == CaseStatus::Ok);
  // Flange climb is a state of the wheelset, not a limit of the methods (their answers there
  // agree within a few per cent): the row stays ok, the warning says it.
  CaseResult climb = ok_with({Warning(C::FlangeClimb, K::Ellipse, 4)});
  REQUIRE(warning_text(climb.warnings[0]) == "flange_climb:ellipse=4");
  judge_validity(climb, kDcomb);
  REQUIRE(climb.status == CaseStatus::Ok);
  REQUIRE(climb.warnings.size() == 1);
  // Several classes: named once each, in order of appearance.
  CaseResult two = ok_with({Warning(C::NonHertzian, K::Ellipse, 1).add(Q::BOverR, 0.4, '>', 0.3),
                            Warning(C::FlangeClimb, K::Ellipse, 4), Warning(C::OffProfile, K::Ellipse, 4),
                            Warning(C::NonHertzian, K::Ellipse, 2).add(Q::GapError, 0.6, '>', 0.5)});
  judge_validity(two, kDcomb);
  REQUIRE(two.message == "outside the validity of the method: non_hertzian, off_profile (see warnings)");
}

TEST_CASE("status: a failed row keeps its status, whatever its warnings", "[status]") {
  for (CaseStatus s : {CaseStatus::NoContact, CaseStatus::OutOfRange, CaseStatus::NotConverged}) {
    CaseResult r = ok_with({Warning(C::FlangeClimb, K::Ellipse, 4), Warning(C::OffProfile, K::Patch, 1)});
    r.status = s;
    r.message = "why";
    judge_validity(r, kDcomb);
    REQUIRE(r.status == s);
    REQUIRE(r.message == "why");
    REQUIRE(is_failure(s));
  }
  REQUIRE_FALSE(is_failure(CaseStatus::Ok));
  REQUIRE_FALSE(is_failure(CaseStatus::OutsideValidity));
}

TEST_CASE("status: interacting ellipses of a multi-Hertzian row, by the edge gap against d_comb", "[status]") {
  // Edge gap = |y1 − y2| − b1 − b2 (γ = 0): 20 − 3 − 2 = 15 mm apart: independent;
  // 12 − 3 − 2 = 7 mm < 8 mm: interacting.
  CaseResult far = ok_with({}, Method::MultiHertzian);
  far.loaded = {ellipse_at(1, 0, 3e-3), ellipse_at(3, -20e-3, 2e-3)};
  REQUIRE_FALSE(interacting_ellipses(far, kDcomb).found);
  judge_validity(far, kDcomb);
  REQUIRE(far.status == CaseStatus::Ok);
  REQUIRE(far.warnings.empty());

  CaseResult near = ok_with({}, Method::MultiHertzian);
  near.loaded = {ellipse_at(1, 0, 3e-3), ellipse_at(3, -12e-3, 2e-3)};
  const EllipseInteraction e = interacting_ellipses(near, kDcomb);
  REQUIRE(e.found);
  REQUIRE(e.first == 1);
  REQUIRE(e.second == 3);
  REQUIRE(e.edge_gap == Approx(7e-3).epsilon(1e-12));
  judge_validity(near, kDcomb);
  REQUIRE(near.status == CaseStatus::OutsideValidity);
  REQUIRE(warning_texts(near.warnings) == std::vector<std::string>{"interacting:ellipses=1+3:edge_gap_mm=7<8"});

  // A grid method couples its regions itself: its loaded ellipses (none) are not tested.
  CaseResult grid = ok_with({}, Method::Strips);
  grid.loaded = near.loaded;
  judge_validity(grid, kDcomb);
  REQUIRE(grid.status == CaseStatus::Ok);
}

TEST_CASE("status: Manchester t_Y = 1 mm, 50 kN by the multi-Hertzian method is outside validity, numbers kept",
          "[status]") {
  // The row: 56.8 mm² by the multi-Hertzian method against 113.9 mm² by the half-space
  // method, `ok` before with only the warning gap_mean_error=0.314>0.1.
  const CaseFile cf = load_case_file(std::string(MHCONTACT_SOURCE_DIR) + "/cases/manchester.json", true);
  const PairGeometry pg = build_pair_geometry(cf);
  const ContactGeometry& G = pg.geo;
  const Material& steel = cf.material;
  MethodOptions mo = cf.method_options();
  const CaseResult r = solve_contact(G, steel, 1e-3, 50e3, mo);
  REQUIRE(r.status == CaseStatus::OutsideValidity);
  REQUIRE(r.area * 1e6 == Approx(56.77).margin(0.05));
  REQUIRE(r.pmax > 0);
  REQUIRE(r.message.find("non_hertzian") != std::string::npos);
  // At t_Y = −2 mm the tread contact is one Hertzian ellipse: ok.
  REQUIRE(solve_contact(G, steel, -2e-3, 50e3, mo).status == CaseStatus::Ok);
  // auto hands the case to the strip method, whose checks pass: ok, with auto's note.
  mo.method = Method::Auto;
  const CaseResult a = solve_contact(G, steel, 1e-3, 50e3, mo);
  REQUIRE(a.method == Method::Strips);
  REQUIRE(a.status == CaseStatus::Ok);
  REQUIRE(a.warnings.size() == 1);
  REQUIRE(warning_text(a.warnings[0]).rfind("auto:strips:", 0) == 0);
}

TEST_CASE("status: every warning class is documented in docs/status.md", "[status]") {
  std::ifstream f(std::string(MHCONTACT_SOURCE_DIR) + "/docs/status.md");
  REQUIRE(f);
  std::stringstream ss;
  ss << f.rdbuf();
  const std::string doc = ss.str();
  REQUIRE(doc.find("`outside_validity`") != std::string::npos);
  for (const WarningClassInfo& c : warning_classes()) {
    CAPTURE(c.name);
    REQUIRE(doc.find("`" + std::string(c.name) + "`") != std::string::npos);
    REQUIRE(is_validity_class(c.name) == c.outside_validity);
  }
}
