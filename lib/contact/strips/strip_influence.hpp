// The elastic influence of one strip (docs/method.md §9, "Algorithm" item 4): the normal
// displacement at a collocation point from a semi-elliptic (optionally capped) pressure of unit
// amplitude on strip j. Across the strip width the Boussinesq 1/r kernel (Johnson, Contact
// Mechanics §3.2) integrates in closed form; along x the singular part is subtracted (uniform
// pressure on a rectangle, Johnson §3.2) and the remainder integrated by Gauss–Legendre in theta
// (x = c + a sin theta). Centre-line entries of uncapped strips use the tabulated kernel instead
// (contact/strips/strip_kernel.hpp).
//
// Internal to the strip solver (contact/strips/strip_patch.hpp): namespace strips_detail.
#pragma once

#include <vector>

namespace mh {
namespace strips_detail {

/// Gauss–Legendre nodes/weights on [-1, 1] (Newton on P_n).
void gauss_legendre(int n, std::vector<double>* x, std::vector<double>* w);

/// Influence integral (see strips_detail::strip_influence) with given nodes.
/// Singularity subtraction: f = f(t0) + (f - f(t0)); the constant part is the
/// closed-form rectangle integral of 1/r (Johnson §3.2, uniform pressure on a
/// rectangle); the remainder vanishes at the singular point and is integrated
/// by Gauss–Legendre in theta (x = a sin theta) on sub-intervals split at the
/// point and at the kinks of the capped profile.
double influence(double X0, double a, double e1, double e2, double rcap,
                 const std::vector<double>& gx, const std::vector<double>& gw);

/// The same integral on the strip's centre line (X0 = 0) for a whole column of strips of width ds:
/// out[d] = influence(0, a, (d − ½) ds, (d + ½) ds, rcap) for d = 0 … dmax (a point d strips away,
/// either side). The rectangle term and the root of the lateral kernel are taken once per strip
/// edge, the Gauss nodes (sin, cos, f) once per column, and the flat top (f − f0 = 0 there) is
/// not integrated: per distance one logarithm per node of one interval, where influence() takes
/// two intervals, a sine, a cosine and two roots per node. A capped strip's column of the
/// collocation (docs/method.md §9 item 6) and its displacement at the centres in the end-gap drops.
/// `need` (size dmax + 1): only the distances d with need[d] are computed, the others left 0, and
/// only their edges' roots are taken (the collocation passes its elastic rows, the drops their
/// field strips: few of dmax on a mostly capped patch).
void influence_centre_line(double a, double ds, double rcap, int dmax, const std::vector<double>& gx,
                           const std::vector<double>& gw, std::vector<double>& out,
                           const std::vector<char>* need = nullptr);

/// influence_centre_line read from a table (same arguments, same result within 5e-4 nm of
/// displacement at p_lim = 900 MPa on steel, measured 2.9e-4 nm; tests/unit/contact/test_strip_capped.cpp).
/// On the centre line the column is a difference of one function of two variables,
///   out[d] = a [F(th, rho_d) − F(th, rho_{d−1})], out[0] = 2 a F(th, rho_0), rho_m = (m + ½) ds / a,
///   F(th, rho) = 2 r P(1, rho) + Σ_k W_k(th) asinh(rho / sin theta_k),
/// th = asin sqrt(1 − r²), P the rectangle term and theta_k, W_k the nodes and weights of the
/// quadrature above on [th, π/2] (the same sum, divided by a). F and ∂F/∂ log2 rho are tabulated
/// for the solver's 8 nodes (StripOptions::gauss_points = 16) on 257 rows in th, graded towards
/// th = 0 and π/2 (th = (π/4)(1 − cos π i/256)), and 16 cells per binade of rho over 2^-10 … 2^7,
/// each row built on first use; read by cubic Lagrange interpolation across rows and cubic Hermite
/// in log2 rho: per distance one log2 and 16 table values instead of 8 roots, 8 logarithms and two
/// asinh. Other node counts, and rho outside the table, take the quadrature.
/// `log2_edge` (optional): log2((m + ½) ds) for m = 0 … dmax, which the solver keeps (Solver::log2_edge).
void capped_centre_line(double a, double ds, double rcap, int dmax, const std::vector<double>& gx,
                        const std::vector<double>& gw, std::vector<double>& out,
                        const std::vector<char>* need = nullptr, const double* log2_edge = nullptr);

/// A capped strip (flat top at rcap < 1) as a source seen from many points of its own centre line's
/// direction (the ends of other strips, X0 >= 0): influence()'s sub-intervals that do not depend on
/// the point (the two tails |t| > sqrt(1 − rcap²) and the flat top), their nodes, f and weights,
/// prepared once per strip. At a point inside the flat top (|X0| < x_flat) f − f0 vanishes on it
/// and only the tails are summed; at a point on a tail that tail is split there as influence()
/// does; beyond the strip's end every piece is prepared.
struct CappedSource {
  double a = 0, r = 1, th = 0, x_flat = 0;  ///< half-length, flat top, asin sqrt(1 − r²), a sqrt(1 − r²)
  const std::vector<double>* gx = nullptr;  ///< the Gauss nodes and weights per sub-interval
  const std::vector<double>* gw = nullptr;
  std::vector<double> x, f, w;              ///< the tails' nodes (left, then right): x = a sin theta, f, gw half a cos theta
  std::vector<double> x_flat_nodes, f_flat_nodes, w_flat_nodes;  ///< the same on the flat top
};
void capped_source(double a, double rcap, const std::vector<double>& gx, const std::vector<double>& gw,
                   CappedSource& out);
/// influence(X0, a, e1, e2, rcap) of a prepared source, X0 >= 0.
double capped_source_influence(const CappedSource& src, double X0, double e1, double e2);

/// Integral over one strip of f(t)/r, f(t) = min(sqrt(1 - t^2), r_cap),
/// t = (xi - c_j)/a_j, for a point at x-offset X0 = x_i - c_j and lateral
/// offsets eta1 < eta2 of the strip edges from the point (eta = s_j +- ds/2 - s_i).
/// r_cap >= 1: plain semi-ellipse. Unit [m] (multiply by H q_j for the displacement).
double strip_influence(double X0, double a, double eta1, double eta2, double r_cap, int gauss_points);

}  // namespace strips_detail
}  // namespace mh
