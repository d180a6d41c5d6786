// Row-by-row real transforms (row_fft.hpp) on the FFT backend (fft_backend.hpp).
#include "contact/half_space/fft_backend.hpp"
#include "contact/half_space/row_fft.hpp"

#include <algorithm>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>

#include "core/mru.hpp"

namespace mh {

#ifdef MHCONTACT_FFTW
/// FFTW: r2c / c2r plans of each length on their own buffers, the last 16 lengths per object.
struct RowFft::Impl {
  struct Plans {
    int m;
    std::unique_ptr<double, fft::FftwFree> real;
    std::unique_ptr<fftw_complex, fft::FftwFree> spec;
    fft::Plan forward, backward;
    explicit Plans(int m_) : m(m_) {
      real.reset(static_cast<double*>(fftw_malloc(sizeof(double) * static_cast<std::size_t>(m))));
      spec.reset(static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * static_cast<std::size_t>(m / 2 + 1))));
      if (!real || !spec) throw std::bad_alloc();
      std::lock_guard<std::mutex> lock(fft::planner_mutex());
      forward.reset(fftw_plan_dft_r2c_1d(m, real.get(), spec.get(), FFTW_ESTIMATE));
      backward.reset(fftw_plan_dft_c2r_1d(m, spec.get(), real.get(), FFTW_ESTIMATE));
      if (!forward || !backward) throw std::runtime_error("RowFft: FFTW planning failed");
    }
  };
  MruCache<int, std::unique_ptr<Plans>> cache{16};
  Plans* p = nullptr;
  void reset(int m) {
    p = cache.get(m, [m] { return std::make_unique<Plans>(m); }).get();
  }
  void fwd(const double* x, int len, std::complex<double>* X) {
    const int m = p->m;
    double* r = p->real.get();
    std::memcpy(r, x, sizeof(double) * static_cast<std::size_t>(len));
    std::fill(r + len, r + m, 0.0);
    fftw_execute(p->forward.get());
    for (int k = 0; k <= m / 2; ++k) X[k] = {p->spec.get()[k][0], p->spec.get()[k][1]};
  }
  void bwd(const std::complex<double>* X, double* x, int n) {
    const int m = p->m;
    for (int k = 0; k <= m / 2; ++k) {
      p->spec.get()[k][0] = X[k].real();
      p->spec.get()[k][1] = X[k].imag();
    }
    fftw_execute(p->backward.get());
    const double s = 1.0 / m;
    for (int i = 0; i < n; ++i) x[i] = p->real.get()[i] * s;
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
/// PocketFFT: the thread's real plan of length m (fft::real_plan) on the SIMD vector type,
/// sequence a in lane 0 and b in lane 1 (one call each when there are no vectors); the
/// transforms' scratch comes from the thread's ScratchStack.
struct RowFft::Impl {
  using Vd = mh_pocketfft::Vd;
  static constexpr int L = mh_pocketfft::L;
  int m = 0;
  std::shared_ptr<const fft::RealPlan> plan;
  std::vector<Vd> rows;  ///< m values per lane
  void reset(int m_) {
    if (m_ != m || !plan) plan = fft::real_plan(m_);
    m = m_;
    rows.assign(static_cast<std::size_t>(m), Vd{});
  }
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
      plan->exec(rows.data(), 1.0, true);
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
      plan->exec(rows.data(), 1.0 / m, false);
      for (int l = 0; l < L && s0 + l < 2; ++l)
        for (int i = 0; i < n; ++i) dst[s0 + l][i] = at(i, l);
    }
  }
};
#endif

RowFft::RowFft(int n) : impl_(std::make_unique<Impl>()) { reset(n); }

void RowFft::reset(int n) {
  if (n < 1) throw std::invalid_argument("RowFft: n = " + std::to_string(n) + ": needs ≥ 1 value per row");
  const int m = fft::smooth_size(2 * n - 1);
  impl_->reset(m);
  n_ = n;
  m_ = m;
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
bool RowFft::offset(int i, int* di) const { return fft::wrapped_offset(i, n_, m_, di); }

}  // namespace mh
