#pragma once
// Elastic half-space influence coefficients for a normal surface pressure, and their discrete
// convolution by FFT. SI throughout (m, Pa, N).
//
// Sources
//  [L]  A. E. H. Love, "The stress produced in a semi-infinite solid by pressure on part of the
//       boundary", Phil. Trans. R. Soc. A 228 (1929) 377–420: uniform pressure on a rectangle.
//  [J]  K. L. Johnson, Contact Mechanics, CUP 1985, §3.2 (Boussinesq point load,
//       u_z = (1−ν²)/(π E) · P / r) and §3.9 eq. (3.96) (the rectangle, Love's closed form).
//  [LI] H. M. Stanley, T. Kato, "An FFT-based method for rough surface contact", J. Tribol. 119
//       (1997) 481–485, and S. Liu, Q. Wang, G. Liu, "A versatile method of discrete convolution
//       and FFT (DC-FFT) for contact analyses", Wear 243 (2000) 101–111: the aperiodic discrete
//       convolution of n points done exactly as a cyclic one on ≥ 2n−1 points with a zero-padded
//       pressure and the wrapped-around kernel ("DC-FFT").
//  [P]  M. Reinecke, P. Bell, PocketFFT (C++ header-only version, BSD-3-Clause; the FFT of
//       NumPy and SciPy), pocketfft_hdronly.h as shipped by Debian's gemmi-dev: mixed-radix
//       FFTPACK-style real (radices 2, 3, 4, 5 and a generic one) and complex transforms, each
//       able to transform several sequences at once in SIMD lanes. The default backend; FFTW 3
//       (GPL-2+) replaces it when the build sets MHCONTACT_FFTW=ON (docs/embedding.md "FFT
//       backends").
#include <complex>
#include <functional>
#include <memory>
#include <vector>

namespace mh {

/// ∫∫ over the rectangle |ξ| ≤ a, |η| ≤ b of dξ dη / √((x−ξ)² + (y−η)²)  [m]  ([L], [J] eq. 3.96).
/// Times the combined compliance H and a uniform pressure p it is the normal surface displacement
/// at (x, y) ([J] §3.2 point load integrated over the rectangle).
///
/// Closed form: with F(u, v) = ∫₀ᵘ∫₀ᵛ dξ dη / √(ξ²+η²) = u·asinh(v/|u|) + v·asinh(u/|v|)
/// (odd in u and in v; each term is 0 where its factor u or v is 0, its limit),
///     love_rectangle = F(a+x, b+y) + F(a−x, b+y) + F(a+x, b−y) + F(a−x, b−y).
/// Valid everywhere including on the edges, the corners and the centre (there 4·F(a, b); for a
/// square of side 2a that is 8 a asinh(1)). Far field → 4ab/r. a, b > 0 expected (a = 0 or b = 0
/// gives 0). Loses about 2·log10(r/max(a, b)) digits far away (cancellation of the four terms);
/// at r = 100 a that leaves ~1e-12 relative, far below the discretisation error.
double love_rectangle(double x, double y, double a, double b);

/// The FFT library this build convolves with: "pocketfft" (default) or "fftw3" (MHCONTACT_FFTW=ON).
const char* fft_backend();

/// The discrete operator u = C p on an nx × ny grid of dx × dy elements: piecewise-constant
/// pressure per element, displacement collocated at the element centres,
///     C_ij = H · love_rectangle(x_i − x_j, y_i − y_j, dx/2, dy/2)   [m/Pa]   (H = compliance).
/// Storage is row-major with x fastest: index = ix + nx·iy, for p and u alike.
/// apply() is the exact (aperiodic) discrete convolution done by DC-FFT ([LI]): the kernel of the
/// offsets −(n−1)…(n−1) is wrapped onto a padded grid of mx × my points (the smallest sizes
/// ≥ 2n−1 whose prime factors the backend has fast butterflies for: 2, 3, 5 for PocketFFT, also 7
/// for FFTW; e.g. 120 × 100 for 60 × 50) and transformed once; each apply() zero-pads p,
/// transforms, multiplies and transforms back: O(n log n). Only the half spectrum of the real
/// data is kept (kx = 0 … mx/2), and rows of p that are all padding are not transformed.
///
/// Deterministic: the same bytes for any thread count and run (FFTW: FFTW_ESTIMATE plans, created
/// and destroyed under a planner mutex). The two backends agree to round-off (~1e-15 relative to
/// the largest displacement), not bitwise. The object owns its work buffers, so apply() on ONE
/// object must be called from one thread at a time; distinct objects may be used concurrently.
/// Movable, not copyable; a moved-from object may only be destroyed or assigned to.
class InfluenceGrid {
 public:
  /// Throws std::invalid_argument unless nx, ny ≥ 1, dx, dy, compliance > 0 and finite, and
  /// std::bad_alloc / std::runtime_error if the FFT cannot allocate or plan.
  InfluenceGrid(int nx, int ny, double dx, double dy, double compliance);
  /// As InfluenceGrid(nx, ny, dx, dy, compliance), in this object's buffers (the same bits as a
  /// new one): with PocketFFT nothing is allocated when holds(nx, ny) and the padded lengths are
  /// among the thread's last plans (fft_backend.hpp), and the grid is no larger than the thread
  /// has built before (its coefficient scratch). Throws as the constructor, before changing
  /// anything for invalid arguments; after a failed allocation the object matches no grid
  /// (nx() = 0) until reset again.
  void reset(int nx, int ny, double dx, double dy, double compliance);
  /// Whether this object's buffers hold an nx × ny grid (reset() to it allocates none of them):
  /// PocketFFT, any grid whose padded sizes fit the buffers; FFTW, whose plans belong to one
  /// padded size, only grids of the same padded sizes.
  bool holds(int nx, int ny) const;
  /// The same convolution with another kernel: C_ij = kernel(ix_i − ix_j, iy_i − iy_j) for the
  /// offsets in elements (any parity; e.g. the tangential coefficients of tangential_influence.hpp).
  /// compliance() is then NaN. Throws as above, and std::invalid_argument for an empty kernel.
  using Kernel = std::function<double(int dix, int diy)>;
  InfluenceGrid(int nx, int ny, double dx, double dy, Kernel kernel);
  ~InfluenceGrid();
  InfluenceGrid(InfluenceGrid&&) noexcept;
  InfluenceGrid& operator=(InfluenceGrid&&) noexcept;
  InfluenceGrid(const InfluenceGrid&) = delete;
  InfluenceGrid& operator=(const InfluenceGrid&) = delete;

  /// u = C p; p and u hold nx·ny values each (they may alias). No plan is built here. FFTW
  /// allocates nothing; PocketFFT's 1-D calls take their scratch from a per-thread stack
  /// (fft_backend.hpp, ScratchStack), so after a thread's first apply() of its largest grid nothing
  /// is allocated either (tests/alloc).
  void apply(const double* p, double* u) const;
  /// u += C d for a d that is zero but at the m elements idx[k] (values d[k]), by direct sums over
  /// the kernel's coefficients (the same as apply() gives, to round-off): m·nx·ny multiply-adds,
  /// against about 4 nx ny log2(4 nx ny) for apply(), so cheaper for up to a few hundred elements
  /// (the CG loop's correction for the elements a step moved off its linear path, normal_cg.cpp).
  void add_sparse(const int* idx, const double* d, int m, double* u) const;
  /// C_00 = H · love_rectangle(0, 0, dx/2, dy/2) [m/Pa]: displacement of an element's centre per
  /// unit pressure on that element alone.
  double self_coefficient() const { return c00_; }
  /// C for the offset (dix, diy) in elements [m/Pa] (direct evaluation, for checks).
  double coefficient(int dix, int diy) const;

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double dx() const { return dx_; }
  double dy() const { return dy_; }
  double compliance() const { return compliance_; }
  int padded_nx() const { return mx_; }  ///< mx, FFT size along x
  int padded_ny() const { return my_; }  ///< my, FFT size along y

 private:
  struct Fft;  ///< the backend's plans and work buffers (influence.cpp)
  int nx_ = 0, ny_ = 0, mx_ = 0, my_ = 0;
  double dx_ = 0, dy_ = 0, compliance_ = 0, c00_ = 0;
  Kernel kernel_;  ///< set by the kernel-generic constructor; empty: Love's kernel times compliance_
  /// C for the offsets (dix, diy), dix + nx−1 + (2nx−1)(diy + ny−1): add_sparse's coefficients.
  std::vector<double> direct_;
  std::unique_ptr<Fft> fft_;
  void init_fft();  ///< padded sizes, plans and the wrapped kernel's spectrum
};

}  // namespace mh
