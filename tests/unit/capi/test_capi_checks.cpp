// The library checks what the command line checks (docs/c-api.md "Errors", issue 32 §6): the
// case file's plausible ranges on the fields of mhc_pair_options and on the load, the pair's
// warnings in the command's words, explicit positioning, and a conformal contact that the
// multi-Hertzian method cannot solve reported as such, never as no_contact (zero force).
#include <catch2/catch.hpp>

#include <mhcontact.h>

#include <cmath>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "cli.hpp"
#include "geometry/contact_geometry.hpp"
#include "profile/standard_profiles.hpp"

namespace fs = std::filesystem;

namespace {
const std::string kSrc = MHCONTACT_SOURCE_DIR;

struct Profiles {
  mhc_profile *w = nullptr, *r = nullptr;
  Profiles(const char* wheel, const char* rail) {
    auto get = [](const char* name, int kind, mhc_profile** p) {
      const std::string s = name;
      return s.find('.') == std::string::npos ? mhc_profile_standard(name, p)
                                              : mhc_profile_read((kSrc + "/tests/data/profiles/" + s).c_str(), kind, p);
    };
    REQUIRE(get(wheel, MHC_WHEEL, &w) == MHC_OK);
    REQUIRE(get(rail, MHC_RAIL, &r) == MHC_OK);
  }
  ~Profiles() {
    mhc_profile_free(w);
    mhc_profile_free(r);
  }
};

mhc_pair_options defaults() {
  mhc_pair_options o;
  mhc_pair_options_init(&o);
  return o;
}

mhc_result fresh() {
  mhc_result r;
  std::memset(&r, 0xab, sizeof r);
  r.struct_size = sizeof r;
  return r;
}

/// Solve one case on a pair, through a workspace of its own.
mhc_error solve(const mhc_pair* p, double tY, double Q, mhc_result* r) {
  mhc_workspace* ws = nullptr;
  REQUIRE(mhc_workspace_create(p, &ws) == MHC_OK);
  const mhc_error e = mhc_solve_load(p, ws, tY, 0.0, Q, r);
  mhc_workspace_free(ws);
  return e;
}
}  // namespace

TEST_CASE("C interface: the case file's plausible ranges on the options, with the field, value, rule and unit",
          "[capi][checks]") {
  Profiles P("S1002", "60E1");
  // Each row: one field set to a value a unit slip gives; the message names the field, the
  // value (SI and the table's unit), the range, and the SI unit. Before the check, E = 210e3 Pa
  // (MPa typed as Pa) solved to a 0.23 MPa peak.
  struct Row {
    double mhc_pair_options::*field;
    double value;
    const char* message;
  };
  const Row rows[] = {
      {&mhc_pair_options::E_wheel_Pa, 210e3,
       "options.E_wheel_Pa: value 210000 Pa (0.00021 GPa): must be between 50 and 400 GPa (plausible range of E"},
      {&mhc_pair_options::E_rail_Pa, 210e12, "options.E_rail_Pa: value 2.1e+14 Pa (210000 GPa)"},
      {&mhc_pair_options::nu_wheel, 28, "options.nu_wheel: value 28 -: must be between 0.1 and 0.45"},
      {&mhc_pair_options::p_lim_Pa, 1500, "options.p_lim_Pa: value 1500 Pa (0.0015 MPa): must be between 100 and 20000 MPa"},
      {&mhc_pair_options::yield_wheel_Pa, 350, "options.yield_wheel_Pa: value 350 Pa (0.00035 MPa)"},
      {&mhc_pair_options::nominal_radius_m, 460, "options.nominal_radius_m: value 460 m (460000 mm): must be between 100 and 2000 mm"},
  };
  for (const Row& row : rows) {
    mhc_pair_options o = defaults();
    o.*row.field = row.value;
    mhc_pair* p = nullptr;
    INFO(row.message);
    CHECK(mhc_pair_create(P.w, P.r, &o, &p) == MHC_ERR_ARGUMENT);
    CHECK_THAT(mhc_last_message(), Catch::Contains(row.message));
    CHECK_THAT(mhc_last_message(), Catch::Contains("docs/case-file.md \"Plausible ranges\""));
    CHECK(p == nullptr);
  }
  CHECK_THAT(mhc_last_message(), Catch::Contains("nominal_radius_m is in m: 460 mm is 0.46"));  // the fix
  // The defaults pass, and so do the values that mean "not given".
  mhc_pair_options o = defaults();
  o.rail_inclination = 40;
  mhc_pair* p = nullptr;
  REQUIRE(mhc_pair_create(P.w, P.r, &o, &p) == MHC_OK);
  // The load: 5e9 N (5e6 kN: nothing plausible) and a negative load are argument errors; a
  // wheel lifted (Q = 0) is no_contact, a status.
  mhc_result r = fresh();
  CHECK(solve(p, 0.0, 5e9, &r) == MHC_ERR_ARGUMENT);
  CHECK_THAT(mhc_last_message(), Catch::Contains("Q_N: value 5e+09 N (5e+06 kN): must be at most 2000 kN"));
  CHECK_THAT(mhc_last_message(), Catch::Contains("Q_N is in N"));
  CHECK(solve(p, 0.0, -5e3, &r) == MHC_ERR_ARGUMENT);
  CHECK_THAT(mhc_last_message(), Catch::Contains("Q_N: value -5000 N (-5 kN): a wheel load must not be negative"));
  CHECK(solve(p, 0.0, NAN, &r) == MHC_ERR_ARGUMENT);
  REQUIRE(solve(p, 0.0, 0.0, &r) == MHC_OK);
  CHECK(r.status == MHC_STATUS_NO_CONTACT);
  REQUIRE(solve(p, 0.0, 2000e3, &r) == MHC_OK);  // the top of the range solves
  // solve_many: the first bad load is the call's error, the other cases are solved.
  const double tY[3] = {0, 0, 0}, Q[3] = {50e3, 5e9, 60e3};
  mhc_result many[3];
  CHECK(mhc_solve_many(p, MHC_PRESCRIBE_LOAD, 3, tY, nullptr, Q, many, sizeof(mhc_result), 1) == MHC_ERR_ARGUMENT);
  CHECK_THAT(mhc_last_message(), Catch::Contains("Q_N: value 5e+09 N"));
  mhc_result one = fresh();
  REQUIRE(solve(p, 0.0, 60e3, &one) == MHC_OK);
  CHECK(std::memcmp(&one, &many[2], sizeof one) == 0);
  mhc_pair_free(p);
}

TEST_CASE("C interface: the pair's warnings are the command's (a rail canted twice)", "[capi][checks]") {
  // The Manchester rail file is canted 1:40 already; a case that cants it again lays it at
  // 2.86 deg. The command warns; the library gives the same words (before: silent).
  const std::string dir = fs::temp_directory_path() / ("mhcontact_capi_warn_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string rail = kSrc + "/tests/data/profiles/MBench_UIC60_v3.prr";
  const std::string wheel = kSrc + "/tests/data/profiles/MBench_S1002_v3.prw";
  const std::string cf = dir + "/twice.json";
  std::ofstream(cf) << "{\"wheel\": {\"profile\": \"" << wheel << "\"}, \"rail\": {\"profile\": \"" << rail
                    << "\", \"inclination\": \"1:40\"}, \"sweep\": {\"tY_mm\": [0], \"Q_kN\": [50]}}";
  std::ostringstream o, e;
  REQUIRE(mh::run_cli({"geometry", cf, "-o", dir + "/geo"}, o, e) == 0);
  std::vector<std::string> command;
  std::istringstream es(e.str());
  const std::string prefix = "mhcontact: warning: ";
  for (std::string line; std::getline(es, line);)
    if (line.rfind(prefix, 0) == 0) command.push_back(line.substr(prefix.size()));
  REQUIRE_FALSE(command.empty());
  bool twice = false;
  for (const auto& w : command) twice = twice || w.find("canted already (1.432 deg, 1:40) and the case cants it again") != std::string::npos;
  CHECK(twice);
  // The case file's pair, and the same pair from profiles and options.
  mhc_pair* from_file = nullptr;
  REQUIRE(mhc_pair_from_case_file(cf.c_str(), &from_file) == MHC_OK);
  mhc_profile *w = nullptr, *r = nullptr;
  REQUIRE(mhc_profile_read(wheel.c_str(), MHC_WHEEL, &w) == MHC_OK);
  REQUIRE(mhc_profile_read(rail.c_str(), MHC_RAIL, &r) == MHC_OK);
  mhc_pair_options opt = defaults();
  opt.rail_inclination = 40;
  mhc_pair* created = nullptr;
  REQUIRE(mhc_pair_create(w, r, &opt, &created) == MHC_OK);
  for (const mhc_pair* p : {static_cast<const mhc_pair*>(from_file), static_cast<const mhc_pair*>(created)}) {
    std::vector<std::string> lib;
    for (int32_t i = 0; i < mhc_pair_n_warnings(p); ++i) lib.push_back(mhc_pair_warning(p, i));
    CHECK(lib == command);
    CHECK(mhc_pair_warning(p, mhc_pair_n_warnings(p)) == nullptr);
    CHECK(mhc_pair_warning(p, -1) == nullptr);
  }
  // The same pair canted once (the file as it is): no warning.
  opt.rail_inclination = 0;
  mhc_pair* once = nullptr;
  REQUIRE(mhc_pair_create(w, r, &opt, &once) == MHC_OK);
  CHECK(mhc_pair_n_warnings(once) == 0);
  CHECK(mhc_pair_n_warnings(nullptr) == 0);
  mhc_pair_free(once);
  mhc_pair_free(created);
  mhc_pair_free(from_file);
  fs::remove_all(dir);
  mhc_profile_free(w);
  mhc_profile_free(r);
}

TEST_CASE("C interface: explicit positioning reproduces gauge positioning at its offset, and moves the wheel",
          "[capi][checks]") {
  Profiles P("S1002", "60E1");
  // The offset gauge positioning computes for S1002 on 60E1 at 1:40 (method.md §7), from the library.
  const mh::ContactGeometry G =
      mh::build_geometry(mh::make_standard_profile("S1002", mh::Inclination::None, 0.1e-3),
                         mh::make_standard_profile("60E1", mh::Inclination::In40, 0.1e-3), mh::TrackSetup{},
                         mh::GeometryOptions{});
  mhc_pair_options o = defaults();
  o.rail_inclination = 40;
  mhc_pair *gauge = nullptr, *at = nullptr, *moved = nullptr, *older = nullptr;
  REQUIRE(mhc_pair_create(P.w, P.r, &o, &gauge) == MHC_OK);
  o.positioning = MHC_POSITIONING_EXPLICIT;
  o.lateral_offset_m = G.y_offset;
  REQUIRE(mhc_pair_create(P.w, P.r, &o, &at) == MHC_OK);
  o.lateral_offset_m = G.y_offset + 2e-3;
  REQUIRE(mhc_pair_create(P.w, P.r, &o, &moved) == MHC_OK);
  // A caller of a header before positioning: its struct ends there, gauge positioning.
  o.struct_size = offsetof(mhc_pair_options, positioning);
  REQUIRE(mhc_pair_create(P.w, P.r, &o, &older) == MHC_OK);
  for (double tY : {-2e-3, 0.0, 4e-3, 7e-3}) {
    INFO("tY " << tY);
    mhc_result a = fresh(), b = fresh(), c = fresh(), d = fresh();
    REQUIRE(solve(gauge, tY, 80e3, &a) == MHC_OK);
    REQUIRE(solve(at, tY, 80e3, &b) == MHC_OK);
    REQUIRE(solve(moved, tY, 80e3, &c) == MHC_OK);
    REQUIRE(solve(older, tY, 80e3, &d) == MHC_OK);
    CHECK(std::memcmp(&a, &b, sizeof a) == 0);
    CHECK(std::memcmp(&a, &d, sizeof a) == 0);
    CHECK(a.contact[0].y_rail_m != c.contact[0].y_rail_m);  // the offset is used
  }
  // Refused: an unknown positioning, an offset beyond 0.2 m, an offset with gauge positioning.
  o = defaults();
  mhc_pair* none = nullptr;
  o.positioning = 2;
  CHECK(mhc_pair_create(P.w, P.r, &o, &none) == MHC_ERR_ARGUMENT);
  CHECK_THAT(mhc_last_message(), Catch::Contains("options.positioning: value 2: must be MHC_POSITIONING_GAUGE"));
  o.positioning = MHC_POSITIONING_EXPLICIT;
  o.lateral_offset_m = -3.4;
  CHECK(mhc_pair_create(P.w, P.r, &o, &none) == MHC_ERR_ARGUMENT);
  CHECK_THAT(mhc_last_message(), Catch::Contains("options.lateral_offset_m: value -3.4 m: must lie within"));
  o.positioning = MHC_POSITIONING_GAUGE;
  o.lateral_offset_m = -3.4e-3;
  CHECK(mhc_pair_create(P.w, P.r, &o, &none) == MHC_ERR_ARGUMENT);
  CHECK_THAT(mhc_last_message(), Catch::Contains("only used with positioning MHC_POSITIONING_EXPLICIT"));
  CHECK(none == nullptr);
  // A misplaced wheel (a flange-back distance 50 mm short) is refused with the explicit
  // placement that reproduces it, the command's words.
  o = defaults();
  o.rail_inclination = 40;
  o.flange_back_distance_m = 1.260;
  CHECK(mhc_pair_create(P.w, P.r, &o, &none) == MHC_ERR_INPUT);
  CHECK_THAT(mhc_last_message(), Catch::Contains("gauge positioning misplaces the wheel"));
  CHECK_THAT(mhc_last_message(), Catch::Contains("\"positioning\": \"explicit\", \"lateral_offset_mm\": "));
  mhc_pair_free(gauge);
  mhc_pair_free(at);
  mhc_pair_free(moved);
  mhc_pair_free(older);
}
