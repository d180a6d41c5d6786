#pragma once
// One entry for every method: the runner solves a case through solve_contact(), whatever the case
// file's "method" is (docs/method.md §4 multi-Hertzian, §8 half-space, §9 strips).
#include "contact/options.hpp"
#include "contact/case_result.hpp"
#include "contact/judge/judge.hpp"
#include "contact/half_space/half_space_method.hpp"
#include "contact/half_space/tangential_patch.hpp"
#include "contact/multi_hertz/multi_hertz.hpp"
#include "contact/strips/strip_method.hpp"

namespace mh {

/// Solve one case by opt.method. Never throws for a numerical reason (the status says it). The
/// case's relative roll (opt.multi_hertzian.roll, method.md §3.8) reaches every method: the grid
/// methods' options take it (HalfSpaceOptions::roll, StripMethodOptions::roll).
CaseResult solve_contact(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt);

/// The same into `out`. The multi-Hertzian method reuses out's vectors (solve_multi_hertz's
/// second form: no allocation once they have grown, for the C interface's workspace); the other
/// methods assign a fresh result.
void solve_contact(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt,
                   CaseResult& out);

/// One thread's memory for the grid methods' cases (the C interface's workspace holds one; a
/// caller solving case after case on one thread, an MBS at every time step, keeps one). Empty
/// until used; it carries nothing from case to case that a result depends on.
struct GridWorkspace {
  HalfSpaceWorkspace half_space;
  StripWorkspace strips;
  TangentialPatchWorkspace tangential;  ///< the grid patches' tangential solvers (friction given)
  /// `auto`'s rows (solve.cpp): the multi-Hertzian answer it judges, that answer at Q before the
  /// creep equilibrium, the elastic start of a plastic case, the strip and half-space rows; the
  /// one kept is swapped into the caller's result, so each keeps its vectors' capacity.
  struct AutoRows {
    CaseResult mh, mh_at_Q, elastic_mh, strips, half_space;
  } auto_rows;
};

/// The same with the grid methods' memory in `ws` (null: as the form above): the half-space method
/// then allocates nothing once `ws` and `out` have seen a case of the same pair with patches as
/// large (a status message aside; docs/c-api.md "What a call allocates"). The same bytes.
void solve_contact(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt,
                   CaseResult& out, GridWorkspace* ws);

/// The same, the judge left to the caller where it can be: a caller that solves whole cases inside
/// a search (the wheelset's roll) and keeps only the last judges that one (judge_case), once.
/// Returns whether `out` was judged already (`auto`, whose choice is the judge's, and a grid method
/// without `ws`); false: judge_case(out, G, mat, tY, opt) gives it its status and warnings.
bool solve_contact_unjudged(const ContactGeometry& G, const Material& mat, double tY, double Q,
                            const MethodOptions& opt, CaseResult& out, GridWorkspace* ws);

/// The smoothing's uncertainty band of a solved case (profiles.md §7 "Uncertainty band"): r
/// solved again on the pair's geometries at L/2 and 2L by the method that solved it (a grid row
/// on band.half / twice, a multi-Hertzian row, `auto`'s kept ellipses included, on
/// band.window_half / window_twice), keeping nothing but the case summary, and judged by
/// judge_smoothing_band() (the band's values and `smoothing_sensitive`). Nothing where the row's
/// geometries are not there, or for a row without an answer. `opt` as for the case itself (its
/// roll and creep forces); what it keeps for output is dropped. The command's sweeps, batches
/// and the C interface call this one function.
void add_smoothing_band(CaseResult& r, const BandGeometries& band, const Material& mat, double tY, double Q,
                        const MethodOptions& opt);

/// pg.band for `method`'s rows (set_band_geometries): the spline's tables for the grid methods,
/// the window's for the multi-Hertzian one, both for `auto`; none when `on` is false. The
/// command's pairs (jobs/run.cpp) and the C interface's make them here.
void set_pair_band(PairGeometry& pg, const TrackSetup& track, const GeometryOptions& geo, bool on, Method method);

}  // namespace mh
