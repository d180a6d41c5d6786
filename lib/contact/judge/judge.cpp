#include "contact/judge/judge.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "contact/ellipse/hertz_validity.hpp"
#include "contact/judge/evidence.hpp"
#include "core/units.hpp"
#include "geometry/gap.hpp"

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

PlanarTilt planar_tilt(const PatchResult& P, const ContactGeometry& G) {
  PlanarTilt t;
  const ProfileCurve* rail = G.rail_gap_curve ? G.rail_gap_curve.get() : G.rail_curve.get();
  if (!rail || !std::isfinite(P.y_peak)) return t;
  auto at = [&](double y) {  // the angle between two lines: folded into [0, 90°]
    double dz = 0;
    rail->z(y, &dz);
    const double d = std::fmod(std::fabs(std::atan(dz) - P.gamma), M_PI);
    return d > 0.5 * M_PI ? M_PI - d : d;
  };
  t.peak = at(P.y_peak);
  const double c = std::cos(P.gamma);  // rail y ≈ y_r + s cos γ
  t.edge = std::max(at(P.y_r + P.s_lo * c), at(P.y_r + P.s_hi * c));
  return t;
}

namespace {

// A grid patch whose plane is tilted against the rail beyond what the planar approach's evidence
// covers (evidence.hpp), at its peak or at an edge: beyond_evidence with the tilts' magnitudes
// (either side of the plane, as the bounds).
void add_plane_tilt_warnings(CaseResult& r, const ContactGeometry& G) {
  const double bound = planar_evidence_domain(Quantity::PlaneTilt).bound * units::deg;
  const double edge_bound = planar_evidence_domain(Quantity::EdgeTilt).bound * units::deg;
  for (const PatchResult& P : r.patches) {
    const PlanarTilt t = planar_tilt(P, G);
    Warning w(WarningClass::BeyondEvidence, ContactKind::Patch, P.patch);
    if (t.peak > bound) w.add(Quantity::PlaneTilt, t.peak, '>', bound);
    if (t.edge > edge_bound) w.add(Quantity::EdgeTilt, t.edge, '>', edge_bound);
    if (w.n > 0) r.warnings.push_back(w);
  }
}

void add_interaction_warning(CaseResult& r, double d_comb) {
  if (r.method != Method::MultiHertzian) return;
  const EllipseInteraction e = interacting_ellipses(r, d_comb);
  if (!e.found) return;
  Warning w(WarningClass::Interacting, ContactKind::EllipsePair, e.first);
  w.contact2 = e.second;
  r.warnings.push_back(w.add(Quantity::EdgeGap, e.edge_gap, '<', d_comb));
}

}  // namespace

void add_validity_warnings(CaseResult& r, const ContactGeometry& G, const Material& mat, double tY,
                           const MethodOptions& opt) {
  // Every method: a plastic contact loaded beyond the domain its tests cover (evidence.hpp).
  add_evidence_warnings(r, mat);
  // Friction given, the tangential problem not solved (strips; a half-space patch whose exact
  // solve failed: docs/status.md).
  if (r.tangential.asked && !r.tangential.solved && r.method != Method::MultiHertzian)
    r.warnings.push_back(Warning(WarningClass::TangentialUnsupported));
  if (r.method != Method::MultiHertzian) {
    add_plane_tilt_warnings(r, G);
    return;
  }
  add_interaction_warning(r, opt.strips.d_comb);
  if (r.status != CaseStatus::Ok || r.loaded.empty()) return;
  // The gap-corner test only where every other Hertz test passed: it samples the gap across
  // each patch (~165 gap evaluations per ellipse), the costliest of the tests, and a row that
  // failed another is outside validity already.
  for (const Warning& w : r.warnings)
    if (w.cls == WarningClass::NonHertzian || w.cls == WarningClass::NonHertzianExcluded ||
        w.cls == WarningClass::Interacting)
      return;
  const HertzValidityOptions& vo = opt.multi_hertzian.validity;
  // The first contact lies at the loaded candidate of least gap (0 at the main one).
  const LoadedEllipse* first = &r.loaded.front();
  for (const LoadedEllipse& L : r.loaded)
    if (L.g.gap < first->g.gap) first = &L;
  // The gap is that of t_Y and the first contact's candidate only, not of the load: kept per
  // thread for the next case with the same three (a sweep's cases at one t_Y, every Q).
  struct GapCache {
    std::uint64_t id = 0;
    const ProfileCurve *w = nullptr, *r = nullptr;
    double tY = 0, y = 0;
    std::optional<WheelRailGap> gap;
  };
  thread_local GapCache cache;
  const ProfileCurve* wc = G.wheel_gap_curve ? G.wheel_gap_curve.get() : G.wheel_curve.get();
  const ProfileCurve* rc = G.rail_gap_curve ? G.rail_gap_curve.get() : G.rail_curve.get();
  if (!cache.gap || G.build_id == 0 || cache.id != G.build_id || cache.w != wc || cache.r != rc || cache.tY != tY ||
      cache.y != first->g.y_r) {
    cache.gap.emplace(G, tY, first->g.y_r);
    cache.id = G.build_id;
    cache.w = wc;
    cache.r = rc;
    cache.tY = tY;
    cache.y = first->g.y_r;
  }
  const WheelRailGap& gap = *cache.gap;
  for (const LoadedEllipse& L : r.loaded) {
    const GapKink k = gap_kink(gap, L.g, L.B, L.s.b, L.s.p0, 0.5 * mat.E_star(), r.approach, vo);
    if (k.valid) continue;
    Warning w(WarningClass::NonHertzian, ContactKind::Ellipse, L.ellipse);
    k.add_to(w, vo);
    r.warnings.push_back(w);
  }
}

double y_over_q(const CaseResult& r) {
  if (!(r.Fz > 0)) return NAN;
  // With friction the lateral force Y includes the creep forces' lateral component (docs/tangential.md).
  return r.tangential.solved ? (r.Fy + r.tangential.Fy_creep) / r.Fz : r.Fy / r.Fz;
}

void add_vehicle_state_warnings(CaseResult& r, const ContactGeometry& G, const VehicleStateLimits& lim) {
  if (is_failure(r.status)) return;
  const double yq = y_over_q(r);
  if (yq > lim.nadal) r.warnings.push_back(Warning(WarningClass::NadalLimit).add(Quantity::YOverQ, yq, '>', lim.nadal));
  if (!G.has_flange) return;
  // The main contact: the loaded ellipse or grid patch carrying the largest normal force (as the
  // r_roll_main_mm column).
  double N = -1, y_w = 0, r_roll = 0;
  int contact = 0;
  ContactKind kind = ContactKind::None;
  for (const LoadedEllipse& L : r.loaded)
    if (L.s.N > N) { N = L.s.N; y_w = L.g.y_w; r_roll = L.g.r_roll; contact = L.ellipse; kind = ContactKind::Ellipse; }
  for (const PatchResult& P : r.patches)
    if (P.N > N) { N = P.N; y_w = P.y_w; r_roll = P.r_roll; contact = P.patch; kind = ContactKind::Patch; }
  if (kind == ContactKind::None || !(y_w < G.flange_y_steepest)) return;
  const double r_lim = G.flange_r_tip - lim.derail_margin;
  if (r_roll >= r_lim) r.warnings.push_back(Warning(WarningClass::Derailed, kind, contact).add(Quantity::RRoll, r_roll, '>', r_lim));
}

void decide_status(CaseResult& r) {
  if (r.status != CaseStatus::Ok && r.status != CaseStatus::OutsideValidity) return;
  // The distinct validity classes in order of first appearance (validity_failures()), on the
  // stack and the message appended in place: a time-stepping caller's result, its message's
  // capacity grown, allocates nothing here (tests/alloc: the wheelset call).
  std::array<WarningClass, 64> classes{};
  std::size_t n = 0;
  for (const Warning& w : r.warnings)
    if (is_validity_class(w.cls) && n < classes.size() &&
        std::find(classes.begin(), classes.begin() + static_cast<std::ptrdiff_t>(n), w.cls) ==
            classes.begin() + static_cast<std::ptrdiff_t>(n))
      classes[n++] = w.cls;
  if (r.status == CaseStatus::Ok && n > 0) {
    r.status = CaseStatus::OutsideValidity;
    r.message = "outside the validity of the method: ";
    for (std::size_t i = 0; i < n; ++i) {
      if (i) r.message += ", ";
      r.message += to_string(classes[i]);
    }
    r.message += " (see warnings)";
  }
  if (has_class(r.warnings, WarningClass::Derailed)) {
    r.status = CaseStatus::Derailed;
    r.message = "the wheel rides on its flange tip, off the rail (see warnings)" +
                (n == 0 ? std::string() : "; " + r.message);
  }
}

void judge_smoothing_band(CaseResult& r, const CaseResult& half, const CaseResult& twice, const SmoothingBandLimits& lim) {
  auto answer = [](const CaseResult& c, double v) { return is_failure(c.status) ? NAN : v; };
  r.pmax_half_L = answer(half, half.pmax);
  r.area_half_L = answer(half, half.area);
  r.pmax_double_L = answer(twice, twice.pmax);
  r.area_double_L = answer(twice, twice.area);
  if (is_failure(r.status)) return;
  // The largest relative move of x away from the row's own x0 (NaN values take no part).
  auto band = [](double x0, double a, double b) {
    double m = 0;
    for (double x : {a, b})
      if (std::isfinite(x) && x0 > 0) m = std::max(m, std::fabs(x - x0) / x0);
    return m;
  };
  const double dp = band(r.pmax, r.pmax_half_L, r.pmax_double_L), da = band(r.area, r.area_half_L, r.area_double_L);
  if (!(dp > lim.pmax) && !(da > lim.area)) return;
  Warning w(WarningClass::SmoothingSensitive);
  if (dp > lim.pmax) w.add(Quantity::PmaxBand, dp, '>', lim.pmax);
  if (da > lim.area) w.add(Quantity::AreaBand, da, '>', lim.area);
  r.warnings.push_back(w);
}

void judge_case(CaseResult& r, const ContactGeometry& G, const Material& mat, double tY, const MethodOptions& opt) {
  add_validity_warnings(r, G, mat, tY, opt);
  add_vehicle_state_warnings(r, G);
  decide_status(r);
}

void judge_validity(CaseResult& r, double d_comb) {
  add_interaction_warning(r, d_comb);
  decide_status(r);
}

}  // namespace mh
