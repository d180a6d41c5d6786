#pragma once
// One-dimensional real DC-FFT transforms for row-by-row convolutions along x (the steady-rolling
// tangential solver, tangential_rolling.hpp). Sources [LI], [P] in influence.hpp.
#include <complex>
#include <memory>

namespace mh {

/// Rows of n values zero-padded to m points (the smallest smooth size ≥ 2n−1, as InfluenceGrid),
/// half spectra of m/2 + 1 complex values. Two sequences per call (an x and a y component),
/// transformed together in PocketFFT's SIMD lanes. After the first call no allocation (PocketFFT
/// with SIMD vectors; FFTW). Not thread-safe per object. Movable, not copyable.
class RowFft {
 public:
  explicit RowFft(int n);  ///< throws std::invalid_argument unless n ≥ 1
  ~RowFft();
  RowFft(RowFft&&) noexcept;
  RowFft& operator=(RowFft&&) noexcept;
  RowFft(const RowFft&) = delete;
  RowFft& operator=(const RowFft&) = delete;

  /// As RowFft(n), in this object's buffers: a padded length met before (PocketFFT: by this
  /// thread, its last fft::kPlans lengths; FFTW: by this object, its last 16) makes no plan, and
  /// once the buffers have grown nothing is allocated.
  void reset(int n);

  int n() const { return n_; }
  int m() const { return m_; }          ///< padded length
  int half() const { return m_ / 2 + 1; }  ///< spectrum length
  /// Spectra A, B (half() values each) of a, b (len ≤ m values each, zero beyond): unscaled.
  void forward(const double* a, const double* b, int len, std::complex<double>* A,
               std::complex<double>* B) const;
  /// The first n values of the inverse transforms of A, B, times 1/m (so that backward(forward(x))
  /// = x). A and B are not modified.
  void backward(const std::complex<double>* A, const std::complex<double>* B, double* a,
                double* b) const;
  /// The offset of index i of the wrapped (cyclic) row: true for the offsets −(n−1)…(n−1).
  bool offset(int i, int* di) const;

 private:
  struct Impl;  ///< the backend's plan of length m and its buffers (row_fft.cpp)
  int n_ = 0, m_ = 0;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mh
