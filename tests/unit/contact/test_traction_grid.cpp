// The tractions per element kept for the traction grid (contact/tangential/traction_grid.hpp),
// against closed forms nobody computed with this code:
//  - FASTSIM in full sliding: the traction is μ times the Hertz pressure p0 √(1 − x²/a² − y²/b²)
//    everywhere, directed against the creepage (Coulomb; Kalker 1982);
//  - the exact half-space solution of a 2-D rolling contact: Carter's traction (Carter 1926;
//    Johnson, Contact Mechanics §8.2, eqs. 8.41–8.43), its adhesion zone at the leading edge of
//    half-width a' = a √(1 − |F|/(μN)).
// Breaks seen to fail: the FASTSIM sample's bound pressure taken from the nearest cell instead of
// at the point (full-slip |p| off μ p by 17 % of μ p0, and above the bound in partial slip); the
// kept half-space tractions negated (their sum no longer Fx; 2-D profile off Carter); every
// seventh kept element flagged slip (inside Carter's adhesion zone).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "contact/case_result.hpp"
#include "contact/half_space/tangential_patch.hpp"
#include "contact/tangential/fastsim.hpp"
#include "contact/tangential/traction_grid.hpp"

using namespace mh;

namespace {
constexpr double pi = 3.14159265358979323846;
}  // namespace

TEST_CASE("FASTSIM cells in full sliding: |p| = mu p_Hertz at every cell, against the creepage",
          "[tangential][fastsim][traction]") {
  // a = 6, b = 4 mm, N = 50 kN, μ = 0.3, ξ = 0.05: far beyond saturation (μN/(G c² C11) ≈ 1e-3).
  const double a = 6e-3, b = 4e-3, N = 50e3, mu = 0.3, G = 82e9, nu = 0.28;
  const double p0 = 1.5 * N / (pi * a * b);
  EllipseTraction t;
  const TangentialResult r = fastsim({0.05, 0, 0}, a, b, N, mu, G, nu, FastsimOptions{}, &t.cells);
  REQUIRE(r.solved);
  REQUIRE(t.cells.nx == 32);
  REQUIRE(t.cells.ny == 32);
  CHECK(r.adhesion_fraction == 0);
  double worst_cell = 0, worst_point = 0;
  for (std::size_t i = 0; i < t.cells.px.size(); ++i) {
    const double x = t.cells.x[i], y = t.cells.y[i];
    const double ph = p0 * std::sqrt(1 - x * x / (a * a) - y * y / (b * b));
    CHECK(t.cells.slip[i] == 1);
    CHECK(t.cells.px[i] < 0);  // on the wheel, against ξ > 0 (tangential_types.hpp)
    CHECK(std::abs(t.cells.py[i]) <= 1e-9 * mu * p0);
    worst_cell = std::max(worst_cell, std::abs(std::hypot(t.cells.px[i], t.cells.py[i]) - mu * ph) / (mu * p0));
  }
  // The bound's pressure is normalised to carry N on the cells (fastsim.hpp): a uniform factor,
  // 0.22 % below Hertz at 32 × 32 (docs/python.md's grid example: |p_t|/(μ p) = 0.9978).
  CHECK(worst_cell < 3e-3);
  // Anywhere inside the ellipse, between and beyond the cell centres (a 41 × 41 grid).
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j) {
      const double x = -a + 2 * a * i / 40, y = -b + 2 * b * j / 40;
      const double q = 1 - x * x / (a * a) - y * y / (b * b);
      const TractionSample s = fastsim_traction_at(t, a, b, mu, x, y);
      if (!(q > 0)) {
        CHECK(s.px == 0);
        CHECK(s.py == 0);
        CHECK_FALSE(s.slip);
        continue;
      }
      CHECK(s.slip);
      CHECK(s.px < 0);
      worst_point = std::max(worst_point, std::abs(std::hypot(s.px, s.py) - mu * p0 * std::sqrt(q)) / (mu * p0));
    }
  CHECK(worst_point < 3e-3);
  WARN("full sliding: largest | |p| - mu p_Hertz | / (mu p0): cells " << worst_cell << ", grid points " << worst_point);
}

TEST_CASE("FASTSIM sample in partial slip: never above the bound, slip on it, the cells' values at their centres",
          "[tangential][fastsim][traction]") {
  const double a = 5e-3, b = 7e-3, N = 60e3, mu = 0.3, G = 82e9, nu = 0.28;
  EllipseTraction t;
  const TangentialResult r = fastsim({-6e-4, 4e-4, 0.3}, a, b, N, mu, G, nu, FastsimOptions{}, &t.cells);
  REQUIRE(r.solved);
  REQUIRE(r.adhesion_fraction > 0.2);
  REQUIRE(r.adhesion_fraction < 0.8);
  const double P = 1.5 * N / (pi * a * b) * 1.01;  // above the cells' bound (normalised within 0.3 %)
  int n_slip = 0, n_adh = 0;
  for (int i = 0; i <= 60; ++i)
    for (int j = 0; j <= 60; ++j) {
      const double x = -a + 2 * a * i / 60, y = -b + 2 * b * j / 60;
      const double q = 1 - x * x / (a * a) - y * y / (b * b);
      if (!(q > 0)) continue;
      const TractionSample s = fastsim_traction_at(t, a, b, mu, x, y);
      const double pt = std::hypot(s.px, s.py), bound = mu * P * std::sqrt(q);
      CHECK(pt <= bound);
      (s.slip ? n_slip : n_adh) += 1;
    }
  CHECK(n_slip > 0);
  CHECK(n_adh > 0);
  // At a cell centre the sample is that cell's traction.
  for (std::size_t i = 0; i < t.cells.px.size(); i += 37) {
    const TractionSample s = fastsim_traction_at(t, a, b, mu, t.cells.x[i], t.cells.y[i]);
    CHECK(s.px == Approx(t.cells.px[i]).margin(1e-9 * mu * P));
    CHECK(s.py == Approx(t.cells.py[i]).margin(1e-9 * mu * P));
    CHECK(s.slip == (t.cells.slip[i] != 0));
  }
}

TEST_CASE("Kept half-space tractions, 2-D rolling: Carter's traction and adhesion zone",
          "[tangential_rolling][traction]") {
  // One row of elements 10⁴ a long in y: the 2-D problem (as in test_tangential_half_space.cpp).
  // Hertz in 2-D: p0 = a E*/(2R), E* = G/(1 − ν) for equal bodies. Carter: with k = R ξ/(μ a),
  // |F|/(μN) = 1 − (1 − k)², the adhesion zone x ∈ [a − 2a', a] with a' = a √(1 − |F|/(μN));
  // the traction on the wheel px = −μ p0 [√(1 − x²/a²) − (a'/a) √(1 − ((x − a + a')/a')²)] there,
  // −μ p(x) in the slip zone (ξ > 0).
  const double a = 1e-3, p0 = 1e9, G = 82e9, nu = 0.28, mu = 0.3, L = 1e4 * a;
  const int n = 200;
  const double dx = 2 * a / n, R = a * G / (2 * (1 - nu) * p0);
  PatchResult patch;
  patch.patch = 1;
  patch.nx = n;
  patch.ns = 1;
  patch.dx = dx;
  patch.ds = L;
  patch.x0 = -a + dx / 2;
  patch.s0 = 0;
  patch.p.resize(n);
  double N = 0;
  for (int i = 0; i < n; ++i) {
    const double x = patch.x0 + i * dx;
    patch.p[i] = p0 * std::sqrt(1 - x * x / (a * a));
    N += patch.p[i] * dx * L;
  }
  Material m;  // steel: only equal bodies matter here; G, ν of the solve are the material's
  m.E = 2 * G * (1 + nu);
  m.nu = nu;
  for (double k : {0.3, 0.6}) {
    const double xi = k * mu * a / R;
    PatchTraction keep;
    const HalfSpaceTangentialResult r = solve_tangential_patch(patch, m, {xi, 0, 0}, mu, {}, &keep);
    INFO("R xi/(mu a) = " << k);
    REQUIRE(r.status == TangentialStatus::Ok);
    REQUIRE(keep.nx == n);
    REQUIRE(keep.ns == 1);
    REQUIRE(keep.pn == patch.p);
    // The kept tractions are the forces' elements.
    double Fx = 0;
    for (int i = 0; i < n; ++i) Fx += keep.px[i] * dx * L;
    CHECK(Fx == Approx(r.forces.Fx).epsilon(1e-12));
    const double f = std::abs(r.forces.Fx) / (mu * N);
    const double ap = a * std::sqrt(1 - f);  // Carter's a' from the solve's own force
    // Adhesion zone: from the leading edge back to x = a − 2a', within one element.
    double x_trail = a;
    for (int i = 0; i < n; ++i)
      if (!keep.slip[i]) x_trail = std::min(x_trail, patch.x0 + i * dx);
    CHECK(std::abs(x_trail - (a - 2 * ap)) <= 1.0 * dx);
    for (int i = 0; i < n; ++i) {
      const double x = patch.x0 + i * dx;
      if (x > a - 2 * ap + dx) CHECK_FALSE(keep.slip[i]);
      if (x < a - 2 * ap - dx) CHECK(keep.slip[i]);
    }
    // The profile: within 1.5 % of μ p0 at every element (200 elements over 2a).
    double worst = 0;
    for (int i = 0; i < n; ++i) {
      const double x = patch.x0 + i * dx, d = a - ap;
      double c = std::sqrt(1 - x * x / (a * a));
      if (std::abs(x - d) < ap) c -= (ap / a) * std::sqrt(1 - (x - d) * (x - d) / (ap * ap));
      worst = std::max(worst, std::abs(keep.px[i] - (-mu * p0 * c)) / (mu * p0));
      CHECK(std::abs(keep.py[i]) <= 1e-9 * mu * p0);
    }
    CHECK(worst < 0.015);
    WARN("Carter k = " << k << ": a'/a " << ap / a << " (closed form " << 1 - k << "), largest |px - Carter| / (mu p0) "
                       << worst);
  }
}

TEST_CASE("Kept tractions: nothing kept unless asked, and cleared on a failed solve", "[tangential_rolling][traction]") {
  PatchResult patch;
  patch.nx = 4;
  patch.ns = 4;
  patch.dx = patch.ds = 1e-3;
  patch.p.assign(16, 1e8);
  Material m;
  m.E_rail = 100e9;  // unequal bodies: refused
  PatchTraction keep;
  keep.nx = 3;
  keep.px.assign(9, 1.0);
  const HalfSpaceTangentialResult r = solve_tangential_patch(patch, m, {1e-3, 0, 0}, 0.3, {}, &keep);
  CHECK(r.status == TangentialStatus::NotConverged);
  CHECK(keep.empty());
  CHECK(keep.px.empty());
}
