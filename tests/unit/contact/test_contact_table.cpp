// The per-ellipse FASTSIM and the exact half-space tangential solver against CONTACT's 3,220-case
// table of Hertzian creep-force solutions (tests/data/contact_tangential/test_table_mx31.csv and
// its README: CONTACT 25.2's own program src/test_table.f90, exact steady rolling; 5 aspects a/b
// 0.2 … 5 × 4 spins × 7 directions × 23 magnitudes of the creepage; FN 82 kN, μ 0.3, ν 0.28,
// G 82 GPa; 27 elements across each ellipse). Issue 33 §4: the median and 95th percentile of
// |ΔFx|/(μN), |ΔFy|/(μN) (each component) and of |ΔMz|/(μN c) (c = √(ab)), targets median ≤ 3 %,
// 95th ≤ 10 % in force. The figures of docs/trust.md ("Creep forces") come from these tests.
//  - FASTSIM on all 3,220 cases (microseconds a case), both traction bounds, default grid.
//  - The exact solver on CONTACT's grid, the Hertzian pressure given on it, every 20th case (161,
//    a few seconds); the whole table and a grid twice as fine in the hidden tests
//    "[contact_table_exact_all]", "[contact_table_exact_fine]" (minutes; docs/trust.md).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "contact/half_space/tangential_rolling.hpp"
#include "contact/tangential/fastsim.hpp"
#include "support/data_csv.hpp"
#include "support/hertz_grid.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;
// The table's constants (its header line and README).
constexpr double kFN = 82000.0, kMu = 0.3, kG = 82e9, kNu = 0.28;
constexpr int kMx = 31;  // CONTACT's grid: kMx × kMx elements over kMx/(kMx − 4) × the ellipse

using Case = mh::test::DataRow;

std::vector<Case> read_table() { return mh::test::read_data_rows("contact_tangential/test_table_mx31.csv"); }

/// The q-quantile of v (nearest rank).
double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const std::size_t k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size()))) - 1;
  return v[std::min(k, v.size() - 1)];
}

struct Errors {
  std::vector<double> fx, fy, mz, adh;
  std::vector<double> fy_no_spin, fy_spin;  // |ΔFy|/(μN) on the cases without and with spin
  void add(const Case& r, double Fx, double Fy, double Mz, double adhesion) {
    const double c = std::sqrt(r["a_mm"] * r["b_mm"]) * 1e-3;
    fx.push_back(std::fabs(Fx / (kMu * kFN) - r["Fx_muN"]));
    fy.push_back(std::fabs(Fy / (kMu * kFN) - r["Fy_muN"]));
    (r["spin"] == 0 ? fy_no_spin : fy_spin).push_back(fy.back());
    mz.push_back(std::fabs(Mz / (kMu * kFN * c) - r["Mz_muNc"]));
    if (!std::isnan(adhesion)) adh.push_back(std::fabs(adhesion - r["adhesion_fraction"]));
  }
  void print(const char* what) const {
    std::printf("%s, %zu cases: |dFx|/muN median %.4f p95 %.4f max %.4f; |dFy|/muN median %.4f p95 %.4f max %.4f; "
                "|dMz|/(muN c) median %.4f p95 %.4f max %.4f", what, fx.size(), quantile(fx, 0.5), quantile(fx, 0.95),
                quantile(fx, 1), quantile(fy, 0.5), quantile(fy, 0.95), quantile(fy, 1), quantile(mz, 0.5),
                quantile(mz, 0.95), quantile(mz, 1));
    if (!adh.empty()) std::printf("; adhesion median %.3f p95 %.3f max %.3f", quantile(adh, 0.5), quantile(adh, 0.95),
                                  quantile(adh, 1));
    std::printf("\n");
  }
};

mh::Creepages creepages(const Case& r) { return {r["xi"], r["eta"], r["phi_per_mm"] * 1e3}; }

Errors fastsim_errors(const std::vector<Case>& rows, mh::TractionBound bound) {
  Errors e;
  mh::FastsimOptions o;
  o.bound = bound;
  for (const Case& r : rows) {
    const mh::TangentialResult f =
        mh::fastsim(creepages(r), r["a_mm"] * 1e-3, r["b_mm"] * 1e-3, kFN, kMu, kG, kNu, o);
    e.add(r, f.Fx, f.Fy, f.Mz, NAN);
  }
  return e;
}

/// The exact solver on the grid of CONTACT's layout with mx × mx elements (mx − 4 across the
/// ellipse; CONTACT's own: kMx), the Hertzian pressure given on it (carrying FN).
Errors exact_errors(const std::vector<Case>& rows, int every, int mx = kMx) {
  Errors e;
  for (std::size_t k = 0; k < rows.size(); k += static_cast<std::size_t>(every)) {
    const Case& r = rows[k];
    const double a = r["a_mm"] * 1e-3, b = r["b_mm"] * 1e-3;
    HertzGrid h(a, b, 3 * kFN / (2 * kPi * a * b), mx, mx, double(mx) / (mx - 4));
    for (double& p : h.p) p *= kFN / h.N;
    mh::HalfSpaceTangentialSolver s(h.nx, h.ny, h.dx, h.dy, kG, kNu);
    const auto t = s.solve(h.p.data(), h.x0, h.y0, creepages(r), kMu);
    INFO("case " << r["case"]);
    REQUIRE(t.status == mh::TangentialStatus::Ok);
    e.add(r, t.forces.Fx, t.forces.Fy, t.forces.Mz, t.forces.adhesion_fraction);
  }
  return e;
}

}  // namespace

TEST_CASE("CONTACT's 3,220-case table is what its README says", "[contact_table]") {
  const std::vector<Case> rows = read_table();
  REQUIRE(rows.size() == 3220);
  // Full sliding at the largest magnitude without spin: |F| = μN (the table's own consistency).
  for (const Case& r : rows)
    if (r["magnitude"] == 12 && r["spin"] == 0)
      CHECK(std::hypot(r["Fx_muN"], r["Fy_muN"]) == Approx(1).margin(1e-3));  // measured 5e-5
}

TEST_CASE("FASTSIM per ellipse against CONTACT's 3,220 Hertzian cases (issue 33 section 4 statistics)",
          "[contact_table][fastsim]") {
  const std::vector<Case> rows = read_table();
  REQUIRE(rows.size() == 3220);
  const Errors el = fastsim_errors(rows, mh::TractionBound::Elliptical);
  const Errors pa = fastsim_errors(rows, mh::TractionBound::Parabolic);
  el.print("FASTSIM (elliptical bound, 32 x 32) vs CONTACT test_table");
  pa.print("FASTSIM (parabolic bound, 32 x 32) vs CONTACT test_table");
  for (const auto* e : {&el.fx, &el.fy, &pa.fx, &pa.fy}) {
    CHECK(quantile(*e, 0.5) <= 0.03);   // issue 33 §4 targets, each force component
    CHECK(quantile(*e, 0.95) <= 0.10);
  }
}

TEST_CASE("The exact half-space solver against CONTACT's table, every 20th case", "[contact_table][tangential_rolling]") {
  const std::vector<Case> rows = read_table();
  REQUIRE(rows.size() == 3220);
  const Errors e = exact_errors(rows, 20);
  e.print("exact half-space (31 x 31, Hertz pressure) vs CONTACT test_table, every 20th case");
  std::printf("  |dFy|/muN without spin: max %.4f; with spin: median %.4f max %.4f\n", quantile(e.fy_no_spin, 1),
              quantile(e.fy_spin, 0.5), quantile(e.fy_spin, 1));
  // Issue 33 §4: |ΔFx|, |ΔFy| within 2 % of μN, Mz within 5 % (of μN c), adhesion within 0.05.
  CHECK(quantile(e.fx, 1) <= 0.02);
  CHECK(quantile(e.fy_no_spin, 1) <= 0.02);
  CHECK(quantile(e.mz, 1) <= 0.05);
  CHECK(quantile(e.adh, 1) <= 0.05);
  // The lateral force from spin: 0.55 % of μN at most (every 20th case, 29 Nov 2026), with the
  // spin's rigid slip taken where CONTACT takes it (tangential_rolling.hpp, eq. R1; taken at the
  // element centre it was 2.8 %). Held at about 1.5 × what was measured.
  CHECK(quantile(e.fy_spin, 1) <= 0.008);
}

TEST_CASE("The exact half-space solver against CONTACT's whole table (long: minutes)", "[.][contact_table_exact_all]") {
  const std::vector<Case> rows = read_table();
  REQUIRE(rows.size() == 3220);
  const Errors e = exact_errors(rows, 1);
  e.print("exact half-space (31 x 31, Hertz pressure) vs CONTACT test_table, all cases");
  std::printf("  |dFy|/muN without spin: median %.4f p95 %.4f max %.4f; with spin: median %.4f p95 %.4f max %.4f\n",
              quantile(e.fy_no_spin, 0.5), quantile(e.fy_no_spin, 0.95), quantile(e.fy_no_spin, 1),
              quantile(e.fy_spin, 0.5), quantile(e.fy_spin, 0.95), quantile(e.fy_spin, 1));
}

TEST_CASE("The exact half-space solver on a grid twice as fine against CONTACT's table (long: minutes)",
          "[.][contact_table_exact_fine]") {
  const std::vector<Case> rows = read_table();
  REQUIRE(rows.size() == 3220);
  const Errors e = exact_errors(rows, 10, 2 * (kMx - 4) + 4);
  e.print("exact half-space (58 x 58: 54 elements across) vs CONTACT test_table (27 across), every 10th case");
  CHECK(quantile(e.fx, 1) <= 0.02);
  // Across two grids the difference holds the reference's own grid error: with the spin slip taken
  // as CONTACT takes it (eq. R1) this solver follows CONTACT on its grid, and on the 5:1 elements
  // of a/b = 5 the lateral force under spin still moves by up to 3 % of μN between 27 and 54
  // elements across (case 2741: −0.4254 → −0.4534 μN; CONTACT −0.4239 at 27; CONTACT's own
  // 17 → 27 change is up to 3.5 %). Measured 0.0295 (29 Nov 2026); held at 0.035.
  CHECK(quantile(e.fy, 1) <= 0.035);
  CHECK(quantile(e.mz, 1) <= 0.05);
  CHECK(quantile(e.adh, 1) <= 0.05);
}

TEST_CASE("Exact solver, pure spin on a/b = 1: convergence in the elements across (prints)",
          "[.][tangential_spin_convergence]") {
  const std::vector<Case> rows = read_table();
  REQUIRE(rows.size() == 3220);
  const Case* pick = nullptr;
  for (const Case& r : rows)
    if (r["case"] == 1611) pick = &r;
  REQUIRE(pick);
  const Case& r = *pick;
  std::printf("case 1611 (a/b = 1, pure spin s = 1): CONTACT Fy/muN %.6f (27 across), %.6f (17 across)\n",
              r["Fy_muN"], r["Fy_muN_coarse"]);
  for (int across : {17, 27, 37, 57, 117}) {
    const int mx = across + 4;
    const double a = r["a_mm"] * 1e-3, b = r["b_mm"] * 1e-3;
    HertzGrid h(a, b, 3 * kFN / (2 * kPi * a * b), mx, mx, double(mx) / (mx - 4));
    for (double& p : h.p) p *= kFN / h.N;
    mh::HalfSpaceTangentialSolver s(h.nx, h.ny, h.dx, h.dy, kG, kNu);
    const auto t = s.solve(h.p.data(), h.x0, h.y0, creepages(r), kMu);
    REQUIRE(t.status == mh::TangentialStatus::Ok);
    const double c = std::sqrt(a * b);
    std::printf("  %3d across: Fy/muN %.6f  Mz/muNc %.6f  adhesion %.3f  sweeps %d\n", across,
                t.forces.Fy / (kMu * kFN), t.forces.Mz / (kMu * kFN * c), t.forces.adhesion_fraction, t.sweeps);
  }
}
