// Multi-Hertzian solver (solver.hpp) on real profile pairs and on hand-made geometries.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "geometry/contact_geometry.hpp"
#include "input/case_file.hpp"
#include "jobs/run.hpp"
#include "profile/read.hpp"
#include "manchester_fixture.hpp"
#include "contact/multi_hertz/approach_given.hpp"
#include "contact/multi_hertz/multi_hertz.hpp"
#include "support/hertz_reference.hpp"

using namespace mh;

namespace {
constexpr double kPi = 3.14159265358979323846;

double rel(double x, double ref) { return std::fabs(x / ref - 1.0); }

Profile read(const std::string& name, ProfileKind kind, bool check = true) {
  return testing::read_test_profile(name, kind, check);
}
const ContactGeometry& manchester() { return testing::manchester_geometry(); }
using testing::steel;
}  // namespace

TEST_CASE("circular profiles: one ellipse equal to closed-form Hertz", "[solver]") {
  // Source: closed-form Hertz (tests/support/hertz_reference.hpp, Johnson §4.2) for R_wxx = 50 mm,
  // R_rxx = 100 mm (the circ_* files, exact to 5e−7 mm) and R_wyy = r/cos γ; N = Q / cos γ.
  // Tolerance 1e-4 relative on a, b, p0, h0 and the approach: measured at most 1.7e-5, from the
  // curvatures the geometry fits to the profile points.
  const ContactGeometry G = build_geometry(read("circ_r50.prw", ProfileKind::Wheel, false),
                                           read("circ_r100.prr", ProfileKind::Rail, false),
                                           TrackSetup{}, GeometryOptions{});
  const Material mat = steel();
  const double EJ = testing::johnson_modulus(mat.E, mat.nu, mat.E, mat.nu);
  for (double tY : {-8e-3, 0.0, 7.3e-3}) {
    for (double Q : {10e3, 100e3}) {
      const CaseResult r = solve_multi_hertz(G, mat, tY, Q);
      REQUIRE(r.status == CaseStatus::Ok);
      REQUIRE(r.loaded.size() == 1);
      const LoadedEllipse& e = r.loaded[0];
      const double cg = std::cos(e.g.gamma);
      const double A = cg / (2 * e.g.r_roll), B = 0.5 * (1 / 0.050 + 1 / 0.100);  // R_wyy = r/cos γ
      const double N = Q / cg;
      const testing::HertzReference h = testing::hertz_reference(A, B, N, EJ);
      CAPTURE(tY, Q);
      REQUIRE(e.s.N == Approx(N).epsilon(1e-9));
      CHECK(rel(e.s.a, h.a) <= 1e-4);
      CHECK(rel(e.s.b, h.b) <= 1e-4);
      CHECK(rel(e.s.p0, h.p0) <= 1e-4);
      CHECK(rel(e.s.h0, h.b * h.b * B) <= 1e-4);  // eq. 6
      CHECK(rel(e.s.approach, h.delta) <= 1e-4);
    }
  }
}

TEST_CASE("Manchester pair, t_Y −6 … 10 mm, Q 10/50/100 kN: all ok, equilibrium, contacts", "[solver]") {
  // All cases ok; one contact on most of the tread; two loaded ellipses next to the
  // CAF jumps (near t_Y = 0 and 5 mm); vertical equilibrium to 1e−9 relative.
  const ContactGeometry& G = manchester();
  const Material mat = steel();
  int two_near_0 = 0, two_near_5 = 0, single = 0, total = 0;
  for (int i = 0; i <= 32; ++i) {
    const double tY = (-6.0 + 0.5 * i) * 1e-3;
    for (double Q : {10e3, 50e3, 100e3}) {
      const CaseResult r = solve_multi_hertz(G, mat, tY, Q);
      CAPTURE(tY, Q, r.message);
      REQUIRE(r.status == CaseStatus::Ok);
      REQUIRE(std::fabs(r.Fz - Q) <= 1e-9 * Q);
      REQUIRE(std::fabs(r.residual) <= 1e-9);
      ++total;
      if (r.loaded.size() == 1) ++single;
      if (r.loaded.size() == 2 && std::fabs(tY) <= 1.5e-3) ++two_near_0;
      if (r.loaded.size() == 2 && std::fabs(tY - 5e-3) <= 0.5e-3) ++two_near_5;
      if (tY <= -1.5e-3) REQUIRE(r.loaded.size() == 1);  // tread only
      if (tY >= 7e-3) {                                  // flange: ellipse 4
        REQUIRE(r.loaded.size() == 1);
        REQUIRE(r.loaded[0].ellipse == 4);
        REQUIRE(r.loaded[0].g.gamma > 50 * kPi / 180);
      }
    }
  }
  REQUIRE(two_near_0 >= 3);
  REQUIRE(two_near_5 >= 1);
  REQUIRE(single > total / 2);
}

TEST_CASE("a second ellipse comes into contact continuously as Q grows", "[solver]") {
  // At t_Y = −0.5 mm the tread ellipse carries light loads alone; the R80 ellipse joins as Q
  // grows. N_i must be continuous in Q: no jump larger than what 0.1 kN more load can carry.
  const ContactGeometry& G = manchester();
  const Material mat = steel();
  double prevN1 = 0, prevN2 = 0;
  bool joined = false, alone_first = false;
  for (int i = 1; i <= 2000; ++i) {
    const double Q = 100.0 * i;  // 0.1 … 200 kN
    const CaseResult r = solve_multi_hertz(G, mat, -0.5e-3, Q);
    REQUIRE(r.status == CaseStatus::Ok);
    double N1 = 0, N2 = 0;
    for (const auto& e : r.loaded) (e.ellipse == 1 ? N1 : N2) = e.s.N;
    if (i == 1) alone_first = (N2 == 0);
    if (N2 > 0) joined = true;
    if (i > 1) {
      REQUIRE(std::fabs(N1 - prevN1) <= 2 * 100.0);
      REQUIRE(std::fabs(N2 - prevN2) <= 2 * 100.0);
    }
    prevN1 = N1;
    prevN2 = N2;
  }
  REQUIRE(alone_first);
  REQUIRE(joined);
}

TEST_CASE("edges: 1 N to 1 MN, ellipse boundaries, outside the table, bad Q", "[solver]") {
  const ContactGeometry& G = manchester();
  const Material mat = steel();
  for (double Q : {1.0, 1e3, 1e6}) {
    for (double tY : {-6e-3, 0.0, 5e-3, 9e-3}) {
      const CaseResult r = solve_multi_hertz(G, mat, tY, Q);
      CAPTURE(Q, tY);
      REQUIRE(r.status == CaseStatus::Ok);
      REQUIRE(r.Fz == Approx(Q).epsilon(1e-9));
    }
  }
  for (const PotentialEllipse& P : G.ellipses) {
    const CaseResult r = solve_multi_hertz(G, mat, P.tY_min, 50e3);
    REQUIRE(r.status == CaseStatus::Ok);
    REQUIRE(r.Fz == Approx(50e3).epsilon(1e-9));
  }
  const CaseResult out = solve_multi_hertz(G, mat, 20e-3, 50e3);
  REQUIRE(out.status == CaseStatus::OutOfRange);
  REQUIRE_THAT(out.message, Catch::Contains("outside the geometry table"));
  REQUIRE(solve_multi_hertz(G, mat, 0.0, 0.0).status == CaseStatus::NoContact);
  REQUIRE(solve_multi_hertz(G, mat, 0.0, NAN).status == CaseStatus::NoContact);
}

namespace {
// A hand-made geometry: two potential ellipses on a 2-point grid.
ContactGeometry two_candidates(double k_wxx_second, double gap_second) {
  ContactGeometry G;
  G.tY = {0.0, 1e-3};
  G.main_ellipse = {0, 0};
  G.ellipses.resize(2);
  for (int e = 0; e < 2; ++e) G.ellipses[static_cast<std::size_t>(e)].index = e + 1;
  CandidateGeom main;
  main.gamma = 0.02; main.k_rxx = 1 / 0.3; main.k_wxx = 0; main.r_roll = 0.46;
  CandidateGeom second;
  second.gamma = 0.5; second.k_rxx = 1 / 0.013; second.k_wxx = k_wxx_second; second.r_roll = 0.47;
  second.gap = second.sep = gap_second;  // separation above the main candidate's (sep 0)
  G.table = {main, second, main, second};
  return G;
}
}  // namespace

TEST_CASE("non-Hertzian candidates (B <= 0) are excluded and flagged when they would touch", "[solver]") {
  const Material mat = steel();
  // Second candidate conformal: wheel concave R 12 mm on the rail's R 13 corner: B < 0.
  const ContactGeometry near = two_candidates(-1 / 0.012, 1e-6);
  const CaseResult r = solve_multi_hertz(near, mat, 0.5e-3, 100e3);
  REQUIRE(r.status == CaseStatus::Ok);
  REQUIRE(r.loaded.size() == 1);
  REQUIRE(r.loaded[0].ellipse == 1);
  REQUIRE(r.warnings.size() == 1);
  REQUIRE(mh::warning_text(r.warnings[0]) == "non_hertzian_excluded:ellipse=2");
  REQUIRE(r.Fz == Approx(100e3).epsilon(1e-12));
  // Far away (1 mm gap) it would not touch: no warning.
  const CaseResult far = solve_multi_hertz(two_candidates(-1 / 0.012, 1e-3), mat, 0.5e-3, 100e3);
  REQUIRE(far.warnings.empty());
  // Regression: a nearly conformal candidate (B > 0 but λ = A/B beyond the Hertz range) threw
  // from make_ellipse_law inside a worker thread and aborted the whole run. Now it is excluded
  // like B <= 0, and flagged.
  const CaseResult tiny = solve_multi_hertz(two_candidates(-1 / 0.013 + 1e-11, 1e-6), mat, 0.5e-3, 100e3);
  REQUIRE(tiny.status == CaseStatus::Ok);
  REQUIRE(mh::warning_texts(tiny.warnings) == std::vector<std::string>{"non_hertzian_excluded:ellipse=2"});
  // Hertzian second candidate (convex wheel): loaded, equilibrium with two ellipses.
  const CaseResult both = solve_multi_hertz(two_candidates(1 / 0.020, 1e-6), mat, 0.5e-3, 100e3);
  REQUIRE(both.loaded.size() == 2);
  REQUIRE(both.Fz == Approx(100e3).epsilon(1e-12));
}

TEST_CASE("a conformal contact (every candidate B <= 0) is not no_contact: the method has no answer", "[solver]") {
  // A vehicle-dynamics code applies zero force on no_contact; here the wheel touches the rail,
  // conformally, and the multi-Hertzian method cannot solve it: not_converged, with the message.
  const Material mat = steel();
  ContactGeometry G = two_candidates(-1 / 0.012, 1e-6);
  for (std::size_t k = 0; k < G.table.size(); k += 2) G.table[k].k_wxx = -1 / 0.29;  // main: concave wheel R 290 mm on R 300
  const CaseResult r = solve_multi_hertz(G, mat, 0.5e-3, 100e3);
  CHECK(r.status == CaseStatus::NotConverged);
  CHECK_THAT(r.message, Catch::Contains("a conformal contact"));
  CHECK_THAT(r.message, Catch::Contains("no force computed"));
  CHECK(r.loaded.empty());
  // The approach prescribed: pressed in, every candidate conformal: the same.
  ApproachWorkspace ws;
  CaseResult a;
  solve_multi_hertz_approach(G, mat, 0.5e-3, 10e-6, MultiHertzOptions{}, ws, a);
  CHECK(a.status == CaseStatus::NotConverged);
  CHECK_THAT(a.message, Catch::Contains("a conformal contact"));
  // Not pressed in: the wheel above the rail, no_contact.
  solve_multi_hertz_approach(G, mat, 0.5e-3, -10e-6, MultiHertzOptions{}, ws, a);
  CHECK(a.status == CaseStatus::NoContact);
}

TEST_CASE("load sharing next to a jump does not depend on the t_Y grid", "[solver]") {
  // Manchester pair, Q = 100 kN, t_Y around the jumps at 0.21279, 5.02274 and 6.61399 mm. Before
  // the fix the gaps were interpolated linearly across the jump's grid interval and the lateral
  // force at t_Y = 6.6 mm was 130 / 140 / 83 / 84 / 75 kN for steps 0.005 / 0.01 / 0.05 / 0.1 /
  // 0.5 mm. Reference: the finest grid. Measured after the fix: the forces agree to 0.01 kN.
  const Profile W = read("MBench_S1002_v3.prw", ProfileKind::Wheel);
  const Profile R = read("MBench_UIC60_v3.prr", ProfileKind::Rail);
  const Material mat = steel();
  const std::vector<double> tY_mm = {0.2, 0.21, 0.22, 0.3, 5.0, 5.02, 5.03, 5.1, 6.5, 6.6, 6.61, 6.62, 6.63, 6.7, 7.0};
  auto forces = [&](double step_mm) {
    GeometryOptions o;
    o.tY_step = step_mm * 1e-3;
    const ContactGeometry G = build_geometry(W, R, TrackSetup{}, o);
    std::vector<CaseResult> out;
    for (double t : tY_mm) out.push_back(solve_multi_hertz(G, mat, t * 1e-3, 100e3));
    return out;
  };
  const std::vector<CaseResult> ref = forces(0.005);
  for (double step : {0.01, 0.05, 0.1, 0.5}) {
    const std::vector<CaseResult> r = forces(step);
    for (std::size_t i = 0; i < tY_mm.size(); ++i) {
      INFO("step " << step << " mm, t_Y " << tY_mm[i] << " mm");
      REQUIRE(r[i].status == CaseStatus::Ok);
      REQUIRE(r[i].n_contacts == ref[i].n_contacts);
      REQUIRE(r[i].Fy == Approx(ref[i].Fy).margin(0.1e3));   // 0.1 kN
      REQUIRE(r[i].Fz == Approx(ref[i].Fz).margin(0.1e3));
    }
  }
}

TEST_CASE("candidate_ellipses: the load-independent part of every loaded ellipse, bit for bit", "[solver]") {
  // geometry.csv is written from candidate_ellipses() and joined to ellipses.csv on (t_Y,
  // ellipse): each loaded ellipse's strip, A, B, λ, m, n and profile heights must be exactly the
  // candidate's, at every load (same code path, not a tolerance).
  const ContactGeometry& G = manchester();
  const Material mat = steel();
  std::vector<CandidateEllipse> cands;
  int loaded = 0;
  for (double tY : {-6e-3, -0.25e-3, 0.5e-3, 5e-3, 7.5e-3}) {
    candidate_ellipses(G, mat, tY, MultiHertzOptions{}, cands);
    REQUIRE(cands.size() == G.n_ellipses());
    for (std::size_t e = 0; e < cands.size(); ++e) REQUIRE(cands[e].ellipse == static_cast<int>(e) + 1);
    for (double Q : {10e3, 100e3, 300e3}) {
      const CaseResult r = solve_multi_hertz(G, mat, tY, Q);
      REQUIRE(r.status == CaseStatus::Ok);
      for (const LoadedEllipse& L : r.loaded) {
        CAPTURE(tY, Q, L.ellipse);
        const CandidateEllipse& c = cands[static_cast<std::size_t>(L.ellipse - 1)];
        REQUIRE(c.hertzian);
        CHECK(c.g.y_r == L.g.y_r);
        CHECK(c.g.y_w == L.g.y_w);
        CHECK(c.g.gamma == L.g.gamma);
        CHECK(c.g.k_rxx == L.g.k_rxx);
        CHECK(c.g.k_wxx == L.g.k_wxx);
        CHECK(c.g.R_wyy() == L.g.R_wyy());
        CHECK(c.g.gap == L.g.gap);
        CHECK(c.A == L.A);
        CHECK(c.B == L.B);
        CHECK(c.c.lambda == L.c.lambda);
        CHECK(c.c.m == L.c.m);
        CHECK(c.c.n == L.c.n);
        CHECK(c.z_r == L.z_r);
        CHECK(c.z_w == L.z_w);
        ++loaded;
      }
    }
  }
  REQUIRE(loaded >= 15);  // at least one ellipse per case, two near the jumps
}

TEST_CASE("roller rig: the roller's radius enters A as cos γ / (2 (R_roller + z_r)), and a, b, p0 follow Hertz",
          "[solver][roller]") {
  // Source: README "Positioning without a gauge point" (A = 1/(2 R_wyy) + 1/(2 R_ryy), R_ryy =
  // (R_roller + z_r)/cos γ, Meusnier) and closed-form Hertz (tests/support/hertz_reference.hpp).
  // The circular pair of "circular profiles" above on a roller of R_roller = 700 mm: A grows from
  // 1.07–1.08 to 1.78–1.80 1/m, a shrinks by 20 %, b grows by 11 %, p0 by 12 %. Tolerance 1e-4
  // relative on a, b, p0 and the approach (measured at most 1.7e-5, the fitted curvatures, as
  // without the roller).
  const double R_roller = 0.700;
  TrackSetup roller;
  roller.roller_radius = R_roller;
  const Profile W = read("circ_r50.prw", ProfileKind::Wheel, false), R = read("circ_r100.prr", ProfileKind::Rail, false);
  const ContactGeometry G = build_geometry(W, R, roller, GeometryOptions{});
  const ContactGeometry G_straight = build_geometry(W, R, TrackSetup{}, GeometryOptions{});
  const Material mat = steel();
  const double EJ = testing::johnson_modulus(mat.E, mat.nu, mat.E, mat.nu);
  for (double tY : {-8e-3, 0.0, 7.3e-3}) {
    for (double Q : {10e3, 100e3}) {
      CAPTURE(tY, Q);
      const CaseResult r = solve_multi_hertz(G, mat, tY, Q), s = solve_multi_hertz(G_straight, mat, tY, Q);
      REQUIRE(r.status == CaseStatus::Ok);
      REQUIRE(r.loaded.size() == 1);
      REQUIRE(s.loaded.size() == 1);
      const LoadedEllipse& e = r.loaded[0];
      const double cg = std::cos(e.g.gamma), B = 0.5 * (1 / 0.050 + 1 / 0.100);
      const double A = cg / (2 * e.g.r_roll) + cg / (2 * (R_roller + e.z_r));  // wheel + roller
      const testing::HertzReference h = testing::hertz_reference(A, B, Q / cg, EJ);
      CHECK(rel(e.s.a, h.a) <= 1e-4);
      CHECK(rel(e.s.b, h.b) <= 1e-4);
      CHECK(rel(e.s.p0, h.p0) <= 1e-4);
      CHECK(rel(e.s.approach, h.delta) <= 1e-4);
      // The same contact point on a straight rail: the roller changes A only.
      CHECK(s.loaded[0].g.gamma == e.g.gamma);
      CHECK(e.s.a < 0.85 * s.loaded[0].s.a);
      CHECK(e.s.p0 > 1.1 * s.loaded[0].s.p0);
    }
  }
  // The case file's track.roller_radius_mm (cases/roller-rig.json: S1002 on a 700 mm roller with
  // a 60E1 head) reaches every candidate: A − cos γ/(2 r_roll) = cos γ/(2 (0.7 m + z_r)) to 1e-12
  // relative (measured 7e-16).
  const CaseFile cf = load_case_file(std::string(MHCONTACT_SOURCE_DIR) + "/cases/roller-rig.json", true);
  REQUIRE(rel(cf.track.roller_radius, R_roller) <= 1e-15);
  const PairGeometry pg = build_pair_geometry(cf);
  std::vector<CandidateEllipse> cands;
  for (double tY : {-4e-3, 0.0, 4e-3, 8e-3}) {
    candidate_ellipses(pg.geo, cf.material, tY, MultiHertzOptions{}, cands);
    REQUIRE(!cands.empty());
    for (const CandidateEllipse& c : cands) {
      CAPTURE(tY, c.ellipse);
      const double cg = std::cos(c.g.gamma);
      CHECK(rel(c.A - cg / (2 * c.g.r_roll), cg / (2 * (cf.track.roller_radius + c.z_r))) <= 1e-12);
    }
  }
}

TEST_CASE("not converged: the iteration limit gives not_converged, a message and the last iterate", "[solver]") {
  // Manchester pair, t_Y = 0, Q = 50 kN: two loaded ellipses; the default solve converges in 4
  // safeguarded Newton steps. With max_iterations = 1 (case file solver.max_iterations) the case is
  // `not_converged` (README "Output tables": a not_converged row keeps its last iterate, its
  // residual says how far it is from equilibrium; measured 0.042). The iterate is one state: every
  // ellipse at h0_i = (δz − gap_i) cos γ_i (eq. 11) of the reported δz, and Σ N_i cos γ_i = Q (1 +
  // residual) (eq. 10), both to 1e-12.
  const ContactGeometry& G = manchester();
  const Material mat = steel();
  const double Q = 50e3;
  REQUIRE(solve_multi_hertz(G, mat, 0.0, Q).status == CaseStatus::Ok);
  MultiHertzOptions one;
  one.max_iterations = 1;
  const CaseResult r = solve_multi_hertz(G, mat, 0.0, Q, one);
  CHECK(r.status == CaseStatus::NotConverged);
  CHECK(std::string(to_string(r.status)) == "not_converged");
  CHECK_THAT(r.message, Catch::Contains("equilibrium not reached in 1 iterations"));
  CHECK(r.iterations == 1);
  CHECK(std::fabs(r.residual) > 1e-3);
  REQUIRE(r.loaded.size() == 2);
  double F = 0;
  for (const LoadedEllipse& L : r.loaded) {
    CAPTURE(L.ellipse);
    const double cg = std::cos(L.g.gamma);
    CHECK(std::fabs(L.s.h0 - (r.dz - L.g.gap) * cg) <= 1e-12 * L.s.h0);
    F += L.s.N * cg;
  }
  CHECK(rel(F, r.Fz) <= 1e-12);
  CHECK(std::fabs((r.Fz - Q) / Q - r.residual) <= 1e-12);
}

TEST_CASE("exact_coefficients through the solver: the exact path's ellipses are closed-form Hertz, the fast path within its error",
          "[solver][fast]") {
  // Manchester pair, t_Y −6 … 10 mm, Q 10/50/100 kN (110 loaded ellipses). With
  // exact_coefficients every loaded ellipse is the closed-form Hertz contact of its own A, B, N
  // (tests/support/hertz_reference.hpp): tolerance 5e-14 relative on a, b, p0 and the approach
  // (measured 7.6e-15; the fast path is 6.6e-11 off, so the test fails when the option does not
  // reach the laws). Fast against exact, whole cases: a, b, p0 5e-10 relative (measured 1.0e-10),
  // N_i 5e-11 Q (measured 9.6e-12), δz 3e-10 relative (measured 6.4e-11): the fast path's error
  // (hertz.hpp kFastPathMaxRelError, measured 4.7e-11) and not more.
  const ContactGeometry& G = manchester();
  const Material mat = steel();
  const double EJ = testing::johnson_modulus(mat.E, mat.nu, mat.E, mat.nu);
  MultiHertzOptions exact;
  exact.exact_coefficients = true;
  int n = 0;
  for (int i = 0; i <= 32; ++i) {
    const double tY = (-6.0 + 0.5 * i) * 1e-3;
    for (double Q : {10e3, 50e3, 100e3}) {
      CAPTURE(tY, Q);
      const CaseResult e = solve_multi_hertz(G, mat, tY, Q, exact), f = solve_multi_hertz(G, mat, tY, Q);
      REQUIRE(e.status == CaseStatus::Ok);
      REQUIRE(f.status == CaseStatus::Ok);
      REQUIRE(e.loaded.size() == f.loaded.size());
      CHECK(rel(f.dz, e.dz) <= 3e-10);
      for (std::size_t k = 0; k < e.loaded.size(); ++k) {
        const LoadedEllipse &x = e.loaded[k], &y = f.loaded[k];
        CAPTURE(x.ellipse);
        const testing::HertzReference h = testing::hertz_reference(x.A, x.B, x.s.N, EJ);
        CHECK(rel(x.s.a, h.a) <= 5e-14);
        CHECK(rel(x.s.b, h.b) <= 5e-14);
        CHECK(rel(x.s.p0, h.p0) <= 5e-14);
        CHECK(rel(x.s.approach, h.delta) <= 5e-14);
        CHECK(y.ellipse == x.ellipse);
        CHECK(rel(y.s.a, x.s.a) <= 5e-10);
        CHECK(rel(y.s.b, x.s.b) <= 5e-10);
        CHECK(rel(y.s.p0, x.s.p0) <= 5e-10);
        CHECK(std::fabs(y.s.N - x.s.N) <= 5e-11 * Q);
        ++n;
      }
    }
  }
  CHECK(n >= 100);
}

namespace {
// Everything a multi-Hertzian result reports that depends on the ellipse laws, compared bit for bit.
void require_same_bytes(const CaseResult& a, const CaseResult& b) {
  REQUIRE(a.status == b.status);
  CHECK(a.dz == b.dz);
  CHECK(a.Fz == b.Fz);
  CHECK(a.pmax == b.pmax);
  CHECK(a.area == b.area);
  REQUIRE(a.loaded.size() == b.loaded.size());
  for (std::size_t k = 0; k < a.loaded.size(); ++k) {
    CHECK(a.loaded[k].s.N == b.loaded[k].s.N);
    CHECK(a.loaded[k].s.a == b.loaded[k].s.a);
    CHECK(a.loaded[k].s.b == b.loaded[k].s.b);
    CHECK(a.loaded[k].s.p_max == b.loaded[k].s.p_max);
    CHECK(a.loaded[k].c.m == b.loaded[k].c.m);
  }
}
}  // namespace

TEST_CASE("law cache: a change of material or coefficient path between two solves at one t_Y is seen", "[solver]") {
  // solve_multi_hertz keeps the ellipse laws of the last t_Y per thread (LawCache, keyed by the
  // material and exact_coefficients): a second solve at the same t_Y with another material must
  // give the bytes a fresh thread (an empty cache: what a new process computes) gives, and not
  // the first material's. Each variant changes one field of the key; each moves the answer.
  // Manchester pair, t_Y = 0 (two ellipses) and −3 mm (one), Q = 50 kN.
  const ContactGeometry& G = manchester();
  const Material steel_ = steel();
  struct Variant { const char* what; Material mat; bool exact; };
  std::vector<Variant> variants;
  auto with = [&](const char* what, auto&& change, bool exact = false) {
    Variant v{what, steel_, exact};
    change(v.mat);
    variants.push_back(v);
  };
  with("E", [](Material& m) { m.E = 200e9; });
  with("nu", [](Material& m) { m.nu = 0.3; });
  with("E_rail", [](Material& m) { m.E_rail = 70e9; });
  with("nu_rail", [](Material& m) { m.nu_rail = 0.33; });
  with("p_lim", [](Material& m) { m.p_lim = 500e6; });  // below the elastic peaks (845, 938 MPa)
  with("exact_coefficients", [](Material&) {}, true);
  for (double tY : {0.0, -3e-3}) {
    for (const Variant& v : variants) {
      CAPTURE(tY, v.what);
      MultiHertzOptions o2;
      o2.exact_coefficients = v.exact;
      const CaseResult first = solve_multi_hertz(G, steel_, tY, 50e3);   // fills this thread's cache
      const CaseResult second = solve_multi_hertz(G, v.mat, tY, 50e3, o2);
      CaseResult fresh;
      std::thread([&] { fresh = solve_multi_hertz(G, v.mat, tY, 50e3, o2); }).join();
      REQUIRE(second.status == CaseStatus::Ok);
      CHECK(second.dz != first.dz);  // the variant matters
      require_same_bytes(second, fresh);
    }
  }
}

TEST_CASE("an invalid material is a bug of the caller, not a non-Hertzian case", "[solver]") {
  // The solver used to turn every exception while building an ellipse law into "no Hertz
  // ellipse": an invalid material then read "every potential ellipse has B <= 0 (conformal)".
  // Now it propagates (the sweep reports an internal error, exit 3), and a λ beyond the Hertz
  // range is the only reason a candidate has no law.
  const ContactGeometry& G = manchester();
  Material bad = steel();
  bad.nu = 0.7;  // Poisson's ratio outside (0, 0.5)
  CHECK_THROWS_AS(solve_multi_hertz(G, bad, 0.0, 50e3), std::invalid_argument);
  // The material is checked once per material, where the law cache takes it (law_material):
  // after a good material, the same bad material a second time, or at another t_Y, throws again
  // (the cache keeps no half-taken key, so no law of the good material is reused for it).
  REQUIRE(solve_multi_hertz(G, steel(), 0.0, 50e3).status == CaseStatus::Ok);
  CHECK_THROWS_AS(solve_multi_hertz(G, bad, 0.0, 50e3), std::invalid_argument);
  CHECK_THROWS_AS(solve_multi_hertz(G, bad, 0.0, 50e3), std::invalid_argument);
  CHECK_THROWS_AS(solve_multi_hertz(G, bad, 1.0e-3, 60e3), std::invalid_argument);
  REQUIRE(solve_multi_hertz(G, steel(), 0.0, 50e3).status == CaseStatus::Ok);
}

TEST_CASE("plastic flange: approach and area near the capped half-space solution", "[solver][plastic]") {
  // Manchester pair, Q = 100 kN, p_lim = 900 MPa, t_Y = 8.5 … 10 mm. Reference: the capped
  // half-space method on the same cases (docs/half_space.md, "plastic flange"; mhcontact run with
  // "method": "half-space", dx = ds = 0.2 mm): approach 1.293, 1.209, 1.107, 1.010 mm; area 283,
  // 265, 247, 232 mm². Before the overlap-held approach (method.md §5) the multi-Hertzian
  // approach was 2.93, 2.56, 2.29, 2.08 mm (+106 … +127 %).
  const ContactGeometry& G = manchester();
  Material mat;
  mat.p_lim = 900e6;
  const double tY[] = {8.5e-3, 9e-3, 9.5e-3, 10e-3};
  const double approach[] = {1.293e-3, 1.209e-3, 1.107e-3, 1.010e-3};
  const double area[] = {283e-6, 265e-6, 247e-6, 232e-6};
  for (int k = 0; k < 4; ++k) {
    CAPTURE(tY[k]);
    const CaseResult r = solve_multi_hertz(G, mat, tY[k], 100e3);
    REQUIRE(r.status == CaseStatus::Ok);
    CHECK(std::fabs(r.approach / approach[k] - 1) <= 0.15);
    CHECK(std::fabs(r.area / area[k] - 1) <= 0.20);
  }
}
