// Collocation solve of the coupled strips at a fixed approach (docs/method.md §9, "Algorithm"
// items 3–7): amplitudes from the displacement condition at the strip centres,
// sum_j K_ij q_j = delta - h(c_i, s_i), with the full influence matrix (contact/strips/strip_influence.hpp,
// contact/strips/strip_kernel.hpp), an active set for q >= 0 (a complementarity problem, one
// factorisation per set of extents), the plastic cap at p_lim (capped strips keep their elastic
// amplitude, drop their displacement equation and are lengthened, within their overlap), the
// load and the outlier flag.
//
// Two ways to the strip extents:
//  - the estimate (evaluate): the rigid-geometry rules of contact/strips/strip_extents.hpp, with strips
//    too short for the interpenetration the others leave at their centres widened (item 7);
//  - the refinement (strip_end_gap.cpp): the extents that close the deformed gap at every strip's
//    ends, g_i + A_i a_i² + u(c_i ± a_i, s_i) = delta (item 3, "end gap"), iterated with the
//    collocation from the estimate. end_gap_error measures how far an estimate is from it.
// Load control on the approach is in strips.cpp. Accuracy and cost: docs/strips.md.
//
// Internal to the strip solver (contact/strips/strip_patch.hpp): namespace strips_detail.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "contact/strips/strip_extents.hpp"
#include "contact/options.hpp"
#include "contact/strips/strip_types.hpp"

namespace mh {
namespace strips_detail {

/// Phi(r) = r sqrt(1 - r^2) + asin r: load of a capped semi-ellipse min(q sqrt(1-t^2), r q) over
/// t in [-1, 1] is q a Phi(r); Phi(1) = pi/2 (docs/method.md §9 item 6).
double Phi(double r);

/// The coupled solve at one approach and one set of extents: its inputs (the strips taking part
/// and their extents) and its outcome. Indices ii run over `cand`.
struct Collocation {
  std::vector<int> cand;        ///< geometry indices of the strips that may carry load (increasing)
  std::vector<double> a;        ///< [m] their extents (for capped strips: before lengthening)
  Eigen::MatrixXd K;            ///< elastic influence among cand, unit amplitude [m/Pa]; zero column for a = 0
  std::vector<double> q;        ///< [Pa] amplitudes (capped strips: the elastic amplitude at capping)
  std::vector<double> aeff;     ///< [m] extents as loaded (capped strips lengthened, at most to their overlap)
  std::vector<double> rcap;     ///< p_lim / q for capped strips, 1 otherwise
  std::vector<char> capped;     ///< flat-topped at p_lim
  Eigen::MatrixXd Ucap;         ///< [m] column jj: displacement at the centres of the elastic strips from capped strip jj
                                ///< (rows of capped strips, whose equations are dropped, are zero; the columns
                                ///< of strips not capped are not set)
  bool as_ok = true;            ///< the active set settled
  bool settled = true;          ///< the plastic set settled
  int newly_capped = 0;         ///< strips newly capped in the plastic set's last pass
  /// Factorisations of K restricted to sets of candidates (indices ii), reused across approaches:
  /// each collocation restarts its plastic passes from the elastic set, and along a load iteration
  /// at fixed extents the passes meet the same sets again. Cleared when K changes; at most
  /// kMaxFactorisations, the oldest dropped first.
  struct Factorisation {
    std::vector<int> of;
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;
    std::vector<Eigen::VectorXd> inv_col;  ///< K⁻¹ e_r of the active-set solves, for the strips r taken so far
    bool factorised = false;               ///< lu holds K_EE (taken on first use)
  };
  std::vector<Factorisation> lus;
  static constexpr std::size_t kMaxFactorisations = 16;
};

/// The load [N] of candidate ii of a collocation on strips of width ds: (π/2) q a ds elastic,
/// q a' Φ(r) ds capped (§9 item 6: its elastic load unless its overlap holds it shorter); zero
/// unloaded.
double strip_load(const Collocation& c, int ii, double ds);

/// The strip solver of one geometry, elastic constant H and options.
struct Solver : StripExtents {
  double H;
  StripOptions opt;
  std::vector<double> gx, gw;     // Gauss nodes per sub-interval
  bool same_xc = true;            // every row's minimum at one x: K_ij depends on |i − j| and a_j only
  std::vector<double> log2_edge;  // log2 |(k − ½) ds| for k = −n … n + 1 (index k + n): the strip edges' offsets

  Solver(const StripGeometry& g, double Hc, const StripOptions& o);

  /// Influence coefficient K_ij of an uncapped strip j of half-length aj at the centre of strip i.
  double K_elastic(int i, int j, double aj) const;
  /// Displacement at the ends of strip i (half-length ai, mean of x = c_i ± ai) from strip j of
  /// half-length aj and unit amplitude, flat-topped at rcap (< 1), by quadrature [m/Pa]: for
  /// capped strips and unequal row centres (the elastic, no-yaw case reads the tabulated drop).
  double K_end(int i, double ai, int j, double aj, double rcap) const;

  /// Column jj of c.Ucap for the newly capped strip jj (c.aeff, c.rcap, c.q set), in the rows of
  /// the strips not capped.
  void capped_column(Collocation& c, int jj) const;
  /// Build c.K for c.a (the columns whose extent differs from `built`, all when it is empty).
  void build_K(Collocation& c, std::vector<double>& built) const;
  /// The amplitudes at approach delta for c's extents: active set and plastic cap. `start`: the
  /// starting active set per candidate (returns the final one).
  void collocate(double delta, double p_lim, Collocation& c, std::vector<char>& start) const;
  /// The result of a collocation (loaded strips, load, area, peak, outliers).
  StripResult assemble(double delta, double p_lim, const Collocation& c) const;

  /// Solve at fixed approach with the estimated extents. `warm`: the strips (geometry indices,
  /// increasing) that carried load in a previous solve of this geometry, as the starting active
  /// set; null or empty: every strip with a positive extent.
  StripResult evaluate(double delta, double p_lim, const std::vector<int>* warm = nullptr) const;

};

}  // namespace strips_detail
}  // namespace mh
