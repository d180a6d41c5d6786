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
#include <fftw3.h>

#include <memory>
#include <mutex>
#include <type_traits>

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

/// The global FFTW planner mutex: FFTW planning (fftw_plan_* and fftw_destroy_plan) is not
/// thread-safe, execution of an existing plan is (FFTW 3 manual §5.4 "Thread safety"). Any code in
/// the project that plans with FFTW should hold this mutex while planning or destroying.
std::mutex& fftw_planner_mutex();

/// The discrete operator u = C p on an nx × ny grid of dx × dy elements: piecewise-constant
/// pressure per element, displacement collocated at the element centres,
///     C_ij = H · love_rectangle(x_i − x_j, y_i − y_j, dx/2, dy/2)   [m/Pa]   (H = compliance).
/// Storage is row-major with x fastest: index = ix + nx·iy, for p and u alike.
/// apply() is the exact (aperiodic) discrete convolution done by DC-FFT ([LI]): the kernel of the
/// offsets −(n−1)…(n−1) is wrapped onto a padded grid of mx × my points (the smallest 2,3,5,7-
/// smooth sizes ≥ 2n−1, e.g. 120 × 100 for 60 × 50) and transformed once (r2c); each apply()
/// zero-pads p, transforms, multiplies and transforms back (c2r): O(n log n).
///
/// Plans are FFTW_ESTIMATE (deterministic: the same bytes for any thread count and run), created
/// and destroyed under fftw_planner_mutex(). The object owns its work buffers, so apply() on ONE
/// object must be called from one thread at a time; distinct objects may be used concurrently.
/// Movable, not copyable; a moved-from object may only be destroyed or assigned to.
class InfluenceGrid {
 public:
  /// Throws std::invalid_argument unless nx, ny ≥ 1, dx, dy, compliance > 0 and finite, and
  /// std::bad_alloc / std::runtime_error if FFTW cannot allocate or plan.
  InfluenceGrid(int nx, int ny, double dx, double dy, double compliance);
  ~InfluenceGrid();
  InfluenceGrid(InfluenceGrid&&) noexcept;
  InfluenceGrid& operator=(InfluenceGrid&&) noexcept;
  InfluenceGrid(const InfluenceGrid&) = delete;
  InfluenceGrid& operator=(const InfluenceGrid&) = delete;

  /// u = C p; p and u hold nx·ny values each (they may alias). No allocation.
  void apply(const double* p, double* u) const;
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
  struct FftwFree {
    void operator()(void* ptr) const { fftw_free(ptr); }
  };
  struct PlanDestroy {
    void operator()(fftw_plan plan) const;
  };
  using Plan = std::unique_ptr<std::remove_pointer_t<fftw_plan>, PlanDestroy>;

  int nx_ = 0, ny_ = 0, mx_ = 0, my_ = 0;
  double dx_ = 0, dy_ = 0, compliance_ = 0, c00_ = 0;
  std::unique_ptr<double, FftwFree> real_;           ///< mx·my work buffer (mutable through get())
  std::unique_ptr<fftw_complex, FftwFree> spectrum_; ///< my·(mx/2+1) work buffer
  std::unique_ptr<fftw_complex, FftwFree> kernel_;   ///< FFT of the wrapped kernel, / (mx·my)
  Plan forward_, backward_;
};

}  // namespace mh
