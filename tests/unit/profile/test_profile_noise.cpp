// Measured or exact (curve.hpp NoiseDecision, profiles.md "Measured or exact"): decided from the
// fit residual against the rounding of the printed coordinates. Exact profiles printed with 3,
// 4 and 6 decimals stay exact; noise added to an exact profile, and the measured files of
// tests/data/profiles, are measured.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "profile/curve.hpp"
#include "profile/read.hpp"
#include "profile/standard_profiles.hpp"

using namespace mh;

namespace {
const std::string kData = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/profiles/";

// Write `p` as a plain table "y z" in mm with `decimals` decimals (as a spreadsheet or another
// tool would print it), adding normal noise of standard deviation `noise_mm` to z.
std::string write_fixed(const Profile& p, int decimals, const std::string& name, double noise_mm = 0) {
  const auto dir = std::filesystem::temp_directory_path() / "mhcontact_test_noise";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream f(path);
  std::mt19937 rng(12345);
  std::normal_distribution<double> n(0.0, 1.0);
  char buf[96];
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%.*f %.*f\n", decimals, p.y[i] * 1e3, decimals, p.z[i] * 1e3 + noise_mm * n(rng));
    f << buf;
  }
  return path;
}

NoiseDecision classify(const std::string& path, ProfileKind kind, ProfileNoise forced = ProfileNoise::Auto) {
  ProfileReadOptions o;
  o.kind = kind;
  CurveOptions co;
  co.noise = forced;
  return ProfileCurve(read_profile(path, o), co).noise();
}
}  // namespace

TEST_CASE("exact profiles printed with 3, 4 and 6 decimals are exact", "[noise]") {
  // Rounding to q gives a residual of about q/√12 (0.29 µm at 3 decimals: above the old fixed
  // 0.2 µm threshold, which took S1002 printed to 3 decimals for a measured profile).
  for (const auto& [name, kind, incl] : {std::tuple<const char*, ProfileKind, Inclination>{"S1002", ProfileKind::Wheel, Inclination::None},
                                        {"60E1", ProfileKind::Rail, Inclination::In40},
                                        {"54E1", ProfileKind::Rail, Inclination::None}})
    for (int d : {3, 4, 6}) {
      const Profile p = make_standard_profile(name, incl);
      const NoiseDecision n = classify(write_fixed(p, d, std::string(name) + "_" + std::to_string(d) + ".dat"), kind);
      CAPTURE(name, d, n.reason);
      REQUIRE(n.print_step == Approx(std::pow(10.0, -d) * 1e-3).epsilon(1e-9));
      REQUIRE_FALSE(n.measured);
      REQUIRE_FALSE(n.forced);
      // The residual is the rounding's: below 1.5 × q/√12 (and above 0.5 × at 3 and 4 decimals).
      REQUIRE(n.median_residual < 1.5 * n.rounding_rms + 0.01e-6);
      if (d <= 4) REQUIRE(n.median_residual > 0.5 * n.rounding_rms);
    }
}

TEST_CASE("noise added to an exact profile printed with 6 decimals makes it measured", "[noise]") {
  // 5 µm normal noise on z: far above the rounding (0.0003 µm) and the 0.2 µm floor.
  const Profile p = make_standard_profile("S1002");
  const NoiseDecision n = classify(write_fixed(p, 6, "S1002_noisy.dat", 5e-3), ProfileKind::Wheel);
  CAPTURE(n.reason);
  REQUIRE(n.measured);
  REQUIRE(n.median_residual > 1e-6);
}

TEST_CASE("scatter as large as the rounding makes a profile printed with 3 decimals measured", "[noise]") {
  // Rounding to 0.001 mm alone: σ ≈ q/√12 = 0.29 µm. Normal noise of 0.6 µm on z (σ about
  // 0.67 µm with the rounding) is scatter beyond the rounding larger than the rounding: measured
  // (the allowance σ > √2 q/√12 = 0.41 µm; the former r > 3 q/√12 = 0.87 µm classed it exact, and
  // its pressures then went unsmoothed: up to 40 % off, profiles.md §7). 0.15 µm of noise
  // (σ about 0.33 µm) is within the allowance: exact.
  const Profile p = make_standard_profile("S1002");
  const NoiseDecision a = classify(write_fixed(p, 3, "S1002_3_noise06.dat", 0.6e-3), ProfileKind::Wheel);
  CAPTURE(a.reason, a.sigma, a.median_residual, a.threshold);
  CHECK(a.measured);
  CHECK(a.sigma > 0.55e-6);
  CHECK(a.sigma < 0.80e-6);
  const NoiseDecision b = classify(write_fixed(p, 3, "S1002_3_noise015.dat", 0.15e-3), ProfileKind::Wheel);
  CAPTURE(b.reason, b.sigma);
  CHECK_FALSE(b.measured);
}

TEST_CASE("a profile printed to 0.01 mm is measured: its rounding is noise to the narrow window", "[noise]") {
  // Rounding RMS 2.9 µm exceeds max_exact_rounding (0.5 µm): no quantisation allowance.
  const NoiseDecision n = classify(write_fixed(make_standard_profile("S1002"), 2, "S1002_2.dat"), ProfileKind::Wheel);
  CAPTURE(n.reason);
  REQUIRE(n.measured);
}

TEST_CASE("the measured files of tests/data/profiles stay measured", "[noise]") {
  // MiniProf measurements (tests/data/profiles/README.md): residuals 1.5, 2.5 and 2.6 µm.
  for (const auto& [f, kind] : {std::pair<const char*, ProfileKind>{"avg_HR.BAN", ProfileKind::Rail},
                                {"avg_low2.ban", ProfileKind::Rail}, {"avg_wheel.whl", ProfileKind::Wheel}}) {
    const NoiseDecision n = classify(kData + f, kind);
    CAPTURE(f, n.reason);
    REQUIRE(n.measured);
  }
  // The exact files stay exact (the Manchester benchmark's, the EN 15302 reference profiles).
  for (const auto& [f, kind] : {std::pair<const char*, ProfileKind>{"MBench_S1002_v3.prw", ProfileKind::Wheel},
                                {"MBench_UIC60_v3.prr", ProfileKind::Rail}, {"EN15302_wheel_A.dat", ProfileKind::Wheel},
                                {"EN15302_rail_A.dat", ProfileKind::Rail}}) {
    const NoiseDecision n = classify(kData + f, kind);
    CAPTURE(f, n.reason);
    REQUIRE_FALSE(n.measured);
  }
}

TEST_CASE("the noise option forces exact or measured", "[noise]") {
  const std::string exact = write_fixed(make_standard_profile("S1002"), 6, "S1002_forced.dat");
  const NoiseDecision m = classify(exact, ProfileKind::Wheel, ProfileNoise::Measured);
  REQUIRE(m.measured);
  REQUIRE(m.forced);
  const NoiseDecision e = classify(kData + "avg_HR.BAN", ProfileKind::Rail, ProfileNoise::Exact);
  REQUIRE_FALSE(e.measured);
  REQUIRE(e.forced);
  REQUIRE(parse_profile_noise("auto") == ProfileNoise::Auto);
  REQUIRE_THROWS_AS(parse_profile_noise("noisy"), std::invalid_argument);
}

TEST_CASE("printed steps are read from the number tokens", "[noise]") {
  // The readers record the smallest printed step (the most decimals) in mm, scaled to metres.
  ProfileReadOptions o;
  o.kind = ProfileKind::Rail;
  REQUIRE(read_profile(kData + "avg_HR.BAN", o).print_step == Approx(1e-7));        // 4 decimals
  REQUIRE(read_profile(kData + "flat_plane.prr").print_step == Approx(1e-4));        // 0.1 mm
  REQUIRE(make_standard_profile("S1002").print_step == 0);                            // generated
}

TEST_CASE("messages give a print step as a person writes it (issue 38)", "[noise][messages]") {
  // 4 decimals: "0.0001 mm", not "1e-04 mm"; 17 significant digits: "full precision", not "1e-17 mm".
  const NoiseDecision four = classify(write_fixed(make_standard_profile("S1002"), 4, "S1002_4.dat"), ProfileKind::Wheel);
  CAPTURE(four.reason);
  CHECK_THAT(four.reason, Catch::Contains("the printed 0.0001 mm"));
  CHECK_THAT(four.reason, !Catch::Contains("e-0"));
  const NoiseDecision two = classify(write_fixed(make_standard_profile("S1002"), 2, "S1002_2m.dat"), ProfileKind::Wheel);
  CHECK_THAT(two.reason, Catch::Contains("printed to 0.01 mm"));
}
