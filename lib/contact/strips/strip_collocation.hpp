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

#include <utility>
#include <vector>

#include "core/dense.hpp"
#include "core/mru.hpp"

#include "contact/strips/strip_extents.hpp"
#include "contact/strips/strip_influence.hpp"
#include "contact/strips/strip_kernel.hpp"
#include "contact/options.hpp"
#include "contact/strips/strip_types.hpp"

namespace mh {
namespace strips_detail {

/// Phi(r) = r sqrt(1 - r^2) + asin r: load of a capped semi-ellipse min(q sqrt(1-t^2), r q) over
/// t in [-1, 1] is q a Phi(r); Phi(1) = pi/2 (docs/method.md §9 item 6).
double Phi(double r);

/// The coupled solve at one approach and one set of extents: its inputs (the strips taking part
/// and their extents) and its outcome. Indices ii run over `cand`. Its buffers keep their
/// capacity from solve to solve (reset(); core/dense.hpp): a warm solver allocates nothing.
struct Collocation {
  std::vector<int> cand;        ///< geometry indices of the strips that may carry load (increasing)
  std::vector<double> a;        ///< [m] their extents (for capped strips: before lengthening)
  DenseMatrix K;                ///< elastic influence among cand, unit amplitude [m/Pa]; zero column for a = 0
  std::vector<double> q;        ///< [Pa] amplitudes (capped strips: the elastic amplitude at capping)
  std::vector<double> aeff;     ///< [m] extents as loaded (capped strips lengthened, at most to their overlap)
  std::vector<double> rcap;     ///< p_lim / q for capped strips, 1 otherwise
  std::vector<char> capped;     ///< flat-topped at p_lim
  DenseMatrix Ucap;             ///< [m] column jj: displacement at the centres of the elastic strips from capped strip jj
                                ///< (rows of capped strips, whose equations are dropped, are zero; the columns
                                ///< of strips not capped are not set)
  bool as_ok = true;            ///< the active set settled
  bool settled = true;          ///< the plastic set settled
  int newly_capped = 0;         ///< strips newly capped in the plastic set's last pass
  /// Factorisations of K restricted to sets of candidates (indices ii), reused across approaches:
  /// each collocation restarts its plastic passes from the elastic set, and along a load iteration
  /// at fixed extents the passes meet the same sets again. Dropped when K changes; at most
  /// kMaxFactorisations, the oldest replaced first. The first n_lus of `lus` are in use, in
  /// order of age from `oldest`; the others keep their buffers for later sets.
  struct Factorisation {
    std::vector<int> of;
    DenseLU lu;
    std::vector<double> inv_col;  ///< column r (of.size() entries from r × of.size()): K⁻¹ e_r, once taken
    std::vector<char> has_col;    ///< K⁻¹ e_r taken
    bool factorised = false;      ///< lu holds K_EE (taken on first use)
  };
  std::vector<Factorisation> lus;
  int n_lus = 0, oldest = 0;
  static constexpr int kMaxFactorisations = 16;
  /// The factorisation of the set E: one in use, else a slot made ready for it (not factorised).
  Factorisation& factorisation_of(const std::vector<int>& E);
  /// Empty, as a new Collocation, its buffers kept.
  void reset();
};

/// A strip solver's memory between calls (the buffers of its passes; none of it carries data from
/// one call to the next that a result depends on).
struct StripScratch {
  Collocation eval, refine;              ///< the collocations of evaluate and of refine_extents
  std::vector<int> band, E, act, newly, R, A;
  std::vector<double> a, built, a_prev, phi_prev, ucap, rhs, qE, w, wR, KqR, qa;
  std::vector<char> start, in_act;
  DenseLU small;                         ///< the active set's small systems (capacitance, active strips)
  std::vector<int> warm;                 ///< load control's active set from one approach to the next
  StripResult best, refined;             ///< load control's closest iterate; a refinement's result
};

/// The memory of the end-gap refinement and its error (strip_end_gap.cpp).
struct StripEndGapScratch {
  /// A loaded strip as a source of displacement: geometry index, half-length as loaded,
  /// amplitude, flat top (rcap < 1: capped at p_lim = rcap q).
  struct Source {
    int j;
    double a, q, rcap;
  };
  std::vector<Source> src;
  std::vector<int> field, kk, cand;
  std::vector<double> end, D, centre, t, u, qv, a, anew, x, f, xn, x_prev, f_prev, sum_col, gam, c;
  std::vector<char> need, was_loaded, act;
  std::vector<StripDropR> R;
  CappedSource cs;
  std::vector<double> built;
  /// Anderson acceleration's last differences of x and f, n × depth each, column (oldest + k) mod
  /// depth the k-th oldest; Fm, Xm + Fm in age order for the least squares.
  DenseMatrix dX, dF, Fm, XF;
  int n_diff = 0, oldest = 0;
  /// Its least-squares factorisations by shape (n, k) (Eigen's, which keeps its memory only at
  /// one shape), the last 40: the Anderson depths k = 1 … 5 of the last 8 strip counts n (a
  /// wheelset's plastic steps meet 5 or 6 strip counts per solver over their loads: with 20 kept
  /// the second pass of the [alloc] test still allocated, with 30 not).
  MruCache<std::pair<int, int>, Eigen::ColPivHouseholderQR<Eigen::MatrixXd>> qrs{40};
  StripResult start;  ///< a refinement's start taken from a warm start (StripSolver::at_load)
};

/// A result reset to a new one's fields, its vectors and message keeping their capacity.
void clear_result(StripResult& r);

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
  /// The buffers of the solves (const methods: a solver is used by one thread at a time).
  mutable StripScratch scratch;
  mutable StripEndGapScratch end_gap;  ///< strip_end_gap.cpp's

  Solver(const StripGeometry& g, double Hc, const StripOptions& o);
  /// The same geometry object (its contents changed), H and options set anew: the state of a new
  /// Solver, the buffers kept.
  void reinit(double Hc, const StripOptions& o);
  /// H, the options and what follows from them.
  void set(double Hc, const StripOptions& o);

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
  /// The result of a collocation (loaded strips, load, area, peak, outliers), into `res` (reset
  /// first, its vectors keeping their capacity).
  void assemble(double delta, double p_lim, const Collocation& c, StripResult& res) const;

  /// Solve at fixed approach with the estimated extents. `warm`: the strips (geometry indices,
  /// increasing) that carried load in a previous solve of this geometry, as the starting active
  /// set; null or empty: every strip with a positive extent.
  void evaluate(double delta, double p_lim, const std::vector<int>* warm, StripResult& res) const;

};

}  // namespace strips_detail
}  // namespace mh
