// The strips' solve on a noisy measured-like gauge corner (issue 32, the `not_converged` rows of
// the seeds measurement at 0.2 and 0.1 mm spacing, docs/profiles.md §7).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>

#include "contact/strips/strip_method.hpp"
#include "input/case_file.hpp"
#include "jobs/run.hpp"
#include "support/constructed_profiles.hpp"

TEST_CASE("diagnosis: the R3-corner rail at 0.2 / 0.1 mm spacing, t_Y 6 mm", "[.notconv_diag]") {
  const mh::CaseFile cf = mh::load_case_file(std::string(MHCONTACT_SOURCE_DIR) + "/cases/s1002-60e1.json", true);
  const mh::PairGeometry base = mh::build_pair_geometry(cf);
  const double cant = std::atan(1.0 / 40);
  for (double step : {0.2e-3, 0.1e-3})
    for (double noise : {3e-6, 1e-6})
      for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        const std::uint64_t s = 7 * seed + 3;
        const mh::Profile rn = mh::testing::worn_corner_rail(3e-3, step, noise, noise > 2e-6 ? 1e-5 : 1e-6, cant, s);
        const mh::ContactGeometry g = mh::build_geometry(base.wheel, rn, cf.track, cf.geometry);
        for (double Q : {40e3, 100e3}) {
          const mh::CaseResult a = mh::solve_strip_method(g, cf.material, 6e-3, Q, cf.strips);
          std::string warnings;
          for (const mh::Warning& w : a.warnings) warnings += " " + mh::warning_text(w);
          std::printf("step %.1f noise %.0f seed %d Q %.0f: %s pmax %.1f iters %d msg: %s; warnings:%s\n", step * 1e3,
                      noise * 1e6, static_cast<int>(s), Q / 1e3, mh::to_string(a.status), a.pmax / 1e6, a.iterations,
                      a.message.c_str(), warnings.c_str());
        }
      }
}
