// The physical checks of a grid result (contact/grid/grid_checks.hpp): each check fires on the
// defect it names and on nothing else, and each puts its row outside validity; a not_converged
// grid row keeps no pressures.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "contact/grid/grid_checks.hpp"
#include "contact/judge/judge.hpp"

using namespace mh;

namespace {

// A Hertz patch on an nx × ns grid of 0.2 mm elements: p = p0 √(1 − x²/a² − s²/b²) and the rigid
// overlap δ − g = δ (1 − x²/a² − s²/b²)·(a Hertz gap at the contact edge: overlap 0 there).
PatchCheckInput hertz_patch(int nx = 61, int ns = 41, double a = 5e-3, double b = 3e-3) {
  PatchCheckInput c;
  c.nx = nx;
  c.ns = ns;
  c.ds = 0.2e-3;
  c.approach = 50e-6;
  c.gap_violation = 0;
  c.spike_check = c.hole_check = true;
  for (int j = 0; j < ns; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = (i - 0.5 * (nx - 1)) * 0.2e-3, s = (j - 0.5 * (ns - 1)) * 0.2e-3;
      const double q = 1 - x * x / (a * a) - s * s / (b * b);
      c.p.push_back(q > 0 ? 1e9 * std::sqrt(q) : 0.0);
      c.overlap.push_back(c.approach * q);
    }
  return c;
}

CaseResult one_patch(double N, double Q) {
  CaseResult r;
  r.method = Method::HalfSpace;
  PatchResult P;
  P.N = N;
  P.gamma = 0.3;
  r.patches.push_back(P);
  (void)Q;
  return r;
}

std::vector<std::string> classes_of(const CaseResult& r) {
  std::vector<std::string> v;
  for (const Warning& w : r.warnings) v.push_back(to_string(w.cls));
  return v;
}

}  // namespace

TEST_CASE("grid checks: a Hertz patch in balance passes every check", "[grid][checks]") {
  const double Q = 50e3;
  CaseResult r = one_patch(Q / std::cos(0.3), Q);
  check_grid_result({hertz_patch()}, Q, r);
  CHECK(r.warnings.empty());
  judge_validity(r, 8e-3);
  CHECK(r.status == CaseStatus::Ok);
}

TEST_CASE("grid checks: each defect gives its own validity class", "[grid][checks]") {
  // Break guarded, per row: drop the check (or its condition) in check_grid_result and the row
  // stays ok.
  const double Q = 50e3, N = Q / std::cos(0.3);
  struct Row { const char* cls; double N; PatchCheckInput in; };
  std::vector<Row> rows;
  rows.push_back({"force_balance", N * (1 + 1e-3), hertz_patch()});  // 0.1 % of Q missing
  {
    PatchCheckInput c = hertz_patch();
    c.p[2 + 61 * 20] = -1e6;  // a negative pressure (outside the patch: not a hole)
    rows.push_back({"complementarity", N, c});
  }
  {
    PatchCheckInput c = hertz_patch();
    c.gap_violation = 0.02 * c.approach;  // the deformed gap 2 % of the approach off its condition
    rows.push_back({"complementarity", N, c});
  }
  {
    PatchCheckInput c = hertz_patch();
    c.p_lim = 0.9e9;  // a pressure above the cap
    rows.push_back({"complementarity", N, c});
  }
  {
    PatchCheckInput c = hertz_patch();
    c.end_gap_error = 0.2;  // strips: an estimate with a 20 % end-gap error, not refined
    c.end_gap_tol = 0.05;
    rows.push_back({"complementarity", N, c});
  }
  {
    PatchCheckInput c = hertz_patch();
    for (int j = 19; j <= 21; ++j)
      for (int i = 29; i <= 31; ++i) c.p[static_cast<std::size_t>(i + 61 * j)] = 0;  // a 3 × 3 hole at the centre
    rows.push_back({"contact_hole", N, c});
  }
  {
    PatchCheckInput c = hertz_patch();
    c.p[5 + 61 * 20] = 40e9;  // an isolated peak
    rows.push_back({"pressure_spike", N, c});
  }
  for (const Row& row : rows) {
    CAPTURE(row.cls);
    CaseResult r = one_patch(row.N, Q);
    check_grid_result({row.in}, Q, r);
    const std::vector<std::string> cls = classes_of(r);
    REQUIRE(cls.size() == 1);
    CHECK(cls[0] == row.cls);
    CHECK((warning_text(r.warnings[0]).find("patch=1") != std::string::npos || cls[0] == "force_balance"));
    judge_validity(r, 8e-3);
    CHECK(r.status == CaseStatus::OutsideValidity);
  }
  // A failed row is left alone: its status says enough.
  CaseResult nc = one_patch(N * 1.5, Q);
  nc.status = CaseStatus::NotConverged;
  check_grid_result({hertz_patch()}, Q, nc);
  CHECK(nc.warnings.empty());
}

TEST_CASE("grid checks: a hole needs overlap and enclosure along x and s", "[grid][checks]") {
  // The 3 × 3 hole at the centre is one; the same elements without overlap (the gap above the
  // tolerance there) are not; a free band across the whole patch (two contacts side by side,
  // as the tread and gauge shoulder of the Manchester pair at t_Y = 5 mm) is not, though the
  // undeformed bodies overlap there.
  PatchCheckInput c = hertz_patch();
  for (int j = 19; j <= 21; ++j)
    for (int i = 29; i <= 31; ++i) c.p[static_cast<std::size_t>(i + 61 * j)] = 0;
  ContactHole h = find_contact_hole(c);
  CHECK(h.elements == 9);
  CHECK(h.i == 30);
  CHECK(h.j == 20);
  CHECK(h.overlap == Approx(c.approach));
  for (int j = 19; j <= 21; ++j)
    for (int i = 29; i <= 31; ++i) c.overlap[static_cast<std::size_t>(i + 61 * j)] = 0.5 * kGapRtol * c.approach;
  CHECK(find_contact_hole(c).elements == 0);  // break guarded: drop the overlap condition
  PatchCheckInput band = hertz_patch();
  for (int j = 18; j <= 22; ++j)
    for (int i = 0; i < 61; ++i) band.p[static_cast<std::size_t>(i + 61 * j)] = 0;
  CHECK(find_contact_hole(band).elements == 0);  // break guarded: enclosure along s alone
  // Elements outside the patch (no overlap, no enclosure) never count.
  CHECK(find_contact_hole(hertz_patch()).elements == 0);
}

TEST_CASE("grid checks: a not_converged grid row keeps its forces, not its pressures", "[grid][checks]") {
  CaseResult r = one_patch(60e3, 50e3);
  r.status = CaseStatus::NotConverged;
  r.Fz = 57e3;
  r.approach = 0.1e-3;
  r.residual = 0.14;
  r.pmax = 2.9e12;  // the 2.9 million MPa of a failed half-space iterate
  r.area = 0.08e-6;
  r.n_contacts = 1;
  withhold_unconverged_pressures(r);
  CHECK(std::isnan(r.pmax));
  CHECK(std::isnan(r.area));
  CHECK(r.patches.empty());
  CHECK(r.Fz == 57e3);
  CHECK(r.approach == 0.1e-3);
  CHECK(r.residual == 0.14);
  CHECK(r.n_contacts == 1);
  CaseResult ok = one_patch(60e3, 50e3);
  ok.pmax = 1e9;
  withhold_unconverged_pressures(ok);  // an answer keeps everything
  CHECK(ok.pmax == 1e9);
  CHECK(ok.patches.size() == 1);
}

TEST_CASE("grid checks: the peak's rail y is the peak row's, a capped plateau's middle row", "[grid][checks]") {
  const double Q = 50e3;
  PatchCheckInput c = hertz_patch();  // 41 rows along s, the peak on row 20
  c.gamma = 0.3;
  c.y_ref = 0.01;
  c.s0 = -20 * c.ds;
  CaseResult r = one_patch(Q / std::cos(0.3), Q);
  check_grid_result({c}, Q, r);
  CHECK(r.patches[0].y_peak == Approx(0.01).margin(1e-9));  // s = 0: the plane's reference point
  // Capped at 0.8 p0: the plateau spans rows 11 … 29 (|s| ≤ 0.6 b = 1.8 mm); its middle is row 20,
  // not its first row 11 (s = −1.8 mm), where a tilted rail would be measured at the plateau's edge.
  for (double& p : c.p) p = std::min(p, 0.8e9);
  c.p_lim = 0.8e9;
  CaseResult rc = one_patch(Q / std::cos(0.3), Q);
  check_grid_result({c}, Q, rc);
  CHECK(rc.patches[0].y_peak == Approx(0.01).margin(1e-9));
}
