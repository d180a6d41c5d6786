#pragma once
// Exact steady rolling on the half-space grid of the normal problem: Kalker's discretised
// variational problem of frictional rolling with the tangential influence coefficients
// (tangential_influence.hpp), Coulomb's bound |p_t| ≤ μ p_n, adhesion and slip areas.
//
// Sources
//  [K]  J. J. Kalker, Three-Dimensional Elastic Bodies in Rolling Contact, Kluwer 1990, ch. 5:
//       bodies of equal elastic constants (the normal and tangential problems decouple: p_n is
//       the normal solver's); the slip of body 1 relative to body 2 in steady rolling,
//           s / V = w − ∂u/∂x,   w = (ξ − φ y, η + φ x),
//       discretised with a one-sided difference against the rolling direction:
//           s_I = w_I + (u_I − u_{I+})/dx,  I+ the element one dx upstream (towards the leading edge);
//       in adhesion s_I = 0 and |p_I| ≤ μ p_n,I; in slip p_I = −μ p_n,I s_I/|s_I|.
//  [C]  E. A. H. Vollebregt, CONTACT (github.com/eve70a/CONTACT, version 25.2), src/m_sdis.f90,
//       set_tang_rhs: in rolling the spin term of the rigid slip is taken dq/6 upstream of the
//       element centre (its input FACPHI, default 1/6; dq = dx for rolling along x):
//           w_I = (ξ − φ y_I,  η + φ (x_I + dx/6))                                      (R1)
// Where the spin's lateral slip is taken decides the spin's lateral force at first order in dx:
// the shift δ in w_y = η + φ (x_I + δ) acts as an extra lateral creepage φ δ over the whole
// adhesion area. Taken at the centre (δ = 0) the a/b = 1 pure-spin case of CONTACT's test_table
// gives Fy = −0.3597, −0.3685, −0.3718, −0.3734, −0.3740 μN at 17, 27, 37, 57, 117 elements
// across (first order, extrapolated −0.3765); at the midpoint of the difference (δ = dx/2, where
// (u_I − u_{I+})/dx approximates −∂u/∂x to second order) −0.4094 … −0.3811, as far off on the
// other side: the one-sided difference's leading error is not only the collocation of w but also
// that of the element-wise constant traction, and (R1) is the offset at which the two first-order
// terms cancel on that case (measured: 0.169 dx from the two series; 1/6 in [C]). With (R1)
// −0.3763, −0.3788, −0.3793, −0.3782, −0.3764, and this solver's forces, moment and adhesion
// fraction equal CONTACT's exact solution on the same grid and pressure to its printed digits
// (tests/data/contact_tangential/hstang; docs/half_space.md "Accuracy").
//  [V]  E. A. H. Vollebregt, "A Gauss–Seidel type solver for special convex programs, with
//       application to frictional contact mechanics", J. Optim. Theory Appl. 87 (1995) 47–67:
//       element-wise non-linear Gauss–Seidel, each element's 2 × 2 problem solved exactly under
//       its bound; and E. A. H. Vollebregt, CONTACT user guide, "SteadyGS": rows processed along
//       the rolling direction, which makes the transport term nearly triangular.
//
// The solver here (the project's own arrangement of [V]'s element-wise Gauss–Seidel): the
// unknowns are the traction differences q_I = p_I − p_{I+} along the rolling direction (zero
// traction beyond the grid), in which the slip is s = w + A q / dx with A the symmetric positive
// definite influence matrix, so that Gauss–Seidel on q converges as on a convex program; the
// tractions p are the sums of q from the leading edge. Rows are taken one after the other, each
// from its trailing to its leading edge. An element's 2 × 2 problem in its own q (coefficient
// A(0,0)/dx) is solved exactly under its bound (slip: one scalar root, safeguarded Newton); the
// change moves the tractions of the adhesion elements downstream with it (their differences,
// hence their slip, kept) up to the first slip or exterior element, whose difference takes the
// change instead, or an element pushed over its bound, which is put back on it. Every change of
// q is carried exactly into the displacement differences:
//  - within the row, directly onto the elements still to be processed (A(k, 0), O(nx));
//  - onto every row, after the row is done, through the row's spectrum: each row keeps the half
//    spectrum of its v = A q along x, updated by the kernel spectra of each row offset
//    (DC-FFT along x, RowFft in influence.hpp), so that a row's v is one inverse transform.
// So each sweep is an exact Gauss–Seidel pass at O(nx·N + ny²·nx) cost, with no 2-D transform.
// Stops when no element's local solve changes a traction component by more than tol·μ·max p_n.
//
// Frame and signs (tangential_types.hpp): x the rolling direction (the contact moves towards +x
// over both bodies, the leading edge at +x), y lateral, z the rail's inward normal; body 1 the
// wheel, creepages the wheel's rigid slip relative to the rail over V, tractions and forces those
// the rail exerts on the wheel.
#include <complex>
#include <string>
#include <vector>

#include "contact/half_space/row_fft.hpp"
#include "contact/half_space/tangential_influence.hpp"
#include "contact/half_space/tangential_options.hpp"
#include "contact/tangential/tangential_types.hpp"

namespace mh {

enum class TangentialStatus {
  Ok,            ///< converged
  NoContact,     ///< no element carries pressure: zero tractions
  NotConverged,  ///< max_sweeps reached, invalid input (message in result) or non-finite values
};

/// What the half-space tangential solve returns beyond TangentialResult.
struct HalfSpaceTangentialResult {
  TangentialStatus status = TangentialStatus::NotConverged;
  TangentialResult forces;  ///< Fx, Fy, Mz (about the reference point), adhesion fraction, Tγ
  int sweeps = 0;           ///< sweeps taken
  double change = 0;        ///< last sweep's largest traction change / (μ max p_n)
  int n_contact = 0;        ///< elements with p_n > 0
  int n_adhesion = 0;       ///< of those, in adhesion (|p_t| < μ p_n, zero slip)
  std::string message;      ///< why, when NotConverged
};

/// Where the spin's lateral rigid slip φ x is taken, in elements upstream of the element centre:
/// w_y = η + φ (x_I + kSpinSlipOffset·dx), eq. (R1) above ([C]'s FACPHI default).
inline constexpr double kSpinSlipOffset = 1.0 / 6.0;

/// Element states of the last solve.
enum class ElementState : unsigned char { Exterior = 0, Adhesion = 1, Slip = 2 };

/// Workspace and solver for one grid (nx × ny elements of dx × dy, the normal solver's grid and
/// index ix + nx·iy). Builds the tangential influence once; solve() allocates nothing. One thread
/// at a time per object. Deterministic.
class HalfSpaceTangentialSolver {
 public:
  /// Throws std::invalid_argument as TangentialInfluence (G [Pa] combined, ν common).
  HalfSpaceTangentialSolver(int nx, int ny, double dx, double dy, double G, double nu);
  /// As a new solver of these arguments, in this one's buffers: once they have grown, and for a
  /// padded row length met before (RowFft::reset), nothing is allocated. Throws as the constructor.
  void reset(int nx, int ny, double dx, double dy, double G, double nu);

  /// Solve steady rolling: pn [Pa] nx·ny pressures (≤ 0 or NaN: exterior); x0, y0 [m] the centre
  /// of element (0, 0) relative to the contact's reference point (Mz is about that point, φ
  /// rotates about it); c the creepages (φ in 1/m); mu > 0 the friction coefficient. Warm start:
  /// the tractions of the previous solve on this object when warm_start is true. Never throws.
  HalfSpaceTangentialResult solve(const double* pn, double x0, double y0, const Creepages& c,
                                  double mu, const HalfSpaceTangentialOptions& options = {},
                                  bool warm_start = false);

  /// Tractions [Pa] on the wheel and slip [-] (slip velocity / V) of the last solve, nx·ny each.
  const std::vector<double>& px() const { return out_px_; }
  const std::vector<double>& py() const { return out_py_; }
  const std::vector<double>& sx() const { return out_sx_; }
  const std::vector<double>& sy() const { return out_sy_; }
  const std::vector<ElementState>& state() const { return out_state_; }
  const TangentialKernel& kernel() const { return K_; }

 private:
  void setup(int nx, int ny, double dx, double dy, double G, double nu);  ///< the constructor's work, fft_ set
  void add_row_change(int iy);  ///< carry the row's dqx_, dqy_ into every contact row's spectrum
  TangentialKernel K_;
  int nx_ = 0, ny_ = 0;  ///< internal grid: the given one and a column of exterior elements before it
  int out_nx_ = 0;   ///< the given nx
  double dx_ = 0, dy_ = 0;
  RowFft fft_;
  int H_ = 0;  ///< spectrum length
  std::vector<double> px_, py_, qx_, qy_, sx_, sy_;  ///< nx·ny
  std::vector<double> rx_, ry_;                      ///< row kernels A(k, 0), k = 0 … nx−1
  std::vector<std::complex<double>> kxx_, kyy_, kxy_;  ///< kernel spectra of row offsets 0 … ny−1 (setup only; kept for the next)
  std::vector<double> build_a_, build_b_, build_xx_, build_yy_, build_xy_;  ///< setup's rows (kept for the next)
  std::vector<std::complex<double>> build_zero_;
  std::vector<double> kxx_r_, kyy_r_, kxy_i_;          ///< their real, real, imaginary parts (kept)
  std::vector<std::complex<double>> vx_hat_, vy_hat_;  ///< per row: spectrum of v = A q
  std::vector<std::complex<double>> qx_hat_, qy_hat_;  ///< one row's change of q, transformed
  std::vector<double> vrx_, vry_, cx_, cy_, dqx_, dqy_;  ///< one row
  std::vector<int> contact_rows_;
  std::vector<ElementState> state_;
  std::vector<double> pn_;  ///< internal copy of the pressure
  std::vector<double> out_px_, out_py_, out_sx_, out_sy_;  ///< results on the given grid
  std::vector<ElementState> out_state_;
};

}  // namespace mh
