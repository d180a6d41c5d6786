// `mhcontact run` / `geometry` through the CLI function: outputs, determinism, errors.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <unistd.h>
#include <sstream>

#include "cli.hpp"
#include "core/errors.hpp"
#include "jobs/sweep.hpp"

namespace fs = std::filesystem;
using mh::run_cli;

namespace {
const std::string kSrc = MHCONTACT_SOURCE_DIR;

struct TempDir {
  fs::path path;
  TempDir() {
    static int counter = 0;
    path = fs::temp_directory_path() / ("mhcontact_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  std::string operator/(const std::string& s) const { return (path / s).string(); }
};

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

int cli(std::vector<std::string> args, std::string* out = nullptr, std::string* err = nullptr) {
  std::ostringstream o, e;
  const int rc = run_cli(args, o, e);
  if (out) *out = o.str();
  if (err) *err = e.str();
  return rc;
}

// A case file in `dir` whose profile paths point at the shipped profiles.
std::string write_case(const TempDir& d, const std::string& body, const std::string& name = "case.json") {
  std::ofstream(d / name) << body;
  return d / name;
}

const std::string kPair =
    "\"wheel\": {\"profile\": \"" + kSrc + "/profiles/MBench_S1002_v3.prw\"},"
    "\"rail\": {\"profile\": \"" + kSrc + "/profiles/MBench_UIC60_v3.prr\", \"inclination\": \"as-is\"}";
}  // namespace

TEST_CASE("run writes the three tables, byte-identical for 1, 2 and 4 threads", "[run]") {
  TempDir d;
  const std::string cf = kSrc + "/cases/manchester.json";
  std::string err;
  REQUIRE(cli({"run", cf, "-o", d / "t1", "--threads", "1", "-q"}) == 0);
  REQUIRE(cli({"run", cf, "-o", d / "t2", "--threads", "2", "-q"}) == 0);
  REQUIRE(cli({"run", cf, "-o", d / "t4", "--threads", "4"}, nullptr, &err) == 0);
  // 25 rows outside the multi-Hertzian method's validity (docs/status.md): answers, exit 0.
  REQUIRE_THAT(err, Catch::Contains("99 cases, ok 72, outside_validity 27"));
  for (const char* f : {"cases.csv", "ellipses.csv", "geometry.csv", "results.json"}) {
    CAPTURE(f);
    const std::string a = slurp(d / (std::string("t1/") + f));
    REQUIRE(!a.empty());
    REQUIRE(a == slurp(d / (std::string("t2/") + f)));
    REQUIRE(a == slurp(d / (std::string("t4/") + f)));
  }
  // No temporaries left behind.
  for (const auto& e : fs::directory_iterator(d / "t1"))
    REQUIRE(e.path().filename().string().find(".tmp.") == std::string::npos);
  // Headers as documented in the README.
  const std::string cases = slurp(d / "t1/cases.csv");
  REQUIRE(cases.rfind("case,tY_mm,Q_kN,status,method,dz_virtual_mm,approach_mm,iterations,residual,n_contacts,Fz_kN,Fy_kN,Y_over_Q,pmax_MPa,area_mm2,gamma_main_deg,r_roll_main_mm,plastic,n_warnings,warnings,message,pmax_half_L_MPa,pmax_double_L_MPa,area_half_L_mm2,area_double_L_mm2\n", 0) == 0);
  REQUIRE(std::count(cases.begin(), cases.end(), '\n') == 100);
  const std::string ell = slurp(d / "t1/ellipses.csv");
  REQUIRE(ell.rfind("case,tY_mm,Q_kN,ellipse,h0_mm,N_kN,a_mm,b_mm,p0_MPa,pmean_MPa,approach_mm,"
                    "hertz_valid,b_over_R,gap_error,gap_mean_error,area_mm2\n", 0) == 0);
  // geometry.csv (schema 3): the candidates' geometry once per (t_Y, ellipse): 33 t_Y x 4
  // potential ellipses.
  const std::string geo = slurp(d / "t1/geometry.csv");
  REQUIRE(geo.rfind("tY_mm,ellipse,y_rail_mm,y_wheel_mm,gamma_deg,R_rxx_mm,R_wxx_mm,R_wyy_mm,A_per_mm,B_per_mm,"
                    "lambda,m,n,gap_mm,z_rail_mm,z_wheel_mm\n", 0) == 0);
  REQUIRE(std::count(geo.begin(), geo.end(), '\n') == 1 + 33 * 4);
  // results.json: valid JSON, schema, inputs with checksums, the same cases.
  const auto j = nlohmann::json::parse(slurp(d / "t1/results.json"));
  REQUIRE(j.at("schema") == "mhcontact.results/10");
  REQUIRE(j.at("profiles").at("wheel").at("sha256").get<std::string>().size() == 64);
  REQUIRE(j.at("cases").size() == 99);
  REQUIRE(j.at("potential_ellipses").size() == 4);
  REQUIRE(j.at("geometry").size() == 33 * 4);
  REQUIRE(j.at("summary").at("failed") == 0);
  double sumFz = 0;
  for (const auto& c : j.at("cases")) sumFz += c.at("Fz_kN").get<double>() - c.at("Q_kN").get<double>();
  REQUIRE(std::fabs(sumFz) < 1e-6);
}

TEST_CASE("run -o - writes results.json to standard output only", "[run]") {
  std::string out;
  REQUIRE(cli({"run", kSrc + "/cases/manchester.json", "-o", "-", "-q"}, &out) == 0);
  const auto j = nlohmann::json::parse(out);
  REQUIRE(j.at("cases").size() == 99);
}

TEST_CASE("a failing case is a row with its status, the sweep goes on, exit 1", "[run]") {
  TempDir d;
  const std::string cf = write_case(d, "{" + kPair + ", \"geometry\": {\"tY_min_mm\": -2, \"tY_max_mm\": 2},"
                                     "\"cases\": [{\"tY_mm\": 0, \"Q_kN\": 50}, {\"tY_mm\": 5, \"Q_kN\": 50}, {\"tY_mm\": 1, \"Q_kN\": 50}]}");
  REQUIRE(cli({"run", cf, "-o", d / "out", "-q"}) == mh::kExitCasesFailed);
  const std::string cases = slurp(d / "out/cases.csv");
  REQUIRE_THAT(cases, Catch::Contains("\n1,5,50,out_of_range,"));
  // t_Y = 1 mm, 50 kN: solved, outside the multi-Hertzian method's validity.
  REQUIRE_THAT(cases, Catch::Contains("\n2,1,50,outside_validity,"));
}

TEST_CASE("geometry writes caf.csv and geometry.json", "[run]") {
  TempDir d;
  std::string err;
  REQUIRE(cli({"geometry", kSrc + "/cases/manchester.json", "-o", d / "g"}, nullptr, &err) == 0);
  REQUIRE_THAT(err, Catch::Contains("4 potential ellipses"));
  const std::string caf = slurp(d / "g/caf.csv");
  REQUIRE(caf.rfind("tY_mm,y_rail_mm,y_wheel_mm,gamma_deg,R_rxx_mm,R_wxx_mm,R_wyy_mm,r_roll_mm,wheel_dz_mm,strip,ellipse\n", 0) == 0);
  const auto j = nlohmann::json::parse(slurp(d / "g/geometry.json"));
  REQUIRE(j.at("potential_ellipses").size() == 4);
  REQUIRE(j.at("potential_ellipses")[1].at("tY_min_mm").get<double>() == Approx(0.22).margin(0.02));
}

TEST_CASE("bad case files: exit 2, JSON path, value and rule, nothing written", "[run][errors]") {
  struct Bad { std::string body, words; };
  const std::string pair = kPair;
  const std::string sweep = "\"sweep\": {\"tY_mm\": [0], \"Q_kN\": [50]}";
  const std::vector<Bad> bad = {
      {"{" + pair + ", " + sweep, "JSON syntax error"},
      {"[1, 2]", "must be an object"},
      {"{\"sweep\": 5E555}", "invalid JSON: number overflow"},  // fuzz finding (json_number_overflow.json)
      {"{" + pair + ", " + sweep + ", \"materail\": {}}", "/materail: unknown key"},
      {"{" + pair + "}", "/sweep: required"},
      {"{\"wheel\": {\"profile\": \"" + kSrc + "/profiles/MBench_S1002_v3.prw\"}, \"rail\": {\"profile\": \"" + kSrc +
           "/profiles/MBench_UIC60_v3.prr\"}, " + sweep + "}", "/rail/inclination: required"},
      {"{" + pair + ", \"sweep\": {\"tY_mm\": [0], \"Q_kN\": [0]}}", "/sweep/Q_kN/0: value 0: must be between 0.01 and 2000 kN"},
      {"{" + pair + ", \"sweep\": {\"tY_mm\": [0], \"Q_kN\": [-5]}}", "value -5: must be between 0.01 and 2000 kN"},
      {"{" + pair + ", \"sweep\": {\"tY_mm\": [], \"Q_kN\": [50]}}", "empty list"},
      {"{" + pair + ", \"sweep\": {\"tY_mm\": {\"from\": 0, \"to\": 1, \"step\": 0}, \"Q_kN\": [50]}}", "/sweep/tY_mm/step: value 0: must be > 0"},
      {"{" + pair + ", \"sweep\": {\"tY_mm\": {\"from\": 2, \"to\": 1, \"step\": 0.1}, \"Q_kN\": [50]}}", "must be >= from"},
      {"{" + pair + ", \"sweep\": {\"tY_mm\": {\"from\": -10, \"to\": 10, \"step\": 1e-5}, \"Q_kN\": {\"from\": 1, \"to\": 1000000, \"step\": 0.001}}}",
       "cases, more than the limit of 1000000000"},
      {"{" + pair + ", " + sweep + ", \"material\": {\"E_GPa\": 0}}", "/material/E_GPa: value 0: must be between 50 and 400 GPa"},
      {"{" + pair + ", " + sweep + ", \"material\": {\"nu\": 0.5}}", "/material/nu: value 0.5: must be between 0.1 and 0.45"},
      {"{" + pair + ", " + sweep + ", \"material\": {\"E_GPa\": \"210\"}}", "must be a number"},
      {"{" + pair + ", " + sweep + ", \"material\": {\"p_lim_MPa\": 900}}", "used by the plastic model only"},
      {"{" + pair + ", " + sweep + ", \"model\": \"plastic\"}", "/material/p_lim_MPa: required for the plastic model"},
      {"{" + pair + ", " + sweep + ", \"model\": \"viscous\"}", "must be \"elastic\" or \"plastic\""},
      {"{" + pair + ", " + sweep + ", \"geometry\": {\"tY_step_mm\": -1}}", "must be > 0"},
      {"{\"wheel\": {\"profile\": \"nope.prw\"}, \"rail\": {\"profile\": \"nope.prr\", \"inclination\": \"1:40\"}, " + sweep + "}", "cannot open"},
      {"{\"wheel\": {\"profile\": {\"standard\": \"60E1\"}}, \"rail\": {\"profile\": {\"standard\": \"60E1\"}, \"inclination\": \"1:40\"}, " + sweep + "}",
       "is a rail profile, but a wheel is needed here"},
      {"{\"wheel\": {\"profile\": \"" + kSrc + "/profiles/MBench_UIC60_v3.prr\"}, \"rail\": {\"profile\": \"" + kSrc +
           "/profiles/MBench_S1002_v3.prw\", \"inclination\": \"as-is\"}, " + sweep + "}", "wheel"},
      {"{" + pair + ", " + sweep + ", \"rail\": 3}", "/rail"},
  };
  for (const Bad& b : bad) {
    TempDir d;
    const std::string cf = write_case(d, b.body);
    std::string err;
    const int rc = cli({"run", cf, "-o", d / "out", "-q"}, nullptr, &err);
    CAPTURE(b.body, err);
    CHECK(rc == mh::kExitInputError);
    CHECK_THAT(err, Catch::Contains(b.words));
    CHECK_THAT(err, Catch::Contains("case.json"));
    REQUIRE_FALSE(fs::exists(d / "out/cases.csv"));
  }
}

TEST_CASE("an output directory that cannot be written: exit 4", "[run][errors]") {
  TempDir d;
  std::ofstream(d / "file") << "x";
  std::string err;
  REQUIRE(cli({"run", kSrc + "/cases/manchester.json", "-o", d / "file/sub", "-q"}, nullptr, &err) == mh::kExitOutput);
  REQUIRE_THAT(err, Catch::Contains("cannot be created"));
}

TEST_CASE("an exception inside a worker is an internal error (exit 3), not a row", "[run][errors]") {
  TempDir d;
  for (const char* threads : {"1", "2"}) {
    mh::set_case_hook_for_tests([](std::uint64_t c) {
      if (c == 7) throw std::runtime_error("injected failure");
    });
    std::string err;
    const int rc = cli({"run", kSrc + "/cases/manchester.json", "-o", d / "out", "-q", "--threads", threads}, nullptr, &err);
    mh::set_case_hook_for_tests(nullptr);
    CAPTURE(threads, err);
    REQUIRE(rc == mh::kExitInternal);
    REQUIRE_THAT(err, Catch::Contains("mhcontact: internal error: case 7: injected failure"));
    REQUIRE_FALSE(fs::exists(d / "out/cases.csv"));
  }
}

TEST_CASE("a full standard output is an error (exit 4)", "[run][errors]") {
  std::ostringstream o, e;
  o.setstate(std::ios::badbit);  // as a stream on /dev/full ends up
  REQUIRE(run_cli({"run", kSrc + "/cases/manchester.json", "-o", "-", "-q"}, o, e) == mh::kExitOutput);
  REQUIRE_THAT(e.str(), Catch::Contains("output could not be written"));
}
