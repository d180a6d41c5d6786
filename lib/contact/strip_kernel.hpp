#pragma once
// The displacement kernel of a semi-elliptic strip centred on the point (docs/method.md §9): a
// strip of half-length a along x with the pressure shape sqrt(1 − x²/a²), whose lateral edges lie
// at e1 < e2 from the point, gives at the point
//   ∫_{-a}^{a} sqrt(1 − x²/a²) ∫_{e1}^{e2} dy / sqrt(x² + y²) dx = a [g(e2/a) − g(e1/a)],
//   g(r) = ∫_{-1}^{1} sqrt(1 − t²) asinh(r/|t|) dt      (odd in r),
// a function of one variable. Its derivative is a complete elliptic integral,
//   g'(r) = 2 D(k) / sqrt(1 + r²),  k = 1/sqrt(1 + r²),  D(k) = (K(k) − E(k))/k²,
// so g is tabulated once (values and slopes at 128 nodes per binade of r over 2^-20 … 2^20, the
// values by 8-point Gauss–Legendre on g' from the series g(r) = 2r ln(4/r) + O(r³ ln r) at the
// bottom) and read by cubic Hermite interpolation; outside the table, that series below and
// g(r) = g(r_max) + (π/2) ln(r/r_max) + O(r⁻²) above. Interpolation error below 1e-9 absolute
// (tests/unit/contact/test_strip_kernel.cpp checks it against direct quadrature of the
// definition). One lookup replaces a Gauss quadrature of 8 logarithms per matrix entry of the
// strip solver.

namespace mh {

/// g(r) above [-].
double strip_kernel_g(double r);
/// g'(r) = 2 D(k)/sqrt(1 + r²), k = 1/sqrt(1 + r²), evaluated directly (GSL, Carlson's R_D) [-].
double strip_kernel_dg(double r);

}  // namespace mh
