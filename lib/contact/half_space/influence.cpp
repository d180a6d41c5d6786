// Half-space influence coefficients and DC-FFT convolution (sources in influence.hpp).
#include "contact/half_space/influence.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#ifdef MHCONTACT_FFTW
#include <fftw3.h>

#include <mutex>
#include <type_traits>
#else
#include <kissfft/kissfft.hh>
#endif

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

/// Smallest n ≥ m whose only prime factors have fast butterflies in the backend: 2, 3, 5, 7 for
/// FFTW (FFTW 3 manual §2.1, "sizes of the form 2^a 3^b 5^c 7^d"); 2, 3, 5 for KissFFT, whose
/// radix 7 goes through its O(p²) generic butterfly ([K] kissfft.hh, kf_bfly_generic).
int smooth_size(int m) {
#ifdef MHCONTACT_FFTW
  static const int factors[] = {2, 3, 5, 7};
#else
  static const int factors[] = {2, 3, 5};
#endif
  for (int n = m > 1 ? m : 1;; ++n) {
    int r = n;
    for (int f : factors)
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

#ifdef MHCONTACT_FFTW

const char* fft_backend() { return "fftw3"; }

namespace {
/// FFTW planning (fftw_plan_* and fftw_destroy_plan) is not thread-safe, execution of an existing
/// plan is (FFTW 3 manual §5.4 "Thread safety"): every plan is made and destroyed under this mutex.
std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}
struct FftwFree {
  void operator()(void* ptr) const { fftw_free(ptr); }
};
struct PlanDestroy {
  void operator()(fftw_plan plan) const {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_destroy_plan(plan);
  }
};
using Plan = std::unique_ptr<std::remove_pointer_t<fftw_plan>, PlanDestroy>;
}  // namespace

/// FFTW backend: r2c / c2r plans over the whole padded grid.
struct InfluenceGrid::Fft {
  int nx, ny, mx, my;
  std::size_t n_real, n_cplx;
  std::unique_ptr<double, FftwFree> real;           ///< mx·my work buffer
  std::unique_ptr<fftw_complex, FftwFree> spectrum; ///< my·(mx/2+1) work buffer
  std::unique_ptr<fftw_complex, FftwFree> kernel;   ///< FFT of the wrapped kernel, / (mx·my)
  Plan forward, backward;

  Fft(int nx_, int ny_, int mx_, int my_) : nx(nx_), ny(ny_), mx(mx_), my(my_) {
    n_real = static_cast<std::size_t>(mx) * static_cast<std::size_t>(my);
    n_cplx = static_cast<std::size_t>(mx / 2 + 1) * static_cast<std::size_t>(my);
    real.reset(static_cast<double*>(fftw_malloc(sizeof(double) * n_real)));
    spectrum.reset(static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * n_cplx)));
    kernel.reset(static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * n_cplx)));
    if (!real || !spectrum || !kernel) throw std::bad_alloc();
    // FFTW's 2-D arrays are row-major with the LAST dimension fastest: n0 = my (y), n1 = mx (x).
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    forward.reset(fftw_plan_dft_r2c_2d(my, mx, real.get(), spectrum.get(), FFTW_ESTIMATE));
    backward.reset(fftw_plan_dft_c2r_2d(my, mx, spectrum.get(), real.get(), FFTW_ESTIMATE));
    if (!forward || !backward) throw std::runtime_error("InfluenceGrid: FFTW planning failed");
  }

  /// The transform of the wrapped kernel k (mx·my values, x fastest), scaled once by 1/(mx·my),
  /// the normalisation FFTW leaves to the caller (FFTW 3 manual §4.8 "What FFTW Really Computes").
  void set_kernel(const std::vector<double>& k) {
    std::memcpy(real.get(), k.data(), sizeof(double) * n_real);
    fftw_execute(forward.get());
    const double scale = 1.0 / static_cast<double>(n_real);
    fftw_complex* kh = kernel.get();
    const fftw_complex* s = spectrum.get();
    for (std::size_t q = 0; q < n_cplx; ++q) {
      kh[q][0] = s[q][0] * scale;
      kh[q][1] = s[q][1] * scale;
    }
  }

  void convolve(const double* p, double* u) {
    const std::size_t mxs = static_cast<std::size_t>(mx), nxs = static_cast<std::size_t>(nx);
    double* r = real.get();
    std::memset(r, 0, sizeof(double) * n_real);
    for (int iy = 0; iy < ny; ++iy) std::memcpy(r + mxs * iy, p + nxs * iy, sizeof(double) * nxs);
    fftw_execute(forward.get());
    fftw_complex* s = spectrum.get();
    const fftw_complex* kh = kernel.get();
    for (std::size_t q = 0; q < n_cplx; ++q) {
      const double re = s[q][0] * kh[q][0] - s[q][1] * kh[q][1];
      const double im = s[q][0] * kh[q][1] + s[q][1] * kh[q][0];
      s[q][0] = re;
      s[q][1] = im;
    }
    fftw_execute(backward.get());  // c2r overwrites the spectrum; it is scratch
    for (int iy = 0; iy < ny; ++iy) std::memcpy(u + nxs * iy, r + mxs * iy, sizeof(double) * nxs);
  }
};

#else  // KissFFT

const char* fft_backend() { return "kissfft"; }

/// KissFFT backend ([K]): kissfft<double> has complex 1-D transforms only, so the 2-D real
/// convolution is built from them, keeping the work of a real-to-complex transform:
///  - rows along x, two real rows per complex transform (z = a + i b, then
///    A_k = (Z_k + conj Z_{mx−k}) / 2, B_k = (Z_k − conj Z_{mx−k}) / 2i), only the ny rows
///    that carry pressure, only the half spectrum kx = 0 … mx/2 kept;
///  - columns along y on that half spectrum, stored transposed ([kx·my + ky]) so that each
///    column is contiguous: forward, times the kernel's spectrum, backward, column by column;
///  - rows back, two per complex transform (Z = A + i B with the Hermitian halves filled in, the
///    imaginary parts at kx = 0 and mx/2 dropped as a c2r transform does), only the ny rows
///    that are wanted.
struct InfluenceGrid::Fft {
  using cpx = std::complex<double>;
  int nx, ny, mx, my, hx;
  kissfft<double> fx, ix, fy, iy;  ///< forward / inverse plans along x and along y
  std::vector<cpx> spec;    ///< half spectrum, transposed: [kx·my + ky], kx < hx
  std::vector<cpx> kernel;  ///< the wrapped kernel's spectrum, same layout, / (mx·my)
  std::vector<cpx> row_in, row_out, col;  ///< mx, mx and my work values

  Fft(int nx_, int ny_, int mx_, int my_)
      : nx(nx_), ny(ny_), mx(mx_), my(my_), hx(mx_ / 2 + 1),
        fx(static_cast<std::size_t>(mx_), false), ix(static_cast<std::size_t>(mx_), true),
        fy(static_cast<std::size_t>(my_), false), iy(static_cast<std::size_t>(my_), true),
        spec(static_cast<std::size_t>(hx) * my_), kernel(spec.size()),
        row_in(static_cast<std::size_t>(mx_)), row_out(row_in.size()), col(static_cast<std::size_t>(my_)) {}

  std::size_t at(int kx, int ky) const { return static_cast<std::size_t>(kx) * my + ky; }

  /// The x half spectra of rows 0 … nrows−1 of `src` (row r at src + r·stride, nvals values, zero
  /// beyond them) into spec; the rows nrows … my−1 are zero.
  void rows_forward(const double* src, int nrows, int nvals, std::size_t stride) {
    for (int r = 0; r < nrows; r += 2) {
      const bool pair = r + 1 < nrows;
      const double* a = src + stride * r;
      const double* b = pair ? a + stride : nullptr;
      for (int i = 0; i < nvals; ++i) row_in[i] = cpx(a[i], pair ? b[i] : 0.0);
      std::fill(row_in.begin() + nvals, row_in.end(), cpx(0.0, 0.0));
      fx.transform(row_in.data(), row_out.data());
      for (int k = 0; k < hx; ++k) {
        const cpx z = row_out[k], zc = std::conj(row_out[(mx - k) % mx]);
        spec[at(k, r)] = 0.5 * (z + zc);
        if (pair) spec[at(k, r + 1)] = cpx(0.0, -0.5) * (z - zc);
      }
    }
    for (int k = 0; k < hx; ++k) std::fill(spec.begin() + at(k, nrows), spec.begin() + at(k, my), cpx(0.0, 0.0));
  }

  void set_kernel(const std::vector<double>& k) {
    rows_forward(k.data(), my, mx, static_cast<std::size_t>(mx));
    const double scale = 1.0 / (static_cast<double>(mx) * static_cast<double>(my));
    for (int kx = 0; kx < hx; ++kx) {
      fy.transform(&spec[at(kx, 0)], &kernel[at(kx, 0)]);
      for (int ky = 0; ky < my; ++ky) kernel[at(kx, ky)] *= scale;
    }
  }

  void convolve(const double* p, double* u) {
    const std::size_t nxs = static_cast<std::size_t>(nx);
    rows_forward(p, ny, nx, nxs);  // reads all of p before u is written: they may alias
    for (int kx = 0; kx < hx; ++kx) {
      fy.transform(&spec[at(kx, 0)], col.data());
      const cpx* kh = &kernel[at(kx, 0)];
      for (int ky = 0; ky < my; ++ky) col[ky] *= kh[ky];
      iy.transform(col.data(), &spec[at(kx, 0)]);
    }
    for (int r = 0; r < ny; r += 2) {
      const bool pair = r + 1 < ny;
      for (int k = 0; k < hx; ++k) {
        cpx A = spec[at(k, r)], B = pair ? spec[at(k, r + 1)] : cpx(0.0, 0.0);
        if (k == 0 || 2 * k == mx) {
          A = cpx(A.real(), 0.0);
          B = cpx(B.real(), 0.0);
        }
        row_in[k] = A + cpx(0.0, 1.0) * B;
      }
      for (int k = hx; k < mx; ++k) {
        const cpx A = std::conj(spec[at(mx - k, r)]);
        const cpx B = pair ? std::conj(spec[at(mx - k, r + 1)]) : cpx(0.0, 0.0);
        row_in[k] = A + cpx(0.0, 1.0) * B;
      }
      ix.transform(row_in.data(), row_out.data());
      double* ua = u + nxs * r;
      for (int i = 0; i < nx; ++i) ua[i] = row_out[i].real();
      if (pair)
        for (int i = 0; i < nx; ++i) ua[nxs + i] = row_out[i].imag();
    }
  }
};

#endif

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
  fft_ = std::make_unique<Fft>(nx_, ny_, mx_, my_);
  c00_ = coefficient(0, 0);

  // Wrapped kernel (DC-FFT, [LI]); zero at the unused indices.
  std::vector<double> k(static_cast<std::size_t>(mx_) * static_cast<std::size_t>(my_));
  for (int j = 0; j < my_; ++j) {
    int dj = 0;
    const bool row = wrapped_offset(j, ny_, my_, &dj);
    for (int i = 0; i < mx_; ++i) {
      int di = 0;
      const bool used = row && wrapped_offset(i, nx_, mx_, &di);
      k[static_cast<std::size_t>(i) + static_cast<std::size_t>(mx_) * j] = used ? coefficient(di, dj) : 0.0;
    }
  }
  fft_->set_kernel(k);
}

InfluenceGrid::~InfluenceGrid() = default;
InfluenceGrid::InfluenceGrid(InfluenceGrid&&) noexcept = default;
InfluenceGrid& InfluenceGrid::operator=(InfluenceGrid&&) noexcept = default;

double InfluenceGrid::coefficient(int dix, int diy) const {
  return compliance_ * love_rectangle(dix * dx_, diy * dy_, 0.5 * dx_, 0.5 * dy_);
}

void InfluenceGrid::apply(const double* p, double* u) const { fft_->convolve(p, u); }

}  // namespace mh
