#pragma once
// The strip extents that close the deformed gap at every strip end (docs/method.md §9 item 3,
// "end gap"): g_i + A_i a_i² + u(c_i ± a_i, s_i) = δ, iterated with the collocation from the
// estimated extents (fixed point with Anderson acceleration), and the error by which an
// estimate misses it. Accuracy and cost: docs/strips.md.
//
// Internal to the strip solver (contact/strips/strip_patch.hpp): namespace strips_detail.
#include "contact/strips/strip_collocation.hpp"

namespace mh {
namespace strips_detail {

/// How far a solution's extents are from closing the deformed gap at their ends: the
/// load-weighted mean over its loaded, uncapped strips of |1 − (δ − g_i − u_end,i)/(A_i a_i²)|,
/// the relative error of a_i² (twice that of a_i). 0 for an exact Hertz patch.
double end_gap_error(const Solver& S, const StripResult& r, double p_lim);

/// The end-gap extents from the solution `start`: approach given (load_given false, `target` =
/// delta) or load given (`target` = N, the approach follows), into `res` (not `start`).
void refine_extents(const Solver& S, bool load_given, double target, double p_lim, const StripResult& start,
                    StripResult& res);

}  // namespace strips_detail
}  // namespace mh
