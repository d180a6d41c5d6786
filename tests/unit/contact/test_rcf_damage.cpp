// Damage and wear from Tγ (contact/rcf/damage.hpp; docs/methods.md "Damage and wear from Tγ").
// Reference values by hand from the functions' definitions (Burstow 2004: 15, 65, 175 J/m, peak
// 1e-5 per axle; Lewis & Dwyer-Joyce 2004: 5.3 Tγ/A below 10.4 N/mm², 55.0 up to 77.2, slope
// 61.9 above, continuous at 77.2 by this project's convention). Tolerances: 1e-12 relative on the
// damage (exact arithmetic on the constants), 1e-9 µg/(m·mm²) on the wear rate.
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/rcf/damage.hpp"

using namespace mh;

TEST_CASE("Burstow damage function: zero, rise, peak, fall, zero at every breakpoint", "[rcf][damage]") {
  const BurstowOptions o;
  CHECK(o.invalid().empty());
  struct Row { double Tg, D; };
  const Row rows[] = {
      {-5, 0},       {0, 0},        {14.999, 0},  {15, 0},        // below and at the threshold
      {15.001, 2e-10}, {40, 5e-6},  {65, 1e-5},                   // rise: 1e-5 (Tγ − 15)/50
      {120, 5e-6},   {174.999, 1e-5 * 0.001 / 110}, {175, 0},     // fall: 1e-5 (175 − Tγ)/110
      {200, 0},      {1e4, 0},
  };
  for (const Row& r : rows) {
    CAPTURE(r.Tg);
    CHECK(burstow_damage(r.Tg, o) == Approx(r.D).epsilon(1e-9).margin(1e-20));
  }
  CHECK(std::isnan(burstow_damage(NAN, o)));
  // The 20 J/m variant of public code (2.22e-7 Tγ − 4.44e-6 up to 65, −9.09e-8 Tγ + 1.59e-5 to
  // 175): the same function with Tgamma_threshold_N = 20, to the 3 digits of its constants.
  BurstowOptions v;
  v.Tgamma_threshold_N = 20;
  for (double Tg : {20.0, 30.0, 50.0, 65.0}) CHECK(burstow_damage(Tg, v) == Approx(2.22e-7 * Tg - 4.44e-6).margin(2e-8));
  for (double Tg : {65.0, 100.0, 150.0, 175.0}) CHECK(burstow_damage(Tg, v) == Approx(-9.09e-8 * Tg + 1.59e-5).margin(2e-8));
  BurstowOptions bad;
  bad.Tgamma_peak_N = 200;
  CHECK(!bad.invalid().empty());
}

TEST_CASE("USFD wear function: the three regimes and both breaks", "[rcf][wear]") {
  const UsfdWearOptions o;
  CHECK(o.invalid().empty());
  struct Row { double x, w; };  // Tγ/A [N/mm²], rate [µg/(m·mm²)]
  const Row rows[] = {
      {-1, 0},     {0, 0},      {5, 26.5},        {10.39, 5.3 * 10.39},   // mild
      {10.4, 55.0}, {40, 55.0}, {77.2, 55.0},                             // severe (first break: 55.12 → 55.0)
      {77.3, 55.0 + 61.9 * 0.1}, {100, 55.0 + 61.9 * 22.8},               // catastrophic, from 55.0 at 77.2
  };
  for (const Row& r : rows) {
    CAPTURE(r.x);
    CHECK(usfd_wear_rate_ug_per_m_mm2(r.x, o) == Approx(r.w).margin(1e-9));
  }
  // Continuous and never decreasing across the second break (the quoted intercept −4778.7 would
  // drop to −0.02 here).
  CHECK(usfd_wear_rate_ug_per_m_mm2(77.2 + 1e-9, o) - usfd_wear_rate_ug_per_m_mm2(77.2, o) < 1e-6);
  CHECK(std::fabs((55.0 - 61.9 * 77.2) - (-4723.68)) < 1e-9);  // the intercept this convention implies
  // SI wrapper: Tγ = 100 N over A = 50 mm² → 2 N/mm², 10.6 µg/(m·mm²) = 10.6e-3 kg/m³, 530 µg/m.
  const Wear w = usfd_wear(100.0, 50e-6, o);
  CHECK(w.rate == Approx(10.6e-3).epsilon(1e-12));
  CHECK(w.per_metre == Approx(530e-9).epsilon(1e-12));
  CHECK(std::isnan(usfd_wear(100.0, 0.0, o).rate));
}
