// The C interface's tangential problem (include/mhcontact.h, "tangential contact"): the creep
// forces of a case file with friction through mhc_result_tangential, the same bytes as the
// library's own solve; mhc_pair_set_tangential on a pair built from options giving the same
// numbers as the case file's keys; an older caller's smaller mhc_tangential_options (without
// vertical_equilibrium) keeping the default; the equilibrium switch; errors naming the field.
// Breaks seen to fail: mhc_pair_set_tangential ignoring yaw_rad_per_m ("set_tangential as the
// case file"); the older struct_size refused ("an older header").
#include <catch2/catch.hpp>

#include <mhcontact.h>

#include <cmath>
#include <cstddef>
#include <string>

#include "contact/solve.hpp"
#include "input/case_file.hpp"
#include "jobs/run.hpp"

namespace {
const std::string kSrc = MHCONTACT_SOURCE_DIR;
const std::string kCase = kSrc + "/cases/manchester-tangential.json";

struct Solved {
  mhc_result r;
  mhc_tangential t;
};

Solved solve(const mhc_pair* pair, double tY, double Q) {
  mhc_workspace* ws = nullptr;
  REQUIRE(mhc_workspace_create(pair, &ws) == MHC_OK);
  Solved s;
  s.r.struct_size = sizeof s.r;
  s.t.struct_size = sizeof s.t;
  REQUIRE(mhc_solve_load(pair, ws, tY, 0.0, Q, &s.r) == MHC_OK);
  REQUIRE(mhc_result_tangential(ws, &s.t) == MHC_OK);
  mhc_workspace_free(ws);
  return s;
}

mhc_pair* manchester_from_options() {
  mhc_profile *w = nullptr, *r = nullptr;
  REQUIRE(mhc_profile_read((kSrc + "/profiles/MBench_S1002_v3.prw").c_str(), MHC_WHEEL, &w) == MHC_OK);
  REQUIRE(mhc_profile_read((kSrc + "/profiles/MBench_UIC60_v3.prr").c_str(), MHC_RAIL, &r) == MHC_OK);
  mhc_pair_options o;
  mhc_pair_options_init(&o);
  mhc_pair* p = nullptr;
  REQUIRE(mhc_pair_create(w, r, &o, &p) == MHC_OK);
  mhc_profile_free(w);
  mhc_profile_free(r);
  return p;
}
}  // namespace

TEST_CASE("C API: creep forces of a case file with friction, as the library solves them", "[capi][tangential]") {
  mhc_pair* pair = nullptr;
  REQUIRE(mhc_pair_from_case_file(kCase.c_str(), &pair) == MHC_OK);
  const mh::CaseFile cf = mh::load_case_file(kCase, false);
  const mh::PairGeometry pg = mh::build_pair_geometry(cf);
  for (double tY : {2e-3, 8e-3}) {
    INFO("t_Y " << tY);
    const Solved s = solve(pair, tY, 10e3);
    const mh::CaseResult ref = mh::solve_contact(pg.geo, cf.material, tY, 10e3, cf.method_options());
    REQUIRE(s.t.asked == 1);
    REQUIRE(s.t.solved == 1);
    CHECK(s.t.mu == 0.3);
    CHECK(s.t.Fx_N == ref.tangential.Fx);
    CHECK(s.t.Fy_creep_N == ref.tangential.Fy_creep);
    CHECK(s.t.Mz_Nm == ref.tangential.Mz);
    CHECK(s.t.Fz_creep_N == ref.tangential.Fz_creep);
    CHECK(s.t.Y_N == ref.Fy + ref.tangential.Fy_creep);
    REQUIRE(s.t.n_contacts == static_cast<int32_t>(ref.loaded.size()));
    for (std::size_t k = 0; k < ref.loaded.size(); ++k) {
      const mh::TangentialResult& t = ref.loaded[k].t;
      CHECK(s.t.contact[k].Fx_N == -t.Fx);  // on the rail
      CHECK(s.t.contact[k].Fy_N == -t.Fy);
      CHECK(s.t.contact[k].eta == t.c.eta);
      CHECK(s.t.contact[k].adhesion_fraction == t.adhesion_fraction);
    }
    // The vertical load balanced with the creep forces (docs/method.md §10).
    double Fz = 0;
    for (int k = 0; k < s.r.n_contacts; ++k) Fz += s.r.contact[k].Fz_N;
    CHECK(Fz + s.t.Fz_creep_N == Approx(10e3).epsilon(1e-6));
  }
  mhc_pair_free(pair);
}

TEST_CASE("C API: set_tangential as the case file, an older header's struct, the equilibrium off, errors", "[capi][tangential]") {
  mhc_pair* file = nullptr;
  REQUIRE(mhc_pair_from_case_file(kCase.c_str(), &file) == MHC_OK);
  mhc_pair* pair = manchester_from_options();
  // Without friction: nothing asked, NaN.
  const Solved none = solve(pair, 8e-3, 10e3);
  CHECK(none.t.asked == 0);
  CHECK(std::isnan(none.t.Fx_N));
  mhc_tangential_options o;
  mhc_tangential_options_init(&o);
  CHECK(std::isnan(o.mu));
  CHECK(o.vertical_equilibrium == 1);
  o.mu = 0.3;
  o.speed_m_s = 30;
  o.yaw_rad_per_m = 2.4;  // the case file's yaw_mrad_per_mm 2.4
  REQUIRE(mhc_pair_set_tangential(pair, &o) == MHC_OK);
  const Solved a = solve(pair, 8e-3, 10e3), b = solve(file, 8e-3, 10e3);
  CHECK(a.t.Fx_N == b.t.Fx_N);
  CHECK(a.t.Fy_creep_N == b.t.Fy_creep_N);
  CHECK(a.t.Fz_creep_N == b.t.Fz_creep_N);
  CHECK(a.r.contact[0].N_N == b.r.contact[0].N_N);

  SECTION("an older header: struct_size without vertical_equilibrium keeps the default (on)") {
    mhc_tangential_options old = o;
    old.vertical_equilibrium = 0;  // beyond the older struct: not read
    old.struct_size = offsetof(mhc_tangential_options, vertical_equilibrium);
    REQUIRE(mhc_pair_set_tangential(pair, &old) == MHC_OK);
    const Solved c = solve(pair, 8e-3, 10e3);
    CHECK(c.r.contact[0].N_N == a.r.contact[0].N_N);
  }
  SECTION("vertical_equilibrium 0: sum N cos(gamma) = Q, N as without friction") {
    o.vertical_equilibrium = 0;
    REQUIRE(mhc_pair_set_tangential(pair, &o) == MHC_OK);
    const Solved c = solve(pair, 8e-3, 10e3);
    REQUIRE(c.r.n_contacts == none.r.n_contacts);
    for (int k = 0; k < c.r.n_contacts; ++k) CHECK(c.r.contact[k].N_N == none.r.contact[k].N_N);
    double Fz = 0;
    for (int k = 0; k < c.r.n_contacts; ++k) Fz += c.r.contact[k].Fz_N;
    CHECK(Fz == Approx(10e3).epsilon(1e-9));
    CHECK(std::abs(Fz + c.t.Fz_creep_N - 10e3) > 1e3);  // the creep forces' share is large on the flange
  }
  SECTION("errors name the field, the value and the rule") {
    mhc_tangential_options bad = o;
    bad.mu = -0.1;
    CHECK(mhc_pair_set_tangential(pair, &bad) == MHC_ERR_ARGUMENT);
    CHECK(std::string(mhc_last_message()).find("tangential options.mu = -0.1") != std::string::npos);
    bad = o;
    bad.speed_m_s = 0;
    CHECK(mhc_pair_set_tangential(pair, &bad) == MHC_ERR_ARGUMENT);
    CHECK(std::string(mhc_last_message()).find("speed_m_s") != std::string::npos);
    bad = o;
    bad.struct_size = 8;
    CHECK(mhc_pair_set_tangential(pair, &bad) == MHC_ERR_ARGUMENT);
    CHECK(std::string(mhc_last_message()).find("struct_size = 8") != std::string::npos);
    mhc_workspace* ws = nullptr;
    REQUIRE(mhc_workspace_create(pair, &ws) == MHC_OK);
    mhc_tangential t;
    t.struct_size = 16;
    CHECK(mhc_result_tangential(ws, &t) == MHC_ERR_ARGUMENT);
    mhc_workspace_free(ws);
  }
  mhc_pair_free(pair);
  mhc_pair_free(file);
}
