// Field-like files of tests/data/field/ (make.sh there says how each was made
// from the standard profiles): what the reader makes of each, against the true surface.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "profile/read.hpp"
#include "profile/standard_profiles.hpp"
#include "support/input_errors.hpp"

namespace {

const std::string kF = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/field/";

std::string error_of(const std::string& path, const mh::ProfileReadOptions& opt = {}) {
  return mh::testing::profile_error(path, opt);
}

bool has_warning(const mh::Profile& p, const std::string& part) { return mh::testing::has_warning(p.warnings, part); }

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

TEST_CASE("Key=Value MiniProf rail with stray MPDC=/MPDN= keys: its points are read", "[field]") {
  // Before: "MiniProf drawing-element file without MPD<k>= elements" (or a number error on the
  // empty MPDC=), no line, no fix. Drawing elements count only when MPD<k>= elements are there.
  const mh::Profile r = mh::read_profile(kF + "kv_rail_stray_mpd.ban");
  REQUIRE(r.kind == mh::ProfileKind::Rail);
  CHECK(r.size() == 979);  // XYPoints=979, five columns X,Y,A,C,K
  CHECK(r.warnings.empty());
  const mh::Profile ref = mh::make_standard_profile("60E1", mh::Inclination::In40, 0.1e-3);
  const mh::RailLandmarks a = mh::rail_landmarks(r), b = mh::rail_landmarks(ref);
  CHECK(a.y_gauge * 1e3 == Approx(b.y_gauge * 1e3).margin(1e-3));
  CHECK(a.z_top * 1e3 == Approx(b.z_top * 1e3).margin(1e-4));
}

TEST_CASE("Key=Value MiniProf wheel: Sd, Sh, qR of the header are the file's measures", "[field]") {
  const mh::Profile w = mh::read_profile(kF + "kv_wheel_measures.whl");
  REQUIRE(w.kind == mh::ProfileKind::Wheel);
  REQUIRE(w.file_measures.size() == 3);
  CHECK(w.file_measures[0] == std::make_pair(std::string("Sd"), std::string("32.50")));
  CHECK(w.file_measures[1] == std::make_pair(std::string("Sh"), std::string("28.00")));
  CHECK(w.file_measures[2] == std::make_pair(std::string("qR"), std::string("10.80")));
  const mh::WheelMeasures M = mh::wheel_measures(w);  // and the profile agrees with them
  CHECK(M.Sd * 1e3 == Approx(32.5).margin(0.01));
  CHECK(M.Sh * 1e3 == Approx(28.0).margin(0.01));
}

TEST_CASE("multi-profile MiniProf file (.mpt): refused without a choice, each section read as asked", "[field]") {
  const std::string f = kF + "multi_profile.mpt";
  // Before: the first profile (a base line under the foot) was taken with a warning.
  const std::string e = error_of(f);
  CAPTURE(e);
  for (const char* part : {"2 of its profiles can be a wheel or a rail", "1 'Base line' 150 mm wide, 1501 points sampled",
                           "2 'Head measured' 72.55 mm wide, 979 points;", "3 'Head new (drawing)' 66 mm wide",
                           "\"section\": K", "--section K"})
    CHECK(e.find(part) != std::string::npos);
  mh::ProfileReadOptions o;
  o.section = 2;  // the measured head: its [Profile2Points] rows, not its two drawing elements
  const mh::Profile p2 = mh::read_profile(f, o);
  CHECK(p2.kind == mh::ProfileKind::Rail);
  CHECK(p2.size() == 979);
  CHECK(has_warning(p2, "read profile 2 'Head measured' (section 2 as asked"));
  CHECK(has_warning(p2, "its [Profile2Points] rows read, its 2 drawing elements not used"));
  const mh::Profile ban = mh::read_profile(kF + "kv_rail_stray_mpd.ban");
  REQUIRE(ban.size() == p2.size());
  for (std::size_t k = 0; k < ban.size(); ++k) REQUIRE(std::abs(ban.z[k] - p2.z[k]) < 1e-12);
  o.section = 3;  // the drawing: sampled elements
  const mh::Profile p3 = mh::read_profile(f, o);
  CHECK(has_warning(p3, "sampled 5 drawing elements of [Profile3Info]"));
  o.section = 7;
  CHECK(error_of(f, o).find("holds no profile 7 ([Profile7Info]); it holds 3: 1 'Base line'") != std::string::npos);
  // A section for a file of one profile is a mistake, said as such.
  CHECK(error_of(kF + "kv_rail_stray_mpd.ban", o).find("drop \"section\"") != std::string::npos);
  CHECK(error_of(kF + "worn_rail_1-40.csv", o).find("only to multi-profile MiniProf files") != std::string::npos);
}

TEST_CASE("multi-profile file whose only rail-like profile is not the first: that one is read", "[field]") {
  // The base line and the measured head of multi_profile.mpt only (the drawing dropped).
  const std::string path = "/tmp/mhcontact_field_two_" + std::to_string(::getpid()) + ".mpt";
  {
    std::ifstream in(kF + "multi_profile.mpt");
    std::ofstream out(path);
    std::string l;
    bool skip = false;
    while (std::getline(in, l)) {
      if (l.rfind("[Profile", 0) == 0) skip = l == "[Profile3Info]";
      if (!skip) out << l << "\n";
    }
  }
  const mh::Profile p = mh::read_profile(path);
  std::remove(path.c_str());
  CHECK(p.kind == mh::ProfileKind::Rail);
  CHECK(p.size() == 979);
  CHECK(has_warning(p, "read profile 2 'Head measured' (the only one of 2 that can be a wheel or a rail"));
}

TEST_CASE("every MiniProf reader error names the line and the fix", "[field]") {
  // Table: file text, the location expected ("<file>:<line>"), a part of the rule, a part of the fix.
  struct Row { const char* ext; const char* text; int line; const char* rule; const char* fix; };
  const Row rows[] = {
      {"ban", "Filename=x\nColumnDef=X,Y\n1 2\n3 4\n", 4, "without the empty line", "must end with an empty line"},
      {"ban", "Filename=x\nXYPoints=2\n\n1 2\n3 4\n", 3, "without ColumnDef", "add e.g. ColumnDef=X,Y"},
      {"ban", "XYPoints=5\nColumnDef=X,Y\n\n1 2\n3 4\n", 1, "only 2 data rows", "correct XYPoints"},
      {"ban", "ColumnDef=X,Y\n\n1 2\n3 x4\n", 4, "not a number", "numbers only"},
      {"ban", "[Profile1Info]\nMPDC=3\n", 2, "no element MPD<k>= found", "add the elements"},
      {"ban", "MPDC=2\nMPD1=L 0 0 1\n", 2, "a drawing element must be", "correct the element"},
      {"ban", "MPDC=x\nMPD1=L 0 0 1 1\n", 1, "not a number", "numbers only"},
      {"mpt", "[Profile1Info]\nName=a\n[Profile1Points]\n1 2\n3\n", 5, "needs X and Y", "X Y [more columns]"},
      {"mpt", "[Profile1Info]\nName=a\nXYPoints=4\n[Profile1Points]\n1 2\n3 4\n", 3, "only 2 rows", "correct XYPoints"},
      {"whl", "#MINIWHEELPROF\nw\n32.5 28.0  (Sd/Sh/qR)\n\n1 2\n", 3, "holds 2 numbers for 3 names", "one number per name"},
      {"whl", "#MINIWHEELPROF\nw\nMINIPROF 2004\n", 3, "without the empty line", "must end with an empty line"},
  };
  int k = 0;
  for (const Row& r : rows) {
    const std::string path = "/tmp/mhcontact_field_err_" + std::to_string(::getpid()) + "_" + std::to_string(k++) + "." + r.ext;
    std::ofstream(path) << r.text;
    const std::string e = error_of(path);
    std::remove(path.c_str());
    CAPTURE(r.text, e);
    CHECK(e.find(path + ":" + std::to_string(r.line) + ":") == 0);
    CHECK(e.find(r.rule) != std::string::npos);
    CHECK(e.find(r.fix) != std::string::npos);
  }
}
