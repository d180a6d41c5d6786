// S1002 on 60E1 canted 1:20, both generated: at 1:20 the rail's gauge flank is vertical, kept as
// its gauge face (profiles.md §3), which the grid methods' normal gap sees (method.md §8).
// Reference: CONTACT's exact half-space solutions of the same placed profiles, the rail with its
// flank (tests/data/contact/field/contact_S1002_60E1_1-20.csv, README there: dx = ds = 0.2 mm,
// E = 210 GPa, nu = 0.28, frictionless), flange cases t_Y = 6, 7, 8, 10 mm x Q = 20, 60, 120 kN.
// Tolerances at about 1.5 times the worst error measured over the 12 cases (printed by the test;
// 28 Nov 2026; CONTACT's peak: the largest of its patches; area: their sum): strips peak pressure
// 2.5 % (measured 1.49 %), area 10 % (6.41 %); half-space 1.5 % (0.93 %), 4 % (2.36 %). Until
// then both at the field trust table's targets, 10 % and 15 % (docs/trust.md), which remain what
// `ok` promises on pairs without a test of their own. Every row must be `ok`: the patches stay
// 4-6 mm above the face's foot, so none reaches a profile's end.
// One row is not a flange contact: t_Y = 6 mm, 120 kN touches the tread, the middle of the head
// and the gauge corner (19 deg off the patch plane), the corner's interpenetration 7.4 mm from the
// rest. CONTACT's reference settings (D_SEP 8, D_COMB 4 mm) would make one patch with two
// sub-patches whose cross-influence is attenuated to ((D_SEP - d)/(D_SEP - D_COMB))^0.8 = 0.23
// (its "blending approach", m_wr_locatecp.f90 combine_cpatches, m_solvpn.f90 facsep), no exact
// solution of any elastic problem: the corner then carries 10.4 kN and the peak (1389 MPa) stands
// on it. The table's row of that case is therefore CONTACT's run without the attenuation
// (D_COMB 8 mm: one plane, full interaction, as d_comb 8 mm here): 1246 MPa, corner 6.5 kN. The
// other runs of the case (contact_S1002_60E1_1-20_tY6_Q120_variants.csv, decks in
// inputs/S1002_60E1_1-20/variants/, docs/trust.md): the conformal approach (curved reference
// surface, D = 4) 6.0 kN and 1248 MPa; the corner as its own patch (D_SEP = D_COMB = 4 mm, as
// d_comb 4 mm here) 11.3 kN and 1329 MPa. Against the runs of the same model (one plane, full
// interaction; the corner as its own patch) the tolerance is the discretisation's: 2 % in peak
// pressure and 3 % in area (measured: 0.2 % and 1.1 %), 3 % in each patch's normal force; against
// the conformal run the trust table's 10 % / 15 %. Now about 1.5 times the worst of both methods
// measured (28 Nov 2026), with a floor of 0.1 %: one plane 0.25 % / 1.7 % (measured 0.14 % /
// 1.09 %), its force 0.1 % (0.00 %); conformal 0.1 % / 3.1 % (0.02 % / 2.02 %); the corner as its
// own patch 0.5 % / 1.4 % (0.31 % / 0.89 %), forces 0.4 % (0.24 %, the corner) and 0.1 % (0.02 %).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "contact/judge/evidence.hpp"
#include "contact/judge/judge.hpp"
#include "contact/solve.hpp"
#include "geometry/gap.hpp"
#include "input/case_file.hpp"
#include "jobs/run.hpp"
#include "output/csv_table.hpp"

namespace {

const std::string kField = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/contact/field/";

// A pair as the trust table runs it (trust.json).
mh::CaseFile pair_case(const std::string& name = "S1002/60E1_1:20") {
  std::ifstream in(kField + "trust.json");
  const nlohmann::json spec = nlohmann::json::parse(in);
  for (const auto& p : spec.at("pairs"))
    if (p.at("name") == name) return mh::parse_case_json(p.at("case"), kField + "trust.json", false);
  FAIL("pair " << name << " not in trust.json");
  return {};
}

}  // namespace

TEST_CASE("flange contact on the vertical 1:20 flank: strips and half-space against CONTACT", "[flank][contact_reference]") {
  const mh::CsvTable ref = mh::read_csv_file(kField + "contact_S1002_60E1_1-20.csv");
  auto col = [&](std::size_t i, const char* c) { return std::stod(ref.rows[i][static_cast<std::size_t>(ref.column(c))]); };
  // CONTACT per case (t_Y mm, Q kN): peak pressure [MPa] (largest patch), area [mm²] (sum).
  std::map<std::pair<int, int>, std::pair<double, double>> contact;
  for (std::size_t i = 0; i < ref.rows.size(); ++i) {
    auto& c = contact[{static_cast<int>(std::lround(col(i, "y_ws_mm"))), static_cast<int>(std::lround(col(i, "Fz_target_N") / 1e3))}];
    c.first = std::max(c.first, col(i, "pmax_MPa"));
    c.second += col(i, "area_mm2");
  }
  REQUIRE(contact.size() == 12);
  const mh::CsvTable var = mh::read_csv_file(kField + "contact_S1002_60E1_1-20_tY6_Q120_variants.csv");
  auto vcol = [&](std::size_t i, const char* c) { return std::stod(var.rows[i][static_cast<std::size_t>(var.column(c))]); };
  const mh::CaseFile cf = pair_case();
  const mh::PairGeometry pg = mh::build_pair_geometry(cf);
  REQUIRE(pg.geo.has_rail_face());
  for (mh::Method m : {mh::Method::Strips, mh::Method::HalfSpace}) {
    for (const auto& [k, c] : contact) {
      const double tY = k.first * 1e-3, Q = k.second * 1e3;
      mh::MethodOptions opt = cf.method_options();
      opt.method = m;
      // CONTACT's grid (0.2 mm) for both: two solvers on one discretisation, no local refinement
      // (test_grid_resolution.cpp); a patch too narrow for it may then be only under_resolved.
      opt.half_space.max_refinements = opt.strips.max_refinements = 0;
      const mh::CaseResult r = mh::solve_contact(pg.geo, cf.material, tY, Q, opt);
      const double dp = r.pmax / 1e6 / c.first - 1, da = r.area / 1e-6 / c.second - 1;
      INFO(mh::to_string(m) << " t_Y = " << k.first << " mm, Q = " << k.second << " kN: " << mh::to_string(r.status)
                            << " " << r.message << "; pmax " << r.pmax / 1e6 << " MPa (CONTACT " << c.first << ", "
                            << 100 * dp << " %), area " << r.area / 1e-6 << " mm2 (CONTACT " << c.second << ", "
                            << 100 * da << " %)");
      const std::vector<mh::WarningClass> failed = mh::validity_failures(r.warnings);
      CHECK((r.status == mh::CaseStatus::Ok ||
             (r.status == mh::CaseStatus::OutsideValidity && failed.size() == 1 &&
              failed[0] == mh::WarningClass::UnderResolved)));
      for (const auto& w : r.warnings) CHECK(w.cls != mh::WarningClass::OffProfile);
      std::printf("flank %s t_Y %d Q %d: pmax %+.2f %% area %+.2f %%\n", mh::to_string(m), k.first, k.second, 100 * dp, 100 * da);
      // Measured worst (28 Nov 2026): strips pmax 1.49 %, area 6.41 %; half-space 0.93 %, 2.36 %.
      const bool strips = m == mh::Method::Strips;
      CHECK(std::fabs(da) <= (strips ? 0.10 : 0.04));
      CHECK(std::fabs(dp) <= (strips ? 0.025 : 0.015));
      if (k != std::make_pair(6, 120)) continue;
      // CONTACT's runs of this case without the blending attenuation (variant, patch): peak
      // pressure [MPa], area [mm²], normal force [N].
      auto variant = [&](const char* v, const char* patch) {
        for (std::size_t i = 0; i < var.rows.size(); ++i)
          if (var.rows[i][static_cast<std::size_t>(var.column("variant"))] == v &&
              var.rows[i][static_cast<std::size_t>(var.column("patch"))] == patch)
            return std::array<double, 3>{vcol(i, "pmax_MPa"), vcol(i, "area_mm2"), vcol(i, "Fn_patch_N")};
        FAIL("variant " << v << " patch " << patch << " not in the variants table");
        return std::array<double, 3>{};
      };
      auto compare = [&](const mh::CaseResult& res, const std::array<double, 3>& ref, double tol_p, double tol_a,
                         const char* what) {
        const double vp = res.pmax / 1e6 / ref[0] - 1, va = res.area / 1e-6 / ref[1] - 1;
        INFO(what << ": pmax " << res.pmax / 1e6 << " MPa (CONTACT " << ref[0] << ", " << 100 * vp << " %), area "
                  << res.area / 1e-6 << " mm2 (CONTACT " << ref[1] << ", " << 100 * va << " %)");
        std::printf("flank %s variant %s: pmax %+.2f %% area %+.2f %%\n", mh::to_string(m), what, 100 * vp, 100 * va);
        CHECK(std::fabs(vp) <= tol_p);
        CHECK(std::fabs(va) <= tol_a);
      };
      REQUIRE(r.patches.size() == 1);
      compare(r, variant("planar_full", "a"), 0.0025, 0.017, "one plane, full interaction (CONTACT D_COMB 8 mm)");
      std::printf("flank %s planar_full N %+.2f %%\n", mh::to_string(m), 100 * (r.patches[0].N / variant("planar_full", "a")[2] - 1));
      CHECK(std::fabs(r.patches[0].N / variant("planar_full", "a")[2] - 1) <= 0.001);
      compare(r, variant("conformal_full", "a"), 0.001, 0.031, "CONTACT conformal, full interaction");
      opt.half_space.d_comb = opt.strips.d_comb = 4e-3;
      const mh::CaseResult split = mh::solve_contact(pg.geo, cf.material, tY, Q, opt);
      INFO("d_comb 4 mm: " << mh::to_string(split.status) << ", " << split.patches.size() << " patches");
      CHECK(split.status == mh::CaseStatus::Ok);
      REQUIRE(split.patches.size() == 2);
      const auto main = variant("planar_separate", "a"), corner = variant("planar_separate", "b");
      compare(split, {std::max(main[0], corner[0]), main[1] + corner[1], 0}, 0.005, 0.014,
              "the corner as its own patch (CONTACT D_SEP = D_COMB = 4 mm)");
      std::printf("flank %s split N corner %+.2f %% main %+.2f %%\n", mh::to_string(m), 100 * (split.patches[0].N / corner[2] - 1), 100 * (split.patches[1].N / main[2] - 1));
      CHECK(std::fabs(split.patches[0].N / corner[2] - 1) <= 0.004);
      CHECK(std::fabs(split.patches[1].N / main[2] - 1) <= 0.001);
    }
  }
}

TEST_CASE("the normal gap meets a vertical gauge face on the face", "[flank]") {
  // Closed form: a normal line (direction (-sin g, cos g), sin g > 0) through the plane point
  // (qy, qz) crosses y = y_f at height qz + (qy - y_f)/tan g; below the face's top it meets the
  // rail there, at y_f exactly (the extrapolation of z(y) beyond its first point would give a y
  // up to 0.04 mm beyond it). Above the top it meets z(y), at y > y_f.
  const mh::CaseFile cf = pair_case();
  const mh::PairGeometry pg = mh::build_pair_geometry(cf);
  const mh::WheelRailGap gap(pg.geo, 7e-3);
  REQUIRE(gap.has_rail_face());
  const double yf = gap.rail_face_y(), ztop = gap.z_rail(yf);
  const mh::PatchPlane P = mh::plane_at(gap, -34.4e-3);  // CONTACT's contact point, gamma ~ 69.5 deg
  REQUIRE(std::sin(P.gamma) > 0.9);
  int below = 0, above = 0;
  for (double s = -8e-3; s <= 0; s += 0.25e-3) {
    const double qy = P.y_ref + s * std::cos(P.gamma), qz = P.z_ref + s * std::sin(P.gamma);
    const double z_cross = qz + (qy - yf) / std::tan(P.gamma);
    double y_rail = 0;
    mh::normal_gap(gap, P, 0, s, 0, &y_rail);
    CAPTURE(s, z_cross, ztop);
    if (z_cross < ztop - 1e-9) {
      ++below;
      CHECK(std::fabs(y_rail - yf) <= 1e-12);
    } else if (z_cross > ztop + 1e-9) {
      ++above;
      CHECK(y_rail > yf);
    }
  }
  CHECK(below >= 5);
  CHECK(above >= 5);
  // The end of the rail for a grid patch (off_profile:patch=K): at z(y)'s first point by y alone,
  // but on the face only at its foot (within a strip width).
  CHECK(pg.geo.off_profile(7e-3, yf));
  CHECK(!pg.geo.off_profile_at(7e-3, yf, ztop - 2e-3));
  CHECK(pg.geo.off_profile_at(7e-3, yf, gap.rail_face_foot() + 0.5 * pg.geo.strip_width));
}

// Flange onset on the same pair (t_Y 6.05-6.45 mm), where the gauge corner's and the tread's
// interpenetrations lie about 8 mm apart: whether they are one patch or several decides the
// answer. CONTACT's runs with D_COMB 8 mm (one plane per combined patch, no blending), planar and
// conformal (contact_S1002_60E1_1-20_flange_onset.csv, README there), combine the regions as they
// are at the solution's approach. Before the regions were combined at that approach (they were
// combined at the grid's 1.25 times), t_Y = 6.45 mm at 100 and 140 kN never settled (the regions
// merged into one plane that could not carry the load, split, merged again: docs/strips.md).
// Against the planar runs (the same model), on CONTACT's grid: the patch count (patches carrying
// more than 0.5 % of Q), each patch's normal force, the peak and the area (measured on six
// cases, both methods; five kept, the half-space on the two that never settled: the suite's
// time). Tolerances about 1.5 times the worst measured (30 Nov 2026, printed): peak 1.1 %
// (strips 0.75 % at 6.05 mm, 60 kN; half-space 0.35 %), area 2.8 % (1.87 %, 1.52 %), patch force
// 0.2 % of Q (0.12 %). Against the conformal runs
// (curved reference surface: the planar approach's own error, up to 6.8 % in peak pressure at
// 6.45 mm where the flange patch spans 39 deg of rail slope) the trust table's 10 % / 15 % and
// the patch count (its normal forces are along the curved normals, not comparable).
TEST_CASE("flange onset: the patches CONTACT makes, at the solution's approach", "[flank][contact_reference]") {
  const mh::CsvTable ref = mh::read_csv_file(kField + "contact_S1002_60E1_1-20_flange_onset.csv");
  auto txt = [&](std::size_t i, const char* c) { return ref.rows[i][static_cast<std::size_t>(ref.column(c))]; };
  const mh::CaseFile cf = pair_case();
  const mh::PairGeometry pg = mh::build_pair_geometry(cf);
  // (t_Y mm, Q kN, both methods): two patches that were one; three patches; one plane over 56 mm;
  // the two that never settled.
  const std::array<std::tuple<double, double, bool>, 5> cases = {
      {{6.05, 60, false}, {6.1875, 50, false}, {6.4, 140, false}, {6.45, 100, true}, {6.45, 140, true}}};
  for (mh::Method m : {mh::Method::Strips, mh::Method::HalfSpace}) {
    for (const auto& [tY_mm, Q_kN, both] : cases) {
      if (m == mh::Method::HalfSpace && !both) continue;  // the suite's time: the half-space on two
      mh::MethodOptions opt = cf.method_options();
      opt.method = m;
      opt.half_space.max_refinements = opt.strips.max_refinements = 0;
      const double Q = Q_kN * 1e3;
      const mh::CaseResult r = mh::solve_contact(pg.geo, cf.material, tY_mm * 1e-3, Q, opt);
      INFO(mh::to_string(m) << " t_Y = " << tY_mm << " mm, Q = " << Q_kN << " kN: " << mh::to_string(r.status) << " "
                            << r.message);
      REQUIRE(r.status == mh::CaseStatus::Ok);
      std::vector<double> N;
      for (const auto& P : r.patches)
        if (P.N > 0.005 * Q) N.push_back(P.N);
      std::sort(N.begin(), N.end());
      for (const char* variant : {"planar_full", "conformal_full"}) {
        double pmax = 0, area = 0;
        std::vector<double> Nref;
        for (std::size_t i = 0; i < ref.rows.size(); ++i)
          if (txt(i, "variant") == variant && std::stod(txt(i, "y_ws_mm")) == tY_mm &&
              std::stod(txt(i, "Fz_target_N")) == Q) {
            REQUIRE(txt(i, "note").empty());
            pmax = std::max(pmax, std::stod(txt(i, "pmax_MPa")));
            area += std::stod(txt(i, "area_mm2"));
            Nref.push_back(std::stod(txt(i, "Fn_patch_N")));
          }
        REQUIRE(!Nref.empty());
        std::sort(Nref.begin(), Nref.end());
        const double dp = r.pmax / 1e6 / pmax - 1, da = r.area / 1e-6 / area - 1;
        INFO(variant << ": " << N.size() << " patches (CONTACT " << Nref.size() << "), pmax " << r.pmax / 1e6
                     << " MPa (CONTACT " << pmax << "), area " << r.area / 1e-6 << " mm2 (CONTACT " << area << ")");
        const bool planar = std::string(variant) == "planar_full";
        double dN = 0;
        if (N.size() == Nref.size())
          for (std::size_t k = 0; k < N.size(); ++k) dN = std::max(dN, std::fabs(N[k] - Nref[k]) / Q);
        std::printf("onset %s t_Y %g Q %g %s: patches %zu/%zu pmax %+.2f %% area %+.2f %% N %.2f %% of Q\n",
                    mh::to_string(m), tY_mm, Q_kN, variant, N.size(), Nref.size(), 100 * dp, 100 * da, 100 * dN);
        CHECK(N.size() == Nref.size());
        if (planar) CHECK(dN <= 0.002);  // CONTACT's conformal force is along its curved normals
        CHECK(std::fabs(dp) <= (planar ? 0.011 : 0.10));
        CHECK(std::fabs(da) <= (planar ? 0.028 : 0.15));
      }
    }
  }
}

// The planar approach's evidence row (contact/judge/evidence.cpp, docs/trust.md "Evidence
// domains"): at the flange root the grid methods' one plane per patch is tilted against the rail
// where the pressure peaks, and CONTACT's conformal runs (a curved reference surface, the
// reference here) put the peak lower than the planar answer, by more the larger the tilt. Every
// case of CONTACT's conformal runs in the two files (flange onset and root, two gauge-corner
// cases) that the strips answer without the tilt warning must be within the trust table's 10 % of
// CONTACT's conformal peak (largest patch); one with it must not be `ok`. Raising the bound past
// the cases 10-16 % high makes this fail.
TEST_CASE("planar approach: every flange-root case within the tilt bound is within 10 % of CONTACT's conformal peak",
          "[flank][evidence][contact_reference]") {
  const double bound = mh::planar_evidence_domain().bound;
  const double edge_bound = mh::planar_evidence_domain(mh::Quantity::EdgeTilt).bound;
  int within = 0, beyond = 0;
  double edge_within = 0;  // [deg] the largest edge tilt of a case left ok
  const std::array<std::pair<const char*, const char*>, 2> files = {
      {{"contact_S1002_60E1_1-20_flange_onset.csv", "S1002/60E1_1:20"},
       {"contact_S1002_60E1_1-40_flange_root.csv", "S1002/60E1_1:40"}}};
  for (const auto& [file, pair] : files) {
    const mh::CsvTable ref = mh::read_csv_file(kField + file);
    auto txt = [&](std::size_t i, const char* c) { return ref.rows[i][static_cast<std::size_t>(ref.column(c))]; };
    std::map<std::pair<double, double>, double> conformal;  // (t_Y mm, Q N) -> peak [MPa]
    for (std::size_t i = 0; i < ref.rows.size(); ++i)
      if (txt(i, "variant") == "conformal_full" && !txt(i, "pmax_MPa").empty()) {
        double& p = conformal[{std::stod(txt(i, "y_ws_mm")), std::stod(txt(i, "Fz_target_N"))}];
        p = std::max(p, std::stod(txt(i, "pmax_MPa")));
      }
    const mh::CaseFile cf = pair_case(pair);
    const mh::PairGeometry pg = mh::build_pair_geometry(cf);
    mh::MethodOptions opt = cf.method_options();
    opt.method = mh::Method::Strips;
    for (const auto& [key, p_ref] : conformal) {
      const auto [tY_mm, Q] = key;
      const mh::CaseResult r = mh::solve_contact(pg.geo, cf.material, tY_mm * 1e-3, Q, opt);
      double tilt = 0;  // [deg] the largest over the patches the judge flags (at the peak or an edge)
      for (const mh::Warning& w : r.warnings)
        for (int k = 0; k < w.n; ++k)
          if (w.m[static_cast<std::size_t>(k)].q == mh::Quantity::PlaneTilt || w.m[static_cast<std::size_t>(k)].q == mh::Quantity::EdgeTilt)
            tilt = std::max(tilt, std::fabs(w.m[static_cast<std::size_t>(k)].value) * 180 / M_PI);
      double edge = 0;  // [deg] the largest edge tilt of the case's patches
      for (const mh::PatchResult& P : r.patches) edge = std::max(edge, mh::planar_tilt(P, pg.geo).edge * 180 / M_PI);
      const double dp = r.pmax / 1e6 / p_ref - 1;
      std::printf("planar evidence %s t_Y %g Q %g: %s, tilt beyond %g / %g deg: %.3f, edge tilt %.3f deg, pmax %+.2f %% of conformal\n",
                  pair, tY_mm, Q / 1e3, mh::to_string(r.status), bound, edge_bound, tilt, edge, 100 * dp);
      INFO(pair << " t_Y = " << tY_mm << " mm, Q = " << Q / 1e3 << " kN: " << mh::to_string(r.status) << " "
                << r.message << "; pmax " << r.pmax / 1e6 << " MPa, CONTACT conformal " << p_ref << " MPa");
      if (r.status == mh::CaseStatus::NotConverged) continue;  // no answer: nothing claimed
      if (tilt > 0) {
        CHECK(r.status != mh::CaseStatus::Ok);
        ++beyond;
      } else {
        CHECK(std::fabs(dp) <= 0.10);
        ++within;
        edge_within = std::max(edge_within, edge);
      }
    }
  }
  // The edge bound is what these cases test: the cases left ok reach it (within 0.5°), none
  // beyond (34.7°, 1:20 at 6.45 mm, 140 kN; 2 Dec 2026). Raised without new cases, this fails.
  INFO("largest edge tilt of a case left ok: " << edge_within << " deg, bound " << edge_bound);
  CHECK(edge_within <= edge_bound);
  CHECK(edge_within >= edge_bound - 0.5);
  // Both sides hold cases (30 Nov 2026: 11 beyond, among them the 1:20 pair's 6.5 and 6.55 mm at
  // 100 kN and the 1:40 pair's 6.6 mm at 120 kN, 11-16 % high; 13 within).
  CHECK(beyond >= 3);
  CHECK(within >= 12);
}

TEST_CASE("planar approach: the tilt is the angle between the rail and the plane, at most 90 degrees",
          "[flank][evidence]") {
  // The worn 1:40 rail's gauge face at t_Y 6.8 mm, 60 kN (strips): the rail's slope angle at the
  // peak lies near −90° and the plane's γ near +70°; their difference, 159.6°, was written as the
  // tilt before it was folded into [0, 90°] (the lines meet at 20.4°).
  const mh::CaseFile cf = pair_case("S1002/worn_rail_1-40");
  const mh::PairGeometry pg = mh::build_pair_geometry(cf);
  mh::MethodOptions opt = cf.method_options();
  opt.method = mh::Method::Strips;
  const mh::CaseResult r = mh::solve_contact(pg.geo, cf.material, 6.8e-3, 60e3, opt);
  double peak = 0, edge = 0;  // [deg] the largest over the patches (the flange's; the tread's is small)
  for (const mh::PatchResult& P : r.patches) {
    const mh::PlanarTilt t = mh::planar_tilt(P, pg.geo);
    peak = std::max(peak, t.peak * 180 / M_PI);
    edge = std::max(edge, t.edge * 180 / M_PI);
  }
  CHECK(peak == Approx(20.4).margin(0.5));
  CHECK(edge <= 90);
  CHECK(r.status == mh::CaseStatus::OutsideValidity);  // beyond the 15° bound either way
}

// Near flange onset the flange root's interpenetration and the tread's own minimum of the gap lie
// in one interval of the grid's wider interpenetration (margin × the approach), or in two closer
// than d_comb, but 8 mm and more apart at the solution's approach, at contact angles 40° apart: one patch with one plane spanned
// both (87 mm at 44° at 6.5 mm, 140 kN), its planar gap gave no positive approach, and the
// placements alternated with the flange alone, never settling (15 of the 36 strips cases of the band
// below did not converge). find_patch_regions keeps such a minimum apart (geometry/contact_patches.hpp).
// Every case of the band settles but one (6.45 mm, 160 kN: there the two regions join at the
// solution's approach itself, over a saddle 6 % below it, one interpenetration from 36° to 0° that
// no plane carries; docs/strips.md); where CONTACT ran the same model (planar, D_COMB 8 mm: one
// patch on the flange, the tread unloaded; 6.4 … 6.65 mm) the strips' peak and flange force agree
// within about 1.5 times the worst measured (1 Dec 2026: 1.43 % in peak, 0.91 % of Q in force,
// both at 6.65 mm, 59-61°, where a tenth of a degree of plane is 0.3 % of the normal force).
TEST_CASE("flange onset: the tread's own minimum apart from the flange root, the placements settle", "[flank][contact_reference]") {
  const mh::CsvTable ref = mh::read_csv_file(kField + "contact_S1002_60E1_1-20_flange_onset.csv");
  auto txt = [&](std::size_t i, const char* c) { return ref.rows[i][static_cast<std::size_t>(ref.column(c))]; };
  const mh::CaseFile cf = pair_case();
  const mh::PairGeometry pg = mh::build_pair_geometry(cf);
  mh::MethodOptions opt = cf.method_options();
  opt.method = mh::Method::Strips;
  int compared = 0;
  for (int i = 0; i <= 8; ++i) {
    const double tY_mm = 6.3 + 0.05 * i;
    for (double Q_kN : {100.0, 120.0, 140.0, 160.0}) {
      const double Q = Q_kN * 1e3;
      const mh::CaseResult r = mh::solve_contact(pg.geo, cf.material, tY_mm * 1e-3, Q, opt);
      INFO("t_Y = " << tY_mm << " mm, Q = " << Q_kN << " kN: " << mh::to_string(r.status) << " " << r.message);
      std::printf("onset band t_Y %.2f Q %g: %s, %zu patches, pmax %.1f MPa\n", tY_mm, Q_kN, mh::to_string(r.status),
                  r.patches.size(), r.pmax / 1e6);
      if (tY_mm > 6.449 && tY_mm < 6.451 && Q_kN == 160.0) continue;  // the joined regions (above)
      CHECK(r.status != mh::CaseStatus::NotConverged);
      if (r.status == mh::CaseStatus::NotConverged) continue;
      double pmax = 0, N = 0;
      int rows = 0;
      for (std::size_t k = 0; k < ref.rows.size(); ++k)
        if (txt(k, "variant") == "planar_full" && std::fabs(std::stod(txt(k, "y_ws_mm")) - tY_mm) < 1e-9 &&
            std::stod(txt(k, "Fz_target_N")) == Q && !txt(k, "pmax_MPa").empty()) {
          pmax = std::max(pmax, std::stod(txt(k, "pmax_MPa")));
          N = std::max(N, std::stod(txt(k, "Fn_patch_N")));
          ++rows;
        }
      if (rows != 1) continue;  // CONTACT's one-patch cases (the flange alone)
      double N_max = 0;
      for (const auto& P : r.patches) N_max = std::max(N_max, P.N);
      const double dp = r.pmax / 1e6 / pmax - 1, dN = (N_max - N) / Q;
      std::printf("  against CONTACT planar: pmax %+.2f %%, flange force %+.2f %% of Q\n", 100 * dp, 100 * dN);
      CHECK(std::fabs(dp) <= 0.022);
      CHECK(std::fabs(dN) <= 0.014);
      ++compared;
    }
  }
  CHECK(compared >= 6);
  // A steeper minimum beside a flatter patch stays with it: the gauge corner's scarcely touching
  // minimum beside the tread's patch at 2.5° (kept apart too, it became a patch 2 elements across
  // and these rows `under_resolved`).
  for (const auto& [tY_mm, Q_kN] : std::array<std::pair<double, double>, 3>{{{5.72, 180}, {5.8, 140}, {5.86, 100}}}) {
    const mh::CaseResult r = mh::solve_contact(pg.geo, cf.material, tY_mm * 1e-3, Q_kN * 1e3, opt);
    INFO("t_Y = " << tY_mm << " mm, Q = " << Q_kN << " kN: " << mh::to_string(r.status) << " " << r.message);
    CHECK(r.status == mh::CaseStatus::Ok);
    CHECK(r.patches.size() == 1);
  }
}
