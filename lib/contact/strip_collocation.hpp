// Collocation solve of the coupled strips at a fixed approach (docs/method.md §9, "Algorithm"
// items 4–7): amplitudes from the displacement condition at the strip centres,
// sum_j K_ij q_j = delta - h(c_i, s_i), with the full influence matrix (contact/strip_influence.hpp,
// contact/strip_kernel.hpp), an active set for q >= 0 (a complementarity problem, one
// factorisation per approach), the plastic cap at p_lim (capped strips keep their elastic
// amplitude, drop their displacement equation and are lengthened), the widening of strips too
// short for the interpenetration the others leave at their centres (item 7), the load and the
// outlier flag. The strip extents come from contact/strip_extents.hpp; load control on
// the approach is in strips.cpp. Accuracy and cost: docs/strips.md.
//
// Internal to the strip solver (contact/strips.hpp): namespace strips_detail.
#pragma once

#include <vector>

#include "contact/strip_extents.hpp"
#include "contact/strips.hpp"

namespace mh {
namespace strips_detail {

/// The strip solver of one geometry, elastic constant H and options.
struct Solver : StripExtents {
  double H;
  StripOptions opt;
  std::vector<double> gx, gw;     // Gauss nodes per sub-interval
  bool same_xc = true;            // every row's minimum at one x: K_ij depends on |i − j| and a_j only

  Solver(const StripGeometry& g, double Hc, const StripOptions& o);

  /// Influence coefficient K_ij of an uncapped strip j of half-length aj at the centre of strip i.
  double K_elastic(int i, int j, double aj) const;

  /// Solve at fixed approach. `warm`: the strips (geometry indices, increasing) that carried
  /// load in a previous solve of this geometry, as the starting active set; null or empty: every
  /// strip with a positive extent.
  StripResult evaluate(double delta, double p_lim, const std::vector<int>* warm = nullptr) const;
};

}  // namespace strips_detail
}  // namespace mh
