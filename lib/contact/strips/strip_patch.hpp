#pragma once
// The strip solver of one contact patch (docs/method.md §9): approach or load given, warm starts
// across the solves of one patch, and the mapping of a solution onto a new placement of its
// plane. The data it works on and returns are in contact/strips/strip_types.hpp; the collocation
// and the extents behind it in strip_collocation.hpp and strip_end_gap.hpp.
#include <memory>
#include <string>
#include <vector>

#include "contact/options.hpp"
#include "contact/strips/strip_types.hpp"

namespace mh {

/// Approach given. `warm`: geometry indices (increasing) of the strips expected to carry load,
/// e.g. those of a solve at a nearby approach, as the starting active set. The active set
/// method ends where no strip has q < 0 and no unloaded strip is penetrated, whatever it
/// started from: a warm start changes the cost (fewer factorisations), not the answer. Null or
/// empty: every strip with a positive extent.
StripResult solve_strips_approach(const StripGeometry& geo, double H, double delta, double p_lim,
                                  const StripOptions& opt = {}, const std::vector<int>* warm = nullptr);
/// Load given. `warm`: as for solve_strips_approach, for the first approach; each later one
/// starts from the strips of the one before.
StripResult solve_strips_load(const StripGeometry& geo, double H, double N, double p_lim,
                              const StripOptions& opt = {}, const std::vector<int>* warm = nullptr);

namespace strips_detail { struct Solver; }

/// A strip solver bound to one geometry, H and p_lim: the input is checked once and what
/// depends on the geometry only (the ANALYN shape per strip, the deepest row) computed once, for
/// the many solves of one patch; solve_strips_approach and solve_strips_load are this for one
/// call. `geo` must outlive the solver. Invalid input: every solve returns InvalidInput.
/// A solver keeps the buffers of its solves: once they have grown, and when reset to the same
/// geometry object, the forms that write into a given result allocate nothing (results whose
/// vectors have grown too). Not for concurrent use (one thread at a time).
class StripSolver {
 public:
  StripSolver(const StripGeometry& geo, double H, double p_lim, const StripOptions& opt = {});
  ~StripSolver();
  StripSolver(const StripSolver&) = delete;
  StripSolver& operator=(const StripSolver&) = delete;
  /// As a new solver; with the geometry object of the last reset (its contents changed, e.g. a
  /// pooled patch set up again) the memory is kept.
  void reset(const StripGeometry& geo, double H, double p_lim, const StripOptions& opt = {});
  StripResult at_approach(double delta, StripWarmStart* warm = nullptr) const;
  /// `delta_start`: the first approach tried (e.g. a previous solve's), if above the minimum gap;
  /// else the Hertz approach of the deepest row.
  StripResult at_load(double N, StripWarmStart* warm = nullptr, double delta_start = NAN) const;
  /// The same into `out` (reset first; not warm->previous).
  void at_approach(double delta, StripWarmStart* warm, StripResult& out) const;
  void at_load(double N, StripWarmStart* warm, double delta_start, StripResult& out) const;

 private:
  /// Load control with the estimated extents (a safeguarded secant on the approach).
  void estimate_at_load(double N, const std::vector<int>* warm, double delta_start, StripResult& out) const;
  std::unique_ptr<strips_detail::Solver> s_;  ///< the solver of the last valid input
  bool valid_ = false;                        ///< false: invalid input (why_)
  std::string why_;
  double p_lim_ = INFINITY;
};

/// The geometry indices of a result's loaded strips (increasing): a warm start's active set.
std::vector<int> loaded_strips(const StripResult& r);
void loaded_strips(const StripResult& r, std::vector<int>& out);

/// A solution's strips carried onto another strip geometry of the same patch (the patch on a
/// new placement of its plane): the start of the next refinement of the extents
/// (StripWarmStart::previous). New strip j has its centre at `s_new[j]`, which is `s_old[j]` in
/// the old geometry's coordinate (the same rail y). Its half-length and amplitude are
/// interpolated linearly between the two old loaded strips around it, never across a gap
/// between bands (non-adjacent old indices); a new strip beyond the end of a band by less than
/// `ds_old` takes its end strip's values, so that a tail strip is not lost (the refinement keeps
/// a strip only if it starts with an extent). `old` in increasing s; the
/// result in increasing new index, index and s of the new geometry.
std::vector<StripState> map_strips(const std::vector<StripState>& old, double ds_old,
                                   const std::vector<double>& s_old, const std::vector<double>& s_new);
void map_strips(const std::vector<StripState>& old, double ds_old, const std::vector<double>& s_old,
                const std::vector<double>& s_new, std::vector<StripState>& out);

}  // namespace mh
