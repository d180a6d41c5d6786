// MiniProf styles, clean-up of folds and loops, spreadsheet files and encodings, on the
// constructed files of tests/data/profiles/constructed/ (make.sh there says how they were made).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "profile/read.hpp"
#include "profile/standard_profiles.hpp"
#include "support/input_errors.hpp"

namespace {

const std::string kC = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/profiles/constructed/";

std::string error_of(const std::string& path, const mh::ProfileReadOptions& opt = {}) {
  return mh::testing::profile_error(path, opt);
}

/// Largest |z − z_ref(y)| [mm] of a profile against a standard one (linear interpolation);
/// sign > 0: only deviations above the reference count, < 0: only below.
double max_dev_mm(const mh::Profile& p, const mh::Profile& ref, double ylo, double yhi, int sign = 0) {
  double d = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (p.y[k] * 1e3 < ylo || p.y[k] * 1e3 > yhi) continue;  // ylo, yhi in mm
    std::size_t j = 1;
    while (j + 1 < ref.size() && ref.y[j] < p.y[k]) ++j;
    const double t = (p.y[k] - ref.y[j - 1]) / (ref.y[j] - ref.y[j - 1]);
    const double dz = (p.z[k] - (ref.z[j - 1] + t * (ref.z[j] - ref.z[j - 1]))) * 1e3;
    d = std::max(d, sign > 0 ? dz : sign < 0 ? -dz : std::abs(dz));
  }
  return d;
}

}  // namespace

TEST_CASE("MiniProf old wheel style is recognised by its content and its measures read", "[profile][miniprof]") {
  const mh::Profile p = mh::read_profile(kC + "old_style_wheel.whl");
  CHECK(p.kind == mh::ProfileKind::Wheel);
  CHECK(p.format == "miniprof");
  bool sd = false, sh = false, qr = false, axle = false;
  for (const auto& kv : p.file_measures) {
    sd |= kv.first == "Sd" && kv.second == "32.50";
    sh |= kv.first == "Sh" && kv.second == "28.00";
    qr |= kv.first == "qR" && kv.second == "10.80";
    axle |= kv.first == "Axle Number" && kv.second == "2";
  }
  CHECK(sd);
  CHECK(sh);
  CHECK(qr);
  CHECK(axle);
  // The S1002 it was made from (3 decimals): flange tip at y = -55, z = -28 after the taping-line rule.
  const mh::Profile s = mh::make_standard_profile("S1002");
  CHECK(max_dev_mm(p, s, -69, 59) < 0.002);
  // Without the .whl extension the first line says it is a wheel.
  mh::ProfileReadOptions o;
  o.format = mh::ProfileFormat::MiniProf;
  CHECK(mh::read_profile(kC + "old_style_wheel.whl", o).kind == mh::ProfileKind::Wheel);
}

TEST_CASE("MiniProf drawing elements are sampled, arcs exactly, and gaps reported", "[profile][miniprof]") {
  const mh::Profile p = mh::read_profile(kC + "elements_rail.ban");
  CHECK(p.kind == mh::ProfileKind::Rail);
  // The crown arc: centre (0, -298.333) in canonical axes (y = -X, z = -Y), R = 300.
  std::size_t on_crown = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const double y = p.y[k] * 1e3, z = p.z[k] * 1e3;
    if (std::abs(y) < 19.9) {
      CHECK(std::hypot(y, z + 298.333333) == Approx(300.0).margin(2e-5));
      ++on_crown;
    }
    if (y > -32.9 && y < -20.1 && z > -12)  // gauge corner R13, centre (-20, -12)
      CHECK(std::hypot(y + 20, z + 12) == Approx(13.0).margin(1e-6));
  }
  CHECK(on_crown > 390);  // 40 mm of crown at <= 0.1 mm spacing
  for (std::size_t k = 1; k < p.size(); ++k)  // the vertical flanks' points share one y: dropped
    if (std::abs(p.y[k]) < 32.9e-3) CHECK(std::hypot(p.y[k] - p.y[k - 1], p.z[k] - p.z[k - 1]) <= 0.1e-3 + 1e-12);
  const mh::Profile g = mh::read_profile(kC + "elements_gap.ban");
  bool said = false;
  for (const auto& w : g.warnings) said |= w.find("do not join") != std::string::npos && w.find("0.5 mm") != std::string::npos;
  CHECK(said);
}

TEST_CASE("folds and loops are replaced by the outer envelope, with a report", "[profile][cleanup]") {
  mh::ProfileReadOptions o;
  o.kind = mh::ProfileKind::Rail;
  const mh::Profile p = mh::read_profile(kC + "folded_rail.txt", o);
  CHECK(p.cleanup.mode == "envelope");
  CHECK(p.cleanup.folds == 2);
  CHECK(p.cleanup.duplicates == 1);
  CHECK(p.cleanup.largest_fold_mm == Approx(0.3).margin(1e-9));
  CHECK(p.cleanup.y_from_mm < -33);
  for (std::size_t k = 1; k < p.size(); ++k) REQUIRE(p.y[k] > p.y[k - 1]);
  // The envelope keeps the outer surface: nothing of the cleaned profile lies below the 60E1 it
  // was made from by more than the file's 4 decimals; the folds lie outside it by < 0.3 mm.
  const mh::Profile r = mh::make_standard_profile("60E1", mh::Inclination::None, 0.5e-3);
  CHECK(max_dev_mm(p, r, -36, 36, -1) < 1e-3);  // nothing inside the rail
  CHECK(max_dev_mm(p, r, -36, 36, +1) < 0.35);  // the outer fold points stay (outer envelope)
  CHECK(max_dev_mm(p, r, -25, 36) < 1e-3);
  bool warned = false;
  for (const auto& w : p.warnings) warned |= w.find("outer envelope") != std::string::npos && w.find("y -3") != std::string::npos;
  CHECK(warned);
  // strict and off reject the same file, naming the line, the rule and the fix
  o.cleanup = mh::ProfileCleanup::Strict;
  std::string e = error_of(kC + "folded_rail.txt", o);
  CHECK(e.find("folded_rail.txt:") != std::string::npos);
  CHECK(e.find("steps backward") != std::string::npos);
  CHECK(e.find("cleanup \"envelope\"") != std::string::npos);
  o.cleanup = mh::ProfileCleanup::Off;
  CHECK(error_of(kC + "folded_rail.txt", o).find("steps backward") != std::string::npos);
  // a fold deeper than the limit stays rejected
  o.cleanup = mh::ProfileCleanup::Envelope;
  e = error_of(kC + "big_loop_rail.txt", o);
  CHECK(e.find("big_loop_rail.txt:150") != std::string::npos);
  CHECK(e.find("deeper than 1 mm") != std::string::npos);
  // folds over most of the width stay rejected
  e = error_of(kC + "zigzag_rail.txt", o);
  CHECK(e.find("zigzag_rail.txt") != std::string::npos);
  CHECK(e.find("folds over most of the width") != std::string::npos);
}

TEST_CASE("a wheel zig-zag is cleaned with the lower envelope", "[profile][cleanup]") {
  const mh::Profile s = mh::make_standard_profile("S1002", mh::Inclination::None, 0.5e-3);
  std::string t;
  char buf[64];
  for (std::size_t k = 0; k < s.size(); ++k) {
    std::snprintf(buf, sizeof buf, "%.6f %.6f\n", s.y[k] * 1e3, s.z[k] * 1e3);
    t += buf;
    if (k == 200) {  // tread: the scan steps 0.2 mm back, 0.05 mm inside the wheel, and on
      std::snprintf(buf, sizeof buf, "%.6f %.6f\n", s.y[k] * 1e3 - 0.2, s.z[k] * 1e3 + 0.05);
      t += buf;
    }
  }
  const std::string tmp = "/tmp/mh_zigzag_wheel.txt";
  FILE* f = std::fopen(tmp.c_str(), "wb");
  std::fputs(t.c_str(), f);
  std::fclose(f);
  mh::ProfileReadOptions o;
  o.kind = mh::ProfileKind::Wheel;
  const mh::Profile p = mh::read_profile(tmp, o);
  CHECK(p.cleanup.folds == 1);
  CHECK(p.cleanup.fold_points >= 1);
  CHECK(max_dev_mm(p, s, -69, 59) < 1e-5);  // the point inside the wheel is gone
}

TEST_CASE("spreadsheet files: BOM, CRLF, semicolons with decimal commas, tabs", "[profile][table]") {
  mh::ProfileReadOptions o;
  o.kind = mh::ProfileKind::Rail;
  const mh::Profile a = mh::read_profile(kC + "excel_semicolon.csv", o);
  const mh::Profile b = mh::read_profile(kC + "tabs_decimal_comma.txt", o);
  const mh::Profile r = mh::make_standard_profile("60E1", mh::Inclination::None, 0.5e-3);
  REQUIRE(a.size() == r.size());
  REQUIRE(b.size() == r.size());
  for (std::size_t k = 0; k < r.size(); ++k) {
    CHECK(std::abs(a.y[k] - r.y[k]) < 0.51e-7);
    CHECK(std::abs(b.z[k] - r.z[k]) < 0.51e-7);
  }
}

TEST_CASE("UTF-16, gzip and binary files are refused with their type named", "[profile][table]") {
  std::string e = error_of(kC + "utf16.csv");
  CHECK(e.find("UTF-16") != std::string::npos);
  CHECK(e.find("save it as UTF-8") != std::string::npos);
  e = error_of(kC + "gzip.csv");
  CHECK(e.find("gzip") != std::string::npos);
  CHECK(e.find("gunzip") != std::string::npos);
  e = error_of(kC + "nul_bytes.txt");
  CHECK(e.find("binary") != std::string::npos);
  CHECK(e.find("export the profile as text") != std::string::npos);  // not cut at the NUL
  // a message quoting a control byte keeps its rule and fix
  const mh::InputError x("f", std::string("a\0b", 3), "rule", "fix");
  CHECK(std::string(x.what()) == "f: value a\\x00b: rule (fix)");
}
