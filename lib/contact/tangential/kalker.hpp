#pragma once
// Kalker's linear theory of steady rolling contact on a Hertzian ellipse: the creepage
// coefficients C11, C22, C23, C33 as functions of the ellipse's aspect a/b and Poisson's ratio ν,
// and the linear-theory forces (docs/tangential.md, "Linear theory").
//
// Source: J.J. Kalker, Three-dimensional elastic bodies in rolling contact, Kluwer 1990,
// Appendix E, Table E.3 (ν = 0, 0.25, 0.5; a/b and b/a = 0.1 … 1), and the asymptotes of that
// appendix for slender ellipses (g = min(a/b, b/a) → 0) for C11, C22, C23.
// C33: the same table's column as a public copy gives it (SimRail, github.com/RoccoLiberoGiossi/
// SimRail, lib/contact_kalkers_table.py, commit 1f6760a; values below 1 rounded there to two
// decimals, so up to 2 % at C33 = 0.23), held against CONTACT's exact steady-rolling solver at
// a small pure spin, extrapolated to zero element size (tests/data/contact_tangential/
// c33_convergence.csv, docs/tangential.md "Linear theory"). Below g = 0.101 the project has no
// source for C33's asymptote: C33 is NaN there, and so is the linear Mz when φ ≠ 0.
//
// a is the semi-axis along the rolling direction x, b the lateral one (tangential_types.hpp).
#include "contact/tangential/tangential_types.hpp"

namespace mh {

struct KalkerCoefficients {
  double C11 = NAN;  ///< [-] longitudinal
  double C22 = NAN;  ///< [-] lateral
  double C23 = NAN;  ///< [-] lateral–spin coupling
  double C33 = NAN;  ///< [-] spin (NaN for slender ellipses, g < kKalkerTableMin)
  /// true when a/b or b/a < kKalkerTableMin: the slender-ellipse asymptote was used, not the table.
  bool asymptote = false;
};

/// Smallest g = min(a/b, b/a) read from Table E.3; below it the asymptotes of Appendix E apply.
/// (The table starts at g = 0.1; CONTACT's linrol switches at 0.101, and so do we, so that the
/// two agree to the last digit; the switch costs a jump of about 4 % in C11 near a/b ≈ 9.9.)
constexpr double kKalkerTableMin = 0.101;

/// C11, C22, C23, C33 at the aspect a_over_b (> 0) and Poisson's ratio nu (0 … 0.5).
/// Table E.3 is interpolated linearly in g between its rows (steps of 0.1), and in ν by the
/// quadratic through the three columns in 1/C (the coefficients vary smoothly as 1/C in ν).
KalkerCoefficients kalker_coefficients(double a_over_b, double nu);

/// Kalker's linear theory on the ellipse a × b [m] with shear modulus G [Pa]: Fx, Fy [N] and the
/// spin moment Mz = G c³ C23 η − G c⁴ C33 φ [N m] (NaN when φ ≠ 0 on a slender ellipse: no C33).
/// Sign convention of tangential_types.hpp (forces on the wheel; c = √(ab)); the sign of the C33
/// term as CONTACT's module 3 gives it (a positive φ, a negative Mz on the wheel).
TangentialResult kalker_linear(const Creepages& cr, double a, double b, double G, double nu);

}  // namespace mh
