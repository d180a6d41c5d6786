#pragma once
// The displacement kernel of a semi-elliptic strip (docs/method.md §9). A strip of half-length a
// along x with the pressure shape sqrt(1 − ξ²/a²), whose lateral edges lie at e1 < e2 from a
// point at x = t·a (measured from the strip's centre), gives at that point
//   ∫_{-a}^{a} sqrt(1 − ξ²/a²) ∫_{e1}^{e2} dy / sqrt((ξ − t a)² + y²) dξ = a [G(t, e2/a) − G(t, e1/a)],
//   G(t, r) = ∫_{-1}^{1} sqrt(1 − τ²) asinh(r / |τ − t|) dτ      (odd in r, even in t).
//
// On the strip's centre line (t = 0) G is the function of one variable g(r) = G(0, r). Its
// derivative is a complete elliptic integral,
//   g'(r) = 2 D(k) / sqrt(1 + r²),  k = 1/sqrt(1 + r²),  D(k) = (K(k) − E(k))/k²,
// so g is tabulated once (values and slopes at 128 nodes per binade of r over 2^-20 … 2^20, the
// values by 8-point Gauss–Legendre on g' from the series g(r) = 2r ln(4/r) + O(r³ ln r) at the
// bottom) and read by cubic Hermite interpolation; outside the table, that series below and
// g(r) = g(r_max) + (π/2) ln(r/r_max) + O(r⁻²) above. Interpolation error below 1e-9 absolute
// (tests/unit/contact/test_strip_kernel.cpp checks it against direct quadrature of the
// definition). One lookup replaces a Gauss quadrature of 8 logarithms per matrix entry of the
// strip solver.
//
// Off the centre line, the strip solver needs the displacement at the ends of the strips (their
// extents follow from a closed deformed gap there, §9 item 3). It uses the drop of the kernel from
// the centre line, E(t, r) = g(r) − G(t, r), a function of two variables, tabulated once per
// process (about 25 ms) and read by bicubic Hermite interpolation:
//   - in t, cells graded towards the strip's end t = 1, where G has a boundary layer of width r
//     and a (1 − t)^{3/2} singularity: 4 cells per binade of |1 − t| from 2^-22 to 1 inside the
//     strip and to 128 beyond it (t ≤ 129);
//   - in v = ln r, 4 cells per binade from r = 2^-16 to 2^12.
// Node values and their derivatives (∂t, ∂r, ∂t∂r) come from strip_kernel_G_quadrature. The
// subtraction of g makes E bounded at large r (E → L(t) − L(0), L below), so that the difference
// E(t, r2) − E(t, r1) of two close lateral edges keeps its digits: measured within 2.2e-5 of
// quadrature relative to the centre-line value g(r2) − g(r1), over t in [0, 12] and strips from
// the point's own to 21 widths away (test_strip_kernel.cpp). Outside the table: t > 129 by Gauss–Chebyshev quadrature of G (analytic on the
// strip there), r > 2^12 by the limit L(t) − L(0) (error below r⁻² ≈ 6e-8), r < 2^-16 by
// quadrature.

namespace mh {

/// g(r) above [-].
double strip_kernel_g(double r);
/// g'(r) = 2 D(k)/sqrt(1 + r²), k = 1/sqrt(1 + r²), evaluated directly (Carlson's R_D, Boost.Math) [-].
double strip_kernel_dg(double r);

/// G(t, r) and its derivatives, t ≥ 0, r > 0.
struct StripKernelValue {
  double G = 0, G_r = 0, G_t = 0, G_tr = 0;
};
/// G(t, r) by quadrature: τ = sin θ, asinh(r/|x|) = ln(r + sqrt(r² + x²)) − ln|x| with the
/// logarithmic part integrated in closed form (L(t) = ∫ sqrt(1 − τ²) ln|τ − t| dτ, the
/// logarithmic potential of the semicircle density), the smooth part by 8-point Gauss–Legendre
/// on panels graded geometrically (ratio 0.3) towards the point θ = asin(min(t, 1)) down to a
/// twentieth of the width r of the kernel's peak. About 3 µs; within 1e-8 relative of adaptive
/// quadrature for r ≥ 1e-3 and 1e-9 absolute below (test_strip_kernel.cpp).
StripKernelValue strip_kernel_G_quadrature(double t, double r);

/// E(t, r) = g(r) − G(t, r) (table above), any t (even in t), any r (odd in r) [-].
double strip_kernel_drop(double t, double r);

/// One r of E(t, r) prepared for many t: the r half of the interpolation done once (the strip
/// solver evaluates each lateral edge of a strip at the ends of many other strips).
struct StripDropR {
  enum Kind { Zero, Nan, Table, LargeR, SmallR };
  Kind kind = Zero;
  double r = 0;      ///< |r|
  double sign = 1;   ///< sign of r
  int j = 0;         ///< table cell in r
  double bw[4] = {0, 0, 0, 0};  ///< its Hermite basis
};
StripDropR strip_kernel_drop_prepare(double r);
/// The same with log2|r| given (the strip solver forms it from a table of the edges' log2).
StripDropR strip_kernel_drop_prepare(double r, double log2_abs_r);
/// E(t, R.r), equal to strip_kernel_drop(t, r).
double strip_kernel_drop(const StripDropR& R, double t);
/// E(t, R2.r) − E(t, R1.r): the drop across one strip's width, with the t half shared.
double strip_kernel_drop_diff(const StripDropR& R2, const StripDropR& R1, double t);
/// The same for one strip seen from n points: out[i] += f (E(t[i], R[k[i] + 1].r) − E(t[i], R[k[i]].r)).
void strip_kernel_drop_diffs(const StripDropR* R, const int* k, const double* t, int n, double f, double* out);

}  // namespace mh
