// Half-space influence coefficients and DC-FFT convolution (sources in influence.hpp).
#include "contact/half_space/influence.hpp"

#include <cmath>
#include <cstddef>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>
#include "core/units.hpp"

namespace mh {

namespace {

/// F(u, v) = ∫₀ᵘ∫₀ᵛ dξ dη / √(ξ²+η²) = u asinh(v/|u|) + v asinh(u/|v|) (influence.hpp); the term
/// with a zero factor is its limit 0 (u asinh(v/|u|) ~ u ln(2|v|/|u|) → 0).
double love_corner(double u, double v) {
  double f = 0.0;
  if (u != 0.0) f += u * std::asinh(v / std::fabs(u));
  if (v != 0.0) f += v * std::asinh(u / std::fabs(v));
  return f;
}

/// Smallest n ≥ m whose only prime factors are 2, 3, 5, 7 (sizes FFTW handles with its fast
/// codelets; FFTW 3 manual §2.1, "sizes of the form 2^a 3^b 5^c 7^d").
int smooth_size(int m) {
  for (int n = m > 1 ? m : 1;; ++n) {
    int r = n;
    for (int f : {2, 3, 5, 7})
      while (r % f == 0) r /= f;
    if (r == 1) return n;
  }
}

/// Offset (in elements) represented by index i of a cyclic axis of m points carrying the offsets
/// −(n−1)…(n−1); false for the unused indices between them (DC-FFT wrap-around, [LI]).
bool wrapped_offset(int i, int n, int m, int* offset) {
  if (i < n) {
    *offset = i;
    return true;
  }
  if (i >= m - n + 1) {
    *offset = i - m;
    return true;
  }
  return false;
}

}  // namespace

double love_rectangle(double x, double y, double a, double b) {
  // Summed in pairs so that the result is bitwise even in x and in y (floating-point addition is
  // commutative): the influence matrix is then exactly symmetric.
  return (love_corner(a + x, b + y) + love_corner(a - x, b + y)) +
         (love_corner(a + x, b - y) + love_corner(a - x, b - y));
}

std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}

void InfluenceGrid::PlanDestroy::operator()(fftw_plan plan) const {
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  fftw_destroy_plan(plan);
}

InfluenceGrid::InfluenceGrid(int nx, int ny, double dx, double dy, double compliance)
    : nx_(nx), ny_(ny), dx_(dx), dy_(dy), compliance_(compliance) {
  if (nx < 1 || ny < 1)
    throw std::invalid_argument("InfluenceGrid: nx = " + std::to_string(nx) + ", ny = " +
                                std::to_string(ny) + ": the grid needs at least 1 × 1 elements");
  if (!(dx > 0) || !(dy > 0) || !std::isfinite(dx) || !std::isfinite(dy))
    throw std::invalid_argument("InfluenceGrid: dx = " + std::to_string(dx) + " m, dy = " +
                                std::to_string(dy) + " m: element sizes must be > 0 and finite");
  if (!(compliance > 0) || !std::isfinite(compliance))
    throw std::invalid_argument("InfluenceGrid: compliance = " + std::to_string(compliance) +
                                " 1/Pa: must be > 0 and finite");
  mx_ = smooth_size(2 * nx - 1);
  my_ = smooth_size(2 * ny - 1);
  const std::size_t n_real = static_cast<std::size_t>(mx_) * static_cast<std::size_t>(my_);
  const std::size_t n_cplx =
      static_cast<std::size_t>(mx_ / 2 + 1) * static_cast<std::size_t>(my_);

  real_.reset(static_cast<double*>(fftw_malloc(sizeof(double) * n_real)));
  spectrum_.reset(static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * n_cplx)));
  kernel_.reset(static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * n_cplx)));
  if (!real_ || !spectrum_ || !kernel_) throw std::bad_alloc();

  {
    // FFTW's 2-D arrays are row-major with the LAST dimension fastest: n0 = my (y), n1 = mx (x).
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    forward_.reset(fftw_plan_dft_r2c_2d(my_, mx_, real_.get(), spectrum_.get(), FFTW_ESTIMATE));
    backward_.reset(fftw_plan_dft_c2r_2d(my_, mx_, spectrum_.get(), real_.get(), FFTW_ESTIMATE));
  }
  if (!forward_ || !backward_) throw std::runtime_error("InfluenceGrid: FFTW planning failed");

  c00_ = coefficient(0, 0);

  // Wrapped kernel (DC-FFT, [LI]); zero at the unused indices. Its transform is scaled once by
  // 1/(mx·my), the normalisation FFTW leaves to the caller (FFTW 3 manual §4.8 "What FFTW Really Computes").
  double* k = real_.get();
  for (int j = 0; j < my_; ++j) {
    int dj = 0;
    const bool row = wrapped_offset(j, ny_, my_, &dj);
    for (int i = 0; i < mx_; ++i) {
      int di = 0;
      const bool used = row && wrapped_offset(i, nx_, mx_, &di);
      k[static_cast<std::size_t>(i) + static_cast<std::size_t>(mx_) * j] =
          used ? coefficient(di, dj) : 0.0;
    }
  }
  fftw_execute(forward_.get());
  const double scale = 1.0 / static_cast<double>(n_real);
  fftw_complex* kh = kernel_.get();
  const fftw_complex* s = spectrum_.get();
  for (std::size_t q = 0; q < n_cplx; ++q) {
    kh[q][0] = s[q][0] * scale;
    kh[q][1] = s[q][1] * scale;
  }
}

InfluenceGrid::~InfluenceGrid() = default;
InfluenceGrid::InfluenceGrid(InfluenceGrid&&) noexcept = default;
InfluenceGrid& InfluenceGrid::operator=(InfluenceGrid&&) noexcept = default;

double InfluenceGrid::coefficient(int dix, int diy) const {
  return compliance_ * love_rectangle(dix * dx_, diy * dy_, 0.5 * dx_, 0.5 * dy_);
}

void InfluenceGrid::apply(const double* p, double* u) const {
  const std::size_t mx = static_cast<std::size_t>(mx_);
  const std::size_t nx = static_cast<std::size_t>(nx_);
  const std::size_t n_real = mx * static_cast<std::size_t>(my_);
  const std::size_t n_cplx = (mx / 2 + 1) * static_cast<std::size_t>(my_);
  double* r = real_.get();
  std::memset(r, 0, sizeof(double) * n_real);
  for (int iy = 0; iy < ny_; ++iy)
    std::memcpy(r + mx * iy, p + nx * iy, sizeof(double) * nx);
  fftw_execute(forward_.get());
  fftw_complex* s = spectrum_.get();
  const fftw_complex* kh = kernel_.get();
  for (std::size_t q = 0; q < n_cplx; ++q) {
    const double re = s[q][0] * kh[q][0] - s[q][1] * kh[q][1];
    const double im = s[q][0] * kh[q][1] + s[q][1] * kh[q][0];
    s[q][0] = re;
    s[q][1] = im;
  }
  fftw_execute(backward_.get());  // c2r overwrites the spectrum; it is scratch
  for (int iy = 0; iy < ny_; ++iy)
    std::memcpy(u + nx * iy, r + mx * iy, sizeof(double) * nx);
}

}  // namespace mh
