// The C interface's subsurface stresses of a solved contact (include/mhcontact.h,
// lib/capi/subsurface.cpp; docs/c-api.md "Subsurface stresses"): mhc_result_subsurface against the
// subsurface columns of patches.csv / ellipses.csv of `mhcontact run --digits max` on the same
// case file (the same computation: equal, value for value, as the writer converts them), for a
// half-space patch with its solved traction and for FASTSIM ellipses; one check of the patch's
// peaks against CONTACT's stresses below its own solution of the same case
// (tests/data/contact_subsurface_wheelrail/, A-2.2 case 2); the grids not kept (the Hertz
// ellipse, with its warning) and the arguments.
#include <catch2/catch.hpp>

#include <mhcontact.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "cli.hpp"
#include "support/case_text.hpp"
#include "support/data_csv.hpp"

namespace fs = std::filesystem;

namespace {
const std::string kSrc = MHCONTACT_SOURCE_DIR;

using Row = mh::test::TextRow;
using mh::test::read_text_rows;

// The Manchester pair (S1002 on UIC60 1:40) by the half-space method on 0.2 mm elements, with
// friction 0.3 and CONTACT's creepages of case 2 (t_Y 0.5 mm, yaw 1.2 mrad; module 1's signs
// turned into ours: all three negated, tests/data/contact_tangential/README.md), 10 kN, the
// subsurface columns from the patch's own grid with FI_sub at c = 0.3.
std::string write_case(const std::string& tag) {
  std::string j = mh::test::manchester_halfspace_case(
            "\"friction\": {\"coefficient\": 0.3},\n"
            "  \"creepages\": {\"xi\": -4.948e-4, \"eta\": -1.202e-3, \"phi_per_mm\": -1.233e-4},\n"
            "  \"rcf\": {\"shear_yield_MPa\": 300, \"subsurface\": {\"grid\": true, \"dang_van_c\": 0.3}},\n"
            "  \"sweep\": {\"tY_mm\": [0.5], \"Q_kN\": [10]}\n}\n");
  const std::string path = fs::temp_directory_path() / ("mhcontact_capi_subs_" + tag + std::to_string(::getpid()) + ".json");
  std::ofstream(path) << j;
  return path;
}

const char* source_name(int32_t s) {
  switch (s) {
    case MHC_SUBSURFACE_HERTZ_ELLIPSE: return "hertz_ellipse";
    case MHC_SUBSURFACE_GRID_PATCH: return "grid_patch";
    case MHC_SUBSURFACE_GRID_PATCH_SOLVED_TRACTION: return "grid_patch_solved_traction";
    case MHC_SUBSURFACE_HERTZ_ELLIPSE_FASTSIM: return "hertz_ellipse_fastsim_traction";
  }
  return "";
}

struct Handles {
  mhc_pair* pair = nullptr;
  mhc_workspace* ws = nullptr;
  explicit Handles(const std::string& case_file) {
    REQUIRE(mhc_pair_from_case_file(case_file.c_str(), &pair) == MHC_OK);
    REQUIRE(mhc_workspace_create(pair, &ws) == MHC_OK);
  }
  ~Handles() {
    mhc_workspace_free(ws);
    mhc_pair_free(pair);
  }
};

// Every contact row of the command's `file` (patches.csv or ellipses.csv) against the C call on
// the same case file; the rows compared.
std::size_t compare_with_command(const std::string& case_file, const char* file, double dang_van_c,
                                 std::vector<mhc_contact_subsurface>* kept = nullptr) {
  const std::string dir = fs::temp_directory_path() / ("mhcontact_capi_subs_" + std::to_string(::getpid()));
  std::ostringstream o, e;
  REQUIRE(mh::run_cli({"run", case_file, "-o", dir, "--digits", "max", "-q", "--format", "csv", "--force"}, o, e) == 0);
  const auto cases = read_text_rows(dir + "/cases.csv");
  const auto rows = read_text_rows(dir + "/" + file);
  fs::remove_all(dir);
  Handles h(case_file);
  REQUIRE(mhc_workspace_keep_grids(h.ws, 1) == MHC_OK);
  mhc_subsurface_options opt;
  mhc_subsurface_options_init(&opt);
  opt.dang_van_c = dang_van_c;
  std::size_t row = 0;
  for (const Row& c : cases) {
    mhc_result r;
    r.struct_size = sizeof r;
    REQUIRE(mhc_solve_load(h.pair, h.ws, std::stod(c.at("tY_mm")) * 1e-3, 0.0, std::stod(c.at("Q_kN")) * 1e3, &r) ==
            MHC_OK);
    for (int32_t i = 0; i < r.n_contacts; ++i, ++row) {
      REQUIRE(row < rows.size());
      const Row& w = rows[row];
      INFO("case " << c.at("case") << ", contact " << i);
      REQUIRE(w.at("case") == c.at("case"));
      mhc_contact_subsurface s;
      s.struct_size = sizeof s;
      REQUIRE(mhc_result_subsurface(h.ws, i, &opt, &s) == MHC_OK);
      CHECK(w.at("sub_source") == source_name(s.source));
      CHECK(s.warnings == 0u);
      // The writer's conversions (x / MPa, depth * per_mm): the same doubles.
      CHECK(std::stod(w.at("sub_vm_max_MPa")) == s.vm_max_Pa / 1e6);
      CHECK(std::stod(w.at("sub_vm_depth_mm")) == s.vm_depth_m * 1e3);
      CHECK(std::stod(w.at("sub_tau_max_MPa")) == s.tau_max_Pa / 1e6);
      CHECK(std::stod(w.at("sub_tau_depth_mm")) == s.tau_depth_m * 1e3);
      CHECK(std::stod(w.at("sub_tau_orth_amp_MPa")) == s.tau_orth_amp_Pa / 1e6);
      CHECK(std::stod(w.at("sub_tau_orth_depth_mm")) == s.tau_orth_depth_m * 1e3);
      CHECK(std::stod(w.at("sub_tau_eq_amp_MPa")) == s.tau_eq_amp_Pa / 1e6);
      CHECK(std::stod(w.at("sub_sigma_h_MPa")) == s.sigma_h_Pa / 1e6);
      if (std::isnan(dang_van_c))  // no c: FI_sub NaN in both
        CHECK((std::isnan(std::stod(w.at("FI_sub_MPa"))) && std::isnan(s.FI_sub_Pa)));
      else
        CHECK(std::stod(w.at("FI_sub_MPa")) == s.FI_sub_Pa / 1e6);
      if (kept) kept->push_back(s);
    }
  }
  CHECK(row == rows.size());
  return row;
}

}  // namespace

TEST_CASE("C subsurface: a half-space patch's stresses are patches.csv's, and CONTACT's", "[capi][rcf][subsurface]") {
  const std::string path = write_case("hs");
  std::vector<mhc_contact_subsurface> got;
  CHECK(compare_with_command(path, "patches.csv", 0.3, &got) == 1);
  fs::remove(path);
  REQUIRE(got.size() == 1);
  const mhc_contact_subsurface& s = got[0];
  CHECK(s.source == MHC_SUBSURFACE_GRID_PATCH_SOLVED_TRACTION);
  // CONTACT's peak over its points below its own solution of the same case (module 1,
  // tests/data/contact_subsurface_wheelrail/tread_yaw_depths.csv: von Mises 405.8 MPa at 0.75 mm,
  // the orthogonal shear amplitude 107.6 MPa at 0.75 mm; test_grid_subsurface_wheelrail_contact.cpp).
  WARN("C API vm " << s.vm_max_Pa / 1e6 << " MPa at " << s.vm_depth_m * 1e3 << " mm, orth " << s.tau_orth_amp_Pa / 1e6
                   << " MPa at " << s.tau_orth_depth_m * 1e3 << " mm");
  // docs/c-api.md "Subsurface stresses" shows this case's output as its example prints it: each
  // line is a line of the page.
  std::ifstream doc(kSrc + "/docs/c-api.md");
  REQUIRE(doc);
  std::vector<std::string> page;
  for (std::string l; std::getline(doc, l);) page.push_back(l);
  char buf[4][160];
  std::snprintf(buf[0], sizeof buf[0], "    source %d, warnings %u", static_cast<int>(s.source), static_cast<unsigned>(s.warnings));
  std::snprintf(buf[1], sizeof buf[1], "    von Mises %.1f MPa at %.3f mm", s.vm_max_Pa / 1e6, s.vm_depth_m * 1e3);
  std::snprintf(buf[2], sizeof buf[2], "    orthogonal shear amplitude %.1f MPa at %.3f mm", s.tau_orth_amp_Pa / 1e6,
                s.tau_orth_depth_m * 1e3);
  std::snprintf(buf[3], sizeof buf[3], "    tau_eq,a %.1f MPa, sigma_h %.1f MPa, FI_sub %.1f MPa", s.tau_eq_amp_Pa / 1e6,
                s.sigma_h_Pa / 1e6, s.FI_sub_Pa / 1e6);
  for (const char* line : buf) {
    INFO(line);
    CHECK(std::find(page.begin(), page.end(), std::string(line)) != page.end());
  }
}

TEST_CASE("C subsurface: FASTSIM ellipses' stresses are ellipses.csv's", "[capi][rcf][subsurface]") {
  // cases/manchester-rcf.json's first t_Y only would do; the tangential case file has friction and
  // kinematics: its rows with "rcf": {"subsurface": {}} added.
  std::ifstream in(kSrc + "/cases/manchester-tangential.json");
  std::stringstream text;
  text << in.rdbuf();
  std::string j = text.str();
  for (const char* prof : {"MBench_S1002_v3.prw", "MBench_UIC60_v3.prr"}) {
    const std::string rel = std::string("../profiles/") + prof;
    const std::size_t at = j.find(rel);
    if (at != std::string::npos) j.replace(at, rel.size(), kSrc + "/profiles/" + prof);
  }
  const std::string sweep = "\"sweep\"";
  j.replace(j.find(sweep), j.size() - j.find(sweep),
            "\"rcf\": {\"shear_yield_MPa\": 300, \"subsurface\": {}},\n"
            "  \"sweep\": {\"tY_mm\": [2], \"Q_kN\": [50]}\n}\n");
  const std::string path = fs::temp_directory_path() / ("mhcontact_capi_subs_fs" + std::to_string(::getpid()) + ".json");
  { std::ofstream(path) << j; }
  CHECK(compare_with_command(path, "ellipses.csv", NAN) >= 1);
  fs::remove(path);
}

TEST_CASE("C subsurface: grids not kept, options and arguments", "[capi][rcf][subsurface]") {
  const std::string path = write_case("args");
  Handles h(path);
  fs::remove(path);
  mhc_result r;
  r.struct_size = sizeof r;
  REQUIRE(mhc_solve_load(h.pair, h.ws, 0.5e-3, 0.0, 10e3, &r) == MHC_OK);
  REQUIRE(r.n_contacts == 1);
  mhc_contact_subsurface s;
  s.struct_size = sizeof s;
  // Solved without keeping the grid: the patch's pressure (kept for its tangential solve) with full
  // slip, not its solved traction, and the warning saying so.
  REQUIRE(mhc_result_subsurface(h.ws, 0, nullptr, &s) == MHC_OK);
  CHECK(s.source == MHC_SUBSURFACE_GRID_PATCH);
  CHECK((s.warnings & MHC_SUBSURFACE_WARN_GRID_NOT_KEPT) != 0u);
  CHECK(s.vm_max_Pa > 0);
  CHECK(std::isnan(s.FI_sub_Pa));
  mhc_subsurface_options opt;
  mhc_subsurface_options_init(&opt);
  opt.traction = 0.3;  // with friction: each contact's own
  CHECK(mhc_result_subsurface(h.ws, 0, &opt, &s) == MHC_ERR_ARGUMENT);
  CHECK(std::string(mhc_last_message()).find("traction") != std::string::npos);
  mhc_subsurface_options_init(&opt);
  opt.dang_van_c = 2;
  CHECK(mhc_result_subsurface(h.ws, 0, &opt, &s) == MHC_ERR_ARGUMENT);
  opt.dang_van_c = NAN;
  opt.grid = 2;
  CHECK(mhc_result_subsurface(h.ws, 0, &opt, &s) == MHC_ERR_ARGUMENT);
  CHECK(mhc_result_subsurface(h.ws, 1, nullptr, &s) == MHC_ERR_ARGUMENT);
  CHECK(mhc_result_subsurface(h.ws, -1, nullptr, &s) == MHC_ERR_ARGUMENT);
  s.struct_size = sizeof s - 8;
  CHECK(mhc_result_subsurface(h.ws, 0, nullptr, &s) == MHC_ERR_ARGUMENT);
  CHECK(mhc_result_subsurface(h.ws, 0, nullptr, nullptr) == MHC_ERR_ARGUMENT);
}
