#pragma once
// Tangential influence coefficients of the elastic half-space: the in-plane surface displacement
// difference of two bodies of EQUAL elastic constants under a uniform tangential traction on a
// rectangle, and its DC-FFT convolution (influence.hpp). SI throughout (m, Pa, N).
//
// Sources
//  [J]  K. L. Johnson, Contact Mechanics, CUP 1985, §3.2 eq. (3.86) (Cerruti's point load on the
//       surface of a half-space): at z = 0, a force Q_x at the origin displaces the surface by
//           u_x = Q_x/(2πG₁) [(1−ν)/r + ν x²/r³],   u_y = Q_x/(2πG₁) ν x y / r³,
//       and symmetrically for Q_y. For bodies of equal constants the normal–tangential coupling
//       terms (1−2ν) cancel between the two bodies (quasi-identity), and the displacement
//       difference u = u₁ − u₂ under traction p on body 1 and −p on body 2 is
//           u_x = 1/(πG) [(1−ν)/r + ν x²/r³] p_x + ν x y/(πG r³) p_y,   with 2/G = 1/G₁ + 1/G₂
//  [K]  J. J. Kalker, Three-Dimensional Elastic Bodies in Rolling Contact, Kluwer 1990, §1.4 and
//       ch. 5: the same kernel, G the combined modulus of rigidity, the element-wise constant
//       traction on a rectangular grid collocated at the element centres.
//
// The integrals over the rectangle |ξ| ≤ a, |η| ≤ b of the three kernels, at the point (x, y)
// relative to its centre, in closed form (derived by integrating [J]'s kernel twice; s = x − ξ,
// t = y − η, r = √(s² + t²)):
//     I₀  = ∫∫ 1/r          = love_rectangle(x, y, a, b)                    (influence.hpp)
//     Iₓₓ = ∫∫ s²/r³        = Σ± T(a±x, b±y),  T(u, v) = v asinh(u/|v|)    (odd in u and v)
//     I_yy = ∫∫ t²/r³       = Σ± T(b±y, a±x)                               (I₀ = Iₓₓ + I_yy)
//     Iₓᵧ = ∫∫ s t/r³       = −R(x+a, y+b) + R(x−a, y+b) + R(x+a, y−b) − R(x−a, y−b),
//                             R(u, v) = √(u² + v²)                          (odd in x and in y)
// (∫₀ᵛ s²/r³ dt = v/√(s²+v²) and ∫₀ᵘ that ds = v asinh(u/|v|); the primitive of s t/r³ is
// |u| + |v| − R(u, v), whose |u|, |v| parts cancel between the four corners.) Far field:
// 4ab times the point kernel. Tested against a direct quadrature of [J]'s kernel.
#include <vector>

#include "contact/half_space/influence.hpp"

namespace mh {

/// Iₓₓ(x, y, a, b) = ∫∫ over |ξ| ≤ a, |η| ≤ b of (x−ξ)²/r³ dξ dη  [m] (closed form above).
double cerruti_rectangle_xx(double x, double y, double a, double b);
/// I_yy(x, y, a, b) = ∫∫ (y−η)²/r³ dξ dη  [m].
double cerruti_rectangle_yy(double x, double y, double a, double b);
/// Iₓᵧ(x, y, a, b) = ∫∫ (x−ξ)(y−η)/r³ dξ dη  [m]; odd in x and in y.
double cerruti_rectangle_xy(double x, double y, double a, double b);

/// The coefficients of the element grid below at offsets (i, j) in elements [m/Pa]:
///     Aₓₓ = [(1−ν) I₀ + ν Iₓₓ]/(πG),  A_yy = [(1−ν) I₀ + ν I_yy]/(πG),  Aₓᵧ = ν Iₓᵧ/(πG)
/// at (x, y) = (i dx, j dy) for the rectangle of half-sides dx/2, dy/2 ([J], [K]).
struct TangentialKernel {
  double dx, dy;  ///< [m] element sizes
  double G, nu;   ///< [Pa] combined modulus of rigidity, [-] common Poisson ratio
  double xx(int i, int j) const;
  double yy(int i, int j) const;
  double xy(int i, int j) const;
  /// xx(i, j) and yy(i, j), the same bits, their common Love term evaluated once.
  void xx_yy(int i, int j, double* axx, double* ayy) const;
  // xx and yy are bitwise even in i and in j, xy bitwise odd in each (the rectangle sums are
  // paired: tangential_influence.cpp), so a grid needs only the offsets i ≥ 0.
};

/// The tangential operator u = A p on an nx × ny grid of dx × dy elements (storage as
/// InfluenceGrid: index ix + nx·iy): u_x = Aₓₓ p_x + Aₓᵧ p_y, u_y = Aₓᵧ p_x + A_yy p_y with
///     Aₓₓ(i) = [(1−ν) I₀ + ν Iₓₓ]/(πG),  A_yy(i) = [(1−ν) I₀ + ν I_yy]/(πG),  Aₓᵧ(i) = ν Iₓᵧ/(πG)
/// at the offsets i of element centres ([J], [K]); each by its own DC-FFT convolution.
/// G [Pa] the combined modulus of rigidity (2/G = 1/G₁ + 1/G₂), ν the common Poisson ratio.
/// Threading and movability as InfluenceGrid.
class TangentialInfluence {
 public:
  /// Throws std::invalid_argument unless nx, ny ≥ 1, dx, dy, G > 0 and finite, 0 ≤ ν < 0.5.
  TangentialInfluence(int nx, int ny, double dx, double dy, double G, double nu);

  /// ux, uy from px, py (nx·ny each; outputs must not alias inputs). Four convolutions.
  void apply(const double* px, const double* py, double* ux, double* uy) const;
  /// Throws std::invalid_argument with the rule when the arguments above are invalid.
  static void check(int nx, int ny, double dx, double dy, double G, double nu);
  /// The coefficients at the offset (dix, diy) in elements [m/Pa] (direct evaluation).
  double Axx(int dix, int diy) const;
  double Ayy(int dix, int diy) const;
  double Axy(int dix, int diy) const;

  int nx() const { return xx_.nx(); }
  int ny() const { return xx_.ny(); }
  double dx() const { return xx_.dx(); }
  double dy() const { return xx_.dy(); }
  double G() const { return G_; }
  double nu() const { return nu_; }

 private:
  double G_, nu_;
  InfluenceGrid xx_, yy_, xy_;
  mutable std::vector<double> tmp_;  ///< nx·ny scratch of apply()
};

}  // namespace mh
