// Kalker's creepage coefficients (contact/tangential/kalker.hpp) against Kalker 1990, Table E.3
// (values read from the table at its columns ν = 0.25, 0.5), against CONTACT's linrol at ν = 0.28
// (values quoted by its routine for the three aspects below), and the trap of the circulating copy.
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/tangential/kalker.hpp"

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
  CHECK(r.Mz == Approx(-G * c * c * c * k.C23 * 2e-4).epsilon(1e-14));
  // Without spin, Tγ (forces on the rail times creepages) is the dissipated work, > 0.
  CHECK(kalker_linear({1e-4, -2e-4, 0}, a, b, G, nu).Tgamma > 0);
}
