// Semi-Hertzian strip solver with elastic coupling between strips, for one
// contact patch (no yaw).
//
// Method: every lateral strip carries a semi-elliptic pressure along x,
//   p_i(x) = q_i sqrt(1 - ((x - c_i)/a_i)^2),  uniform across the strip width ds.
// Strip extents are the union of a KPEC-type estimate (equivalent ellipse per
// lateral band; Kik & Piotrowski 1996, Piotrowski & Kik 2008) and an
// ANALYN-type estimate (local Hertz solution per strip; Sichani et al. 2014).
// Amplitudes follow from collocation at the strip centres with the full
// Boussinesq influence matrix (Johnson, Contact Mechanics §3.2), an active set
// for q >= 0, an optional plastic cap p_lim, and load control on the approach;
// strips too short for the interpenetration the others leave at their centres are
// widened (docs/method.md §9 item 7).
//
// Interpretation used for the extent estimates: within a lateral band the
// approach is measured from the band's deepest gap g0 (delta_b = delta - g0,
// gaps g - g0). For a band touching g = 0 this is the specification verbatim;
// for a shallower band it keeps both estimates exact for an elliptic patch.
// The collocation right-hand side is always the absolute delta - h(c_i, s_i).
//
// Units: SI throughout (m, Pa, N). Never throws on numerical trouble; the
// result carries a status.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "contact/judge/status.hpp"

namespace mh {

/// Undeformed gap of one contact patch, sampled on lateral strips.
/// Row i: h(x, s_i) = g_i + A_i (x - xc_i)^2; interpenetration at approach
/// delta is delta - h(x, s).
struct StripGeometry {
  double ds = 0.0;         ///< [m] strip width (lateral, in the contact plane)
  std::vector<double> s;   ///< [m] lateral coordinate of each strip centre, increasing, uniform spacing ds
  std::vector<double> g;   ///< [m] minimum undeformed normal gap of the row at s_i, before approach
  std::vector<double> A;   ///< [1/m] gap curvature along x (A_i > 0)
  std::vector<double> xc;  ///< [m] x of the row's minimum (0 without yaw)
};


enum class StripStatus { Ok, NoContact, NotConverged, InvalidInput };

/// One loaded strip.
struct StripState {
  double s = 0.0;        ///< [m] lateral coordinate of the strip centre
  double c = 0.0;        ///< [m] x of the pressure centre
  double a = 0.0;        ///< [m] half-length (for plastic strips: lengthened a', at most to the overlap)
  double a_elastic = 0.0;  ///< [m] half-length before the plastic lengthening (= a for an elastic strip)
  double q = 0.0;        ///< [Pa] amplitude of the semi-ellipse (plastic: elastic amplitude, flat top at p_lim)
  bool plastic = false;  ///< capped at p_lim
  int band = 0;          ///< lateral band index (0-based, increasing s)
  int index = 0;         ///< index of the strip in StripGeometry
  double load = 0.0;     ///< [N] load carried by the strip
};

struct StripResult {
  StripStatus status = StripStatus::NoContact;
  std::string message;
  /// NotConverged or InvalidInput: what did not converge, as data (a not_converged_* class with
  /// its measures; the patch is named by the caller).
  Warning failure;
  int iterations = 0;     ///< delta iterations (load control), 0 for approach given
  double delta = 0.0;     ///< [m] approach
  double N = 0.0;         ///< [N] normal load
  double pmax = 0.0;      ///< [Pa] min(max q, p_lim)
  double area = 0.0;      ///< [m^2] sum 2 a_i ds over loaded strips (with plastic lengthening)
  int n_bands = 0;        ///< lateral bands found at the final delta
  double end_gap_error = NAN;  ///< the estimate's end-gap error (StripOptions::end_gap_tol), NaN if not checked
  bool refined = false;   ///< the extents close the end gap (refined), else the estimate
  int n_outliers = 0;     ///< strips flagged by outlier_factor
  int worst_outlier = -1; ///< index into `strips` of the worst outlier, -1 if none
  std::vector<StripState> strips;  ///< loaded strips only, in increasing s
};

/// What one solve of a geometry hands to the next solve of the same geometry (another approach,
/// another load, or the same patch on the next plane): its loaded strips as the first active
/// set, and whether this patch's extents are refined, with the last refined solution as the
/// start of the next refinement. The decision to refine is taken once, at the first solve, so
/// that N(δ) stays one smooth function along an approach iteration.
struct StripWarmStart {
  std::vector<int> loaded;  ///< geometry indices (increasing) of the strips that carried load
  int end_gap = -1;         ///< -1 not decided yet, 0 the estimate is kept, 1 refined extents
  double end_gap_error = NAN;  ///< the estimate's end-gap error the decision was taken on
  StripResult previous;     ///< the last refined solution (end_gap == 1), in this geometry's indices
};

}  // namespace mh
