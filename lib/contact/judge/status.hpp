#pragma once
// A case's status and its warnings as data (docs/status.md). The solvers and the judge
// (contact/judge/judge.hpp) fill Warning structs; a warning becomes text only where it is
// written (warning_text(), called by the writers: CSV/JSON, messages, summaries, the C and
// Python accessors). A light header: no solver, no geometry.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "contact/options.hpp"

namespace mh {

/// The outcome of one case's solve (a batch's `invalid_pair` is not a solver outcome: jobs/batch.hpp).
/// Ok and OutsideValidity rows carry an answer (their numbers are written); OutsideValidity says
/// it is not to be trusted: the method solved the case outside the conditions it is valid in, and
/// the warnings say which (the judge, contact/judge/judge.hpp; docs/status.md). NoContact and
/// OutOfRange rows have no answer; a NotConverged row keeps its last iterate. A Derailed row
/// carries its answer too, for a wheel that rides on its flange tip (off the rail: the judge's
/// `derailed` warning, docs/status.md): never `ok`, whatever the method says of its accuracy.
enum class CaseStatus { Ok, OutsideValidity, NoContact, OutOfRange, NotConverged, Derailed };
const char* to_string(CaseStatus s);
/// True for the statuses without a usable answer (no_contact, out_of_range, not_converged): the
/// cases a run counts as `failed` and exits 1 for. Ok, OutsideValidity and Derailed are answers.
bool is_failure(CaseStatus s);

/// The class of a warning (the text before its first ':'). The table of classes, with whether
/// each puts a row outside validity, is warning_classes() below.
enum class WarningClass : std::uint8_t {
  NonHertzian,
  NonHertzianExcluded,
  Interacting,
  OffProfile,
  FlangeClimb,
  PressureSpike,
  StripOutlier,
  ForceBalance,
  Complementarity,
  UnderResolved,
  ContactHole,
  Auto,
  BeyondEvidence,
  NadalLimit,
  Derailed,
  SmoothingSensitive,
  TangentialUnsupported,
  // Why a grid row is not_converged (patch_driver.hpp, the strip and half-space solvers): one
  // class per exit, each with what was measured at it.
  NotConvergedPlacement,
  NotConvergedSetup,
  NotConvergedLoad,
  NotConvergedActiveSet,
  NotConvergedPlasticSet,
  NotConvergedEndGap,
  NotConvergedCg,
};
/// The class's name as written ("non_hertzian").
const char* to_string(WarningClass c);

/// The warning classes a case can carry, each with whether it puts the row outside its method's
/// validity (docs/status.md; a unit test checks every one is documented there). Every class but
/// the informational `auto`, `flange_climb`, `nadal_limit`, `derailed` and `smoothing_sensitive` does
/// (`derailed` sets its own status, CaseStatus::Derailed). In the order of WarningClass.
struct WarningClassInfo {
  WarningClass cls;
  const char* name;
  bool outside_validity;
  const char* meaning;
};
const std::vector<WarningClassInfo>& warning_classes();
/// Whether a warning of class `c` puts its row outside validity.
bool is_validity_class(WarningClass c);
/// The same by name: a name not in warning_classes() (a check added later) does, so a new check
/// can never leave a row `ok` by omission.
bool is_validity_class(const std::string& name);

/// A measured quantity of a warning. Each has its written name (with its unit, e.g.
/// "edge_gap_mm"), the SI unit of Measure::value and ::limit, and how the text rounds it
/// (warning_text(); byte-identical to the text the solvers built before).
enum class Quantity : std::uint8_t {
  BOverR,               ///< [1] b / min(|R_rxx|, |R_wxx|)           "b_over_R"
  GapError,             ///< [1] hertz_validity.hpp                   "gap_error"
  GapMeanError,         ///< [1]                                      "gap_mean_error"
  SurfaceGapError,      ///< [1]                                      "surface_gap_error"
  SurfaceGapMeanError,  ///< [1]                                      "surface_gap_mean_error"
  GapKink,              ///< [1] E* Δθ / (2π p0) (hertz_validity.hpp) "gap_kink"
  EdgeGap,              ///< [m] lateral gap between two ellipses' edges "edge_gap_mm"
  Residual,             ///< [1] (Σ N cos γ − Q) / Q                  "residual"
  PMin,                 ///< [Pa] lowest element pressure             "p_min_MPa"
  PMax,                 ///< [Pa] highest element pressure, limit p_lim "p_max_MPa"
  GapViolation,         ///< [m] deformed-gap violation               "gap_um"
  EndGapError,          ///< [1] strip end-gap error                  "end_gap_error"
  YRail,                ///< [m] rail y of a spike or hole            "y_rail_mm"
  PSpike,               ///< [Pa] the spike's pressure                "p_MPa"
  PNeighbours,          ///< [Pa] its neighbours' pressure            "neighbours_MPa"
  Elements,             ///< [count] unloaded elements of a hole      "elements"
  Overlap,              ///< [m] the bodies' overlap at the hole      "overlap_um"
  Strips,               ///< [count] outlier strips of a patch        "strips"
  YRailStrip,           ///< [m] rail y of the worst outlier strip    "y_rail_mm"
  QStrip,               ///< [Pa] its peak, min(amplitude, p_lim)     "q_MPa"
  ElementsAcross,       ///< [count] elements across a grid patch      "elements_across"
  PeakChange,           ///< [1] peak change on the last refinement    "peak_change"
  Element,              ///< [m] element size across the patch         "element_mm"
  P0ElOverSigmaY,       ///< [1] elastic Hertz p0 of the load / σ_y (evidence.hpp) "p0_el_over_sigma_y"
  P0ElOverPLim,         ///< [1] elastic Hertz p0 of the load / p_lim (evidence.hpp) "p0_el_over_p_lim"
  YOverQ,               ///< [1] Fy / Fz, the Nadal ratio Y/Q          "Y_over_Q"
  RRoll,                ///< [m] rolling radius at the main contact    "r_roll_mm"
  PmaxBand,             ///< [1] largest |pmax(L/2 or 2L) − pmax(L)| / pmax(L) "pmax_band"
  AreaBand,             ///< [1] the same for the total area           "area_band"
  Placements,           ///< [count] placements of the patches made (the limit max_passes) "placements"
  ApproachChange,       ///< [m] |δz − δz_ref| of the last placement, limit ref_rtol·δz "approach_change_um"
  EdgeReached,          ///< [count] patches whose solution reached their grid's edge "edge_reached"
  Patches,              ///< [count] interpenetration regions found       "patches"
  Passes,               ///< [count] passes of an iteration (the limit it ran to) "passes"
  StripsCapped,         ///< [count] strips newly capped in the plastic set's last pass "strips_capped"
  ExtentsMoved,         ///< [1] Σ|Δa| / Σa of the end-gap extents' last pass "extents_moved"
  CgError,              ///< [1] the CG's convergence measure ε (NormalCGOptions::tol) "cg_error"
  Iterations,           ///< [count] iterations made                      "iterations"
  PlaneTilt,            ///< [rad] |rail slope angle at a grid patch's peak − its plane's γ| (evidence.hpp) "plane_tilt_deg"
  EdgeTilt,             ///< [rad] the same at the patch's first or last loaded row, the larger (evidence.hpp) "edge_tilt_deg"
};
/// The written name ("edge_gap_mm") and the SI unit of value and limit ("1", "m", "Pa", "rad", "count").
const char* name(Quantity q);
const char* si_unit(Quantity q);

/// One measured value of a warning, with the limit it crossed. `rel` is '>' (value above the
/// limit), '<' (below) or 0 (no limit: the value locates or sizes what was found).
struct Measure {
  Quantity q = Quantity::BOverR;
  char rel = 0;
  double value = 0;  ///< [si_unit(q)]
  double limit = 0;  ///< [si_unit(q)]
};

/// What a warning is about: a loaded ellipse (1-based potential-ellipse index), a grid patch
/// (1-based, in increasing rail y), a pair of ellipses (`interacting`), or the case as a whole.
enum class ContactKind : std::uint8_t { None, Ellipse, Patch, EllipsePair };

/// Why `auto` handed a case on (class Auto; docs/methods.md "auto").
enum class AutoReason : std::uint8_t {
  Status,               ///< the multi-Hertzian solve ended with `status`
  NotHertzian,          ///< ellipse `contact` failed the Hertz validity test
  CandidateExcluded,    ///< a non-Hertzian candidate was excluded
  Interact,             ///< ellipses `contact` and `contact2` interact
  GapKink,              ///< ellipse `contact` has a corner of the gap (m[0]: gap_kink)
  StripsFailed,         ///< the strip row carried a warning of class `failed`
  StripsNotConverged,   ///< the strip solve did not converge
  HalfSpaceRejected,    ///< the half-space row ended with `status` (and `failed`, if has_failed)
};

/// One warning of a case, as data. A Hertz validity test can fail several limits of one ellipse:
/// each is one Measure of the same warning (up to kMaxMeasures).
struct Warning {
  static constexpr int kMaxMeasures = 6;
  WarningClass cls = WarningClass::Auto;
  ContactKind kind = ContactKind::None;
  int contact = 0;   ///< 1-based ellipse or patch index (0: the case)
  int contact2 = 0;  ///< the second ellipse of an EllipsePair
  int n = 0;         ///< measures used
  std::array<Measure, kMaxMeasures> m{};
  // Class Auto only: the method the case went to, and why.
  Method to = Method::Strips;
  AutoReason reason = AutoReason::Status;
  CaseStatus status = CaseStatus::Ok;           ///< AutoReason::Status, HalfSpaceRejected
  WarningClass failed = WarningClass::Auto;     ///< AutoReason::StripsFailed, HalfSpaceRejected
  bool has_failed = false;

  Warning() = default;
  Warning(WarningClass c, ContactKind k = ContactKind::None, int i = 0) : cls(c), kind(k), contact(i) {}
  /// Append a measure (ignored beyond kMaxMeasures; the Hertz test has at most six limits).
  Warning& add(Quantity q, double value, char rel = 0, double limit = 0) {
    if (n < kMaxMeasures) m[static_cast<std::size_t>(n++)] = Measure{q, rel, value, limit};
    return *this;
  }
  static Warning auto_to(Method to, AutoReason why) {
    Warning w(WarningClass::Auto);
    w.to = to;
    w.reason = why;
    return w;
  }
};

/// The warning as written in `cases.csv`, `results.json`, messages and the C/Python accessors:
/// "non_hertzian:ellipse=4:b_over_R=22.331>0.3", "interacting:ellipses=1+3:edge_gap_mm=7<8",
/// "auto:strips:ellipse 2 not Hertzian". The one place a warning becomes text.
std::string warning_text(const Warning& w);
/// The same text appended to `s` (a row's cell built in place: no string per warning).
void append_warning_text(std::string& s, const Warning& w);
/// Each of `ws` as text, in order.
std::vector<std::string> warning_texts(const std::vector<Warning>& ws);

/// The distinct validity classes among `warnings`, in order of first appearance.
std::vector<WarningClass> validity_failures(const std::vector<Warning>& warnings);
/// Whether any of `warnings` is of a validity class; the first one's class into *first (no
/// allocation: `auto`'s choice at every row).
bool first_validity_failure(const std::vector<Warning>& warnings, WarningClass* first);
/// Whether any of `warnings` is of class `c`.
bool has_class(const std::vector<Warning>& warnings, WarningClass c);

}  // namespace mh
