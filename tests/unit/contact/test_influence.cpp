// Tests of the half-space influence coefficients and their DC-FFT convolution
// (lib/contact/half_space/influence.hpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <algorithm>
#include <functional>
#include <string>
#include <vector>
#include <utility>

#include "contact/half_space/influence.hpp"
#include "contact/options.hpp"

#include "support/gauss_legendre.hpp"

namespace {

constexpr double pi = 3.14159265358979323846;

using Gauss = GaussLegendre<16>;  // tests/support/gauss_legendre.hpp
const Gauss gauss;

using F2 = std::function<double(double, double)>;

double gauss2(const F2& f, double u0, double u1, double v0, double v1) {
  double s = 0;
  for (int i = 0; i < Gauss::n; ++i)
    for (int j = 0; j < Gauss::n; ++j) {
      const double u = 0.5 * (u0 + u1) + 0.5 * (u1 - u0) * gauss.x[i];
      const double v = 0.5 * (v0 + v1) + 0.5 * (v1 - v0) * gauss.x[j];
      s += gauss.w[i] * gauss.w[j] * f(u, v);
    }
  return s * 0.25 * (u1 - u0) * (v1 - v0);
}

/// Adaptive tensor Gauss on a rectangle not containing the singular point in its interior.
double adaptive(const F2& f, double u0, double u1, double v0, double v1, double whole, int depth) {
  const double um = 0.5 * (u0 + u1), vm = 0.5 * (v0 + v1);
  const double coarse = gauss2(f, u0, u1, v0, v1);
  const double fine = gauss2(f, u0, um, v0, vm) + gauss2(f, um, u1, v0, vm) +
                      gauss2(f, u0, um, vm, v1) + gauss2(f, um, u1, vm, v1);
  if (std::fabs(fine - coarse) <= 1e-14 * std::fabs(whole) || depth >= 14) return fine;
  return adaptive(f, u0, um, v0, vm, whole, depth + 1) + adaptive(f, um, u1, v0, vm, whole, depth + 1) +
         adaptive(f, u0, um, vm, v1, whole, depth + 1) + adaptive(f, um, u1, vm, v1, whole, depth + 1);
}

/// ∫∫ over [0,U]×[0,V] (U, V > 0) of 1/√(ξ²+η²): the singular point at the corner. Duffy
/// transformation (M. G. Duffy, SIAM J. Numer. Anal. 19 (1982) 1260–1262) of the two triangles
/// split by the diagonal: ξ = U s, η = V s t (Jacobian U V s) cancels the 1/r singularity; then
/// 2-D Gauss in (s, t).
double corner_integral(double U, double V) {
  const F2 lower = [&](double s, double t) {
    const double xi = U * s, eta = V * s * t;
    return U * V * s / std::sqrt(xi * xi + eta * eta);
  };
  const F2 upper = [&](double s, double t) {
    const double xi = U * s * t, eta = V * s;
    return U * V * s / std::sqrt(xi * xi + eta * eta);
  };
  // The transformed integrands are smooth but peaked near t = 0 (width ~U/V or V/U) for
  // elongated pieces: adaptive Gauss on the unit square.
  const double whole = std::sqrt(U * V);
  return adaptive(lower, 0, 1, 0, 1, whole, 0) + adaptive(upper, 0, 1, 0, 1, whole, 0);
}

/// Independent quadrature of love_rectangle(x, y, a, b): the rectangle in coordinates relative to
/// the point, split along the lines through the point; pieces with the point at a corner by
/// Duffy, the others (point outside, at positive distance) by adaptive Gauss.
double love_quadrature(double x, double y, double a, double b) {
  std::vector<double> us = {-a - x}, vs = {-b - y};
  if (-a - x < 0 && a - x > 0) us.push_back(0.0);
  if (-b - y < 0 && b - y > 0) vs.push_back(0.0);
  us.push_back(a - x);
  vs.push_back(b - y);
  const F2 kernel = [](double u, double v) { return 1.0 / std::sqrt(u * u + v * v); };
  const double scale = 4 * a * b / std::sqrt(x * x + y * y + a * a + b * b);
  double sum = 0;
  for (std::size_t i = 0; i + 1 < us.size(); ++i)
    for (std::size_t j = 0; j + 1 < vs.size(); ++j) {
      const double u0 = us[i], u1 = us[i + 1], v0 = vs[j], v1 = vs[j + 1];
      const bool corner_u = u0 == 0 || u1 == 0, corner_v = v0 == 0 || v1 == 0;
      if (corner_u && corner_v)
        sum += corner_integral(u1 - u0, v1 - v0);
      else
        sum += adaptive(kernel, u0, u1, v0, v1, scale, 0);
    }
  return sum;
}

}  // namespace

TEST_CASE("love_rectangle: closed form at the centre of a square, 8 a asinh(1)", "[influence]") {
  // Johnson (1985) §3.9 eq. (3.96) at x = y = 0, a = b: 4·(a asinh 1 + a asinh 1).
  for (double a : {1e-4, 1.0, 3.5}) {
    INFO("a = " << a);
    CHECK(mh::love_rectangle(0, 0, a, a) == Approx(8 * a * std::asinh(1.0)).epsilon(1e-15));
  }
}

TEST_CASE("love_rectangle: symmetric in x, in y, and under (x,a)<->(y,b)", "[influence]") {
  const double a = 0.7, b = 0.3;
  for (double x : {0.0, 0.2, 0.7, 1.9})
    for (double y : {0.0, 0.1, 0.3, 2.5}) {
      INFO("x = " << x << ", y = " << y);
      const double f = mh::love_rectangle(x, y, a, b);
      // Reflections: bitwise (the four terms are summed in mirror-symmetric pairs).
      CHECK(mh::love_rectangle(-x, y, a, b) == f);
      CHECK(mh::love_rectangle(x, -y, a, b) == f);
      CHECK(mh::love_rectangle(-x, -y, a, b) == f);
      // Exchange of the axes regroups the sum: equal to rounding (a few ulps).
      CHECK(mh::love_rectangle(y, x, b, a) == Approx(f).epsilon(1e-14));
    }
}

TEST_CASE("love_rectangle agrees with an independent 2-D quadrature (inside, edges, corner, outside)",
          "[influence]") {
  const double a = 0.5e-3, b = 0.2e-3;  // a 1 mm × 0.4 mm element
  struct Point {
    double x, y;
    const char* where;
  };
  const Point points[] = {
      {0.0, 0.0, "centre"},          {0.3e-3, 0.1e-3, "inside"},   {-0.45e-3, 0.19e-3, "near corner"},
      {0.5e-3, 0.0, "edge x = a"},   {0.1e-3, -0.2e-3, "edge y = -b"}, {0.5e-3, 0.2e-3, "corner"},
      {0.51e-3, 0.05e-3, "just outside"}, {1.3e-3, 0.7e-3, "outside"}, {-4e-3, 2.5e-3, "far outside"},
  };
  for (const Point& q : points) {
    const double closed = mh::love_rectangle(q.x, q.y, a, b);
    const double quad = love_quadrature(q.x, q.y, a, b);
    INFO(q.where << ": closed " << closed << " m, quadrature " << quad << " m, rel "
                 << (closed - quad) / quad);
    CHECK(closed == Approx(quad).epsilon(1e-12));  // measured ≤ 1.5e-14
  }
}

TEST_CASE("love_rectangle: far field tends to area / r", "[influence]") {
  // Boussinesq: a force p·4ab at distance r gives H p 4ab / r (Johnson §3.2); the relative
  // correction is O((a/r)²) (second moment of the rectangle), so at r = 1e3 a it is ≲ 1e-6.
  const double a = 1.0, b = 0.4;
  for (double r : {1e3, 3e3}) {
    for (double angle : {0.0, 0.4, 1.2}) {
      const double x = r * std::cos(angle), y = r * std::sin(angle);
      INFO("r = " << r << ", angle " << angle);
      CHECK(mh::love_rectangle(x, y, a, b) == Approx(4 * a * b / r).epsilon(2.0 * (a * a) / (r * r)));
    }
  }
}

TEST_CASE("Material::compliance: (1-nu^2)/(pi E) summed over both bodies", "[influence]") {
  // Johnson, Contact Mechanics, §3.2 (point load) summed over the two bodies.
  mh::Material same;
  same.E = 210e9;
  same.nu = 0.28;
  CHECK(same.compliance() == Approx(2 * (1 - 0.28 * 0.28) / (pi * 210e9)).epsilon(1e-15));
  mh::Material two;
  two.E = 200e9;
  two.nu = 0.3;
  two.E_rail = 70e9;
  two.nu_rail = 0.33;
  CHECK(two.compliance() == Approx((1 - 0.09) / (pi * 200e9) + (1 - 0.33 * 0.33) / (pi * 70e9)).epsilon(1e-15));
}

TEST_CASE("InfluenceGrid::apply equals the direct O(n^2) sum", "[influence]") {
  const double H = 2 * (1 - 0.28 * 0.28) / (pi * 210e9);  // two steel bodies (Johnson §3.2)
  struct Size {
    int nx, ny;
  };
  // Padded sizes (PocketFFT): 15 × 9, 1 × 1, 1 × 18, 25 × 3 (odd lengths, no Nyquist term) and
  // 18 × 8 for 9 × 4 (even, its Nyquist term kx = 9 in the second lane of a full SIMD block);
  // odd ny leaves the last block of rows one short.
  for (Size s : {Size{7, 5}, Size{1, 1}, Size{1, 9}, Size{13, 2}, Size{9, 4}}) {
    const int nx = s.nx, ny = s.ny;
    const double dx = 0.25e-3, dy = 0.4e-3;
    mh::InfluenceGrid C(nx, ny, dx, dy, H);
    CHECK(C.padded_nx() >= 2 * nx - 1);
    CHECK(C.padded_ny() >= 2 * ny - 1);
    CHECK(C.self_coefficient() == H * mh::love_rectangle(0, 0, dx / 2, dy / 2));

    // Deterministic pseudo-random pressures (LCG, Knuth MMIX constants), 0…1 GPa.
    std::vector<double> p(nx * ny), u(nx * ny), direct(nx * ny, 0.0);
    std::uint64_t state = 12345;
    for (double& v : p) {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      v = 1e9 * static_cast<double>(state >> 11) / 9007199254740992.0;
    }
    for (int i = 0; i < nx * ny; ++i)
      for (int j = 0; j < nx * ny; ++j)
        direct[i] += H * mh::love_rectangle((i % nx - j % nx) * dx, (i / nx - j / nx) * dy, dx / 2, dy / 2) * p[j];
    C.apply(p.data(), u.data());
    double max_rel = 0, max_u = 0;
    for (int i = 0; i < nx * ny; ++i) max_u = std::max(max_u, std::fabs(direct[i]));
    for (int i = 0; i < nx * ny; ++i) max_rel = std::max(max_rel, std::fabs(u[i] - direct[i]) / max_u);
    INFO(nx << " x " << ny << ": max |u_fft - u_direct| / max|u| = " << max_rel);
    CHECK(max_rel <= 1e-12);

    // In place (p and u aliased) gives the same bytes.
    std::vector<double> q = p;
    C.apply(q.data(), q.data());
    CHECK(q == u);
  }
}

// add_sparse (the CG loop's correction for the few elements a step moved off its linear path,
// normal_cg.cpp) against apply() of the same sparse vector: Love's kernel (even) and a kernel
// odd in both offsets and not symmetric under their exchange, which catches a transposed or
// mirrored offset; elements at the grid's corners and edges (the kernel's extreme offsets).
TEST_CASE("InfluenceGrid::add_sparse equals apply() of the sparse vector", "[influence]") {
  const double H = 2 * (1 - 0.28 * 0.28) / (pi * 210e9);
  const mh::InfluenceGrid::Kernel odd = [](int dix, int diy) { return 1e-12 * (dix + 0.37 * diy * diy * diy + 0.05 * dix * diy); };
  for (int kind = 0; kind < 2; ++kind)
    for (auto [nx, ny] : {std::pair<int, int>{7, 5}, {1, 9}, {13, 2}, {12, 11}}) {
      const mh::InfluenceGrid C = kind == 0 ? mh::InfluenceGrid(nx, ny, 0.25e-3, 0.4e-3, H)
                                            : mh::InfluenceGrid(nx, ny, 0.25e-3, 0.4e-3, odd);
      const int n = nx * ny;
      const std::vector<int> idx = {0, n - 1, nx - 1, n - nx, n / 2, n / 3};
      const std::vector<double> d = {1e8, -3e8, 5e7, 2e8, -1e8, 7e7};
      std::vector<double> full(static_cast<std::size_t>(n), 0.0), u_fft(full.size()), u_sparse(full.size(), 0.0);
      for (std::size_t k = 0; k < idx.size(); ++k) full[static_cast<std::size_t>(idx[k])] += d[k];
      C.apply(full.data(), u_fft.data());
      C.add_sparse(idx.data(), d.data(), static_cast<int>(idx.size()), u_sparse.data());
      double max_u = 0, max_dev = 0;
      for (int i = 0; i < n; ++i) max_u = std::max(max_u, std::fabs(u_fft[static_cast<std::size_t>(i)]));
      for (int i = 0; i < n; ++i)
        max_dev = std::max(max_dev, std::fabs(u_sparse[static_cast<std::size_t>(i)] - u_fft[static_cast<std::size_t>(i)]));
      INFO((kind == 0 ? "Love" : "odd") << " kernel, " << nx << " x " << ny << ": max |dev| / max |u| = " << max_dev / max_u);
      REQUIRE(max_u > 0);
      CHECK(max_dev <= 1e-12 * max_u);
    }
}

TEST_CASE("InfluenceGrid: moved-to object works, repeated apply is bitwise identical", "[influence]") {
  const double H = 2 * (1 - 0.28 * 0.28) / (pi * 210e9);  // two steel bodies (Johnson §3.2)
  mh::InfluenceGrid a(6, 4, 1e-3, 1e-3, H);
  std::vector<double> p(24, 0.0), u1(24), u2(24);
  p[7] = 1e9;
  a.apply(p.data(), u1.data());
  mh::InfluenceGrid b(std::move(a));
  b.apply(p.data(), u2.data());
  CHECK(u1 == u2);
  CHECK(u1[7] == Approx(1e9 * b.self_coefficient()).epsilon(1e-13));
  mh::InfluenceGrid c(2, 2, 1e-3, 1e-3, H);
  c = std::move(b);
  CHECK(c.nx() == 6);
  c.apply(p.data(), u2.data());
  CHECK(u1 == u2);
}

// reset() rebuilds an operator in its own buffers (the half-space workspace's operators once it
// keeps as many as it may, half_space_method.cpp): the same operator as a new object, bit for bit,
// whether the grid grows, shrinks, changes parity, element size or compliance, and after an
// operator of another kernel; holds() tells which grids fit the buffers; an invalid reset throws
// and leaves the operator as it was.
TEST_CASE("InfluenceGrid::reset gives a new operator's bits in the same object", "[influence]") {
  const double H = 2 * (1 - 0.28 * 0.28) / (pi * 210e9);
  const mh::InfluenceGrid::Kernel odd = [](int dix, int diy) { return 1e-12 * (dix + 0.37 * diy * diy * diy); };
  mh::InfluenceGrid R(3, 2, 0.3e-3, 0.2e-3, odd);
  struct Grid {
    int nx, ny;
    double dx, dy, H;
  };
  const Grid grids[] = {{40, 25, 0.2e-3, 0.2e-3, H}, {7, 5, 0.25e-3, 0.4e-3, H},   {41, 26, 0.2e-3, 0.2e-3, H},
                        {1, 9, 0.1e-3, 0.5e-3, 2 * H}, {64, 3, 0.2e-3, 0.2e-3, H}, {12, 11, 0.2e-3, 0.3e-3, H}};
  std::uint64_t seed = 88172645463325252ull;
  for (const Grid& g : grids) {
    R.reset(g.nx, g.ny, g.dx, g.dy, g.H);
    const mh::InfluenceGrid F(g.nx, g.ny, g.dx, g.dy, g.H);
    INFO(g.nx << " x " << g.ny);
    CHECK(R.padded_nx() == F.padded_nx());
    CHECK(R.padded_ny() == F.padded_ny());
    CHECK(R.compliance() == F.compliance());
    CHECK(R.self_coefficient() == F.self_coefficient());
    const std::size_t n = static_cast<std::size_t>(g.nx) * g.ny;
    std::vector<double> p(n), uR(n), uF(n), sR(n, 0.0), sF(n, 0.0);
    for (double& v : p) {  // xorshift: pressures of both signs, some rows empty
      seed ^= seed << 13, seed ^= seed >> 7, seed ^= seed << 17;
      v = (seed % 3 == 0) ? 0.0 : 1e9 * (static_cast<double>(seed % 2001) / 1000.0 - 1.0);
    }
    R.apply(p.data(), uR.data());
    F.apply(p.data(), uF.data());
    CHECK(uR == uF);
    const int idx[] = {0, static_cast<int>(n) - 1, static_cast<int>(n) / 2};
    const double d[] = {1e8, -2e8, 3e7};
    R.add_sparse(idx, d, 3, sR.data());
    F.add_sparse(idx, d, 3, sF.data());
    CHECK(sR == sF);
  }
  // PocketFFT: the buffers hold every grid met (41 × 26 and 64 × 3 the largest), and what fits in
  // them; not a grid both wide and long (64 × 26) nor one a padded size larger (42 × 26: 90 × 54
  // points). FFTW's plans belong to one padded size: only that size is held.
  if (std::string(mh::fft_backend()) == "pocketfft") {
    CHECK(R.holds(41, 26));
    CHECK(R.holds(64, 3));
    CHECK(R.holds(10, 10));
  } else {
    CHECK(R.holds(12, 11));
    CHECK_FALSE(R.holds(41, 26));
  }
  CHECK_FALSE(R.holds(64, 26));
  CHECK_FALSE(R.holds(42, 26));
  CHECK_FALSE(mh::InfluenceGrid(5, 5, 1e-3, 1e-3, H).holds(40, 25));
  // Invalid arguments: thrown before anything changes.
  CHECK_THROWS_AS(R.reset(0, 3, 1e-3, 1e-3, H), std::invalid_argument);
  CHECK_THROWS_AS(R.reset(3, 3, 1e-3, 1e-3, -H), std::invalid_argument);
  CHECK(R.nx() == 12);
  CHECK(R.ny() == 11);
}

TEST_CASE("fft_backend() names the FFT library the build was configured with", "[influence]") {
  // MHCONTACT_FFT_BACKEND_CONFIGURED: tests/CMakeLists.txt, from the MHCONTACT_FFTW option.
  CHECK(std::string(mh::fft_backend()) == MHCONTACT_FFT_BACKEND_CONFIGURED);
}

TEST_CASE("InfluenceGrid rejects invalid grids", "[influence]") {
  CHECK_THROWS_AS(mh::InfluenceGrid(0, 3, 1e-3, 1e-3, 1e-12), std::invalid_argument);
  CHECK_THROWS_AS(mh::InfluenceGrid(3, 3, -1e-3, 1e-3, 1e-12), std::invalid_argument);
  CHECK_THROWS_AS(mh::InfluenceGrid(3, 3, 1e-3, 1e-3, NAN), std::invalid_argument);
}

TEST_CASE("InfluenceGrid::apply equals the direct sum on a larger grid with odd and even sizes", "[influence]") {
  // 31 × 24: padded sizes 64 (2^6) × 48 (2^4·3); the half spectrum has 33 columns, so the last
  // SIMD block of columns has unused lanes (PocketFFT); odd sizes are covered by the table above.
  const double H = 2 * (1 - 0.28 * 0.28) / (pi * 210e9);  // two steel bodies (Johnson §3.2)
  const int nx = 31, ny = 24;
  const double dx = 0.2e-3, dy = 0.2e-3;
  mh::InfluenceGrid C(nx, ny, dx, dy, H);
  std::vector<double> p(nx * ny), u(nx * ny), direct(nx * ny, 0.0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) p[i + nx * j] = 1e9 * (1.0 + 0.5 * std::sin(0.7 * i + 1.3 * j));
  for (int i = 0; i < nx * ny; ++i)
    for (int j = 0; j < nx * ny; ++j)
      direct[i] += H * mh::love_rectangle((i % nx - j % nx) * dx, (i / nx - j / nx) * dy, dx / 2, dy / 2) * p[j];
  C.apply(p.data(), u.data());
  double umax = 0;
  for (double v : direct) umax = std::max(umax, std::fabs(v));
  for (int i = 0; i < nx * ny; ++i) CHECK(std::fabs(u[i] - direct[i]) <= 1e-12 * umax);
}
