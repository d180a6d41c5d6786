// Tests of the half-space tangential influence coefficients (tangential_influence.hpp), the row
// DC-FFT (influence.hpp, RowFft) and the exact steady-rolling solver (tangential_rolling.hpp),
// against references computed without this code: a direct quadrature of Cerruti's kernel,
// Coulomb's full sliding, Carter's 2-D closed form, Kalker's linear theory (Table E.3) and
// CONTACT's exact solution on the same grid (tests/data/contact_tangential/hstang/).
#include <catch2/catch.hpp>

#include <chrono>
#include <cstdio>
#include <cmath>
#include <complex>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "contact/half_space/influence.hpp"
#include "contact/half_space/tangential_influence.hpp"
#include "contact/half_space/tangential_patch.hpp"
#include "contact/half_space/tangential_rolling.hpp"
#include "contact/tangential/kalker.hpp"
#include "support/gauss_legendre.hpp"
#include "support/hertz_grid.hpp"
#include "support/kalker_series.hpp"

namespace {

constexpr double pi = 3.14159265358979323846;

using GaussLegendre24 = GaussLegendre<24>;  // tests/support/gauss_legendre.hpp
const GaussLegendre24 gl;

/// ∫ f over [t0, t1], composite Gauss on m pieces.
double gauss1(const std::function<double(double)>& f, double t0, double t1, int m) {
  double s = 0;
  const double h = (t1 - t0) / m;
  for (int k = 0; k < m; ++k)
    for (int i = 0; i < GaussLegendre24::n; ++i)
      s += 0.5 * h * gl.w[i] * f(t0 + h * (k + 0.5 + 0.5 * gl.x[i]));
  return s;
}

/// Cerruti's kernels as functions of the angle θ of the source seen from the field point
/// (s = x − ξ = −ρ cos θ, t = y − η = −ρ sin θ): K = f(θ)/ρ with f = 1, cos², sin², cos·sin.
/// Over a rectangle containing the field point, in polar coordinates about it,
/// ∫∫ K dA = ∫ f(θ) R(θ) dθ (R the distance to the boundary): a 1-D quadrature per edge, with
/// the singular point handled exactly ([J] §3.2 kernel; not the closed form under test).
double polar_quadrature(int which, double x, double y, double a, double b) {
  auto f = [which](double th) {
    const double c = std::cos(th), s = std::sin(th);
    return which == 0 ? 1.0 : which == 1 ? c * c : which == 2 ? s * s : c * s;
  };
  const double u0 = -a - x, u1 = a - x, v0 = -b - y, v1 = b - y;  // rectangle about the point
  double sum = 0;
  // right edge u = u1: θ from atan2(v0, u1) to atan2(v1, u1), R = u1 / cos θ; etc.
  sum += gauss1([&](double t) { return f(t) * u1 / std::cos(t); }, std::atan2(v0, u1), std::atan2(v1, u1), 64);
  sum += gauss1([&](double t) { return f(t) * v1 / std::sin(t); }, std::atan2(v1, u1), std::atan2(v1, u0), 64);
  sum += gauss1([&](double t) { return f(t) * u0 / std::cos(t); }, std::atan2(v1, u0), std::atan2(v0, u0) + 2 * pi, 64);
  sum += gauss1([&](double t) { return f(t) * v0 / std::sin(t); }, std::atan2(v0, u0), std::atan2(v0, u1), 64);
  return sum;
}

/// Outside the rectangle (at a positive distance): a tensor Gauss rule on 64 × 64 pieces of the
/// smooth kernel.
double tensor_quadrature(int which, double x, double y, double a, double b) {
  auto K = [&](double xi, double eta) {
    const double s = x - xi, t = y - eta, r = std::hypot(s, t);
    const double num = which == 0 ? r * r : which == 1 ? s * s : which == 2 ? t * t : s * t;
    return num / (r * r * r);
  };
  return gauss1([&](double xi) { return gauss1([&](double eta) { return K(xi, eta); }, -b, b, 64); }, -a, a, 64);
}

double quadrature(int which, double x, double y, double a, double b) {
  return std::fabs(x) < a && std::fabs(y) < b ? polar_quadrature(which, x, y, a, b)
                                              : tensor_quadrature(which, x, y, a, b);
}

/// Kalker's linear-theory coefficients (Kalker 1990, Table E.3) at ν by the library's one table
/// (contact/tangential/kalker.hpp, checked entry by entry against the book and CONTACT's linrol
/// in test_kalker.cpp). Values at ν = 0.28:
///   a/b = 0.2: 3.4959, 2.6341, 0.6218;  0.5: 3.7335, 3.0256, 0.9435;  1: 4.2262, 3.7049, 1.4881;
///   2: 5.2037, 4.9715, 2.6566;  5: 7.8916, 8.3085, 6.7593.
using Linear = mh::KalkerCoefficients;
Linear kalker(double aob, double nu) { return mh::kalker_coefficients(aob, nu); }

/// Kalker's coefficients from the exact solver at small creepage (ξ, η = 10⁻⁶, φ c = 10⁻⁶,
/// μ = 10⁴: no slip, so only the set of contact elements matters), c = √(ab) = 5 mm, G = 82 GPa,
/// ν = 0.28, on n × n elements of (2a/n) × (2b/n), averaged over K × K placements of the ellipse
/// at the sub-element offsets ((i + ½)/K, (j + ½)/K) of an element. Why the average: which
/// element centres fall inside the ellipse changes erratically with n (the count of lattice
/// points in an ellipse), and with it the coefficients, by ±1 % near n = 40 (docs/half_space.md,
/// "Kalker's linear theory"); over the placements the
/// expected contact area is the ellipse's, and what is left converges at first order in the
/// element size, which Richardson's extrapolation needs. The grid has n + 1 elements per axis so
/// that the ellipse's box lies inside it at every offset.
struct Coefficients {
  double C11 = 0, C22 = 0, C23 = 0;
  double seconds = 0;  ///< per solve
};
Coefficients shift_averaged(double aob, int n, int K) {
  const double G = 82e9, nu = 0.28, c = 5e-3, k = 1e-6, mu = 1e4;
  const double a = c * std::sqrt(aob), b = c / std::sqrt(aob), dx = 2 * a / n, dy = 2 * b / n;
  const int m = n + 1;
  mh::HalfSpaceTangentialSolver s(m, m, dx, dy, G, nu);
  std::vector<double> p(static_cast<std::size_t>(m * m));
  Coefficients sum;
  const auto t0 = std::chrono::steady_clock::now();
  for (int kx = 0; kx < K; ++kx)
    for (int ky = 0; ky < K; ++ky) {
      // Centre of element (0, 0): the ellipse's trailing (lower) edge lies at the offset within
      // element 0, or within element 1 for offsets ≥ ½ (element 0 then empty).
      const double sx = (kx + 0.5) / K, sy = (ky + 0.5) / K;
      const double x0 = -a + (sx - (sx >= 0.5 ? 1 : 0)) * dx, y0 = -b + (sy - (sy >= 0.5 ? 1 : 0)) * dy;
      for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
          const double x = x0 + i * dx, y = y0 + j * dy, q = 1 - x * x / (a * a) - y * y / (b * b);
          p[static_cast<std::size_t>(i + m * j)] = q > 0 ? 1e9 * std::sqrt(q) : 0.0;
        }
      const auto rx = s.solve(p.data(), x0, y0, {k, 0, 0}, mu);
      const auto ry = s.solve(p.data(), x0, y0, {0, k, 0}, mu);
      const auto rp = s.solve(p.data(), x0, y0, {0, 0, k / c}, mu);
      REQUIRE(rx.status == mh::TangentialStatus::Ok);
      REQUIRE(ry.status == mh::TangentialStatus::Ok);
      REQUIRE(rp.status == mh::TangentialStatus::Ok);
      // Fx = −G c² C11 ξ; Fy = −G c² C22 η − G c³ C23 φ (tangential_types.hpp).
      sum.C11 += -rx.forces.Fx / (G * c * c * k);
      sum.C22 += -ry.forces.Fy / (G * c * c * k);
      sum.C23 += -rp.forces.Fy / (G * c * c * k);
    }
  const double placements = static_cast<double>(K) * K;
  sum.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / (3 * placements);
  sum.C11 /= placements;
  sum.C22 /= placements;
  sum.C23 /= placements;
  return sum;
}

}  // namespace

TEST_CASE("Cerruti rectangle integrals agree with a direct quadrature of the point-load kernel",
          "[tangential_influence]") {
  const double cases[][4] = {// x, y, a, b
                             {0, 0, 0.5, 0.5},    {0.1, 0.3, 0.5, 0.5}, {0, 0, 0.5, 0.2},
                             {-0.3, 0.1, 0.5, 0.2}, {1, 0, 0.5, 0.5},   {0, 1, 0.5, 0.5},
                             {1, 1, 0.5, 0.5},    {3, -2, 0.5, 0.2},    {-2, 0.7, 0.2, 0.5},
                             {0.4, -1.3, 0.5, 0.2}};
  for (const auto& c : cases) {
    const double x = c[0], y = c[1], a = c[2], b = c[3];
    INFO("x = " << x << ", y = " << y << ", a = " << a << ", b = " << b);
    const double scale = mh::love_rectangle(x, y, a, b);
    CHECK(mh::love_rectangle(x, y, a, b) == Approx(quadrature(0, x, y, a, b)).margin(1e-10 * scale));
    CHECK(mh::cerruti_rectangle_xx(x, y, a, b) == Approx(quadrature(1, x, y, a, b)).margin(1e-10 * scale));
    CHECK(mh::cerruti_rectangle_yy(x, y, a, b) == Approx(quadrature(2, x, y, a, b)).margin(1e-10 * scale));
    CHECK(mh::cerruti_rectangle_xy(x, y, a, b) == Approx(quadrature(3, x, y, a, b)).margin(1e-10 * scale));
  }
}

TEST_CASE("Tangential coefficients: symmetries and the far field of Cerruti's point load",
          "[tangential_influence]") {
  const double G = 82e9, nu = 0.28, dx = 4e-4, dy = 2e-4;
  const mh::TangentialKernel K{dx, dy, G, nu};
  // Aₓₓ, A_yy even in both offsets, Aₓᵧ odd in each (zero on the axes): bitwise, which the
  // steady-rolling solver relies on when it evaluates only the offsets i ≥ 0 and mirrors them
  // (tangential_rolling.cpp; its answers the same bits as before it did), as does xx_yy.
  for (int i : {0, 1, 3, 17})
    for (int j : {0, 2, 5, 40}) {
      INFO("offset " << i << ", " << j);
      CHECK(K.xx(-i, j) == K.xx(i, j));
      CHECK(K.xx(i, -j) == K.xx(i, j));
      CHECK(K.yy(-i, j) == K.yy(i, j));
      CHECK(K.yy(i, -j) == K.yy(i, j));
      CHECK(K.xy(-i, j) == -K.xy(i, j));
      CHECK(K.xy(i, -j) == -K.xy(i, j));
      double xx = 0, yy = 0;
      K.xx_yy(i, j, &xx, &yy);
      CHECK(xx == K.xx(i, j));
      CHECK(yy == K.yy(i, j));
      if (i == 0 || j == 0) CHECK(std::fabs(K.xy(i, j)) <= 1e-12 * K.xx(0, 0));
    }
  // Far field: the element's area dx·dy times [J] eq. (3.86) for the two bodies.
  for (auto ij : {std::pair<int, int>{400, 0}, {0, 800}, {300, 500}, {-250, 700}}) {
    const double x = ij.first * dx, y = ij.second * dy, r = std::hypot(x, y), A = dx * dy;
    INFO("offset " << ij.first << ", " << ij.second);
    CHECK(K.xx(ij.first, ij.second) == Approx(A / (pi * G) * ((1 - nu) / r + nu * x * x / (r * r * r))).epsilon(1e-5));
    CHECK(K.yy(ij.first, ij.second) == Approx(A / (pi * G) * ((1 - nu) / r + nu * y * y / (r * r * r))).epsilon(1e-5));
    CHECK(K.xy(ij.first, ij.second) == Approx(A / (pi * G) * nu * x * y / (r * r * r)).epsilon(1e-4));
  }
}

TEST_CASE("TangentialInfluence::apply equals the direct sum", "[tangential_influence]") {
  const int nx = 7, ny = 5;
  const mh::TangentialInfluence A(nx, ny, 3e-4, 2e-4, 80e9, 0.3);
  std::vector<double> px(nx * ny), py(nx * ny), ux(nx * ny), uy(nx * ny);
  for (int e = 0; e < nx * ny; ++e) {
    px[e] = std::sin(1.7 * e) * 1e8;
    py[e] = std::cos(0.9 * e + 0.3) * 1e8;
  }
  A.apply(px.data(), py.data(), ux.data(), uy.data());
  double umax = 0, err = 0;
  for (int i = 0; i < nx * ny; ++i) {
    double sx = 0, sy = 0;
    for (int j = 0; j < nx * ny; ++j) {
      const int di = i % nx - j % nx, dj = i / nx - j / nx;
      sx += A.Axx(di, dj) * px[j] + A.Axy(di, dj) * py[j];
      sy += A.Axy(di, dj) * px[j] + A.Ayy(di, dj) * py[j];
    }
    umax = std::max(umax, std::max(std::fabs(sx), std::fabs(sy)));
    err = std::max(err, std::max(std::fabs(sx - ux[i]), std::fabs(sy - uy[i])));
  }
  CHECK(err <= 1e-12 * umax);
}

TEST_CASE("RowFft: a row convolution through it equals the direct sum", "[tangential_influence]") {
  for (int n : {1, 2, 5, 33}) {
    const mh::RowFft f(n);
    const int m = f.m(), H = f.half();
    std::vector<double> k(m), z(m, 0.0), q(n), q2(n), out(n), out2(n);
    auto K = [](int d) { return 1.0 / (1 + d * d) + 0.3 * d; };  // neither even nor odd
    for (int i = 0; i < m; ++i) {
      int di = 0;
      k[i] = f.offset(i, &di) ? K(di) : 0;
    }
    for (int i = 0; i < n; ++i) {
      q[i] = std::sin(1.3 * i + 0.2);
      q2[i] = std::cos(0.7 * i);
    }
    std::vector<std::complex<double>> KH(H), ZH(H), QH(H), Q2H(H);
    f.forward(k.data(), z.data(), m, KH.data(), ZH.data());
    f.forward(q.data(), q2.data(), n, QH.data(), Q2H.data());
    for (int j = 0; j < H; ++j) {
      QH[j] *= KH[j];
      Q2H[j] *= KH[j];
    }
    f.backward(QH.data(), Q2H.data(), out.data(), out2.data());
    for (int i = 0; i < n; ++i) {
      double s = 0, s2 = 0;
      for (int j = 0; j < n; ++j) {
        s += K(i - j) * q[j];
        s2 += K(i - j) * q2[j];
      }
      CHECK(out[i] == Approx(s).margin(1e-12 * n));
      CHECK(out2[i] == Approx(s2).margin(1e-12 * n));
    }
  }
}

TEST_CASE("Steady rolling, full sliding: |F| = mu N opposite to the creepage within 0.1 %",
          "[tangential_rolling]") {
  const HertzGrid h(6e-3, 4e-3, 1e9, 24, 16);
  mh::HalfSpaceTangentialSolver s(h.nx, h.ny, h.dx, h.dy, 82e9, 0.28);
  const double mu = 0.3;
  for (auto c : {mh::Creepages{0.05, 0, 0}, mh::Creepages{0, -0.04, 0}, mh::Creepages{0.03, 0.04, 0}}) {
    INFO("xi = " << c.xi << ", eta = " << c.eta);
    const auto r = s.solve(h.p.data(), h.x0, h.y0, c, mu);
    REQUIRE(r.status == mh::TangentialStatus::Ok);
    const double F = std::hypot(r.forces.Fx, r.forces.Fy), w = std::hypot(c.xi, c.eta);
    CHECK(F == Approx(mu * h.N).epsilon(1e-3));
    CHECK(r.forces.Fx * w == Approx(-F * c.xi).margin(1e-3 * F * w));
    CHECK(r.forces.Fy * w == Approx(-F * c.eta).margin(1e-3 * F * w));
    CHECK(r.forces.adhesion_fraction == 0.0);
  }
}

TEST_CASE("Steady rolling, 2-D: Carter's closed form F/(mu N) = 1 - (1 - R xi/(mu a))^2 within 1 %",
          "[tangential_rolling]") {
  // Carter (1926); Johnson, Contact Mechanics §8.2 eq. (8.43). The 2-D problem as one row of
  // elements 10⁴ a long in y: the slip sees only differences of the kernel along x, in which the
  // row's ends are 10⁴ a away. Hertz in 2-D (equal bodies, Johnson's E* = G/(1−ν)):
  // p0 = a E*/(2R), so R = a G/(2(1−ν) p0).
  const double a = 1e-3, p0 = 1e9, G = 82e9, nu = 0.28, mu = 0.3, L = 1e4 * a;
  const int n = 200;
  const double dx = 2 * a / n, R = a * G / (2 * (1 - nu) * p0);
  std::vector<double> p(n);
  double N = 0;
  for (int i = 0; i < n; ++i) {
    const double x = -a + (i + 0.5) * dx;
    p[i] = p0 * std::sqrt(1 - x * x / (a * a));
    N += p[i] * dx * L;
  }
  mh::HalfSpaceTangentialSolver s(n, 1, dx, L, G, nu);
  for (double k : {0.2, 0.5, 0.8}) {  // R ξ / (μ a)
    const double xi = k * mu * a / R, expected = 1 - (1 - k) * (1 - k);
    const auto r = s.solve(p.data(), -a + dx / 2, 0.0, {xi, 0, 0}, mu);
    INFO("R xi/(mu a) = " << k);
    REQUIRE(r.status == mh::TangentialStatus::Ok);
    CHECK(-r.forces.Fx / (mu * N) == Approx(expected).epsilon(0.01));
    // The adhesion zone is the leading (1 − k) of the width (Carter).
    CHECK(r.forces.adhesion_fraction == Approx(1 - k).margin(0.02));
  }
}

TEST_CASE("Steady rolling, small creepage: Kalker's linear theory (Table E.3, nu = 0.28)",
          "[tangential_rolling]") {
  // The coarse family of the convergence table (docs/half_space.md): the placement-averaged
  // coefficients at 20 (4 × 4 placements) and 40 (2 × 2) elements across, extrapolated to zero
  // element size at first order, C0 = 2 C(40) − C(20). Measured (29 Nov 2026), C0 against the
  // table: −0.23 … +0.38 % in C11, −0.09 … +0.66 % in C22, −0.36 … +0.17 % in C23, the 0.66 % at
  // a/b = 5 (the fine family gives +0.69 % there: the 0.5 % is missed in C22 at a/b = 5);
  // held at 0.6 % and 0.9 % for C22 at a/b = 5. The grid error is positive (each coefficient
  // falls from 20 to 40, as CONTACT's on the same discretisation): with the spin's rigid slip at
  // the element centre instead of eq. R1, C23 rises with n, and the extrapolation alone would not
  // see it (the offset is a first-order term).
  for (double aob : {0.2, 0.5, 1.0, 2.0, 5.0}) {
    const Linear ref = kalker(aob, 0.28);
    const Coefficients h = shift_averaged(aob, 20, 4), f = shift_averaged(aob, 40, 2);
    INFO("a/b = " << aob << ": C11 " << h.C11 << " → " << f.C11 << ", C22 " << h.C22 << " → " << f.C22
                  << ", C23 " << h.C23 << " → " << f.C23);
    CHECK(f.C11 < h.C11);
    CHECK(f.C22 < h.C22);
    CHECK(f.C23 < h.C23);
    CHECK(2 * f.C11 - h.C11 == Approx(ref.C11).epsilon(0.006));
    CHECK(2 * f.C22 - h.C22 == Approx(ref.C22).epsilon(aob == 5.0 ? 0.009 : 0.006));
    CHECK(2 * f.C23 - h.C23 == Approx(ref.C23).epsilon(0.006));
    // Against Kalker's series solved to convergence (tests/data/kalker_series/, no grid): the
    // table's C22 at a/b = 5 is 0.63 % below it, the solver is not (measured −0.11 … +0.05 %,
    // 29 Nov 2026; held at 0.17 %).
    const mh::test::SeriesCoefficients ser = mh::test::kalker_series(aob, 0.28);
    CHECK(2 * f.C11 - h.C11 == Approx(ser.C11).epsilon(0.0017));
    CHECK(2 * f.C22 - h.C22 == Approx(ser.C22).epsilon(0.0017));
    CHECK(2 * f.C23 - h.C23 == Approx(ser.C23).epsilon(0.0017));
  }
}

TEST_CASE("Steady rolling against CONTACT's exact solution on the same Hertzian patch and grid",
          "[tangential_rolling]") {
  // tests/data/contact_tangential/hstang/README.md. Targets (issue 33 §4): Fx, Fy within 2 % of
  // μN, Mz within 5 %, adhesion fraction within 0.05. Both discretise the same way (the spin's
  // rigid slip dx/6 upstream, tangential_rolling.hpp eq. R1): measured within 0.0002 μN in force,
  // 0.01 % in Mz, 0.001 in adhesion (29 Nov 2026); held at 0.001 μN, 0.2 %, 0.003.
  const std::string dir = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/contact_tangential/hstang/";
  const int mx = 44, my = 44;
  const double dx = 0.4e-3, dy = 0.2e-3, x0 = -8.6e-3, y0 = -4.3e-3, G = 82e9, nu = 0.28, mu = 0.3;
  std::vector<double> pn(mx * my, 0.0);
  {
    std::ifstream f(dir + "hertz44_pressure.csv");
    REQUIRE(f);
    std::string line;
    std::getline(f, line);
    while (std::getline(f, line)) {
      int e = 0;
      double p = 0;
      char comma = 0;
      std::istringstream s(line);
      REQUIRE(s >> e >> comma >> p);
      pn[static_cast<std::size_t>(e - 1)] = p * 1e6;
    }
  }
  double N = 0;
  for (double p : pn) N += p * dx * dy;
  REQUIRE(N == Approx(82000).epsilon(1e-3));
  mh::HalfSpaceTangentialSolver s(mx, my, dx, dy, G, nu);
  std::ifstream f(dir + "hertz44_totals.csv");
  REQUIRE(f);
  std::string line;
  std::getline(f, line);
  int cases = 0;
  while (std::getline(f, line)) {
    std::istringstream in(line);
    std::vector<double> v;
    std::string cell;
    while (std::getline(in, cell, ',')) v.push_back(std::stod(cell));
    REQUIRE(v.size() == 10);
    const mh::Creepages c{v[1], v[2], v[3] * 1e3};
    const double Fx = v[5], Fy = v[6], Mz = v[7] * 1e-3, adh = v[9] / v[8];
    INFO("case " << v[0] << ": xi = " << c.xi << ", eta = " << c.eta << ", phi = " << c.phi << " 1/m");
    const auto r = s.solve(pn.data(), x0, y0, c, mu);
    REQUIRE(r.status == mh::TangentialStatus::Ok);
    CHECK(r.n_contact == static_cast<int>(v[8]));
    CHECK(r.forces.Fx == Approx(Fx).margin(0.001 * mu * N));
    CHECK(r.forces.Fy == Approx(Fy).margin(0.001 * mu * N));
    CHECK(r.forces.Mz == Approx(Mz).epsilon(0.002).margin(1e-3));
    CHECK(r.forces.adhesion_fraction == Approx(adh).margin(0.003));
    ++cases;
  }
  CHECK(cases == 6);
}

TEST_CASE("Steady rolling, small creepage: convergence to Kalker's linear theory (20, 40, 80)",
          "[.][tangential_rolling_convergence]") {
  // Prints the convergence table of docs/half_space.md: the placement-averaged coefficients
  // (shift_averaged) at 20 (8 × 8 placements), 40 and 80 (4 × 4) elements across, the observed
  // order p = log2((C20 − C40)/(C40 − C80)), and the first-order extrapolation C0 = 2 C80 − C40
  // (the one-sided difference of the slip is first order; the observed p is 1.02–1.15 wherever the
  // changes are well above the placement average's noise, ~0.03 %). Holds C0 within the issue's
  // 0.5 % of Table E.3 except C22 at a/b = 5 (measured +0.69 %, held at 0.8 %: the table's entry is
  // 0.63 % below the converged series, tests/data/kalker_series/), within 0.13 % of that series,
  // and the grid error positive (each coefficient falls as n grows). Several minutes on a loaded
  // 2-core machine.
  for (double aob : {0.2, 0.5, 1.0, 2.0, 5.0}) {
    const Linear ref = kalker(aob, 0.28);
    Coefficients c[3];
    const int ns[3] = {20, 40, 80}, Ks[3] = {8, 4, 4};
    for (int g = 0; g < 3; ++g) {
      c[g] = shift_averaged(aob, ns[g], Ks[g]);
      std::printf("| %g | %d | %d × %d | %.4f (%+.2f %%) | %.4f (%+.2f %%) | %.4f (%+.2f %%) | %.3f |\n", aob, ns[g],
                  Ks[g], Ks[g], c[g].C11, 100 * (c[g].C11 / ref.C11 - 1), c[g].C22, 100 * (c[g].C22 / ref.C22 - 1),
                  c[g].C23, 100 * (c[g].C23 / ref.C23 - 1), c[g].seconds);
    }
    auto order = [](double a, double b, double d) { return std::log2((a - b) / (b - d)); };
    std::printf("| %g | order p | | %.2f | %.2f | %.2f | |\n", aob, order(c[0].C11, c[1].C11, c[2].C11),
                order(c[0].C22, c[1].C22, c[2].C22), order(c[0].C23, c[1].C23, c[2].C23));
    const double C11 = 2 * c[2].C11 - c[1].C11, C22 = 2 * c[2].C22 - c[1].C22, C23 = 2 * c[2].C23 - c[1].C23;
    std::printf("| %g | extrapolated (p = 1) | | %.4f (%+.2f %%) | %.4f (%+.2f %%) | %.4f (%+.2f %%) | |\n", aob, C11,
                100 * (C11 / ref.C11 - 1), C22, 100 * (C22 / ref.C22 - 1), C23, 100 * (C23 / ref.C23 - 1));
    std::fflush(stdout);
    INFO("a/b = " << aob);
    for (int g = 0; g < 2; ++g) {
      CHECK(c[g + 1].C11 < c[g].C11);
      CHECK(c[g + 1].C22 < c[g].C22);
      CHECK(c[g + 1].C23 < c[g].C23);
    }
    CHECK(C11 == Approx(ref.C11).epsilon(0.005));
    CHECK(C22 == Approx(ref.C22).epsilon(aob == 5.0 ? 0.008 : 0.005));
    CHECK(C23 == Approx(ref.C23).epsilon(0.005));
    // Against Kalker's series solved to convergence (no grid): measured +0.06 … +0.09 %.
    const mh::test::SeriesCoefficients ser = mh::test::kalker_series(aob, 0.28);
    CHECK(C11 == Approx(ser.C11).epsilon(0.0013));
    CHECK(C22 == Approx(ser.C22).epsilon(0.0013));
    CHECK(C23 == Approx(ser.C23).epsilon(0.0013));
  }
}

TEST_CASE("solve_tangential_patch: a half-space patch's grid and pressure, equal materials only",
          "[tangential_rolling]") {
  const HertzGrid h(6e-3, 4e-3, 1e9, 24, 16);
  mh::PatchResult patch;
  patch.patch = 1;
  patch.nx = h.nx;
  patch.ns = h.ny;
  patch.dx = h.dx;
  patch.ds = h.dy;
  patch.x0 = h.x0;
  patch.s0 = h.y0;
  patch.p = h.p;
  mh::Material m;  // steel, 210 GPa, ν = 0.28
  const mh::Creepages c{3e-4, -2e-4, 0.4};
  const auto r = mh::solve_tangential_patch(patch, m, c, 0.3);
  REQUIRE(r.status == mh::TangentialStatus::Ok);
  mh::HalfSpaceTangentialSolver s(h.nx, h.ny, h.dx, h.dy, 210e9 / (2 * 1.28), 0.28);
  const auto d = s.solve(h.p.data(), h.x0, h.y0, c, 0.3);
  CHECK(r.forces.Fx == d.forces.Fx);
  CHECK(r.forces.Fy == d.forces.Fy);
  CHECK(r.forces.Mz == d.forces.Mz);
  m.E_rail = 200e9;
  const auto bad = mh::solve_tangential_patch(patch, m, c, 0.3);
  CHECK(bad.status == mh::TangentialStatus::NotConverged);
  CHECK(bad.message.find("equal elastic constants") != std::string::npos);
  patch.p.clear();
  m.E_rail = NAN;
  CHECK(mh::solve_tangential_patch(patch, m, c, 0.3).status == mh::TangentialStatus::NotConverged);
}

TEST_CASE("Steady rolling: invalid input and no contact give a status, a warm start the same answer",
          "[tangential_rolling]") {
  const HertzGrid h(6e-3, 4e-3, 1e9, 24, 16);
  mh::HalfSpaceTangentialSolver s(h.nx, h.ny, h.dx, h.dy, 82e9, 0.28);
  const mh::Creepages c{2e-4, 1e-4, 0.3};
  const auto cold = s.solve(h.p.data(), h.x0, h.y0, c, 0.3);
  REQUIRE(cold.status == mh::TangentialStatus::Ok);
  // Deterministic, and a warm start from the converged tractions stops at once with the same forces.
  const auto again = s.solve(h.p.data(), h.x0, h.y0, c, 0.3);
  CHECK(again.forces.Fx == cold.forces.Fx);
  CHECK(again.forces.Mz == cold.forces.Mz);
  const auto warm = s.solve(h.p.data(), h.x0, h.y0, c, 0.3, {}, true);
  REQUIRE(warm.status == mh::TangentialStatus::Ok);
  CHECK(warm.sweeps <= 2);
  CHECK(warm.forces.Fx == Approx(cold.forces.Fx).margin(1e-5 * 0.3 * h.N));
  CHECK(warm.forces.Fy == Approx(cold.forces.Fy).margin(1e-5 * 0.3 * h.N));
  // Invalid input: NotConverged with a message, no throw.
  CHECK(s.solve(h.p.data(), h.x0, h.y0, c, 0.0).status == mh::TangentialStatus::NotConverged);
  CHECK(s.solve(h.p.data(), h.x0, h.y0, {NAN, 0, 0}, 0.3).status == mh::TangentialStatus::NotConverged);
  mh::HalfSpaceTangentialOptions bad;
  bad.tol = 0;
  const auto r = s.solve(h.p.data(), h.x0, h.y0, c, 0.3, bad);
  CHECK(r.status == mh::TangentialStatus::NotConverged);
  CHECK(r.message.find("tol") != std::string::npos);
  // Too few sweeps: NotConverged, with the forces of the last iterate.
  mh::HalfSpaceTangentialOptions one;
  one.max_sweeps = 1;
  CHECK(s.solve(h.p.data(), h.x0, h.y0, c, 0.3, one).status == mh::TangentialStatus::NotConverged);
  // No pressure anywhere: NoContact, zero forces.
  const std::vector<double> zero(h.p.size(), 0.0);
  const auto none = s.solve(zero.data(), h.x0, h.y0, c, 0.3);
  CHECK(none.status == mh::TangentialStatus::NoContact);
  CHECK(none.forces.Fx == 0.0);
  CHECK(s.px()[h.p.size() / 2] == 0.0);
}
