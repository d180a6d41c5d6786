#include "contact/judge/status.hpp"

#include <algorithm>
#include <cmath>

#include "core/numfmt.hpp"
#include "core/units.hpp"

namespace mh {

const char* to_string(CaseStatus s) {
  switch (s) {
    case CaseStatus::Ok: return "ok";
    case CaseStatus::OutsideValidity: return "outside_validity";
    case CaseStatus::NoContact: return "no_contact";
    case CaseStatus::OutOfRange: return "out_of_range";
    case CaseStatus::NotConverged: return "not_converged";
    case CaseStatus::Derailed: return "derailed";
  }
  return "?";
}

bool is_failure(CaseStatus s) {
  return s != CaseStatus::Ok && s != CaseStatus::OutsideValidity && s != CaseStatus::Derailed;
}

const std::vector<WarningClassInfo>& warning_classes() {
  using C = WarningClass;
  // docs/status.md lists the same classes; a test checks that every one is documented there.
  static const std::vector<WarningClassInfo> k = {
      {C::NonHertzian, "non_hertzian", true, "a loaded ellipse fails the Hertz validity test (docs/method.md §4)"},
      {C::NonHertzianExcluded, "non_hertzian_excluded", true, "a candidate without a Hertz ellipse would have carried load"},
      {C::Interacting, "interacting", true, "two loaded ellipses closer than d_comb, solved as independent (docs/method.md §9)"},
      {C::OffProfile, "off_profile", true, "a loaded contact on geometry extrapolated beyond a profile's end (docs/method.md §3.7)"},
      // Informational: a geometric state (the flange climbing the rail, a derailment indicator),
      // not a limit of the methods: on the Manchester pair at t_Y 8.5–10 mm the multi-Hertzian
      // peak pressures are within 1.2 % and the areas within 8 % of the half-space method's.
      {C::FlangeClimb, "flange_climb", false, "the main contact has passed the wheel flange's steepest point (docs/method.md §3.7)"},
      {C::PressureSpike, "pressure_spike", true, "a half-space patch whose peak stands on one element (docs/half_space.md)"},
      {C::StripOutlier, "strip_outlier", true, "a strip whose peak stands far above its neighbours' (docs/strips.md)"},
      // The physical checks of a grid result (contact/grid/grid_checks.hpp).
      {C::ForceBalance, "force_balance", true, "a grid result whose patch forces do not balance Q (grid_checks.hpp)"},
      {C::Complementarity, "complementarity", true, "a grid result that violates 0 <= p <= p_lim or the deformed-gap conditions (grid_checks.hpp)"},
      {C::UnderResolved, "under_resolved", true, "a grid patch with fewer elements across than the method's accuracy needs, or whose peak still moved on its last refinement (grid_checks.hpp)"},
      {C::ContactHole, "contact_hole", true, "a grid patch with unloaded elements enclosed by loaded ones where the bodies overlap (grid_checks.hpp)"},
      {C::Auto, "auto", false, "which method auto handed the case to, and why (informational)"},
      {C::BeyondEvidence, "beyond_evidence", true, "a plastic contact loaded beyond the domain the project's tests establish for its method and law (contact/judge/evidence.hpp, docs/trust.md)"},
      // States of the vehicle, not limits of the methods (judge.hpp, docs/status.md).
      {C::NadalLimit, "nadal_limit", false, "the ratio Y/Q of lateral to vertical wheel force exceeds EN 14363's flange-climbing limit 0.8 (informational)"},
      {C::Derailed, "derailed", false, "the wheel rides on its flange tip, off the rail: the row's status is derailed"},
      // A sensitivity, not an error (docs/status.md "smoothing_sensitive" gives the reason it
      // is informational): the row's own answer is at the length chosen from the noise.
      {C::SmoothingSensitive, "smoothing_sensitive", false, "the peak pressure or the area moves by more than the trust table's tolerance when the contact smoothing length is halved or doubled (docs/profiles.md §7; informational)"},
      // Friction given, but the row's method does not solve the tangential problem yet
      // (contact/tangential/tangential_solve.hpp): its creep forces are empty, not 0.
      {C::TangentialUnsupported, "tangential_unsupported", true, "friction given, but the row's tangential problem is not solved (half-space or strips: a patch's exact solve failed or the bodies' elastic constants differ): its creep-force columns are empty (docs/tangential.md)"},
      // What did not converge on a grid row whose status is not_converged (docs/status.md). A
      // validity class, so that a row carrying one is never `ok` (the status says not_converged).
      {C::NotConvergedPlacement, "not_converged_placement", true, "the grid's patches did not settle in their placements: a patch reached its grid's edge (edge_reached) or the approach moved by more than ref_rtol (approach_change_um) at the last placement (patch_driver.hpp)"},
      {C::NotConvergedSetup, "not_converged_setup", true, "a grid patch could not be set up (more elements than the grid allows, or no interpenetration region)"},
      {C::NotConvergedLoad, "not_converged_load", true, "the load was not reached: the patches' forces off Q, or a strip patch's load control that did not close (residual)"},
      {C::NotConvergedActiveSet, "not_converged_active_set", true, "a strip patch's active set (q >= 0) did not settle within max_active_set passes"},
      {C::NotConvergedPlasticSet, "not_converged_plastic_set", true, "a strip patch's plastic set did not settle within max_active_set passes (strips_capped: newly capped in the last pass)"},
      {C::NotConvergedEndGap, "not_converged_end_gap", true, "a strip patch's end-gap extents did not settle (extents_moved: the last pass's relative move)"},
      {C::NotConvergedCg, "not_converged_cg", true, "a half-space patch's CG solve did not reach its tolerance (cg_error)"},
  };
  return k;
}

const char* to_string(WarningClass c) { return warning_classes()[static_cast<std::size_t>(c)].name; }

bool is_validity_class(WarningClass c) { return warning_classes()[static_cast<std::size_t>(c)].outside_validity; }

bool is_validity_class(const std::string& name) {
  for (const WarningClassInfo& c : warning_classes())
    if (name == c.name) return c.outside_validity;
  return true;  // a class not listed (a check added later) never leaves a row ok by omission
}

namespace {

// How a quantity is written: the text's name, the SI unit, and how value and limit are rounded.
// The rounding of each is the one its check used when it built the text itself (kept so that
// tests/ref and tests/cli compare the same bytes).
enum class Fmt : std::uint8_t {
  Round3,        // format_number(round(x·s·1e3)/1e3): three decimals of the scaled value
  Raw,           // format_number(x·s)
  Count,         // an integer
  MilliOfMicro,  // format_number(round(x·1e6)/1e3): metres as mm to the µm
  MegaOfKilo,    // format_number(round(x/1e3)/1e3): pascals as MPa to the kPa
  PLim,          // the word "p_lim"
};
struct QuantityInfo {
  const char* name;
  const char* unit;
  double scale;  // SI → written unit
  Fmt value, limit;
};
const QuantityInfo& info(Quantity q) {
  static const QuantityInfo k[] = {
      {"b_over_R", "1", 1, Fmt::Round3, Fmt::Raw},
      {"gap_error", "1", 1, Fmt::Round3, Fmt::Raw},
      {"gap_mean_error", "1", 1, Fmt::Round3, Fmt::Raw},
      {"surface_gap_error", "1", 1, Fmt::Round3, Fmt::Raw},
      {"surface_gap_mean_error", "1", 1, Fmt::Round3, Fmt::Raw},
      {"gap_kink", "1", 1, Fmt::Round3, Fmt::Raw},
      {"edge_gap_mm", "m", units::per_mm, Fmt::MilliOfMicro, Fmt::Raw},
      {"residual", "1", 1, Fmt::Raw, Fmt::Raw},
      {"p_min_MPa", "Pa", 1e-6, Fmt::Round3, Fmt::Raw},
      {"p_max_MPa", "Pa", 1e-6, Fmt::Round3, Fmt::PLim},
      {"gap_um", "m", 1e6, Fmt::Round3, Fmt::Round3},
      {"end_gap_error", "1", 1, Fmt::Round3, Fmt::Raw},
      {"y_rail_mm", "m", 1e3, Fmt::Round3, Fmt::Raw},
      {"p_MPa", "Pa", 1e-6, Fmt::Round3, Fmt::Raw},
      {"neighbours_MPa", "Pa", 1e-6, Fmt::Round3, Fmt::Raw},
      {"elements", "count", 1, Fmt::Count, Fmt::Count},
      {"overlap_um", "m", 1e6, Fmt::Round3, Fmt::Round3},
      {"strips", "count", 1, Fmt::Count, Fmt::Count},
      {"y_rail_mm", "m", 1e3, Fmt::MilliOfMicro, Fmt::Raw},
      {"q_MPa", "Pa", 1e-6, Fmt::MegaOfKilo, Fmt::Raw},
      {"elements_across", "count", 1, Fmt::Count, Fmt::Count},
      {"peak_change", "1", 1, Fmt::Round3, Fmt::Raw},
      {"element_mm", "m", 1e3, Fmt::Round3, Fmt::Raw},
      {"p0_el_over_sigma_y", "1", 1, Fmt::Round3, Fmt::Raw},
      {"p0_el_over_p_lim", "1", 1, Fmt::Round3, Fmt::Raw},
      {"Y_over_Q", "1", 1, Fmt::Round3, Fmt::Raw},
      {"r_roll_mm", "m", 1e3, Fmt::Round3, Fmt::Round3},
      {"pmax_band", "1", 1, Fmt::Round3, Fmt::Raw},
      {"area_band", "1", 1, Fmt::Round3, Fmt::Raw},
      {"placements", "count", 1, Fmt::Count, Fmt::Count},
      {"approach_change_um", "m", 1e6, Fmt::Round3, Fmt::Round3},
      {"edge_reached", "count", 1, Fmt::Count, Fmt::Count},
      {"patches", "count", 1, Fmt::Count, Fmt::Count},
      {"passes", "count", 1, Fmt::Count, Fmt::Count},
      {"strips_capped", "count", 1, Fmt::Count, Fmt::Count},
      {"extents_moved", "1", 1, Fmt::Raw, Fmt::Raw},
      {"cg_error", "1", 1, Fmt::Raw, Fmt::Raw},
      {"iterations", "count", 1, Fmt::Count, Fmt::Count},
      {"plane_tilt_deg", "rad", 1 / units::deg, Fmt::Round3, Fmt::Round3},
      {"edge_tilt_deg", "rad", 1 / units::deg, Fmt::Round3, Fmt::Round3},
  };
  return k[static_cast<std::size_t>(q)];
}

void append_formatted(std::string& s, double x, const QuantityInfo& q, Fmt f) {
  switch (f) {
    // The scaled value as the checks computed it: x / 1e6 for MPa (not x · 1e-6), x · 1e6 for µm.
    case Fmt::Round3: {
      const double v = q.scale == 1e-6 ? x / 1e6 : x * q.scale;
      append_number(s, std::round(v * 1e3) / 1e3);
      return;
    }
    case Fmt::Raw: append_number(s, x * q.scale); return;
    case Fmt::Count: append_number(s, static_cast<long long>(x)); return;
    case Fmt::MilliOfMicro: append_number(s, std::round(x * 1e6) / 1e3); return;
    case Fmt::MegaOfKilo: append_number(s, std::round(x / 1e3) / 1e3); return;
    case Fmt::PLim: s += "p_lim"; return;
  }
}

}  // namespace

const char* name(Quantity q) { return info(q).name; }
const char* si_unit(Quantity q) { return info(q).unit; }

std::string warning_text(const Warning& w) {
  std::string s;
  append_warning_text(s, w);
  return s;
}

void append_warning_text(std::string& s, const Warning& w) {
  s += to_string(w.cls);
  if (w.cls == WarningClass::Auto) {
    s += ':';
    s += to_string(w.to);
    s += ':';
    auto ellipse = [&](int e) { s += "ellipse "; append_number(s, static_cast<long long>(e)); };
    switch (w.reason) {
      case AutoReason::Status: s += to_string(w.status); break;
      case AutoReason::NotHertzian: ellipse(w.contact); s += " not Hertzian"; break;
      case AutoReason::CandidateExcluded: s += "non-Hertzian candidate excluded"; break;
      case AutoReason::Interact:
        s += "ellipses ";
        append_number(s, static_cast<long long>(w.contact));
        s += " and ";
        append_number(s, static_cast<long long>(w.contact2));
        s += " interact";
        break;
      case AutoReason::GapKink: ellipse(w.contact); s += ' '; break;  // the measure follows
      case AutoReason::StripsFailed: s += "strips failed "; s += to_string(w.failed); break;
      case AutoReason::StripsNotConverged: s += "strips not converged"; break;
      case AutoReason::HalfSpaceRejected:
        s += "rejected:";
        s += to_string(w.status);
        if (w.has_failed) { s += ':'; s += to_string(w.failed); }
        break;
    }
    if (w.reason != AutoReason::GapKink) return;
  } else {
    switch (w.kind) {
      case ContactKind::None: break;
      case ContactKind::Ellipse: s += ":ellipse="; append_number(s, static_cast<long long>(w.contact)); break;
      case ContactKind::Patch: s += ":patch="; append_number(s, static_cast<long long>(w.contact)); break;
      case ContactKind::EllipsePair:
        s += ":ellipses=";
        append_number(s, static_cast<long long>(w.contact));
        s += '+';
        append_number(s, static_cast<long long>(w.contact2));
        break;
    }
  }
  for (int i = 0; i < w.n; ++i) {
    const Measure& m = w.m[static_cast<std::size_t>(i)];
    const QuantityInfo& q = info(m.q);
    if (i > 0 || w.cls != WarningClass::Auto) s += ':';
    s += q.name;
    s += '=';
    append_formatted(s, m.value, q, q.value);
    if (m.rel) {
      s += m.rel;
      append_formatted(s, m.limit, q, q.limit);
    }
  }
}

std::vector<std::string> warning_texts(const std::vector<Warning>& ws) {
  std::vector<std::string> t;
  t.reserve(ws.size());
  for (const Warning& w : ws) t.push_back(warning_text(w));
  return t;
}

std::vector<WarningClass> validity_failures(const std::vector<Warning>& warnings) {
  std::vector<WarningClass> classes;
  for (const Warning& w : warnings)
    if (is_validity_class(w.cls) && std::find(classes.begin(), classes.end(), w.cls) == classes.end())
      classes.push_back(w.cls);
  return classes;
}

bool first_validity_failure(const std::vector<Warning>& warnings, WarningClass* first) {
  for (const Warning& w : warnings)
    if (is_validity_class(w.cls)) {
      *first = w.cls;
      return true;
    }
  return false;
}

bool has_class(const std::vector<Warning>& warnings, WarningClass c) {
  return std::any_of(warnings.begin(), warnings.end(), [c](const Warning& w) { return w.cls == c; });
}

}  // namespace mh
