#include "contact/multi_hertz/approach_given.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/numfmt.hpp"
#include "core/units.hpp"

namespace mh {

double normal_stiffness(const LoadedEllipse& L) {
  if (!(L.s.h0 > 0)) return 0;
  return L.s.dN_dh0;  // dN/dh0 of the ellipse law (eq. 8, method.md §5, §5.1)
}

void solve_multi_hertz_approach(const ContactGeometry& G, const Material& mat, double tY, double dz,
                                const MultiHertzOptions& opt, ApproachWorkspace& ws, CaseResult& r) {
  r.status = CaseStatus::Ok;
  r.method = Method::MultiHertzian;
  r.message.clear();
  r.warnings.clear();
  r.loaded.clear();
  r.patches.clear();
  r.dz = dz;
  r.approach = 0;
  r.iterations = 0;
  r.residual = 0;
  r.Fz = r.Fy = r.pmax = r.area = 0;
  r.n_contacts = 0;
  if (!std::isfinite(dz)) {
    r.status = CaseStatus::NoContact;
    r.message = "the approach dz must be finite";
    return;
  }
  if (!G.covers(tY)) {  // the wording of solve_multi_hertz
    r.status = CaseStatus::OutOfRange;
    r.message = "t_Y = " + format_number(tY * 1e3) + " mm outside the geometry table [" +
                format_number(G.tY.front() * 1e3) + ", " + format_number(G.tY.back() * 1e3) + "] mm";
    return;
  }
  const std::size_t ne = G.n_ellipses();
  ws.geo.resize(ne);
  int main = 0;
  G.candidates_at(tY, opt.roll, ws.geo.data(), &main);
  for (std::size_t e = 0; e < ne; ++e) {
    const CandidateGeom& g = ws.geo[e];
    const double h = (dz - g.gap) * std::cos(g.gamma);  // (eq. 11)
    if (!(h > 0)) continue;
    // A, B, the Hertzian test, the law and the loaded ellipse exactly as solve_multi_hertz
    // builds them (the same helpers: same bits).
    double A = 0, B = 0;
    const bool hertzian = candidate_sums(g, &A, &B);
    const EllipseLaw law = hertzian ? make_ellipse_law(A, B, mat, opt.exact_coefficients) : EllipseLaw{};
    add_loaded_candidate(G, static_cast<int>(e) + 1, g, A, B, hertzian ? &law : nullptr, h, std::cos(g.gamma),
                         std::sin(g.gamma), opt, r);
  }
  r.n_contacts = static_cast<int>(r.loaded.size());
  if (r.loaded.empty() && !r.warnings.empty()) {
    // Candidates are pressed in, each conformal (non_hertzian_excluded): the wheel touches the
    // rail, and this method has no answer; not a wheel in the air (as solve_multi_hertz).
    r.status = CaseStatus::NotConverged;
    r.message = "the approach dz = " + format_number(dz * 1e3) + " mm presses only candidates without a Hertz ellipse "
                "(B <= 0, a conformal contact): the multi-Hertzian method cannot solve it, no force computed";
  } else if (r.loaded.empty()) {
    r.status = CaseStatus::NoContact;
    r.message = "no contact: the approach dz = " + format_number(dz * 1e3) + " mm loads no Hertzian candidate";
  }
  if (ne > 0 && ws.geo[static_cast<std::size_t>(main)].flange_climb)
    r.warnings.emplace_back(WarningClass::FlangeClimb, ContactKind::Ellipse, main + 1);
}

}  // namespace mh
