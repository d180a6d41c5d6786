// Half-space influence coefficients and DC-FFT convolution (sources in influence.hpp).
#include "contact/half_space/fft_backend.hpp"
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

}  // namespace

double love_rectangle(double x, double y, double a, double b) {
  // Summed in pairs so that the result is bitwise even in x and in y (floating-point addition is
  // commutative): the influence matrix is then exactly symmetric.
  return (love_corner(a + x, b + y) + love_corner(a - x, b + y)) +
         (love_corner(a + x, b - y) + love_corner(a - x, b - y));
}

#ifdef MHCONTACT_FFTW

const char* fft_backend() { return "fftw3"; }


/// FFTW backend: r2c / c2r plans over the whole padded grid.
struct InfluenceGrid::Fft {
  int nx, ny, mx, my;
  std::size_t n_real, n_cplx;
  std::unique_ptr<double, fft::FftwFree> real;           ///< mx·my work buffer
  std::unique_ptr<fftw_complex, fft::FftwFree> spectrum; ///< my·(mx/2+1) work buffer
  std::unique_ptr<fftw_complex, fft::FftwFree> kernel;   ///< FFT of the wrapped kernel, / (mx·my)
  fft::Plan forward, backward;

  Fft(int nx_, int ny_, int mx_, int my_) : nx(nx_), ny(ny_), mx(mx_), my(my_) {
    n_real = static_cast<std::size_t>(mx) * static_cast<std::size_t>(my);
    n_cplx = static_cast<std::size_t>(mx / 2 + 1) * static_cast<std::size_t>(my);
    real.reset(static_cast<double*>(fftw_malloc(sizeof(double) * n_real)));
    spectrum.reset(static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * n_cplx)));
    kernel.reset(static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * n_cplx)));
    if (!real || !spectrum || !kernel) throw std::bad_alloc();
    // FFTW's 2-D arrays are row-major with the LAST dimension fastest: n0 = my (y), n1 = mx (x).
    std::lock_guard<std::mutex> lock(fft::planner_mutex());
    forward.reset(fftw_plan_dft_r2c_2d(my, mx, real.get(), spectrum.get(), FFTW_ESTIMATE));
    backward.reset(fftw_plan_dft_c2r_2d(my, mx, spectrum.get(), real.get(), FFTW_ESTIMATE));
    if (!forward || !backward) throw std::runtime_error("InfluenceGrid: FFTW planning failed");
  }

  /// As Fft(…) for these sizes; the buffers and plans kept when the padded sizes are the same.
  void reset(int nx_, int ny_, int mx_, int my_) {
    if (mx_ == mx && my_ == my) {
      nx = nx_;
      ny = ny_;
      return;
    }
    *this = Fft(nx_, ny_, mx_, my_);
  }
  /// Whether reset() to padded sizes mx_ × my_ allocates nothing.
  bool holds(int mx_, int my_) const { return mx_ == mx && my_ == my; }

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

/// PocketFFT backend ([P]): the 1-D plans of pocketfft_hdronly.h used directly, taken when the
/// grid is set up from the thread's plans by length (fft_backend.hpp), so apply() builds no plan
/// and takes no lock. The 2-D real convolution:
///  - rows along x, real-to-complex (FFTPACK half-complex order r0, r1, i1, r2, i2, …), L rows
///    per call, only the ny rows that carry pressure; the half spectrum kx = 0 … mx/2 kept;
///  - columns along y on that half spectrum, L columns per call, stored as blocks of L columns
///    ([b·my + ky], lane kx − L·b) so that a block is transformed in place: forward, times the
///    kernel's spectrum, backward;
///  - rows back, complex-to-real (the imaginary parts at kx = 0 and mx/2 are not read, as a c2r
///    transform does), only the ny rows that are wanted.
/// Each 1-D call's scratch of one sequence (rfftp/cfftp::exec) comes from the thread's
/// ScratchStack (fft_backend.hpp): no allocation once the thread has transformed its largest grid.
struct InfluenceGrid::Fft {
  using Vd = mh_pocketfft::Vd;
  static constexpr int L = mh_pocketfft::L;
  using Cv = pocketfft::detail::cmplx<Vd>;
  int nx = 0, ny = 0, mx = 0, my = 0, hx = 0, nb = 0;  ///< hx = mx/2 + 1 spectrum columns in nb blocks of L
  std::shared_ptr<const fft::RealPlan> plan_x;     ///< real transforms of length mx (the thread's, fft::real_plan)
  std::shared_ptr<const fft::ComplexPlan> plan_y;  ///< complex transforms of length my
  std::vector<Cv> spec;    ///< half spectrum, nb·my blocks of L columns (lanes past hx stay 0)
  std::vector<Cv> kernel;  ///< the wrapped kernel's spectrum, same layout, / (mx·my)
  /// L rows of mx values, then two spare slots: [mx] stays 0 (read for the imaginary parts that
  /// the half-complex order does not hold), [mx+1] takes what is not written back.
  std::vector<Vd> rows;
  /// Per spectrum lane kx = 0 … nb·L−1: the slot of rows holding Re and Im of column kx, to read
  /// from after the forward transform (get_*) and to write to before the backward one (put_*).
  std::vector<int> get_re, get_im, put_re, put_im;

  Fft(int nx_, int ny_, int mx_, int my_) { reset(nx_, ny_, mx_, my_); }

  static int blocks(int mx_) { return (mx_ / 2 + 1 + L - 1) / L; }
  /// Whether reset() to padded sizes mx_ × my_ allocates nothing (its plans aside, which the
  /// thread keeps by length).
  bool holds(int mx_, int my_) const {
    const std::size_t lanes = static_cast<std::size_t>(blocks(mx_)) * L;
    const std::size_t ns = static_cast<std::size_t>(blocks(mx_)) * static_cast<std::size_t>(my_);
    return spec.capacity() >= ns && kernel.capacity() >= ns && rows.capacity() >= static_cast<std::size_t>(mx_) + 2 &&
           get_re.capacity() >= lanes && get_im.capacity() >= lanes && put_re.capacity() >= lanes &&
           put_im.capacity() >= lanes;
  }
  /// As a new Fft of these sizes, in these buffers (every value written again).
  void reset(int nx_, int ny_, int mx_, int my_) {
    if (!plan_x || mx_ != mx) plan_x = fft::real_plan(mx_);
    if (!plan_y || my_ != my) plan_y = fft::complex_plan(my_);
    nx = nx_;
    ny = ny_;
    mx = mx_;
    my = my_;
    hx = mx / 2 + 1;
    nb = blocks(mx);
    spec.assign(static_cast<std::size_t>(nb) * static_cast<std::size_t>(my), Cv(Vd{}, Vd{}));
    kernel.assign(spec.size(), Cv(Vd{}, Vd{}));
    rows.assign(static_cast<std::size_t>(mx) + 2, Vd{});
    const int zero = mx, spare = mx + 1;
    for (auto* v : {&get_re, &get_im, &put_re, &put_im}) {
      v->clear();
      v->reserve(static_cast<std::size_t>(nb) * L);
    }
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
      plan_x->exec(rows.data(), 1.0, true);
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
    for (int b = 0; b < nb; ++b) plan_y->exec(&spec[static_cast<std::size_t>(b) * my], scale, true);
    kernel = spec;
  }

  void convolve(const double* p, double* u) {
    const std::size_t nxs = static_cast<std::size_t>(nx);
    rows_forward(p, ny, nx, nxs);  // reads all of p before u is written: they may alias
    for (int b = 0; b < nb; ++b) {
      Cv* z = &spec[static_cast<std::size_t>(b) * my];
      const Cv* kh = &kernel[static_cast<std::size_t>(b) * my];
      plan_y->exec(z, 1.0, true);
      for (int ky = 0; ky < my; ++ky) z[ky] = z[ky] * kh[ky];
      plan_y->exec(z, 1.0, false);
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
      plan_x->exec(rows.data(), 1.0, false);  // c2r: the Im of kx = 0 and mx/2 are not read
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

InfluenceGrid::InfluenceGrid(int nx, int ny, double dx, double dy, double compliance) {
  reset(nx, ny, dx, dy, compliance);
}

void InfluenceGrid::reset(int nx, int ny, double dx, double dy, double compliance) {
  check_grid(nx, ny, dx, dy);
  if (!(compliance > 0) || !std::isfinite(compliance))
    throw std::invalid_argument("InfluenceGrid: compliance = " + std::to_string(compliance) +
                                " 1/Pa: must be > 0 and finite");
  nx_ = nx;
  ny_ = ny;
  dx_ = dx;
  dy_ = dy;
  compliance_ = compliance;
  kernel_ = nullptr;
  try {
    init_fft();
  } catch (...) {
    nx_ = ny_ = 0;  // matches no grid: a cache keyed by the sizes never hands it out
    throw;
  }
}

bool InfluenceGrid::holds(int nx, int ny) const {
  if (!fft_ || nx < 1 || ny < 1) return false;
  const std::size_t offsets = (2 * static_cast<std::size_t>(nx) - 1) * (2 * static_cast<std::size_t>(ny) - 1);
  return direct_.capacity() >= offsets && fft_->holds(fft::smooth_size(2 * nx - 1), fft::smooth_size(2 * ny - 1));
}

InfluenceGrid::InfluenceGrid(int nx, int ny, double dx, double dy, Kernel kernel)
    : nx_(nx), ny_(ny), dx_(dx), dy_(dy), compliance_(std::nan("")), kernel_(std::move(kernel)) {
  check_grid(nx, ny, dx, dy);
  if (!kernel_) throw std::invalid_argument("InfluenceGrid: the kernel function is empty");
  init_fft();
}

void InfluenceGrid::init_fft() {
  mx_ = fft::smooth_size(2 * nx_ - 1);
  my_ = fft::smooth_size(2 * ny_ - 1);
  if (fft_)
    fft_->reset(nx_, ny_, mx_, my_);
  else
    fft_ = std::make_unique<Fft>(nx_, ny_, mx_, my_);
  c00_ = coefficient(0, 0);
  // The thread's scratch for the coefficients (kept: a grid no larger than the thread's largest
  // allocates nothing here).
  thread_local std::vector<double> quadrant, k;

  // Love's kernel is bitwise even in both offsets (love_rectangle): its nx·ny values for
  // |di| < nx, |dj| < ny give all (2nx − 1)(2ny − 1), a quarter of the evaluations (the same bits).
  const std::size_t qx = static_cast<std::size_t>(nx_);
  if (!kernel_) {
    quadrant.resize(qx * static_cast<std::size_t>(ny_));
    double* q = quadrant.data();
    for (int dj = 0; dj < ny_; ++dj)
      for (int di = 0; di < nx_; ++di) q[static_cast<std::size_t>(di) + qx * dj] = coefficient(di, dj);
  }
  const double* q = quadrant.data();
  auto C = [&](int di, int dj) {
    return kernel_ ? coefficient(di, dj) : q[static_cast<std::size_t>(std::abs(di)) + qx * std::abs(dj)];
  };
  // Wrapped kernel (DC-FFT, [LI]); zero at the unused indices.
  const std::size_t mxs = static_cast<std::size_t>(mx_);
  k.resize(mxs * static_cast<std::size_t>(my_));
  double* kd = k.data();
  for (int j = 0; j < my_; ++j) {
    int dj = 0;
    const bool row = fft::wrapped_offset(j, ny_, my_, &dj);
    for (int i = 0; i < mx_; ++i) {
      int di = 0;
      const bool used = row && fft::wrapped_offset(i, nx_, mx_, &di);
      kd[static_cast<std::size_t>(i) + mxs * j] = used ? C(di, dj) : 0.0;
    }
  }
  // The same coefficients by offset, for add_sparse (copied, not evaluated again).
  const std::size_t W = 2 * static_cast<std::size_t>(nx_) - 1;
  direct_.assign(W * (2 * static_cast<std::size_t>(ny_) - 1), 0.0);
  double* dd = direct_.data();
  for (int j = 0; j < my_; ++j) {
    int dj = 0;
    if (!fft::wrapped_offset(j, ny_, my_, &dj)) continue;
    for (int i = 0; i < mx_; ++i) {
      int di = 0;
      if (fft::wrapped_offset(i, nx_, mx_, &di))
        dd[static_cast<std::size_t>(di + nx_ - 1) + W * static_cast<std::size_t>(dj + ny_ - 1)] = kd[static_cast<std::size_t>(i) + mxs * j];
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

}  // namespace mh
