#pragma once
// The judge (docs/status.md): takes a solved case and decides its status and its warnings, by
// one rule for every method and every entry point (the command line, batches, the C API and
// Python all reach it through solve_contact(), or call it directly for an approach given).
#include "contact/case_result.hpp"

namespace mh {

/// Two loaded ellipses close enough to interact elastically, which the multi-Hertzian method
/// solves each on its own (docs/method.md §9, the gauge-shoulder case): the lateral gap between
/// their edges on the rail is below d_comb, the distance at which the grid methods make the
/// regions one patch. `found` false when no pair is that close.
struct EllipseInteraction {
  bool found = false;
  int first = 0, second = 0;  ///< the ellipses (LoadedEllipse::ellipse) of the first such pair
  double edge_gap = 0;        ///< [m] lateral gap between their edges on the rail (negative: overlap)
};
EllipseInteraction interacting_ellipses(const CaseResult& r, double d_comb);

/// The status rule (docs/status.md), applied once to every method's result (solve_contact):
/// a multi-Hertzian result with interacting ellipses gets the warning
/// `interacting:ellipses=I+J:edge_gap_mm=G<D`; then an `ok` result that carries a warning of a
/// validity class becomes OutsideValidity, its message naming the classes. Other statuses stay.
void judge_validity(CaseResult& r, double d_comb);

}  // namespace mh
