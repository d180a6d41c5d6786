#pragma once
// FASTSIM: Kalker's simplified theory of steady rolling contact on one Hertzian ellipse
// (J.J. Kalker, "A fast algorithm for the simplified theory of rolling contact", Vehicle System
// Dynamics 11 (1982) 1–13; docs/tangential.md of this repository).
//
// The surface deflection is that of three "Winkler" flexibilities L1, L2, L3, chosen so that the
// small-creepage limit reproduces Kalker's linear theory (kalker.hpp):
//   L1 = 8a/(3 C11 G), L2 = 8a/(3 C22 G), L3 = π a √(a/b)/(4 C23 G).
// In adhesion the traction gradient along the rolling direction is
//   ∂px/∂x = ξ/L1 − φ y/L3,  ∂py/∂x = η/L2 + φ x/L3,
// integrated from the leading edge x = +a(y) (where p = 0) towards the trailing edge; where |p|
// exceeds the traction bound μ p_n, p is scaled back onto it (slip).
//
// Discretisation: ny strips across (centres y_j, width 2b/ny); each strip from x = +a(y_j) to
// −a(y_j) in nx equal cells, the tractions marched from cell centre to cell centre with the exact
// integral of the gradient between them, forces and moment by the midpoint rule. The bound's
// pressure is normalised so that its discrete integral is N exactly: in full sliding |F| = μN.
#include <vector>

#include "contact/tangential/tangential_types.hpp"

namespace mh {

/// Shape of the traction bound μ p_n (x, y) used by FASTSIM; both integrate to μN.
enum class TractionBound {
  Elliptical,  ///< the Hertz pressure p0 √(1 − x²/a² − y²/b²) (default: CONTACT's user guide advises it)
  Parabolic,   ///< Kalker's original (2N/(πab)) (1 − x²/a² − y²/b²)
};

/// Largest nx (the strip's steps are tabulated on the stack).
constexpr int kFastsimMaxN = 512;

/// FASTSIM options; light, for the case-file reader.
struct FastsimOptions {
  /// Steps along x per strip and strips across; the defaults reach 0.5 % of the converged linear
  /// limit and ≤ 20 µs per ellipse (docs/tangential.md, "Grid of FASTSIM": the measurements).
  int nx = 32;
  int ny = 32;
  TractionBound bound = TractionBound::Elliptical;
  /// Vollebregt & Voltr's blending (Vehicle System Dynamics 61, 2023) of the three flexibilities
  /// into one at large creepage, as CONTACT 25.2 applies it when the creepages are given (module 3,
  /// F = 0). Off by default: Kalker's three flexibilities.
  bool blend = false;
  /// Also the forces' derivative in the load at fixed creepages (TangentialResult::dFx_dN,
  /// dFy_dN; fastsim() below): what the vertical equilibrium's first step aims with
  /// (contact/solve.cpp). Off by default; the forces are the same bit for bit either way.
  bool load_slope = false;
};

/// The flexibilities [m/Pa] of an ellipse (a along x, b across) of the material G, ν.
struct FastsimFlexibilities { double L1 = NAN, L2 = NAN, L3 = NAN; };
FastsimFlexibilities fastsim_flexibilities(double a, double b, double G, double nu);

/// Optional per-node output of one solve (reused between calls: no allocation once large enough).
/// Cell (k, j): k = 0 … nx − 1 from the leading edge along x, j = 0 … ny − 1 across; index j nx + k;
/// each cell's area is (2 a(y_j) / nx) (2b / ny).
struct FastsimGrid {
  int nx = 0, ny = 0;
  std::vector<double> x, y;       ///< [m] cell centres (contact frame, origin at the ellipse centre)
  std::vector<double> px, py;     ///< [Pa] tractions on the wheel
  std::vector<double> pn;         ///< [Pa] the normal pressure of the bound (μ pn is the bound)
  std::vector<unsigned char> slip;  ///< 1 where the traction is on the bound
};

/// FASTSIM on the ellipse a × b [m] under the normal force N [N], friction μ, shear modulus G [Pa]
/// and Poisson's ratio ν, for the creepages cr (tangential_types.hpp: convention and frame).
/// Allocates nothing unless grid is given (then only while it grows).
///
/// With o.load_slope, dF/dN of the ellipse loaded as Hertz's (a, b ∝ N^(1/3) at a fixed a/b) at
/// fixed creepages, by Kalker's similarity: FASTSIM's F/(μN) depends on ξ and η through
/// G ab ξ/(μN) ∝ ξ N^(−1/3) and on φ through G (ab)^(3/2) φ/(μN), independent of N, so
///   dF/dN = F/N − (ξ ∂F/∂ξ + η ∂F/∂η) / (3N),
/// the bracket the derivative of F(λξ, λη, φ) in λ at λ = 1, marched beside the tractions
/// (exact for the discrete march: adhesion is linear in the gradients, slip projects onto the
/// bound, dp = (B/|p|) (dp − p (p·dp)/|p|²)). With o.blend the flexibilities move with the
/// creepages, which the derivative does not follow: then an approximation.
TangentialResult fastsim(const Creepages& cr, double a, double b, double N, double mu, double G,
                         double nu, const FastsimOptions& o = {}, FastsimGrid* grid = nullptr);

}  // namespace mh
