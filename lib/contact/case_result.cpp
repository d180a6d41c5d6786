#include "contact/case_result.hpp"

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
  }
  return "?";
}

bool is_failure(CaseStatus s) { return s != CaseStatus::Ok && s != CaseStatus::OutsideValidity; }

std::string warning_class(const std::string& warning) { return warning.substr(0, warning.find(':')); }

const std::vector<WarningClassInfo>& warning_classes() {
  // docs/status.md lists the same classes; a test checks that every one is documented there.
  static const std::vector<WarningClassInfo> k = {
      {"non_hertzian", true, "a loaded ellipse fails the Hertz validity test (docs/method.md §4)"},
      {"non_hertzian_excluded", true, "a candidate without a Hertz ellipse would have carried load"},
      {"interacting", true, "two loaded ellipses closer than d_comb, solved as independent (docs/method.md §9)"},
      {"off_profile", true, "a loaded contact on geometry extrapolated beyond a profile's end (docs/method.md §3.7)"},
      // Informational: a geometric state (the flange climbing the rail, a derailment indicator),
      // not a limit of the methods: on the Manchester pair at t_Y 8.5–10 mm the multi-Hertzian
      // peak pressures are within 1.2 % and the areas within 8 % of the half-space method's.
      {"flange_climb", false, "the main contact has passed the wheel flange's steepest point (docs/method.md §3.7)"},
      {"pressure_spike", true, "a half-space patch whose peak stands on one element (docs/half_space.md)"},
      {"strip_outlier", true, "a strip whose peak stands far above its neighbours' (docs/strips.md)"},
      // The physical checks of a grid result (contact/grid/grid_checks.hpp).
      {"force_balance", true, "a grid result whose patch forces do not balance Q (grid_checks.hpp)"},
      {"complementarity", true, "a grid result that violates 0 <= p <= p_lim or the deformed-gap conditions (grid_checks.hpp)"},
      {"under_resolved", true, "a grid patch with fewer elements across than the method's accuracy needs (grid_checks.hpp)"},
      {"contact_hole", true, "a grid patch with unloaded elements enclosed by loaded ones where the bodies overlap (grid_checks.hpp)"},
      {"auto", false, "which method auto handed the case to, and why (informational)"},
  };
  return k;
}

bool is_validity_class(const std::string& cls) {
  for (const WarningClassInfo& c : warning_classes())
    if (cls == c.name) return c.outside_validity;
  return true;  // a class not listed (a check added later) never leaves a row ok by omission
}

std::vector<std::string> validity_failures(const std::vector<std::string>& warnings) {
  std::vector<std::string> classes;
  for (const std::string& w : warnings) {
    std::string c = warning_class(w);
    if (is_validity_class(c) && std::find(classes.begin(), classes.end(), c) == classes.end())
      classes.push_back(std::move(c));
  }
  return classes;
}

EllipseInteraction interacting_ellipses(const CaseResult& r, double d_comb) {
  EllipseInteraction e;
  for (std::size_t i = 0; i < r.loaded.size(); ++i)
    for (std::size_t j = i + 1; j < r.loaded.size(); ++j) {
      const LoadedEllipse &A = r.loaded[i], &B = r.loaded[j];
      // Lateral gap between the patches' edges on the rail: the distance of the contact points
      // less each half-width b projected on the rail's y.
      const double edge_gap = std::fabs(A.g.y_r - B.g.y_r) - A.s.b * std::cos(A.g.gamma) - B.s.b * std::cos(B.g.gamma);
      if (edge_gap < d_comb) return {true, A.ellipse, B.ellipse, edge_gap};
    }
  return e;
}

void judge_validity(CaseResult& r, double d_comb) {
  if (r.method == Method::MultiHertzian) {
    const EllipseInteraction e = interacting_ellipses(r, d_comb);
    if (e.found)
      r.warnings.push_back("interacting:ellipses=" + std::to_string(e.first) + "+" + std::to_string(e.second) +
                           ":edge_gap_mm=" + format_number(std::round(e.edge_gap * 1e6) / 1e3) + "<" +
                           format_number(d_comb * units::per_mm));
  }
  if (r.status != CaseStatus::Ok) return;
  const std::vector<std::string> classes = validity_failures(r.warnings);
  if (classes.empty()) return;
  r.status = CaseStatus::OutsideValidity;
  r.message = "outside the validity of the method: ";
  for (std::size_t i = 0; i < classes.size(); ++i) r.message += (i ? ", " : "") + classes[i];
  r.message += " (see warnings)";
}

}  // namespace mh
