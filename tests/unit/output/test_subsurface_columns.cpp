// The subsurface columns of a grid patch (output/rcf_columns.hpp, their stresses from
// contact/rcf/contact_stresses.hpp; docs/outputs.md "Subsurface columns"): with "subsurface": {"grid": true} from the patch's own element pressure
// (grid_subsurface), otherwise, and always for a patch with elements at the plastic cap, from its
// elastic Hertz ellipse. A patch whose pressure is a Hertzian ellipse's sampled on 0.4 mm elements
// must give the ellipse's columns within the tolerances of the grid-against-Hertz test
// (tests/unit/contact/test_grid_subsurface.cpp, docs/methods.md "Below a grid patch": the same
// ellipse, elements and ν), frictionless and with full-slip traction f = 0.3.
// Broken once to see it fail: the patch's element grid read transposed (nx and ns swapped in
// patch_pressure, contact_stresses.cpp): every peak compared failed.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <string>

#include "output/rcf_columns.hpp"

using namespace mh;

namespace {

struct MapSink {
  std::map<std::string, double> v;
  std::map<std::string, std::string> t;
  void number(const char* n, double x) { v[n] = x; }
  void optional(const char* n, double x) { v[n] = x; }
  void integer(const char* n, long long i) { v[n] = static_cast<double>(i); }
  void text(const char* n, const char* s) { t[n] = s ? s : ""; }
};

// A Hertzian pressure p0 √(1 − x²/a² − s²/b²) at the centres of h × h elements, as a half-space
// patch keeps it, with the ellipse's semi-axes as its elastic Hertz ellipse.
PatchResult hertz_patch(double a, double b, double p0, double h) {
  PatchResult P;
  P.nx = 2 * static_cast<int>(std::ceil(a / h)) + 1, P.ns = 2 * static_cast<int>(std::ceil(b / h)) + 1;
  P.dx = P.ds = h;
  P.x0 = -h * (P.nx / 2), P.s0 = -h * (P.ns / 2);
  P.p.assign(static_cast<std::size_t>(P.nx * P.ns), 0.0);
  for (int j = 0; j < P.ns; ++j)
    for (int i = 0; i < P.nx; ++i) {
      const double x = P.x0 + i * h, s = P.s0 + j * h, q = 1 - x * x / (a * a) - s * s / (b * b);
      P.p[static_cast<std::size_t>(i + P.nx * j)] = q > 0 ? p0 * std::sqrt(q) : 0.0;
    }
  P.a_el = a, P.b_el = b;
  P.N = 2.0 / 3.0 * M_PI * a * b * p0;  // the ellipse's load (subsurface_of takes p0 = 1.5 N/(π a b))
  return P;
}

}  // namespace

TEST_CASE("Subsurface columns: a grid patch's own pressure against its Hertz ellipse", "[rcf][subsurface][grid][output]") {
  const double a = 6e-3, b = 4e-3, p0 = 1e9, p0_MPa = 1e3, b_mm = 4;
  const PatchResult P = hertz_patch(a, b, p0, 0.4e-3);
  for (double f : {0.0, 0.3}) {
    CAPTURE(f);
    RcfOptions o;
    o.f = f, o.k = 300e6, o.subsurface = true, o.nu = 0.3;  // ν of the grid test
    MapSink ell, grid;
    rcf_fields(ell, o, P.N, P.a_el, P.b_el, P.t, &P);  // grid off: the ellipse
    o.subsurface_grid = true;
    rcf_fields(grid, o, P.N, P.a_el, P.b_el, P.t, &P);
    CHECK(ell.t["sub_source"] == "hertz_ellipse");
    CHECK(grid.t["sub_source"] == "grid_patch");
    // The tolerances of the grid-against-Hertz test (test_grid_subsurface.cpp), in units of p0 and b.
    CHECK(grid.v["sub_vm_max_MPa"] == Approx(ell.v["sub_vm_max_MPa"]).margin(1e-3 * p0_MPa));
    CHECK(grid.v["sub_vm_depth_mm"] == Approx(ell.v["sub_vm_depth_mm"]).margin(5e-3 * b_mm));
    CHECK(grid.v["sub_tau_max_MPa"] == Approx(ell.v["sub_tau_max_MPa"]).margin(1e-3 * p0_MPa));
    CHECK(grid.v["sub_tau_depth_mm"] == Approx(ell.v["sub_tau_depth_mm"]).margin(5e-3 * b_mm));
    CHECK(grid.v["sub_tau_orth_amp_MPa"] == Approx(ell.v["sub_tau_orth_amp_MPa"]).margin(3e-3 * p0_MPa));
    CHECK(grid.v["sub_tau_eq_amp_MPa"] == Approx(ell.v["sub_tau_eq_amp_MPa"]).margin(2e-3 * p0_MPa));
    CHECK(grid.v["sub_sigma_h_MPa"] == Approx(ell.v["sub_sigma_h_MPa"]).margin(0.02 * p0_MPa));
  }
  // A patch with elements at the plastic cap: the elastic Hertz ellipse of its load, never its
  // capped pressure.
  PatchResult Q = P;
  Q.plastic_area = 1e-6;
  RcfOptions o;
  o.f = 0, o.k = 300e6, o.subsurface = true, o.subsurface_grid = true, o.nu = 0.28;
  MapSink m;
  rcf_fields(m, o, Q.N, Q.a_el, Q.b_el, Q.t, &Q);
  CHECK(m.t["sub_source"] == "hertz_ellipse");
}
