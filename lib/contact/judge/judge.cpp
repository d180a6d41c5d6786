#include "contact/judge/judge.hpp"

#include <cmath>

namespace mh {

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
    if (e.found) {
      Warning w(WarningClass::Interacting, ContactKind::EllipsePair, e.first);
      w.contact2 = e.second;
      r.warnings.push_back(w.add(Quantity::EdgeGap, e.edge_gap, '<', d_comb));
    }
  }
  if (r.status != CaseStatus::Ok) return;
  const std::vector<WarningClass> classes = validity_failures(r.warnings);
  if (classes.empty()) return;
  r.status = CaseStatus::OutsideValidity;
  r.message = "outside the validity of the method: ";
  for (std::size_t i = 0; i < classes.size(); ++i) r.message += std::string(i ? ", " : "") + to_string(classes[i]);
  r.message += " (see warnings)";
}

}  // namespace mh
