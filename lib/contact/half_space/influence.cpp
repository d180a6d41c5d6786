// Half-space influence coefficients and DC-FFT convolution (sources in influence.hpp).
#include "contact/half_space/influence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
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
// PocketFFT's own thread pool stays out: apply() is called from the project's worker threads
// (lib/jobs), one transform per call.
#define POCKETFFT_NO_MULTITHREADING
// The header's arr<T> takes C11 aligned_alloc(64, n) under glibc without rounding n up to a
// multiple of 64, which C11 requires (AddressSanitizer rejects every plan); this macro, tested by
// the header alone, selects its portable aligned allocator (malloc + 64, aligned by hand) instead.
#define _LIBCPP_HAS_NO_ALIGNED_ALLOCATION
#include <pocketfft_hdronly.h>
#endif

#include "core/units.hpp"

#ifndef MHCONTACT_FFTW
namespace mh_pocketfft {
namespace pf = pocketfft::detail;
/// PocketFFT's SIMD vector of doubles (2 lanes with SSE2, 4 with AVX, 1 without vectors): its
/// 1-D plans transform L independent sequences at once when given arrays of these ([P]).
#ifndef POCKETFFT_NO_VECTORS
using Vd = pf::vtype_t<double>;
#else
using Vd = double;
#endif
constexpr int L = static_cast<int>(sizeof(Vd) / sizeof(double));

/// Per-thread scratch for PocketFFT's 1-D calls: each rfftp/cfftp::exec makes an arr<T> of one
/// sequence (T = Vd or cmplx<Vd> here), which would be an aligned heap allocation per call.
/// The arr<> specialisations below take the buffers from this stack instead (last in, first
/// out, so nested calls each get their own) and keep them for the thread's next call: after the
/// first apply() of the largest grid, a thread allocates nothing in the FFT. This relies on the
/// header's exec() taking its scratch as an arr<T> (pocketfft_hdronly.h of Debian 12's gemmi-dev,
/// and PocketFFT's C++ releases since 2019); were that to change, only the allocations return.
class ScratchStack {
 public:
  static ScratchStack& local() {
    static thread_local ScratchStack s;
    return s;
  }
  void* take(std::size_t bytes) {
    if (top_ == bufs_.size()) bufs_.emplace_back();
    Buffer& b = bufs_[top_++];
    if (b.bytes < bytes) {
      b.mem.reset(static_cast<char*>(::operator new(bytes, std::align_val_t{64})));
      b.bytes = bytes;
    }
    return b.mem.get();
  }
  void give_back() { --top_; }

 private:
  struct Free {
    void operator()(char* p) const { ::operator delete(p, std::align_val_t{64}); }
  };
  struct Buffer {
    std::unique_ptr<char, Free> mem;
    std::size_t bytes = 0;
  };
  std::vector<Buffer> bufs_;
  std::size_t top_ = 0;
};

/// The interface of pocketfft::detail::arr<T> as exec() uses it, on ScratchStack.
template <typename T>
class ScratchArr {
 public:
  ScratchArr() = default;
  explicit ScratchArr(std::size_t n) : sz_(n) {
    if (n > 0) p_ = static_cast<T*>(ScratchStack::local().take(n * sizeof(T)));
  }
  ScratchArr(const ScratchArr&) = delete;
  ScratchArr& operator=(const ScratchArr&) = delete;
  ~ScratchArr() {
    if (p_) ScratchStack::local().give_back();
  }
  T& operator[](std::size_t i) { return p_[i]; }
  const T& operator[](std::size_t i) const { return p_[i]; }
  T* data() { return p_; }
  const T* data() const { return p_; }
  std::size_t size() const { return sz_; }

 private:
  T* p_ = nullptr;
  std::size_t sz_ = 0;
};
}  // namespace mh_pocketfft

#ifndef POCKETFFT_NO_VECTORS  // (without vectors Vd is double, whose arr also holds the twiddles)
template <>
class pocketfft::detail::arr<mh_pocketfft::Vd> : public mh_pocketfft::ScratchArr<mh_pocketfft::Vd> {
 public:
  using ScratchArr::ScratchArr;
};
template <>
class pocketfft::detail::arr<pocketfft::detail::cmplx<mh_pocketfft::Vd>>
    : public mh_pocketfft::ScratchArr<pocketfft::detail::cmplx<mh_pocketfft::Vd>> {
 public:
  using ScratchArr::ScratchArr;
};
#endif
#endif

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
/// FFTW (FFTW 3 manual §2.1, "sizes of the form 2^a 3^b 5^c 7^d"); 2, 3, 5 for PocketFFT, whose
/// real transforms (rfftp) have butterflies for 2, 3, 4 and 5 only, 7 going through the generic
/// O(p²) one (radfg/radbg), the same sizes as util::good_size_real ([P]).
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

#else  // PocketFFT

const char* fft_backend() { return "pocketfft"; }

/// PocketFFT backend ([P]): the 1-D plans of pocketfft_hdronly.h used directly, made once per
/// grid (factors and twiddles), so apply() builds no plan and takes no lock. The 2-D real
/// convolution:
///  - rows along x, real-to-complex (FFTPACK half-complex order r0, r1, i1, r2, i2, …), L rows
///    per call, only the ny rows that carry pressure; the half spectrum kx = 0 … mx/2 kept;
///  - columns along y on that half spectrum, L columns per call, stored as blocks of L columns
///    ([b·my + ky], lane kx − L·b) so that a block is transformed in place: forward, times the
///    kernel's spectrum, backward;
///  - rows back, complex-to-real (the imaginary parts at kx = 0 and mx/2 are not read, as a c2r
///    transform does), only the ny rows that are wanted.
/// Each 1-D call's scratch of one sequence (rfftp/cfftp::exec) comes from the thread's
/// ScratchStack above: no allocation once the thread has transformed its largest grid.
struct InfluenceGrid::Fft {
  using Vd = mh_pocketfft::Vd;
  static constexpr int L = mh_pocketfft::L;
  using Cv = pocketfft::detail::cmplx<Vd>;
  int nx, ny, mx, my, hx, nb;  ///< hx = mx/2 + 1 spectrum columns in nb blocks of L
  pocketfft::detail::pocketfft_r<double> plan_x;  ///< real transforms of length mx
  pocketfft::detail::pocketfft_c<double> plan_y;  ///< complex transforms of length my
  std::vector<Cv> spec;    ///< half spectrum, nb·my blocks of L columns (lanes past hx stay 0)
  std::vector<Cv> kernel;  ///< the wrapped kernel's spectrum, same layout, / (mx·my)
  /// L rows of mx values, then two spare slots: [mx] stays 0 (read for the imaginary parts that
  /// the half-complex order does not hold), [mx+1] takes what is not written back.
  std::vector<Vd> rows;
  /// Per spectrum lane kx = 0 … nb·L−1: the slot of rows holding Re and Im of column kx, to read
  /// from after the forward transform (get_*) and to write to before the backward one (put_*).
  std::vector<int> get_re, get_im, put_re, put_im;

  Fft(int nx_, int ny_, int mx_, int my_)
      : nx(nx_), ny(ny_), mx(mx_), my(my_), hx(mx_ / 2 + 1), nb((hx + L - 1) / L),
        plan_x(static_cast<std::size_t>(mx_)), plan_y(static_cast<std::size_t>(my_)),
        spec(static_cast<std::size_t>(nb) * static_cast<std::size_t>(my_), Cv(Vd{}, Vd{})),
        kernel(spec.size(), Cv(Vd{}, Vd{})), rows(static_cast<std::size_t>(mx_) + 2, Vd{}) {
    const int zero = mx, spare = mx + 1;
    for (auto* v : {&get_re, &get_im, &put_re, &put_im}) v->reserve(static_cast<std::size_t>(nb) * L);
    for (int k = 0; k < nb * L; ++k) {
      // FFTPACK half-complex order: r0, r1, i1, r2, i2, …, and r_{mx/2} last when mx is even.
      const int re = k >= hx ? -1 : k == 0 ? 0 : 2 * k - 1;
      const int im = k >= hx || k == 0 || 2 * k == mx ? -1 : 2 * k;
      get_re.push_back(re < 0 ? zero : re);
      get_im.push_back(im < 0 ? zero : im);
      put_re.push_back(re < 0 ? spare : re);
      put_im.push_back(im < 0 ? spare : im);
    }
  }

  double* spec_at(int b, int ky) {
    return reinterpret_cast<double*>(&spec[static_cast<std::size_t>(b) * my + ky]);
  }

  /// The x half spectra of rows 0 … nrows−1 of `src` (row r at src + r·stride, nvals values, zero
  /// beyond them) into spec; the rows nrows … my−1 are zero.
  void rows_forward(const double* src, int nrows, int nvals, std::size_t stride) {
    double* R = reinterpret_cast<double*>(rows.data());  // R[i·L + l]: value i of lane l
    for (int r0 = 0; r0 < nrows; r0 += L) {
      const int nl = std::min(L, nrows - r0);
      for (int l = 0; l < L; ++l) {
        const double* a = src + stride * static_cast<std::size_t>(r0 + l);
        for (int i = 0; i < nvals; ++i) R[i * L + l] = l < nl ? a[i] : 0.0;
        for (int i = nvals; i < mx; ++i) R[i * L + l] = 0.0;
      }
      plan_x.exec(rows.data(), 1.0, true);
      for (int l = 0; l < nl; ++l)
        for (int b = 0; b < nb; ++b) {
          double* z = spec_at(b, r0 + l);  // z[j]: Re of lane j, z[L + j]: Im
          const int* gr = &get_re[static_cast<std::size_t>(b) * L];
          const int* gi = &get_im[static_cast<std::size_t>(b) * L];
          for (int j = 0; j < L; ++j) {
            z[j] = R[gr[j] * L + l];
            z[L + j] = R[gi[j] * L + l];
          }
        }
    }
    for (int b = 0; b < nb; ++b)
      std::fill(spec.begin() + static_cast<std::ptrdiff_t>(b) * my + nrows,
                spec.begin() + static_cast<std::ptrdiff_t>(b + 1) * my, Cv(Vd{}, Vd{}));
  }

  void set_kernel(const std::vector<double>& k) {
    rows_forward(k.data(), my, mx, static_cast<std::size_t>(mx));
    const double scale = 1.0 / (static_cast<double>(mx) * static_cast<double>(my));
    for (int b = 0; b < nb; ++b) plan_y.exec(&spec[static_cast<std::size_t>(b) * my], scale, true);
    kernel = spec;
  }

  void convolve(const double* p, double* u) {
    const std::size_t nxs = static_cast<std::size_t>(nx);
    rows_forward(p, ny, nx, nxs);  // reads all of p before u is written: they may alias
    for (int b = 0; b < nb; ++b) {
      Cv* z = &spec[static_cast<std::size_t>(b) * my];
      const Cv* kh = &kernel[static_cast<std::size_t>(b) * my];
      plan_y.exec(z, 1.0, true);
      for (int ky = 0; ky < my; ++ky) z[ky] = z[ky] * kh[ky];
      plan_y.exec(z, 1.0, false);
    }
    double* R = reinterpret_cast<double*>(rows.data());
    for (int r0 = 0; r0 < ny; r0 += L) {
      const int nl = std::min(L, ny - r0);
      for (int l = 0; l < L; ++l)
        for (int b = 0; b < nb; ++b) {
          const double* z = spec_at(b, r0 + std::min(l, nl - 1));  // a lane past the last row: unused
          const int* pr = &put_re[static_cast<std::size_t>(b) * L];
          const int* pi = &put_im[static_cast<std::size_t>(b) * L];
          for (int j = 0; j < L; ++j) {
            R[pr[j] * L + l] = z[j];
            R[pi[j] * L + l] = z[L + j];
          }
        }
      plan_x.exec(rows.data(), 1.0, false);  // c2r: the Im of kx = 0 and mx/2 are not read
      for (int l = 0; l < nl; ++l) {
        double* ur = u + nxs * static_cast<std::size_t>(r0 + l);
        for (int i = 0; i < nx; ++i) ur[i] = R[i * L + l];
      }
    }
  }
};

#endif

namespace {
// The grid both constructors need: at least 1 × 1 elements of positive, finite size.
void check_grid(int nx, int ny, double dx, double dy) {
  if (nx < 1 || ny < 1)
    throw std::invalid_argument("InfluenceGrid: nx = " + std::to_string(nx) + ", ny = " +
                                std::to_string(ny) + ": the grid needs at least 1 × 1 elements");
  if (!(dx > 0) || !(dy > 0) || !std::isfinite(dx) || !std::isfinite(dy))
    throw std::invalid_argument("InfluenceGrid: dx = " + std::to_string(dx) + " m, dy = " +
                                std::to_string(dy) + " m: element sizes must be > 0 and finite");
}
}  // namespace

InfluenceGrid::InfluenceGrid(int nx, int ny, double dx, double dy, double compliance)
    : nx_(nx), ny_(ny), dx_(dx), dy_(dy), compliance_(compliance) {
  check_grid(nx, ny, dx, dy);
  if (!(compliance > 0) || !std::isfinite(compliance))
    throw std::invalid_argument("InfluenceGrid: compliance = " + std::to_string(compliance) +
                                " 1/Pa: must be > 0 and finite");
  init_fft();
}

InfluenceGrid::InfluenceGrid(int nx, int ny, double dx, double dy, Kernel kernel)
    : nx_(nx), ny_(ny), dx_(dx), dy_(dy), compliance_(std::nan("")), kernel_(std::move(kernel)) {
  check_grid(nx, ny, dx, dy);
  if (!kernel_) throw std::invalid_argument("InfluenceGrid: the kernel function is empty");
  init_fft();
}

void InfluenceGrid::init_fft() {
  mx_ = smooth_size(2 * nx_ - 1);
  my_ = smooth_size(2 * ny_ - 1);
  fft_ = std::make_unique<Fft>(nx_, ny_, mx_, my_);
  c00_ = coefficient(0, 0);

  // Love's kernel is bitwise even in both offsets (love_rectangle): its nx·ny values for
  // |di| < nx, |dj| < ny give all (2nx − 1)(2ny − 1), a quarter of the evaluations (the same bits).
  std::vector<double> quadrant;
  const std::size_t qx = static_cast<std::size_t>(nx_);
  if (!kernel_) {
    quadrant.resize(qx * static_cast<std::size_t>(ny_));
    for (int dj = 0; dj < ny_; ++dj)
      for (int di = 0; di < nx_; ++di) quadrant[static_cast<std::size_t>(di) + qx * dj] = coefficient(di, dj);
  }
  auto C = [&](int di, int dj) {
    return kernel_ ? coefficient(di, dj) : quadrant[static_cast<std::size_t>(std::abs(di)) + qx * std::abs(dj)];
  };
  // Wrapped kernel (DC-FFT, [LI]); zero at the unused indices.
  std::vector<double> k(static_cast<std::size_t>(mx_) * static_cast<std::size_t>(my_));
  for (int j = 0; j < my_; ++j) {
    int dj = 0;
    const bool row = wrapped_offset(j, ny_, my_, &dj);
    for (int i = 0; i < mx_; ++i) {
      int di = 0;
      const bool used = row && wrapped_offset(i, nx_, mx_, &di);
      k[static_cast<std::size_t>(i) + static_cast<std::size_t>(mx_) * j] = used ? C(di, dj) : 0.0;
    }
  }
  // The same coefficients by offset, for add_sparse (copied, not evaluated again).
  const std::size_t W = 2 * static_cast<std::size_t>(nx_) - 1;
  direct_.assign(W * (2 * static_cast<std::size_t>(ny_) - 1), 0.0);
  for (int j = 0; j < my_; ++j) {
    int dj = 0;
    if (!wrapped_offset(j, ny_, my_, &dj)) continue;
    for (int i = 0; i < mx_; ++i) {
      int di = 0;
      if (wrapped_offset(i, nx_, mx_, &di))
        direct_[static_cast<std::size_t>(di + nx_ - 1) + W * static_cast<std::size_t>(dj + ny_ - 1)] =
            k[static_cast<std::size_t>(i) + static_cast<std::size_t>(mx_) * j];
    }
  }
  fft_->set_kernel(k);
}

InfluenceGrid::~InfluenceGrid() = default;
InfluenceGrid::InfluenceGrid(InfluenceGrid&&) noexcept = default;
InfluenceGrid& InfluenceGrid::operator=(InfluenceGrid&&) noexcept = default;

double InfluenceGrid::coefficient(int dix, int diy) const {
  if (kernel_) return kernel_(dix, diy);
  return compliance_ * love_rectangle(dix * dx_, diy * dy_, 0.5 * dx_, 0.5 * dy_);
}

void InfluenceGrid::apply(const double* p, double* u) const { fft_->convolve(p, u); }

void InfluenceGrid::add_sparse(const int* idx, const double* d, int m, double* u) const {
  const std::size_t W = 2 * static_cast<std::size_t>(nx_) - 1, nxs = static_cast<std::size_t>(nx_);
  for (int k = 0; k < m; ++k) {
    const int jx = idx[k] % nx_, jy = idx[k] / nx_;
    const double v = d[k];
    // u(ix, iy) += C(ix − jx, iy − jy) v: row iy of u against the kernel's row iy − jy from ix − jx = −jx.
    for (int iy = 0; iy < ny_; ++iy) {
      const double* c = &direct_[static_cast<std::size_t>(nx_ - 1 - jx) + W * static_cast<std::size_t>(iy - jy + ny_ - 1)];
      double* ur = u + nxs * static_cast<std::size_t>(iy);
      for (std::size_t ix = 0; ix < nxs; ++ix) ur[ix] += c[ix] * v;
    }
  }
}

// ---- RowFft: 1-D real transforms for row-wise convolutions (influence.hpp) ----

#ifdef MHCONTACT_FFTW
struct RowFft::Impl {
  int m;
  std::unique_ptr<double, FftwFree> real;
  std::unique_ptr<fftw_complex, FftwFree> spec;
  Plan forward, backward;
  explicit Impl(int m_) : m(m_) {
    real.reset(static_cast<double*>(fftw_malloc(sizeof(double) * static_cast<std::size_t>(m))));
    spec.reset(static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * static_cast<std::size_t>(m / 2 + 1))));
    if (!real || !spec) throw std::bad_alloc();
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    forward.reset(fftw_plan_dft_r2c_1d(m, real.get(), spec.get(), FFTW_ESTIMATE));
    backward.reset(fftw_plan_dft_c2r_1d(m, spec.get(), real.get(), FFTW_ESTIMATE));
    if (!forward || !backward) throw std::runtime_error("RowFft: FFTW planning failed");
  }
  void fwd(const double* x, int len, std::complex<double>* X) {
    double* r = real.get();
    std::memcpy(r, x, sizeof(double) * static_cast<std::size_t>(len));
    std::fill(r + len, r + m, 0.0);
    fftw_execute(forward.get());
    for (int k = 0; k <= m / 2; ++k) X[k] = {spec.get()[k][0], spec.get()[k][1]};
  }
  void bwd(const std::complex<double>* X, double* x, int n) {
    for (int k = 0; k <= m / 2; ++k) {
      spec.get()[k][0] = X[k].real();
      spec.get()[k][1] = X[k].imag();
    }
    fftw_execute(backward.get());
    const double s = 1.0 / m;
    for (int i = 0; i < n; ++i) x[i] = real.get()[i] * s;
  }
  void forward2(const double* a, const double* b, int len, std::complex<double>* A, std::complex<double>* B) {
    fwd(a, len, A);
    fwd(b, len, B);
  }
  void backward2(const std::complex<double>* A, const std::complex<double>* B, double* a, double* b, int n) {
    bwd(A, a, n);
    bwd(B, b, n);
  }
};
#else
/// PocketFFT: the real plan of length m on the SIMD vector type, sequence a in lane 0 and b in
/// lane 1 (one call each when there are no vectors): its scratch comes from ScratchStack.
struct RowFft::Impl {
  using Vd = mh_pocketfft::Vd;
  static constexpr int L = mh_pocketfft::L;
  int m;
  pocketfft::detail::pocketfft_r<double> plan;
  std::vector<Vd> rows;  ///< m values per lane
  explicit Impl(int m_) : m(m_), plan(static_cast<std::size_t>(m_)), rows(static_cast<std::size_t>(m_), Vd{}) {}
  double& at(int i, int lane) { return reinterpret_cast<double*>(rows.data())[i * L + lane]; }
  /// FFTPACK half-complex order r0, r1, i1, r2, i2, …, r_{m/2} (m even) of one lane into X.
  void unpack(int lane, std::complex<double>* X) {
    X[0] = {at(0, lane), 0.0};
    for (int k = 1; 2 * k < m; ++k) X[k] = {at(2 * k - 1, lane), at(2 * k, lane)};
    if (m % 2 == 0 && m > 1) X[m / 2] = {at(m - 1, lane), 0.0};
  }
  void pack(int lane, const std::complex<double>* X) {
    at(0, lane) = X[0].real();
    for (int k = 1; 2 * k < m; ++k) {
      at(2 * k - 1, lane) = X[k].real();
      at(2 * k, lane) = X[k].imag();
    }
    if (m % 2 == 0 && m > 1) at(m - 1, lane) = X[m / 2].real();
  }
  void forward2(const double* a, const double* b, int len, std::complex<double>* A, std::complex<double>* B) {
    const double* src[2] = {a, b};
    std::complex<double>* dst[2] = {A, B};
    for (int s0 = 0; s0 < 2; s0 += L) {
      for (int l = 0; l < L; ++l) {
        const double* x = s0 + l < 2 ? src[s0 + l] : nullptr;
        for (int i = 0; i < m; ++i) at(i, l) = x && i < len ? x[i] : 0.0;
      }
      plan.exec(rows.data(), 1.0, true);
      for (int l = 0; l < L && s0 + l < 2; ++l) unpack(l, dst[s0 + l]);
    }
  }
  void backward2(const std::complex<double>* A, const std::complex<double>* B, double* a, double* b, int n) {
    const std::complex<double>* src[2] = {A, B};
    double* dst[2] = {a, b};
    for (int s0 = 0; s0 < 2; s0 += L) {
      for (int l = 0; l < L; ++l) {
        if (s0 + l < 2)
          pack(l, src[s0 + l]);
        else
          for (int i = 0; i < m; ++i) at(i, l) = 0.0;
      }
      plan.exec(rows.data(), 1.0 / m, false);
      for (int l = 0; l < L && s0 + l < 2; ++l)
        for (int i = 0; i < n; ++i) dst[s0 + l][i] = at(i, l);
    }
  }
};
#endif

RowFft::RowFft(int n) { reset(n); }

void RowFft::reset(int n) {
  if (n < 1) throw std::invalid_argument("RowFft: n = " + std::to_string(n) + ": needs ≥ 1 value per row");
  n_ = n;
  m_ = smooth_size(2 * n - 1);
  for (std::size_t k = 0; k < plans_.size(); ++k)
    if (plans_[k]->m == m_) {
      std::rotate(plans_.begin() + static_cast<std::ptrdiff_t>(k), plans_.begin() + static_cast<std::ptrdiff_t>(k) + 1,
                  plans_.end());  // most recently used last
      impl_ = plans_.back().get();
      return;
    }
  if (plans_.size() >= kRowPlans) plans_.erase(plans_.begin());  // the least recently used
  plans_.push_back(std::make_unique<Impl>(m_));
  impl_ = plans_.back().get();
}
RowFft::~RowFft() = default;
RowFft::RowFft(RowFft&&) noexcept = default;
RowFft& RowFft::operator=(RowFft&&) noexcept = default;

void RowFft::forward(const double* a, const double* b, int len, std::complex<double>* A,
                     std::complex<double>* B) const {
  impl_->forward2(a, b, std::min(len, m_), A, B);
}
void RowFft::backward(const std::complex<double>* A, const std::complex<double>* B, double* a,
                      double* b) const {
  impl_->backward2(A, B, a, b, n_);
}
bool RowFft::offset(int i, int* di) const { return wrapped_offset(i, n_, m_, di); }

}  // namespace mh
