// The C interface's RCF accessors (include/mhcontact.h, lib/capi/rcf.cpp): the subsurface peaks of
// a circular Hertz contact against the closed form (Johnson eq. 3.45: (σ1 − σ3)/2 = 0.310 p0 at
// 0.481 a for ν = 0.3, tests/support/hertz_subsurface_reference.hpp), and one contact's damage and
// wear against the published functions re-evaluated here from its own Tγ and area; argument errors.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <string>

#include <mhcontact.h>

#include "support/hertz_subsurface_reference.hpp"

namespace {
const std::string kSrc = MHCONTACT_SOURCE_DIR;
}

TEST_CASE("C API: mhc_hertz_subsurface on a circle against Johnson eq. 3.45", "[capi][rcf]") {
  double tmax = 0, zmax = 0;
  for (int i = 1; i <= 20000; ++i) {
    const auto r = mh::testing::hertz_circle_axis(i * 1e-4, 0.3);
    if (0.5 * (r.r - r.z) > tmax) tmax = 0.5 * (r.r - r.z), zmax = i * 1e-4;
  }
  mhc_subsurface s;
  std::memset(&s, 0xab, sizeof s);
  s.struct_size = sizeof s;
  REQUIRE(mhc_hertz_subsurface(1e-3, 1e-3, 1e9, 0, 0, 0.3, &s) == MHC_OK);
  CHECK(s.tau_max_Pa / 1e9 == Approx(tmax).margin(1e-3));
  CHECK(s.tau_depth_m / 1e-3 == Approx(zmax).margin(0.01));
  CHECK(s.vm_max_Pa / 1e9 == Approx(2 * tmax).margin(2e-3));  // σ_r = σ_θ on the axis: σ_vM = σ1 − σ3
  CHECK(mhc_hertz_subsurface(0, 1e-3, 1e9, 0, 0, 0.3, &s) == MHC_ERR_ARGUMENT);
  CHECK(std::string(mhc_last_message()).find("a_m") != std::string::npos);
  CHECK(mhc_hertz_subsurface(1e-3, 1e-3, 1e9, 1.5, 0, 0.3, &s) == MHC_ERR_ARGUMENT);
  s.struct_size = sizeof s - 8;
  CHECK(mhc_hertz_subsurface(1e-3, 1e-3, 1e9, 0, 0, 0.3, &s) == MHC_ERR_ARGUMENT);
}

TEST_CASE("C API: mhc_result_rcf gives the damage and wear functions of the contact's own Tγ", "[capi][rcf]") {
  mhc_pair* pair = nullptr;
  REQUIRE(mhc_pair_from_case_file((kSrc + "/cases/manchester-rcf.json").c_str(), &pair) == MHC_OK);
  mhc_workspace* ws = nullptr;
  REQUIRE(mhc_workspace_create(pair, &ws) == MHC_OK);
  mhc_result r;
  std::memset(&r, 0, sizeof r);
  r.struct_size = sizeof r;
  REQUIRE(mhc_solve_load(pair, ws, 1e-3, 0.0, 100e3, &r) == MHC_OK);  // Tγ 9 and 59 J/m (docs/methods.md)
  REQUIRE(r.n_contacts >= 1);
  bool damaged = false;
  for (int32_t i = 0; i < r.n_contacts; ++i) {
    mhc_rcf_contact c;
    std::memset(&c, 0xab, sizeof c);
    c.struct_size = sizeof c;
    REQUIRE(mhc_result_rcf(ws, i, 300e6, &c) == MHC_OK);
    CAPTURE(i, c.Tgamma_N, c.traction);
    CHECK(c.traction >= 0);
    CHECK(c.traction <= 0.3 * (1 + 1e-9));  // |F| ≤ μ N
    const double T = c.Tgamma_N;            // Burstow 2004: 15, 65, 175 J/m, 1e-5 at the peak
    const double D = T <= 15 || T >= 175 ? 0.0 : T <= 65 ? 1e-5 * (T - 15) / 50 : 1e-5 * (175 - T) / 110;
    CHECK(c.damage_per_axle == Approx(D).margin(1e-15));
    damaged = damaged || D > 0;
    // FI_surf = f − k/p0_el (Ekberg et al. 2002)
    CHECK(c.FI_surf_el == Approx(c.traction - 300e6 / c.p0_el_Pa).margin(1e-12));
    CHECK(c.p0_el_over_k == Approx(c.p0_el_Pa / 300e6).epsilon(1e-12));
    CHECK(c.shakedown_regime >= 0);
    CHECK(c.wear_kg_per_m >= 0);
  }
  CHECK(damaged);
  mhc_rcf_contact c;
  c.struct_size = sizeof c;
  CHECK(mhc_result_rcf(ws, r.n_contacts, 300e6, &c) == MHC_ERR_ARGUMENT);
  c.struct_size = 8;
  CHECK(mhc_result_rcf(ws, 0, 300e6, &c) == MHC_ERR_ARGUMENT);
  mhc_workspace_free(ws);
  mhc_pair_free(pair);
}
