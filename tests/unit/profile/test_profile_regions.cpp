// Measured or exact region by region (profile/print_regions.hpp, curve.hpp NoiseDecision::regions,
// profiles.md §7 "Region by region"): a stitched file printed partly to 17 digits and partly to
// 4 decimals is split where its printed precision changes, and each region is classed by its
// own fits. References: the files' own printing (the regions are where the test printed them)
// and the exact constructed profile (tests/support/constructed_profiles.hpp) for the curve.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "contact/strips/strip_method.hpp"
#include "input/case_file.hpp"
#include "jobs/run.hpp"
#include "profile/curve.hpp"
#include "profile/print_regions.hpp"
#include "profile/read.hpp"
#include "profile/standard_profiles.hpp"
#include "support/constructed_profiles.hpp"

using namespace mh;

namespace {

const std::string kData = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/profiles/";

// Write a plain table "y z" in mm: the points where `fine(y)` holds to 17 significant digits,
// the others to `decimals` decimals (trailing zeros dropped when `trim`, as some writers do).
template <class Fine>
std::string write_stitched(const Profile& p, Fine fine, int decimals, bool trim, const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "mhcontact_test_regions";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream f(path);
  char a[64], b[64];
  auto print = [&](char* buf, double v, bool full) {
    if (full) {
      std::snprintf(buf, 64, "%.17g", v);
      return;
    }
    std::snprintf(buf, 64, "%.*f", decimals, v);
    if (trim) {
      std::string s(buf);
      while (s.back() == '0') s.pop_back();
      if (s.back() == '.') s.pop_back();
      std::snprintf(buf, 64, "%s", s.c_str());
    }
  };
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool full = fine(p.y[i]);
    print(a, p.y[i] * 1e3, full);
    print(b, p.z[i] * 1e3, full);
    f << a << ' ' << b << '\n';
  }
  return path;
}

Profile read_wheel(const std::string& path) {
  ProfileReadOptions o;
  o.kind = ProfileKind::Wheel;
  return read_profile(path, o);
}

// The stitched hollow-worn S1002 (shoulders over 3 mm, radius 3.1 mm): the shoulders' points,
// wheel y in [−24, −9] and [6, 21] mm, exact and printed to 17 digits; the rest sampled with
// ±3 µm scatter normal to the profile and printed to 4 decimals.
bool in_shoulder(double y) { return (y > -24e-3 && y < -9e-3) || (y > 6e-3 && y < 21e-3); }
Profile stitched_hollow() {
  const Profile exact = testing::hollow_wheel(0.4e-3, 0, 0, 0.5e-3, -15e-3, 12e-3, 3e-3);
  Profile noisy = testing::hollow_wheel(0.4e-3, 3e-6, 0, 0.5e-3, -15e-3, 12e-3, 3e-3);
  // The noisy copy has the exact copy's points where the shoulders are (same sampling; the
  // scatter moved its y, so take the exact points in those ranges and the noisy ones elsewhere).
  Profile s;
  for (std::size_t i = 0; i < noisy.size(); ++i)
    if (!in_shoulder(noisy.y[i])) s.y.push_back(noisy.y[i]), s.z.push_back(noisy.z[i]);
  for (std::size_t i = 0; i < exact.size(); ++i)
    if (in_shoulder(exact.y[i])) s.y.push_back(exact.y[i]), s.z.push_back(exact.z[i]);
  std::vector<std::size_t> order(s.y.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s.y[a] < s.y[b]; });
  Profile out;
  out.kind = ProfileKind::Wheel;
  for (std::size_t i : order)
    if (out.y.empty() || s.y[i] > out.y.back() + 1e-6) out.y.push_back(s.y[i]), out.z.push_back(s.z[i]);
  return read_wheel(write_stitched(out, in_shoulder, 4, false, "stitched_hollow.dat"));
}

}  // namespace

TEST_CASE("printed precision per point: a stitched file has regions, one printing has one", "[noise][regions]") {
  const Profile s1002 = make_standard_profile("S1002", Inclination::None, 0.4e-3);
  const auto flange = [](double y) { return y < -20e-3; };
  {
    const Profile p = read_wheel(write_stitched(s1002, flange, 4, false, "stitched.dat"));
    REQUIRE(p.point_step.size() == p.size());
    const std::vector<PrintRegion> r = print_regions(p);
    REQUIRE(r.size() == 2);
    // The boundary is where the printing changes: the last 17-digit point and the first
    // 4-decimal one.
    CHECK(p.y[r[0].last] < -20e-3);
    CHECK(p.y[r[1].first] >= -20e-3);
    CHECK(r[1].first == r[0].last + 1);
    CHECK(r[0].step == 1e-9);                        // [m] 17 digits: full precision
    CHECK(r[1].step == Approx(1e-7).epsilon(1e-9));  // [m] 1e-4 mm
  }
  // Trailing zeros dropped (one token in ten prints 3 decimals or fewer): still one region.
  for (bool trim : {false, true}) {
    const Profile p = read_wheel(write_stitched(s1002, [](double) { return false; }, 4, trim, "plain.dat"));
    CAPTURE(trim);
    CHECK(print_regions(p).size() == 1);
  }
  // The EN 15302 rail table (printed with 0 to 4 decimals: zeros dropped) and a SIMPACK file.
  ProfileReadOptions ro;
  ro.kind = ProfileKind::Rail;
  CHECK(print_regions(read_profile(kData + "EN15302_rail_A.dat", ro)).size() == 1);
  CHECK(print_regions(read_profile(kData + "MBench_UIC60_v3.prr")).size() == 1);
  // Generated profiles carry no printed steps: one region.
  CHECK(print_regions(s1002).size() == 1);
}

TEST_CASE("a stitched hollow wheel: each region classed by its own noise, the shoulders fitted narrow", "[noise][regions]") {
  const Profile p = stitched_hollow();
  const ProfileCurve c(p, {});
  const NoiseDecision& d = c.noise();
  CAPTURE(d.reason);
  REQUIRE(d.mixed());
  CHECK(d.measured);
  REQUIRE(d.regions.size() == 5);
  for (std::size_t r = 0; r < 5; ++r) CHECK(d.regions[r].measured == (r % 2 == 0));
  // The measured regions' noise: ±3 µm uniform (1.73 µm RMS), rounding 0.03 µm.
  CHECK(d.sigma > 1.5e-6);
  CHECK(d.sigma < 2.4e-6);
  CHECK(std::string(d.class_name()) == "mixed");
  // At the shoulders the curve is the narrow window's fit of the exact points: against the
  // exact profile's own narrow fit (the same points), measured within 19 1/m, 6 % of the
  // shoulder's largest curvature (1/3.1 mm: the fit's frame follows the nodes before, which
  // differ); the whole file taken as measured (the wide window) 222 1/m. Tolerances 29 1/m
  // (9 %) and beyond 50 %.
  const Profile exact = testing::hollow_wheel(0.4e-3, 0, 0, 0.5e-3, -15e-3, 12e-3, 3e-3);
  CurveOptions exact_opt;
  exact_opt.noise = ProfileNoise::Exact;
  const ProfileCurve e(exact, exact_opt);
  CurveOptions measured_opt;
  measured_opt.noise = ProfileNoise::Measured;
  const ProfileCurve m(p, measured_opt);  // the whole file measured: the wide window everywhere
  double worst = 0, worst_wide = 0, y_worst = 0;
  for (double y = -21e-3; y <= -12e-3; y += 0.05e-3) {
    if (std::fabs(c.kappa(y) - e.kappa(y)) > worst) y_worst = y;
    worst = std::max(worst, std::fabs(c.kappa(y) - e.kappa(y)));
    worst_wide = std::max(worst_wide, std::fabs(m.kappa(y) - e.kappa(y)));
  }
  INFO("worst at y " << y_worst * 1e3 << " mm: by region " << c.kappa(y_worst) << ", exact " << e.kappa(y_worst) << " 1/m");
  INFO("largest curvature error at the left shoulder: by region " << worst << " 1/m, the whole file measured " << worst_wide << " 1/m");
  CHECK(worst < 0.09 / 3.1e-3);
  CHECK(worst_wide > 0.5 / 3.1e-3);
  // The smoothing for contact keeps the exact regions' points: the spline passes within 0.1 µm
  // of them, and moves the measured points by about their noise.
  const std::optional<SmoothedProfile> sp = smooth_for_contact(p, d, std::nullopt);
  REQUIRE(sp.has_value());
  double moved_exact = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (d.exact_at(p.y[i])) moved_exact = std::max(moved_exact, std::hypot(p.y[i] - sp->y.values()[i], p.z[i] - sp->z.values()[i]));
  CHECK(moved_exact < 1e-7);  // [m]
  CHECK(sp->rms_change > 0.5e-6);
}

TEST_CASE("a profile printed to one precision is classed as a whole, as before", "[noise][regions]") {
  // One class in every region (a stitched file whose parts are both exact): no regions, the
  // whole-profile decision.
  const Profile s1002 = make_standard_profile("S1002", Inclination::None, 0.4e-3);
  const Profile p = read_wheel(write_stitched(s1002, [](double y) { return y < -20e-3; }, 4, false, "stitched_exact.dat"));
  const ProfileCurve c(p, {});
  CHECK_FALSE(c.noise().mixed());
  CHECK_FALSE(c.noise().measured);
  // Forced, the regions are not looked at.
  CurveOptions forced;
  forced.noise = ProfileNoise::Exact;
  CHECK_FALSE(ProfileCurve(stitched_hollow(), forced).noise().mixed());
}

TEST_CASE("a stitched hollow wheel: the strips' pressure on its exact shoulders is the exact profile's", "[noise][regions][strips]") {
  // Reference: the exact constructed wheel, dense (0.05 mm) and fitted narrow (0.25 mm window),
  // on the same rail, by the same method. The contacts at these t_Y lie on the shoulders, the
  // file's exact regions. Measured: by region within 2.9 % of the exact profile's peak pressure
  // (each row in the INFO lines); the whole file taken as measured (what one class per file
  // gives) up to 11.5 % low (the spline removes the shoulders' curvature with the noise).
  // Tolerances 4.5 % and beyond 8 %.
  const CaseFile cf = load_case_file(std::string(MHCONTACT_SOURCE_DIR) + "/cases/s1002-60e1.json", true);
  const PairGeometry base = build_pair_geometry(cf);
  const Profile exact = testing::hollow_wheel(0.05e-3, 0, 0, 0.5e-3, -15e-3, 12e-3, 3e-3);
  const Profile stitched = stitched_hollow();
  GeometryOptions exact_opt = cf.geometry;
  exact_opt.curve.window_half_width = 0.25e-3;
  exact_opt.wheel_noise = exact_opt.rail_noise = ProfileNoise::Exact;
  const ContactGeometry ref = build_geometry(exact, base.rail, cf.track, exact_opt);
  const ContactGeometry by_region = build_geometry(stitched, base.rail, cf.track, cf.geometry);
  GeometryOptions whole = cf.geometry;
  whole.wheel_noise = ProfileNoise::Measured;
  const ContactGeometry as_measured = build_geometry(stitched, base.rail, cf.track, whole);
  REQUIRE(by_region.wheel_curve->noise().mixed());
  double worst = 0, worst_whole = 0;
  for (double tY : {-4.0, 2.0, 4.0})
    for (double Q : {40e3, 100e3}) {
      const CaseResult r = solve_strip_method(ref, cf.material, tY * 1e-3, Q, cf.strips);
      const CaseResult a = solve_strip_method(by_region, cf.material, tY * 1e-3, Q, cf.strips);
      const CaseResult w = solve_strip_method(as_measured, cf.material, tY * 1e-3, Q, cf.strips);
      INFO("t_Y = " << tY << " mm, Q = " << Q / 1e3 << " kN: exact " << r.pmax / 1e6 << " MPa, by region " << a.pmax / 1e6
                    << ", whole file measured " << w.pmax / 1e6 << "; patches at wheel y "
                    << (r.patches.empty() ? 0.0 : r.patches.front().y_w * 1e3) << " … "
                    << (r.patches.empty() ? 0.0 : r.patches.back().y_w * 1e3) << " mm");
      REQUIRE(r.status == CaseStatus::Ok);
      REQUIRE(a.status == CaseStatus::Ok);
      CHECK(a.pmax == Approx(r.pmax).epsilon(0.045));
      worst = std::max(worst, std::fabs(a.pmax / r.pmax - 1));
      worst_whole = std::max(worst_whole, std::fabs(w.pmax / r.pmax - 1));
    }
  INFO("by region worst " << 100 * worst << " %; whole file measured worst " << 100 * worst_whole << " %");
  CHECK(worst < 0.045);
  CHECK(worst_whole > 0.08);
}
