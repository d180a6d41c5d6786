// Issue #22 §1–2: field-like files of tests/data/field/ (make.sh there says how each was made
// from the standard profiles): what the reader makes of each, against the true surface.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "profile/read.hpp"
#include "profile/standard_profiles.hpp"

namespace {

const std::string kF = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/field/";

std::string error_of(const std::string& path, const mh::ProfileReadOptions& opt = {}) {
  try {
    mh::read_profile(path, opt);
  } catch (const mh::InputError& e) {
    return e.what();
  }
  return "";
}

bool has_warning(const mh::Profile& p, const std::string& part) {
  for (const auto& w : p.warnings)
    if (w.find(part) != std::string::npos) return true;
  return false;
}

/// Largest |z − z_S1002(y)| [mm] over ylo … yhi [mm].
double dev_from_s1002_mm(const mh::Profile& p, double ylo, double yhi) {
  const mh::Profile ref = mh::make_standard_profile("S1002", mh::Inclination::None, 0.1e-3);
  double d = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (p.y[k] * 1e3 < ylo || p.y[k] * 1e3 > yhi) continue;
    std::size_t j = 1;
    while (j + 1 < ref.size() && ref.y[j] < p.y[k]) ++j;
    const double t = (p.y[k] - ref.y[j - 1]) / (ref.y[j] - ref.y[j - 1]);
    d = std::max(d, std::abs(p.z[k] - (ref.z[j - 1] + t * (ref.z[j] - ref.z[j - 1]))) * 1e3);
  }
  return d;
}

}  // namespace

TEST_CASE("old MiniProf wheel with a loop at the flange tip: the loop cleaned where it is, the flange back kept", "[field]") {
  // Before: the "not monotone in y" rule clipped the 260 points of the flange back, the taping
  // line was never found, and the wheel kept y = 0 at its flange back (placed 70 mm off).
  const mh::Profile w = mh::read_profile(kF + "old_wheel_loop.whl");
  REQUIRE(w.kind == mh::ProfileKind::Wheel);
  CHECK(w.y.front() * 1e3 == Approx(-70.0).margin(1e-9));  // first row "0.00 ...": the flange back
  const mh::WheelLandmarks L = mh::wheel_landmarks(w);
  CHECK(L.y_tip * 1e3 == Approx(-55.0).margin(0.35));      // S1002 tip, printed to 0.01 mm (a flat of 0.6 mm)
  CHECK(L.z_tip * 1e3 == Approx(-28.0).margin(0.006));
  CHECK(w.cleanup.folds == 1);
  CHECK(w.cleanup.largest_fold_mm == Approx(0.6).margin(0.011));
  CHECK(has_warning(w, "clean-up extended over"));
  CHECK_FALSE(has_warning(w, "not monotone in y at the flange back"));
  CHECK(has_warning(w, "not monotone in y at the field-side end"));  // the rim face, clipped as before
  CHECK_FALSE(w.taping_line.empty());
  // The surface is S1002 to the rounding of the printed 0.01 mm (0.02 mm on the 70° flange face),
  // the loop's points (0.05 mm and 0.15 mm inside) gone (beyond 1 mm from the
  // back face, where it turns vertical and a 0.01 mm step in y moves z by 0.1 mm).
  CHECK(dev_from_s1002_mm(w, -69, 60) < 0.02);
  const mh::WheelMeasures M = mh::wheel_measures(w);
  REQUIRE(M.valid);
  CHECK(M.Sd * 1e3 == Approx(32.5).margin(0.02));
  CHECK(M.Sh * 1e3 == Approx(28.0).margin(0.02));
  CHECK(M.qR * 1e3 == Approx(10.8).margin(0.02));
  // strict clean-up refuses the loop (no silent clipping of the flange back either)
  mh::ProfileReadOptions strict;
  strict.cleanup = mh::ProfileCleanup::Strict;
  const std::string e = error_of(kF + "old_wheel_loop.whl", strict);
  CHECK(e.find("old_wheel_loop.whl:2") != std::string::npos);
  CHECK(e.find("y steps backward") != std::string::npos);
}
