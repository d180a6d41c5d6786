// Kalker's creepage coefficients (contact/tangential/kalker.hpp) against Kalker 1990, Table E.3
// (values read from the table at its columns ν = 0.25, 0.5), against CONTACT's linrol at ν = 0.28
// (values quoted by its routine for the three aspects below), the trap of the circulating copy,
// all four (C33 among them) against CONTACT's exact solver at small creepage (its own table), and
// all four against Kalker's series method solved to convergence (tests/data/kalker_series/).
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "contact/tangential/kalker.hpp"
#include "support/kalker_series.hpp"

using namespace mh;

TEST_CASE("Kalker C_ij at the table's own entries (Table E.3)", "[tangential][kalker]") {
  struct R { double aob, nu, C11, C22, C23; };
  const R rows[] = {
      {0.8, 0.25, 3.91, 3.41, 1.25},  // the trap: a copy in circulation has C23 = 1.15 here
      {0.3, 0.25, 3.44, 2.75, 0.715},
      {1.0, 0.50, 5.20, 3.98, 1.63},
      {1.0 / 0.2, 0.0, 6.96, 6.96, 5.72},  // a/b = 5: the row b/a = 0.2
      {1.0 / 0.5, 0.25, 5.10, 4.90, 2.62},
  };
  for (const R& r : rows) {
    const KalkerCoefficients k = kalker_coefficients(r.aob, r.nu);
    INFO("a/b " << r.aob << " nu " << r.nu);
    CHECK_FALSE(k.asymptote);
    CHECK(k.C11 == Approx(r.C11).epsilon(1e-9));
    CHECK(k.C22 == Approx(r.C22).epsilon(1e-9));
    CHECK(k.C23 == Approx(r.C23).epsilon(1e-9));
  }
}

TEST_CASE("Kalker C_ij at nu 0.28 agree with CONTACT's linrol to its printed digits", "[tangential][kalker]") {
  // CONTACT src/m_hertz.f90, linrol, as quoted to 4 digits (tolerance: half a unit of the last digit).
  struct R { double aob, C11, C22, C23; };
  const R rows[] = {{0.5, 3.734, 3.026, 0.943}, {1.0, 4.226, 3.705, 1.488}, {2.0, 5.204, 4.971, 2.657}};
  for (const R& r : rows) {
    const KalkerCoefficients k = kalker_coefficients(r.aob, 0.28);
    INFO("a/b " << r.aob);
    CHECK(std::abs(k.C11 - r.C11) <= 5e-4);
    CHECK(std::abs(k.C22 - r.C22) <= 5e-4);
    CHECK(std::abs(k.C23 - r.C23) <= 5e-4);
  }
}

TEST_CASE("Kalker asymptotes below g = 0.1 and their step against the table", "[tangential][kalker]") {
  // a ≪ b: C11 → π²/(4(1−ν)), C22 → π²/4 (Kalker 1990, App. E; 2-D Carter limit).
  const KalkerCoefficients n = kalker_coefficients(0.05, 0.25);
  CHECK(n.asymptote);
  CHECK(n.C11 == Approx(M_PI * M_PI / 3.0).epsilon(1e-12));
  CHECK(n.C22 == Approx(M_PI * M_PI / 4.0).epsilon(1e-12));
  // The asymptote meets the table's first row within a few per cent (the documented jump).
  const KalkerCoefficients t = kalker_coefficients(0.1011, 0.25), s = kalker_coefficients(0.1009, 0.25);
  CHECK_FALSE(t.asymptote);
  CHECK(s.asymptote);
  CHECK(std::abs(s.C11 / t.C11 - 1) < 0.01);
  CHECK(std::abs(s.C22 / t.C22 - 1) < 0.03);
  const KalkerCoefficients tl = kalker_coefficients(1 / 0.1011, 0.25), sl = kalker_coefficients(1 / 0.1009, 0.25);
  CHECK(std::abs(sl.C11 / tl.C11 - 1) < 0.06);
  CHECK(std::abs(sl.C22 / tl.C22 - 1) < 0.06);
  CHECK(std::abs(sl.C23 / tl.C23 - 1) < 0.06);
}

TEST_CASE("Kalker linear forces carry the convention of tangential_types.hpp", "[tangential][kalker]") {
  const double a = 6e-3, b = 4e-3, G = 82e9, nu = 0.28, c = std::sqrt(a * b);
  const KalkerCoefficients k = kalker_coefficients(a / b, nu);
  const TangentialResult r = kalker_linear({1e-4, -2e-4, 0.5}, a, b, G, nu);
  CHECK(r.Fx == Approx(-G * c * c * k.C11 * 1e-4).epsilon(1e-14));
  CHECK(r.Fy == Approx(G * c * c * k.C22 * 2e-4 - G * c * c * c * k.C23 * 0.5).epsilon(1e-14));
  CHECK(r.Mz == Approx(-G * c * c * c * k.C23 * 2e-4 - G * c * c * c * c * k.C33 * 0.5).epsilon(1e-14));
  // CONTACT's module 3: a positive spin alone gives a negative Fy and Mz on the wheel (c33 runs).
  const TangentialResult s = kalker_linear({0, 0, 1.0}, a, b, G, nu);
  CHECK(s.Fy < 0);
  CHECK(s.Mz < 0);
  // Without spin, Tγ (forces on the rail times creepages) is the dissipated work, > 0.
  CHECK(kalker_linear({1e-4, -2e-4, 0}, a, b, G, nu).Tgamma > 0);
}

TEST_CASE("Kalker C33 at the table's own entries (Table E.3, the public copy's digits)", "[tangential][kalker]") {
  // kalker.hpp names the copy; values below 1 are rounded there to two decimals.
  struct R { double aob, nu, C33; };
  const R rows[] = {
      {0.2, 0.0, 3.46}, {0.2, 0.25, 4.27}, {0.5, 0.5, 2.22}, {1.0, 0.0, 1.21}, {1.0, 0.25, 1.19}, {1.0, 0.5, 1.16},
      {0.9, 0.25, 1.27}, {1.0 / 0.9, 0.25, 1.11}, {2.0, 0.25, 0.82}, {5.0, 0.25, 0.60}, {5.0, 0.5, 0.34},
  };
  for (const R& r : rows) {
    const KalkerCoefficients k = kalker_coefficients(r.aob, r.nu);
    INFO("a/b " << r.aob << " nu " << r.nu);
    CHECK(k.C33 == Approx(r.C33).epsilon(1e-9));
  }
  // No source for C33's slender-ellipse asymptote: NaN there, and the linear Mz with φ ≠ 0 too.
  CHECK(std::isnan(kalker_coefficients(0.05, 0.25).C33));
  CHECK(std::isnan(kalker_linear({0, 0, 1.0}, 1e-3, 20e-3, 82e9, 0.28).Mz));
  CHECK(kalker_linear({0, 1e-4, 0}, 1e-3, 20e-3, 82e9, 0.28).Mz != 0);
}

TEST_CASE("Kalker C11 to C33 against CONTACT's exact solver extrapolated to zero element size", "[tangential][kalker]") {
  // tests/data/contact_tangential/c33_convergence.csv (README there): CONTACT 25.2's exact
  // steady-rolling solution at a small creepage (full adhesion: linear theory on its grid), ν = 0.25,
  // a/b = 0.2 … 5, grids of 20, 28, 40, 56 elements across the ellipse. The coefficients zigzag by
  // 1–2 % between the grid families 20, 40 and 28, 56, so each family is extrapolated on its own
  // (first order in h, C0 = 2 C(h/2) − C(h)). Measured against the table as the project reads it
  // (29 Nov 2026, docs/tangential.md "Linear theory"): C11, C22, C23, whose table values linrol
  // confirms, −1.2 … +3.0 % (the a/b = 4 C23 read linearly in g aside, below); C33 −0.3 … +4.5 %,
  // its two families up to 3.3 % apart. Held: all four within 5 %, the resolution of this check
  // (a row shifted by one is 8–12 % off at a/b ≥ 2, the two halves swapped a factor 2 or more).
  std::ifstream f(std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/contact_tangential/c33_convergence.csv");
  REQUIRE(f);
  std::string line, cell;
  std::getline(f, line);
  std::map<std::pair<double, int>, std::array<double, 4>> c;  // (a/b, elements across) → C11 … C33
  while (std::getline(f, line)) {
    std::vector<double> v;
    for (std::istringstream in(line); std::getline(in, cell, ',');) v.push_back(std::stod(cell));
    REQUIRE(v.size() == 13);
    REQUIRE(v[0] == 0.25);
    CHECK(v[11] >= 0.99);  // full adhesion but for a few trailing-edge elements: the linear regime
    c[{v[1], static_cast<int>(v[4]) - 4}] = {v[7], v[8], v[9], v[10]};
  }
  int checked = 0;
  for (const double aob : {0.2, 0.5, 1.0, 2.0, 5.0, 4.0}) {
    const KalkerCoefficients k = kalker_coefficients(aob, 0.25);
    const double table[4] = {k.C11, k.C22, k.C23, k.C33};
    for (const auto& fam : {std::pair<int, int>{20, 40}, std::pair<int, int>{28, 56}}) {
      REQUIRE(c.count({aob, fam.first}) == 1);
      REQUIRE(c.count({aob, fam.second}) == 1);
      const auto& coarse = c.at({aob, fam.first});
      const auto& fine = c.at({aob, fam.second});
      for (int j = 0; j < 4; ++j) {
        const double C0 = 2 * fine[j] - coarse[j];
        INFO("a/b " << aob << ", C" << (j == 0 ? "11" : j == 1 ? "22" : j == 2 ? "23" : "33") << ", grids " << fam.first
                    << " -> " << fam.second << ": CONTACT " << C0 << ", table " << table[j]);
        if (aob == 4.0 && j == 2) {
          // Between the table's rows g = 0.2 and 0.3 the linear reading in g is 2.5–3.3 % above
          // CONTACT where the rows themselves are 0–3 % below it: the curved column read straight.
          CHECK(C0 / table[j] < 0.99);
          continue;
        }
        CHECK(std::abs(C0 / table[j] - 1) <= 0.05);
        ++checked;
      }
    }
  }
  CHECK(checked == 46);
}

TEST_CASE("Table E.3 against Kalker's series method solved to convergence", "[tangential][kalker]") {
  // tests/data/kalker_series/ (scripts/kalker_series.py): the linear theory with the traction a
  // polynomial of degree 14 and 16 over √(1 − x²/a² − y²/b²), no grid, no library code; the two
  // degrees agree within 0.016 %. At ν = 0.25 (a column of the table: no interpolation in ν) the
  // table's entries differ from it by at most (29 Nov 2026): C11 0.41 %, C22 0.61 %, C23 0.26 %,
  // C33 0.74 % (the copy's two decimals: ±0.8 % at 0.60), the largest all at a/b = 5 (b/a = 0.2,
  // table below the converged value): the table's accuracy, of which the 0.5 % target
  // for C22 at a/b = 5 asks more than the table has (docs/tangential.md, "Linear theory").
  // Held at 1.5 × those; an entry mistyped in its second digit (C22 8.14 → 8.04: −1.8 %) fails.
  struct Tol { double C11, C22, C23, C33; };
  const Tol tol{0.006, 0.009, 0.004, 0.011};
  for (double aob : {0.2, 0.5, 1.0, 2.0, 5.0}) {
    const KalkerCoefficients k = kalker_coefficients(aob, 0.25);
    const mh::test::SeriesCoefficients s = mh::test::kalker_series(aob, 0.25);
    INFO("a/b " << aob << ": table/series C11 " << k.C11 / s.C11 << ", C22 " << k.C22 / s.C22 << ", C23 "
                << k.C23 / s.C23 << ", C33 " << k.C33 / s.C33);
    CHECK(k.C11 == Approx(s.C11).epsilon(tol.C11));
    CHECK(k.C22 == Approx(s.C22).epsilon(tol.C22));
    CHECK(k.C23 == Approx(s.C23).epsilon(tol.C23));
    CHECK(k.C33 == Approx(s.C33).epsilon(tol.C33));
  }
  // At ν = 0.28 (the issue's; the table interpolated in ν) the deviations are those at ν = 0.25
  // within 0.05 % (C22 at a/b = 5: −0.63 %).
  for (double aob : {0.2, 1.0, 5.0}) {
    const KalkerCoefficients k = kalker_coefficients(aob, 0.28);
    const mh::test::SeriesCoefficients s = mh::test::kalker_series(aob, 0.28);
    INFO("a/b " << aob);
    CHECK(k.C22 == Approx(s.C22).epsilon(tol.C22));
  }
}
