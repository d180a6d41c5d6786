#pragma once
// The subsurface stresses of one solved contact (docs/outputs.md "Subsurface columns"; docs/methods.md
// "Subsurface stresses"): which load they are of, its peaks and FI_sub. The output tables only
// format this result (lib/output/rcf_columns.hpp).
//
// The load, in order of preference:
// - a grid patch with "subsurface": {"grid": true}, friction given and the per-element traction of
//   its tangential solve kept (PatchResult::traction, TangentialOptions::keep_traction): its element
//   pressure and that solved traction, on the rail (ContactStressSource::GridPatchSolvedTraction);
// - a grid patch with "grid": true otherwise: its element pressure (half-space: PatchResult::p;
//   strips: their semi-ellipses laid on a grid of the strip width across and at least 32 along, as
//   the strips' tangential step lays them, contact/solve.cpp) with full-slip traction f p on the
//   rail along the contact's own force (−F/|F|, F on the wheel; along x without one)
//   (ContactStressSource::GridPatch);
// - an ellipse row with friction given and FASTSIM's cells kept (CaseResult::ellipse_traction,
//   TangentialOptions::keep_traction) on its ELASTIC ellipse (a = a_el, b = b_el: an elastic law):
//   the Hertz pressure of that ellipse and FASTSIM's traction of its cells (traction_grid.hpp,
//   fastsim_traction_at), on the rail, laid on uniform elements of min(a, b)/kEllipseElements and
//   summed as a grid patch's (grid_subsurface.hpp) (ContactStressSource::HertzEllipseFastsim);
// - else the ELASTIC Hertz ellipse of the contact's N (a_el, b_el, p0_el; never a plastic patch's)
//   with full-slip traction f on the rail along the contact's own force (−F/|F|, F on the wheel)
//   with friction given, else along x (ContactStressSource::HertzEllipse; subsurface.hpp).
// Never the grid for a patch with elements at the plastic cap: the elastic stresses of a capped
// pressure are not the stresses of the yielded material (its Hertz ellipse's instead).
#include <cmath>

#include "contact/case_result.hpp"
#include "contact/rcf/grid_subsurface.hpp"
#include "contact/rcf/shakedown.hpp"
#include "contact/rcf/subsurface.hpp"
#include "contact/tangential/traction_grid.hpp"

namespace mh {

/// Which load a contact's subsurface stresses are of (docs/outputs.md, column sub_source).
enum class ContactStressSource { None, HertzEllipse, GridPatch, GridPatchSolvedTraction, HertzEllipseFastsim };
/// The sub_source text; nullptr for None (the cell empty).
inline const char* to_string(ContactStressSource s) {
  switch (s) {
    case ContactStressSource::None: return nullptr;
    case ContactStressSource::HertzEllipse: return "hertz_ellipse";
    case ContactStressSource::GridPatch: return "grid_patch";
    case ContactStressSource::GridPatchSolvedTraction: return "grid_patch_solved_traction";
    case ContactStressSource::HertzEllipseFastsim: return "hertz_ellipse_fastsim_traction";
  }
  return nullptr;
}

/// The stresses below one contact: the source of its load, the peaks (NaN: not computed) and
/// FI_sub [Pa] (NaN without RcfOptions::dang_van_c).
struct ContactStresses {
  ContactStressSource source = ContactStressSource::None;
  SubsurfacePeaks peaks;
  double fi_sub = NAN;
};

/// FASTSIM's kept cells of an ellipse row and the semi-axes a, b [m] of the ellipse it solved (the
/// patch its normal law carries: a plastic patch when plastic). traction null: none kept.
struct EllipseCells {
  const EllipseTraction* traction = nullptr;
  double a = 0, b = 0;
};

/// FASTSIM's kept cells of the ellipse row L of r (CaseResult::ellipse_traction, in the order of
/// r.loaded; none when not kept) and the ellipse they were solved on.
inline EllipseCells ellipse_cells(const CaseResult& r, const LoadedEllipse& L) {
  const std::size_t i = static_cast<std::size_t>(&L - r.loaded.data());
  if (i >= r.ellipse_traction.size() || r.ellipse_traction[i].empty()) return {};
  return {&r.ellipse_traction[i], L.s.a, L.s.b};
}

/// Elements per smaller semi-axis of the grid that carries an ellipse's FASTSIM traction to the
/// stresses (the grid patches' check of test_grid_subsurface.cpp: b/10 gives the Hertz peaks
/// within 3e-4 p0).
inline constexpr int kEllipseElements = 10;

/// The stresses below the contact carrying N [N] with elastic Hertz semi-axes a_el, b_el [m],
/// tangential result t and traction coefficient f [-] (RcfOptions::traction); `patch`: the grid
/// patch, or null for an ellipse; `cells`: an ellipse row's FASTSIM cells (the source above). None (NaN peaks) when f is not finite or the load is not known.
/// The search costs about 0.5 s per ellipse and seconds per grid patch: the last results of this
/// thread are kept, so that the CSV and JSON records of a contact (formatted one after the other)
/// search once.
ContactStresses contact_stresses(const RcfOptions& o, double N, double a_el, double b_el, const TangentialResult& t,
                                 double f, const PatchResult* patch = nullptr, const EllipseCells& cells = {});

/// The load of a grid patch for the stresses (the first two sources above; the rules there): its
/// element pressure, and the solved traction on the rail when `solved` is asked and kept, else
/// full-slip f p along the contact's own force. Empty (no elements) for a patch without its
/// pressure; solved_used says whether the solved traction was taken.
GridLoad patch_stress_load(const RcfOptions& o, const PatchResult& patch, double f, bool solved, bool* solved_used = nullptr);

/// The load of an ellipse row with FASTSIM's traction (the source HertzEllipseFastsim above): the
/// elastic Hertz pressure 3N/(2π a b) √(1 − x²/a² − y²/b²) and FASTSIM's traction of the cells
/// solved with friction mu, reversed (on the rail), at the centres of uniform elements over the
/// ellipse, about min(a, b)/kEllipseElements each way. Empty when the cells are not of an elastic
/// ellipse (cells.a, cells.b not a_el, b_el within 1e-9) or not kept.
GridLoad ellipse_fastsim_load(const RcfOptions& o, double N, double a_el, double b_el, double mu,
                              const EllipseCells& cells);

}  // namespace mh
