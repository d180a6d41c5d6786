// Profile readers, writers and checks on the real files of tests/data/profiles (copies of
// CONTACT and A_WRCC files, provenance in tests/data/profiles/README.md) and on malformed inputs.
// Tolerances are in mm (profile files are in mm; Profile holds metres).
#include <catch2/catch.hpp>
#include <filesystem>
#include <stdexcept>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "core/checksum.hpp"
#include "cli.hpp"
#include "core/errors.hpp"
#include "output/profile_file.hpp"
#include "profile/read.hpp"
#include "profile/standard_profiles.hpp"

namespace {

const std::string kData = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/profiles/";

// One scratch directory per test process, removed when the process exits.
struct ScratchDir {
  std::string dir;
  ScratchDir() {
    char t[] = "/tmp/mh_profio_XXXXXX";
    if (mkdtemp(t) == nullptr) throw std::runtime_error("cannot create a scratch directory in /tmp");
    dir = t;
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
};

std::string tmpdir() {
  static const ScratchDir d;
  return d.dir + "/";
}

std::string write_file(const std::string& name, const std::string& text) {
  const std::string p = tmpdir() + name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

/// A table "y z" in mm from canonical points (metres), optionally transformed.
std::string table_text(const mh::Profile& p, double fy = 1, double fz = 1, double unit = 1e3) {
  std::ostringstream s;
  s.precision(17);
  for (std::size_t k = 0; k < p.size(); ++k) s << fy * p.y[k] * unit << " " << fz * p.z[k] * unit << "\n";
  return s.str();
}

/// Linear interpolation of z [mm] at y [mm].
double z_at(const mh::Profile& p, double y_mm) {
  const double y = y_mm * 1e-3;
  for (std::size_t k = 1; k < p.size(); ++k)
    if (p.y[k] >= y) {
      const double t = (y - p.y[k - 1]) / (p.y[k] - p.y[k - 1]);
      return 1e3 * (p.z[k - 1] + t * (p.z[k] - p.z[k - 1]));
    }
  return NAN;
}

double max_diff_mm(const mh::Profile& a, const mh::Profile& b) {
  REQUIRE(a.size() == b.size());
  double d = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    d = std::max({d, std::abs(a.y[k] - b.y[k]) * 1e3, std::abs(a.z[k] - b.z[k]) * 1e3});
  return d;
}

bool strictly_increasing(const mh::Profile& p) {
  for (std::size_t k = 1; k < p.size(); ++k)
    if (!(p.y[k] > p.y[k - 1])) return false;
  return true;
}

/// Read must throw InputError whose message holds every key word.
void require_error(const std::string& path, const std::vector<std::string>& words,
                   const mh::ProfileReadOptions& opt = {}) {
  INFO("file " << path);
  try {
    mh::read_profile(path, opt);
    FAIL("no error for " << path);
  } catch (const mh::InputError& e) {
    const std::string msg = e.what();
    INFO("message: " << msg);
    CHECK(msg.find(path) != std::string::npos);  // names the file
    for (const auto& w : words) CHECK(msg.find(w) != std::string::npos);
  }
}

std::string simpack(int type, const std::string& points, const std::string& extra = "") {
  return "header.begin\n  type = " + std::to_string(type) + "\nheader.end\nspline.begin\n" + extra +
         "  units.len.f = 1000.\n  point.begin\n" + points + "  point.end\nspline.end\n";
}

std::string circle_points(double R, int n, double sign) {  // SIMPACK z down; sign +1 rail-like
  std::ostringstream s;
  for (int i = 0; i <= n; ++i) {
    const double y = -0.9 * R + 1.8 * R * i / n;
    s << y << " " << sign * (R - std::sqrt(R * R - y * y)) << "\n";
  }
  return s.str();
}

}  // namespace

TEST_CASE("sha256 of known vectors and of a file", "[profile_io][checksum]") {
  // FIPS 180-4 examples (NIST CSRC "SHA256.pdf").
  CHECK(mh::sha256_hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(mh::sha256_hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(mh::sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  CHECK(mh::sha256_hex(std::string(1000000, 'a')) ==
        "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  const std::string p = write_file("abc.txt", "abc");
  CHECK(mh::sha256_file(p) == mh::sha256_hex("abc"));
  CHECK_THROWS_AS(mh::sha256_file(tmpdir() + "missing"), mh::InputError);
}

TEST_CASE("every shipped profile file reads or is rejected with its reason", "[profile_io]") {
  struct Row { const char* file; mh::ProfileKind kind; std::size_t points; const char* error; };
  using K = mh::ProfileKind;
  // points: after cleaning (counted from the files: point rows minus clipped/commented ones).
  const Row rows[] = {
      {"MBench_S1002_v3.prw", K::Wheel, 399, nullptr},
      {"MBench_UIC60_v3.prr", K::Rail, 495, nullptr},
      {"MBench_UIC60_v3.ban", K::Rail, 495, nullptr},
      {"circ_r10.prw", K::Wheel, 199, nullptr},
      {"circ_r50.prw", K::Wheel, 999, nullptr},
      {"circ_r100.prw", K::Wheel, 1001, nullptr},
      {"circ_r100.prr", K::Rail, 1999, nullptr},
      {"circ_r300.prr", K::Rail, 1415, nullptr},  // 1427 lines, '%' lines are commented points
      {"flat_plane.prr", K::Rail, 101, nullptr},
      {"flat_plane.prw", K::Wheel, 101, nullptr},
      {"flat_ang200.prr", K::Rail, 101, nullptr},
      {"flat_ang200.prw", K::Wheel, 101, nullptr},
      {"groove_r1002.prr", K::Rail, 400, nullptr},
      {"site_b_hr.prr", K::Rail, 462, nullptr},   // 493 points, 31 clipped under the head
      {"worn_high_mileage.prw", K::Wheel, 638, nullptr},
      {"avg_wheel.whl", K::Wheel, 671, nullptr},  // 728 rows, 57 on the rim face clipped
      {"fr_ol.csv", K::Unknown, 149, nullptr},
      {"EN15302_wheel_A.dat", K::Wheel, 1001, nullptr},
      {"EN15302_rail_A.dat", K::Rail, 1001, nullptr},
      // Measured MiniProf rails. avg_HR.BAN steps back 0.01 mm on the tread (X 29.27 then 29.26 at
      // line 135): measurement jitter (<= 0.05 mm), the point is dropped with a warning.
      {"avg_HR.BAN", K::Rail, 146, nullptr},
      // avg_low2.ban: its gauge face turns under the head from 11.75 mm below the top (y steps
      // back 0.06 mm at line 537, 0.8 mm in all): rejected by the strict clean-up; the default clean-up now
      // starts the profile at the widest point and clips the hidden face (warning).
      {"avg_low2.ban", K::Rail, 334, nullptr},
      {"synthetic_flange.whe", K::Wheel, 131, nullptr},
  };
  for (const auto& r : rows) {
    const std::string path = kData + r.file;
    INFO(r.file);
    if (r.error) {
      require_error(path, {r.error, "steps backward", "region that can touch"});
      continue;
    }
    const mh::Profile p = mh::read_profile(path);
    if (std::string(r.file) == "avg_HR.BAN")
      CHECK_THAT(p.warnings.at(0), Catch::Contains("dropped 1 points that stepped back in y by at most 0.01 mm"));
    CHECK(p.kind == r.kind);
    CHECK(p.size() == r.points);
    CHECK(strictly_increasing(p));
    CHECK(p.source == path);
    CHECK(p.checksum == mh::sha256_file(path));
    CHECK(!p.format.empty());
  }
}

TEST_CASE("Manchester S1002 wheel in the canonical frame", "[profile_io]") {
  const mh::Profile w = mh::read_profile(kData + "MBench_S1002_v3.prw");
  CHECK(w.format == "simpack");
  const mh::WheelLandmarks L = mh::wheel_landmarks(w);
  // profiles.md: F(-55) = 28.0 mm (flange tip), F(0) = 0, F(60) = -2.6357; canonical z = -F.
  // The file's points are 0.39 mm apart on the flange: tip position within one spacing.
  CHECK(L.y_tip * 1e3 == Approx(-55.0).margin(0.4));
  CHECK(L.z_tip * 1e3 == Approx(-28.0).margin(0.005));   // measured -27.9995
  CHECK(z_at(w, 0.0) == Approx(0.0).margin(0.01));
  CHECK(w.y.back() * 1e3 == Approx(60.0).margin(1e-9));
  CHECK(w.z.back() * 1e3 == Approx(2.6357).margin(1e-4));
  CHECK(w.y.front() * 1e3 == Approx(-69.612628).margin(1e-9));  // flange back end (first uncommented row)
}

TEST_CASE("Manchester UIC60: .ban and .prr read to the same rail", "[profile_io]") {
  const mh::Profile a = mh::read_profile(kData + "MBench_UIC60_v3.prr");
  const mh::Profile b = mh::read_profile(kData + "MBench_UIC60_v3.ban");
  CHECK(b.format == "miniprof");
  // No origin shift needed: both files keep the origin at the highest point.
  CHECK(max_diff_mm(a, b) < 1e-6);
  const mh::RailLandmarks L = mh::rail_landmarks(a);
  CHECK(L.z_top * 1e3 == Approx(0.0).margin(1e-4));  // origin at the highest point (README)
  REQUIRE(L.has_gauge);
  CHECK(L.z_gauge == Approx(L.z_top - 0.014).margin(1e-12));
  CHECK(L.y_gauge * 1e3 < -40.0);  // the gauge side is at negative y
  // Head width 14 mm below the top: UIC60 (60E1, EN 13674-1) head 72 mm wide; canted 1:40.
  double y_field = NAN;
  for (std::size_t k = 1; k < a.size(); ++k)
    if (a.y[k] > L.y_top && a.z[k] <= L.z_gauge && a.z[k - 1] > L.z_gauge) {
      const double t = (L.z_gauge - a.z[k - 1]) / (a.z[k] - a.z[k - 1]);
      y_field = a.y[k - 1] + t * (a.y[k] - a.y[k - 1]);
    }
  CHECK((y_field - L.y_gauge) * 1e3 == Approx(72.0).margin(1.0));
}

TEST_CASE("MiniProf wheel and measured SIMPACK wheel: taping line 70 mm from the flange back", "[profile_io]") {
  const mh::Profile w = mh::read_profile(kData + "avg_wheel.whl");
  CHECK(w.y.front() * 1e3 == Approx(-70.0).margin(1e-9));
  const mh::WheelLandmarks L = mh::wheel_landmarks(w);
  CHECK(L.z_tip * 1e3 == Approx(-28.03).margin(1e-9));  // largest Y of the file
  CHECK(L.y_tip * 1e3 == Approx(14.73 - 71.55).margin(1e-9));  // file row "14.73 28.03", shifted by -(1.55 + 70)
  bool shifted = false, clipped = false;
  for (const auto& s : w.warnings) {
    shifted |= s.find("taping line") != std::string::npos;
    clipped |= s.find("clipped 57 points") != std::string::npos;
  }
  CHECK(shifted);
  CHECK(clipped);
  const mh::Profile h = mh::read_profile(kData + "worn_high_mileage.prw");
  CHECK(h.y.front() * 1e3 == Approx(-70.0).margin(1e-9));
  CHECK(mh::wheel_landmarks(h).y_tip < 0);
  // EN 15302 wheel A is already at the taping line (flange back at -70): no shift.
  const mh::Profile e = mh::read_profile(kData + "EN15302_wheel_A.dat");
  CHECK(e.y.front() * 1e3 == Approx(-70.0).margin(1e-9));
  CHECK(mh::wheel_landmarks(e).z_tip * 1e3 == Approx(-28.0).margin(1e-4));
}

TEST_CASE("write -> read round trips to 1e-9 mm", "[profile_io]") {
  for (const char* f : {"MBench_S1002_v3.prw", "MBench_UIC60_v3.prr", "avg_wheel.whl"}) {
    INFO(f);
    const mh::Profile p = mh::read_profile(kData + f);
    for (const char* ext : {".csv", (p.kind == mh::ProfileKind::Rail ? ".prr" : ".prw")}) {
      const std::string out = tmpdir() + "rt_" + f + ext;
      mh::write_profile(p, out);
      const mh::Profile q = mh::read_profile(out);
      CHECK(q.kind == p.kind);
      CHECK(max_diff_mm(p, q) < 1e-9);
    }
  }
  std::ifstream in(tmpdir() + "rt_MBench_S1002_v3.prw.csv");
  std::string first;
  std::getline(in, first);
  CHECK(first == "y_mm,z_mm");
  const mh::Profile p = mh::read_profile(kData + "MBench_S1002_v3.prw");
  CHECK_THROWS_AS(mh::write_profile(p, tmpdir() + "x.xyz"), mh::InputError);
}

TEST_CASE("user options, GENSYS and VAMPIRE conventions, sniffing", "[profile_io]") {
  const mh::Profile w = mh::read_profile(kData + "MBench_S1002_v3.prw");
  mh::ProfileReadOptions wheel;
  wheel.kind = mh::ProfileKind::Wheel;
  // Mirrored y in a table: rejected, then accepted with mirror_y.
  const std::string mirrored = write_file("s1002_mirror.txt", table_text(w, -1, 1));
  require_error(mirrored, {"flange on the field side", "mirror_y"}, wheel);
  mh::ProfileReadOptions my = wheel;
  my.mirror_y = true;
  CHECK(max_diff_mm(mh::read_profile(mirrored, my), w) < 1e-9);
  // Metres: rejected, then accepted with scale 1000.
  const std::string metres = write_file("s1002_m.csv", "y_m,z_m\n" + table_text(w, 1, 1, 1.0));
  require_error(metres, {"total width 0.129", "looks like metres; use scale 1000"});
  mh::ProfileReadOptions sc;
  sc.scale = 1000;
  CHECK(max_diff_mm(mh::read_profile(metres, sc), w) < 1e-9);
  // GENSYS: y towards the track centre, z down.
  const std::string gensys = write_file("s1002.wheel", "# GENSYS-style\n" + table_text(w, -1, -1));
  const mh::Profile g = mh::read_profile(gensys);
  CHECK(g.kind == mh::ProfileKind::Wheel);
  CHECK(max_diff_mm(g, w) < 1e-9);
  // Mirror z as a user option undoes a z-flipped table.
  const mh::Profile r = mh::read_profile(kData + "MBench_UIC60_v3.prr");
  mh::ProfileReadOptions mz;
  mz.mirror_z = true;
  mz.kind = mh::ProfileKind::Rail;
  CHECK(max_diff_mm(mh::read_profile(write_file("uic_zdown.csv", table_text(r, 1, -1)), mz), r) < 1e-9);
  // Sniffing: a SIMPACK file with an unknown extension; forcing the format.
  std::ifstream src(kData + "MBench_UIC60_v3.prr");
  std::stringstream ss;
  ss << src.rdbuf();
  const std::string odd = write_file("uic.profile", ss.str());
  CHECK(max_diff_mm(mh::read_profile(odd), r) < 1e-12);
  mh::ProfileReadOptions forced;
  forced.format = mh::ProfileFormat::Table;
  CHECK_THROWS_AS(mh::read_profile(odd, forced), mh::InputError);
  CHECK(mh::parse_profile_format("miniprof") == mh::ProfileFormat::MiniProf);
  CHECK_THROWS_AS(mh::parse_profile_format("xls"), std::invalid_argument);
  // VAMPIRE (synthetic file): z up; right flange 28 mm, left 30 mm at y = -55 (1:20 cone).
  const mh::Profile vr = mh::read_profile(kData + "synthetic_flange.whe");
  CHECK(vr.format == "vampire");
  CHECK(mh::wheel_landmarks(vr).y_tip * 1e3 == Approx(-55.0).margin(1e-9));
  CHECK(mh::wheel_landmarks(vr).z_tip * 1e3 == Approx(-55.0 / 20 - 28).margin(1e-6));
  mh::ProfileReadOptions left;
  left.vampire_side = "left";
  CHECK(mh::wheel_landmarks(mh::read_profile(kData + "synthetic_flange.whe", left)).z_tip * 1e3 ==
        Approx(-55.0 / 20 - 30).margin(1e-6));
  // MiniProf Key=Value, comma separated, ColumnDef X,Y,A,C (rail: y = -X, Y up when negative).
  std::string mp = "Filename=x\nXYPoints=61\n\"ColumnDef=X,Y,A,C\"\n\n";
  for (int i = 0; i <= 60; ++i) {
    const double X = -30 + i;
    mp += std::to_string(X) + "," + std::to_string(-(300 - std::sqrt(300.0 * 300 - X * X))) + ",0.1,0.2\n";
  }
  const mh::Profile m = mh::read_profile(write_file("crown.ban", mp));
  CHECK(m.kind == mh::ProfileKind::Rail);
  CHECK(m.size() == 61);
  CHECK(m.z[30] == Approx(0.0).margin(1e-12));
  CHECK(m.z[0] * 1e3 == Approx(-(300 - std::sqrt(300.0 * 300 - 900))).margin(1e-6));
}

TEST_CASE("cleaning: duplicates removed, flank curling under the head clipped", "[profile_io]") {
  // Rail crown R = 100 mm, a duplicate row, and a flank that turns back under the head.
  std::string pts = circle_points(100, 60, +1);
  pts = "-95 40\n-92 39\n-89 35\n" + pts;  // -89 then -90: not monotone; the 3 first rows are clipped
  pts += pts.substr(pts.rfind('\n', pts.size() - 2) + 1);  // exact duplicate of the last circle point
  const std::string f = write_file("curl.prr", simpack(0, pts));
  const mh::Profile p = mh::read_profile(f);
  CHECK(strictly_increasing(p));
  std::string all;
  for (const auto& w : p.warnings) all += w + "|";
  CHECK(all.find("removed 1 duplicated points") != std::string::npos);
  CHECK(all.find("clipped 3 points not monotone in y at the gauge side") != std::string::npos);
}

TEST_CASE("malformed profile files are rejected with file, value, rule and fix", "[profile_io]") {
  const std::string rail = circle_points(100, 40, +1);  // SIMPACK rail crown, z down
  using K = mh::ProfileKind;
  mh::ProfileReadOptions as_rail, as_wheel;
  as_rail.kind = K::Rail;
  as_wheel.kind = K::Wheel;
  const mh::Profile s1002 = mh::read_profile(kData + "MBench_S1002_v3.prw");
  const mh::Profile uic = mh::read_profile(kData + "MBench_UIC60_v3.prr");

  // 1 missing point.end
  require_error(write_file("b01.prr", "header.begin\ntype = 0\nheader.end\nspline.begin\npoint.begin\n" + rail),
                {"missing point.end"});
  // 2 no point list at all
  require_error(write_file("b02.prr", "header.begin\ntype = 0\nheader.end\n"), {"no point.begin"});
  // 3 header type against the extension (a wheel named .prr)
  require_error(write_file("b03.prr", simpack(1, rail)), {"header says wheel", ".prr", "rail"});
  // 4 --kind against the header
  require_error(kData + "MBench_S1002_v3.prw", {"the file says it is a wheel"}, as_rail);
  // 5 too few points
  require_error(write_file("b05.csv", "0 0\n1 0.1\n2 0.3\n3 0.6\n20 1\n"), {"5 points", "at least 10 points"});
  // 6 NaN
  require_error(write_file("b06.csv", "0 0\n1 nan\n" + table_text(s1002)), {"b06.csv:2", "NaN or infinite"});
  // 7 Inf in SIMPACK
  require_error(write_file("b07.prr", simpack(0, "1 inf\n" + rail)), {"'inf'", "NaN or infinite"});
  // 8 trailing junk
  require_error(write_file("b08.dat", "0 0\n1.5abc 0\n"), {"b08.dat:2", "'1.5abc'", "trailing junk"});
  // 9 all points equal
  require_error(write_file("b09.txt", std::string(12 * 4, ' ') + "\n1 2\n1 2\n1 2\n1 2\n1 2\n1 2\n1 2\n1 2\n1 2\n1 2\n1 2\n"),
                {"all points are equal"});
  // 10 metres read as mm
  require_error(write_file("b10.csv", table_text(uic, 1, 1, 1.0)), {"looks like metres; use scale 1000"});
  // 11 micrometres
  require_error(write_file("b11.csv", table_text(uic, 1, 1, 1e6)), {"5-500 mm", "micrometres"});
  // 12 wheel flange on the field side
  require_error(write_file("b12.csv", table_text(s1002, -1, 1)), {"flange on the field side", "mirror_y"}, as_wheel);
  // 13 rail upside down
  require_error(write_file("b13.csv", table_text(uic, 1, -1)), {"upside down", "mirror_z"}, as_rail);
  // 14 a wheel read as a rail
  require_error(write_file("b14.csv", table_text(s1002)), {"shaped like a wheel", "--kind wheel"}, as_rail);
  // 15 a rail read as a wheel
  require_error(write_file("b15.csv", table_text(uic)), {"shaped like a rail"}, as_wheel);
  // 16 loop in the rail head (the top region)
  {
    std::ostringstream loop;  // one point 0.5 mm back on the crown: a small loop
    loop.precision(17);
    for (std::size_t k = 0; k < uic.size(); ++k) {
      loop << uic.y[k] * 1e3 << " " << uic.z[k] * 1e3 << "\n";
      if (k == 250) loop << uic.y[k] * 1e3 - 0.5 << " " << uic.z[k] * 1e3 + 0.01 << "\n";
    }
    mh::ProfileReadOptions strict = as_rail;
    strict.cleanup = mh::ProfileCleanup::Strict;
    require_error(write_file("b16.csv", loop.str()), {"b16.csv:252", "steps backward", "region that can touch the wheel"},
                  strict);
  }
  // 17 zig-zag in the wheel tread, in a GENSYS file (both axes mirrored)
  {
    std::ostringstream g;
    g.precision(17);
    for (std::size_t k = 0; k < s1002.size(); ++k) {
      const double y = (k == 300 ? s1002.y[k - 2] : s1002.y[k]) * 1e3;  // steps back two points
      g << -y << " " << -s1002.z[k] * 1e3 << "\n";
    }
    mh::ProfileReadOptions strict;
    strict.cleanup = mh::ProfileCleanup::Strict;  // the default clean-up removes it (test_profile_cleanup.cpp)
    require_error(write_file("b17.wheel", g.str()), {"steps backward", "region that can touch the rail"}, strict);
  }
  // 18 MiniProf file shorter than XYPoints
  {
    std::istringstream in(table_text(uic));
    std::string rows, line;
    for (int k = 0; k < 20 && std::getline(in, line); ++k) rows += line + "\n";
    require_error(write_file("b18.ban", "XYPoints=50\nColumnDef=X,Y\n\n" + rows),
                  {"XYPoints=50", "only 20 data rows", "truncated"});
  }
  // 19 MiniProf Key=Value without ColumnDef
  require_error(write_file("b19.ban", "XYPoints=5\nFilename=x\n\n1 2\n"), {"without ColumnDef"});
  // 20 table row with three columns
  require_error(write_file("b20.txt", "1 2 3\n"), {"b20.txt:1", "exactly two numbers"});
  // 21 VAMPIRE with a wrong first line
  require_error(write_file("b21.whe", "WHEEL\nt\nEUROPEAN\n1360\n1 2 3 4\n"), {"WHEELPROFILE or RAILPROFILE"});
  // 22 a file that does not exist
  require_error(tmpdir() + "nonexistent.prr", {"cannot open"});
}

TEST_CASE("profile info and convert through run_cli", "[profile_io][cli]") {
  std::ostringstream out, err;
  const std::string w = kData + "MBench_S1002_v3.prw";
  REQUIRE(mh::run_cli({"profile", "info", w}, out, err) == 0);
  CHECK(out.str().find("kind: wheel") != std::string::npos);
  CHECK(out.str().find("points: 399") != std::string::npos);
  CHECK(out.str().find("flange_tip_mm: y -54.892493 z -27.999518") != std::string::npos);
  std::ostringstream o2, e2;
  REQUIRE(mh::run_cli({"profile", "info", kData + "MBench_UIC60_v3.ban", "--json"}, o2, e2) == 0);
  CHECK(o2.str().find("\"kind\": \"rail\"") != std::string::npos);
  CHECK(o2.str().find("\"gauge_point_z_mm\": -14.0000603") != std::string::npos);
  std::ostringstream o3, e3;
  CHECK(mh::run_cli({"profile", "info", w, "--mirror-y"}, o3, e3) == mh::kExitInputError);
  CHECK(e3.str().find("mirror_y") != std::string::npos);
  std::ostringstream o4, e4;
  const std::string csv = tmpdir() + "cli.csv";
  REQUIRE(mh::run_cli({"profile", "convert", w, "-o", csv}, o4, e4) == 0);
  CHECK(max_diff_mm(mh::read_profile(csv), mh::read_profile(w)) < 1e-9);
}

TEST_CASE("SIMPACK spline keys applied in the documented order", "[profile_io]") {
  // File in metres (units.len.f = 1), angles in degrees (units.ang.f = 180/pi). Points
  // y_i = 0.002 i - 0.02, z_i = 0.05 - 0.001 i (i = 0..20). Order (profiles.md): shift
  // (+0.01, -0.002) -> rotate 90 deg counter-clockwise in the file's (y, z) plane:
  // (y, z) -> (-z, y) -> bounds z in [-0.005, 0.025] keeps i = 3..17 -> mirror y -> mirror z ->
  // reverse -> mm -> canonical (y, -z). By hand: y = 48 - i mm, z = 2 i - 10 mm, i.e. 15 points
  // y = 31..45 mm with z = 86 - 2 y.
  std::ostringstream pts;
  pts.precision(17);
  for (int i = 0; i <= 20; ++i) pts << 0.002 * i - 0.02 << " " << 0.05 - 0.001 * i << " 1.0\n";
  std::ostringstream keys;
  keys.precision(17);
  keys << "  shift.y = 0.01\n  shift.z = -0.002\n  rotate = 90\n  units.ang.f = " << 180 / M_PI
       << "\n  bound.y.min = 1\n  bound.y.max = 0\n  bound.z.min = -0.005\n  bound.z.max = 0.025\n"
       << "  mirror.y = 1\n  mirror.z = 1\n  inversion = 1\n  units.len.f = 1 ! metres\n";
  const std::string text = "header.begin\n  type = 0\nheader.end\nspline.begin\n" + keys.str() +
                           "  point.begin\n" + pts.str() + "  point.end\nspline.end\n";
  const mh::Profile p = mh::read_profile(write_file("keys.prr", text));
  REQUIRE(p.size() == 15);
  for (std::size_t k = 0; k < p.size(); ++k) {
    CHECK(p.y[k] * 1e3 == Approx(31.0 + k).margin(1e-9));
    CHECK(p.z[k] * 1e3 == Approx(24.0 - 2.0 * k).margin(1e-9));
  }
  REQUIRE(!p.warnings.empty());
  CHECK(p.warnings[0] == "SIMPACK bounds removed 6 points");
}

TEST_CASE("a point that repeats the previous y is said so, not 'stepped back by at most 0 mm' (issue 38)", "[profile_io][messages]") {
  // S1002 with the point at line 200 repeated at the same y, 1 µm higher, on the flange.
  const mh::Profile s = mh::make_standard_profile("S1002");
  std::istringstream in(table_text(s));
  std::string text, line;
  for (int k = 1; std::getline(in, line); ++k) {
    text += line + "\n";
    if (k == 200) {
      std::istringstream ls(line);
      double y, z;
      ls >> y >> z;
      std::ostringstream dup;
      dup.precision(17);
      dup << y << " " << z + 1e-3 << "\n";
      text += dup.str();
    }
  }
  const mh::Profile p = [&] {
    mh::ProfileReadOptions o;
    o.kind = mh::ProfileKind::Wheel;
    return mh::read_profile(write_file("repeated_y.txt", text), o);
  }();
  bool said = false;
  for (const std::string& w : p.warnings) {
    CHECK_THAT(w, !Catch::Contains("at most 0 mm"));
    said = said || w.find("dropped 1 points that repeat the previous point's y") != std::string::npos;
  }
  CHECK(said);
}
