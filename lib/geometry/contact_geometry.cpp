#include "geometry/contact_geometry.hpp"

#include "geometry/gap_minimum.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "geometry/placement_check.hpp"

namespace mh {

double CandidateGeom::R_wyy() const { return r_roll / std::cos(gamma); }
double CandidateGeom::k_ryy() const { return r_roller > 0 ? std::cos(gamma) / r_roller : 0.0; }

bool GeometryOptions::valid(std::string* why) const {
  auto fail = [&](const std::string& s) { if (why) *why = s; return false; };
  if (!(tY_step > 0)) return fail("tY_step_mm must be > 0");
  if (!(tY_max >= tY_min)) return fail("tY_max_mm must be >= tY_min_mm");
  if ((tY_max - tY_min) / tY_step > 2e6) return fail("the t_Y grid would have more than 2,000,000 points");
  if (!(strip_width > 0) || strip_width > 5e-3) return fail("strip_width_mm must be in (0, 5]");
  if (!(jump_threshold > 0)) return fail("jump_threshold_deg must be > 0");
  if (!(jump_distance >= 0)) return fail("jump_distance_mm must be >= 0");
  if (!(min_ellipse_width >= 0) || min_ellipse_width > 5e-3) return fail("min_ellipse_width_mm must be in [0, 5]");
  if (contact_smoothing && (!(*contact_smoothing >= 0) || *contact_smoothing > 20e-3))
    return fail("smoothing_mm must be \"auto\" or in [0, 20]");
  if (!(auto_smoothing.L_min > 0) || !(auto_smoothing.L_max >= auto_smoothing.L_min))
    return fail("the automatic smoothing length's bounds must satisfy 0 < L_min <= L_max");
  return true;
}

namespace {

// Minimise the gap g(y) = z_w(y − s) − z_r(y) on [a, b] around a discrete minimum
// (gap_minimum.hpp: the roots of g'(y) = z_w'(y − s) − z_r'(y) from negative to positive, each by
// bisection to 0.1 pm); without such a root the lower end is taken.
double refine_minimum(const ProfileCurve& W, const ProfileCurve& R, double s, double a, double b) {
  auto d = [&](double y) {
    double dw, dr;
    W.z(y - s, &dw);
    R.z(y, &dr);
    return dw - dr;
  };
  auto g = [&](double y) { return W.z(y - s) - R.z(y); };
  double best_y = g(a) <= g(b) ? a : b, best_g = std::min(g(a), g(b));
  lowest_gap_minimum(d, g, a, b, GapMinimumScan{}, best_y, best_g);
  return best_y;
}

}  // namespace

ContactGeometry::MainPoint ContactGeometry::locate_main(double t) const {
  const ProfileCurve& W = *wheel_curve;
  const ProfileCurve& R = *rail_curve;
  const std::size_t ns = strip_y.size();
  const double s = y_offset + t;
  double best = std::numeric_limits<double>::infinity();
  std::size_t jb = ns;
  for (std::size_t j = 0; j < ns; ++j) {
    const double yw = strip_y[j] - s;
    if (!W.contains(yw)) continue;
    const double g = W.z(yw) - strip_zr[j];
    if (g < best) { best = g; jb = j; }
  }
  if (jb == ns) return MainPoint{0, 0, ns, false};
  const double a = strip_y[jb > 2 ? jb - 3 : 0], b = strip_y[std::min(jb + 3, ns - 1)];
  const double yc = refine_minimum(W, R, s, std::max(a, W.y_min() + s), std::min(b, W.y_max() + s));
  return MainPoint{yc, W.z(yc - s) - R.z(yc), jb, true};
}

void ContactGeometry::fill_candidate(double t, double y_r, bool is_main, double gmin, CandidateGeom& c) const {
  const ProfileCurve& W = *wheel_curve;
  const ProfileCurve& R = *rail_curve;
  c.y_r = y_r;
  c.y_w = y_r - (y_offset + t);
  double dzr;
  const double z_r = R.z(c.y_r, &dzr);
  c.gamma = std::atan(dzr);
  c.k_rxx = -R.kappa(c.y_r);
  c.k_wxx = W.kappa(c.y_w);
  const double z_w = W.z(c.y_w);
  c.sep = z_w - z_r;
  c.gap = is_main ? 0.0 : std::max(0.0, c.sep - gmin);
  c.r_roll = nominal_radius - (z_w - wheel_z0);
  c.r_roller = roller_radius > 0 ? roller_radius + z_r : 0.0;  // z_r: height above the rail origin
  c.off_profile = off_profile(t, y_r);
  c.flange_climb = has_flange && c.y_w < flange_y_steepest;
}

bool ContactGeometry::off_profile(double t, double y_r) const {
  const ProfileCurve& W = *wheel_curve;
  const double y_w = y_r - (y_offset + t);
  return y_w < W.y_min() + strip_width || y_w > W.y_max() - strip_width ||
         y_r < strip_y.front() + 0.5 * strip_width || y_r > strip_y.back() - 0.5 * strip_width;
}

bool ContactGeometry::off_profile_at(double t, double y_r, double z, double roll) const {
  const ProfileCurve& W = *wheel_curve;
  double y_w = y_r - (y_offset + t);
  if (roll != 0.0) {
    // The rolled wheel's point facing y_r, in the wheel profile's own coordinate (method.md §3.8).
    double z_w;
    rolled_wheel_at(t, roll, y_r, &y_w, &z_w);
  }
  const bool wheel_end = y_w < W.y_min() + strip_width || y_w > W.y_max() - strip_width;
  if (!has_rail_face() || !(y_r < strip_y.front() + 0.5 * strip_width))
    return wheel_end || y_r < strip_y.front() + 0.5 * strip_width || y_r > strip_y.back() - 0.5 * strip_width;
  return wheel_end || z < rail_face_foot + strip_width;
}

bool ContactGeometry::exact_candidates_at(double t, CandidateGeom* out, int* main) const {
  const std::size_t ne = ellipses.size();
  const std::size_t m = std::min(static_cast<std::size_t>(std::upper_bound(jumps.begin(), jumps.end(), t) - jumps.begin()), ne - 1);
  const MainPoint M = locate_main(t);
  if (!M.found) return false;
  for (std::size_t e = 0; e < ne; ++e)
    fill_candidate(t, e == m ? M.y_r : e > m ? ellipses[e].y_r_below : ellipses[e].y_r_above, e == m, M.gmin, out[e]);
  if (main) *main = static_cast<int>(m);
  return true;
}

void ContactGeometry::candidates_at(double t, CandidateGeom* out, int* main) const {
  const std::size_t n = tY.size(), ne = ellipses.size();
  const double step = n > 1 ? (tY.back() - tY.front()) / static_cast<double>(n - 1) : 1.0;
  double s = n > 1 ? (t - tY.front()) / step : 0.0;
  s = std::clamp(s, 0.0, static_cast<double>(n - 1));
  std::size_t k = std::min(static_cast<std::size_t>(s), n > 1 ? n - 2 : 0);
  const double f = n > 1 ? s - static_cast<double>(k) : 0.0;
  const std::size_t k1 = n > 1 ? k + 1 : k;
  // A grid interval that holds a jump: the main candidate moves fast and its curvatures change
  // just before a jump, so interpolating across the interval would make the load sharing depend
  // on the grid step. There the candidates are evaluated at t itself from the profiles (cached
  // per thread for the cases that share a t_Y).
  if (f > 0 && k1 > k && wheel_curve && rail_curve && !strip_y.empty()) {
    const auto j = std::upper_bound(jumps.begin(), jumps.end(), tY[k]);
    if (j != jumps.end() && *j < tY[k1]) {
      struct Cache { std::uint64_t id = 0; bool ok = false; double t = 0; int main = 0; std::vector<CandidateGeom> c; };
      thread_local Cache cache;
      if (build_id == 0 || cache.id != build_id || cache.t != t || cache.c.size() != ne) {
        cache.c.assign(ne, CandidateGeom{});
        cache.ok = exact_candidates_at(t, cache.c.data(), &cache.main);
        cache.id = build_id;
        cache.t = t;
      }
      if (cache.ok) {
        std::copy(cache.c.begin(), cache.c.end(), out);
        if (main) *main = cache.main;
        return;
      }
    }
  }
  for (std::size_t e = 0; e < ne; ++e) {
    const CandidateGeom& a = table[k * ne + e];
    const CandidateGeom& b = table[k1 * ne + e];
    CandidateGeom& c = out[e];
    c.sep = a.sep + f * (b.sep - a.sep);
    c.y_r = a.y_r + f * (b.y_r - a.y_r);
    c.y_w = a.y_w + f * (b.y_w - a.y_w);
    c.gamma = a.gamma + f * (b.gamma - a.gamma);
    c.k_rxx = a.k_rxx + f * (b.k_rxx - a.k_rxx);
    c.k_wxx = a.k_wxx + f * (b.k_wxx - a.k_wxx);
    c.r_roll = a.r_roll + f * (b.r_roll - a.r_roll);
    c.r_roller = a.r_roller + f * (b.r_roller - a.r_roller);
    c.off_profile = (f < 1 && a.off_profile) || (f > 0 && b.off_profile);
    c.flange_climb = (f < 1 && a.flange_climb) || (f > 0 && b.flange_climb);
  }
  // The main candidate: the smallest separation; on a tie, the ellipse whose interval between
  // the (bisected) jumps holds t. Its gap is 0, the others' the difference of separations.
  std::size_t m = static_cast<std::size_t>(std::upper_bound(jumps.begin(), jumps.end(), t) - jumps.begin());
  m = std::min(m, ne - 1);
  for (std::size_t e = 0; e < ne; ++e)
    if (out[e].sep < out[m].sep) m = e;
  for (std::size_t e = 0; e < ne; ++e) out[e].gap = e == m ? 0.0 : std::max(0.0, out[e].sep - out[m].sep);
  if (main) *main = static_cast<int>(m);
}

bool smoothed_for_contact(const ContactGeometry& G) {
  return (G.wheel_gap_curve && G.wheel_gap_curve != G.wheel_curve) || (G.rail_gap_curve && G.rail_gap_curve != G.rail_curve);
}

ContactGeometry build_band_geometry(const Profile& wheel, const Profile& rail, const TrackSetup& track,
                                    const GeometryOptions& opt, double scale, bool window) {
  GeometryOptions o = opt;
  o.auto_smoothing.length_scale = opt.auto_smoothing.length_scale * scale;
  // The multi-Hertzian tables' smoothing of a measured profile is the wide window fit (where it
  // is in use at all: wider than the narrow one).
  if (window && opt.curve.measured_window_half_width > opt.curve.window_half_width)
    o.curve.measured_window_half_width = opt.curve.measured_window_half_width * scale;
  return build_geometry(wheel, rail, track, o);
}

void set_band_geometries(PairGeometry& pg, const TrackSetup& track, const GeometryOptions& opt, bool grid_rows,
                         bool ellipse_rows) {
  pg.band = BandGeometries{};
  if (!smoothed_for_contact(pg.geo)) return;
  auto make = [&](double scale, bool window) {
    return std::make_shared<const ContactGeometry>(build_band_geometry(pg.wheel, pg.rail, track, opt, scale, window));
  };
  if (grid_rows) pg.band.half = make(0.5, false), pg.band.twice = make(2.0, false);
  if (ellipse_rows) pg.band.window_half = make(0.5, true), pg.band.window_twice = make(2.0, true);
}

ContactGeometry build_geometry(const Profile& wheel, const Profile& rail, const TrackSetup& track,
                               const GeometryOptions& opt) {
  std::string why;
  if (!opt.valid(&why)) throw InputError("geometry options", "", why);
  ContactGeometry G;
  static std::atomic<std::uint64_t> next_build_id{1};
  G.build_id = next_build_id++;
  CurveOptions cw = opt.curve, cr = opt.curve;
  cw.noise = opt.wheel_noise;
  cr.noise = opt.rail_noise;
  G.wheel_curve = std::make_shared<const ProfileCurve>(wheel, cw);
  G.rail_curve = std::make_shared<const ProfileCurve>(rail, cr);
  // Smoothing for contact (profiles.md §7): measured profiles only, by the length given or, by
  // default, by the length that removes the profile's own noise.
  auto gap_curve = [&](const Profile& p, const std::shared_ptr<const ProfileCurve>& c) {
    const std::optional<SmoothedProfile> sp = smooth_for_contact(p, c->noise(), opt.contact_smoothing, opt.auto_smoothing);
    return sp ? std::make_shared<const ProfileCurve>(*sp, opt.curve.grid_step, c->noise()) : c;
  };
  G.wheel_gap_curve = gap_curve(wheel, G.wheel_curve);
  G.rail_gap_curve = gap_curve(rail, G.rail_curve);
  if (!rail.face_z.empty()) {
    for (std::size_t i = 0; i < rail.face_z.size(); ++i)
      if (rail.face_y[i] != rail.y.front() || !(rail.face_z[i] < (i ? rail.face_z[i - 1] : rail.z.front())))
        throw std::logic_error("build_geometry: the rail's gauge face is not vertical and downwards from its first point");
    G.rail_face_foot = rail.face_z.back();
  }
  const ProfileCurve& W = *G.wheel_curve;
  const ProfileCurve& R = *G.rail_curve;
  G.wheel_window = W.window_used();
  G.rail_window = R.window_used();
  // Curvature samples for the Hertz validity test (signs as in CandidateGeom), of the curves and,
  // when a profile is smoothed for contact, of the contact surface.
  {
    auto samples = [&](const ProfileCurve& C, double sign) {
      std::vector<double> k;
      for (double y = C.y_min(); y <= C.y_max() + 1e-12; y += G.kappa_dy) k.push_back(sign * C.kappa(std::min(y, C.y_max())));
      return CurvatureSamples(C.y_min(), G.kappa_dy, std::move(k));
    };
    G.rail_k = samples(R, -1);
    G.wheel_k = samples(W, 1);
    if (G.rail_gap_curve != G.rail_curve || G.wheel_gap_curve != G.wheel_curve) {
      G.rail_gap_k = G.rail_gap_curve == G.rail_curve ? G.rail_k : samples(*G.rail_gap_curve, -1);
      G.wheel_gap_k = G.wheel_gap_curve == G.wheel_curve ? G.wheel_k : samples(*G.wheel_gap_curve, 1);
    }
  }

  // Positioning at t_Y = 0 (method.md §7): the gauge point of the rail is gauge/2 from the track
  // centre, the wheel's flange back flange_back_distance/2, its taping line (y = 0) a further
  // −flange_back_position towards the field side.
  const RailLandmarks L = rail_landmarks(rail, track.gauge_height);
  if (track.positioning == TrackSetup::Positioning::Explicit) {
    // The user places the wheel: its origin (taping line) at rail y = lateral_offset.
    G.rail_gauge_y = L.has_gauge ? L.y_gauge : 0.0;
    G.y_offset = track.lateral_offset;
  } else {
    if (!L.has_gauge)
      throw InputError(rail.source, "", "no gauge point found " + format_number(track.gauge_height * 1e3) +
                                            " mm below the top of the rail on its gauge side (negative y)",
                       "the rail profile must reach that low on the gauge side (check mirror_y); for a roller, a "
                       "rail scanned only over its head or a narrow section place the wheel yourself: "
                       "track.positioning \"explicit\" with track.lateral_offset_mm");
    G.rail_gauge_y = L.y_gauge;
    G.y_offset = (L.y_gauge - track.gauge / 2) + (track.flange_back_distance / 2 - track.flange_back_position);
  }

  // Strips over the rail.
  const double w = opt.strip_width;
  for (double y = R.y_min() + w / 2; y <= R.y_max() - w / 2 + 1e-15; y += w) G.strip_y.push_back(y);
  const std::size_t ns = G.strip_y.size();
  G.strip_width = w;
  G.strip_zr.resize(ns);
  for (std::size_t j = 0; j < ns; ++j) G.strip_zr[j] = R.z(G.strip_y[j]);
  G.nominal_radius = track.nominal_radius;
  G.wheel_z0 = W.z(0.0);
  G.roller_radius = track.roller_radius;

  // Placement check (docs/profiles.md "Placement check"), before any t_Y is scanned: a wheel
  // placed by the gauge rule must have its taping line, its flange on the gauge side, and its
  // flange inside the track, near the rail's gauge point, at t_Y = 0. Explicit positioning is the
  // user's placement (a roller, a narrow section): not checked.
  if (track.positioning == TrackSetup::Positioning::Gauge) {
    const PlacementCheck pc = check_placement(G, L.z_gauge, opt.flange_min_height);
    if (!pc.ok)
      throw InputError(wheel.source + " on " + rail.source, pc.found ? "t_Y = 0: " + pc.numbers : "t_Y = 0",
                       "gauge positioning misplaces the wheel: " + pc.why + "; the pair is refused before any case is "
                       "solved",
                       "check the wheel's taping line (mhcontact profile info: taping_line), the mirror options and "
                       "the track data; if the placement is meant (a test rig, a narrow section, a profile without "
                       "a flange), place the wheel yourself: track.positioning \"explicit\" with "
                       "track.lateral_offset_mm; this gauge positioning is \"track\": {" + pc.explicit_placement() + "}");
  }

  const std::size_t nt = static_cast<std::size_t>(std::floor((opt.tY_max - opt.tY_min) / opt.tY_step + 1e-9)) + 1;
  G.tY.resize(nt);
  // Grid values: when t_Y_min is a whole number of steps, each value is computed as an integer
  // times the step in mm, so that the tables print 5 and not 5.000000000000001.
  const double step_mm = opt.tY_step * 1e3, k0 = std::round(opt.tY_min / opt.tY_step);
  const bool aligned = std::fabs(opt.tY_min / opt.tY_step - k0) < 1e-6;
  for (std::size_t k = 0; k < nt; ++k)
    G.tY[k] = aligned ? (k0 + static_cast<double>(k)) * step_mm / 1e3 : opt.tY_min + opt.tY_step * static_cast<double>(k);

  // Main strip and CAF at any t_Y: the strip with the smallest gap, refined between strips.
  using Main = ContactGeometry::MainPoint;
  auto locate = [&](double t) {
    const Main M = G.locate_main(t);
    if (!M.found)
      throw InputError(wheel.source + " on " + rail.source, "t_Y = " + format_number(t * 1e3) + " mm",
                       "the wheel and rail profiles do not overlap laterally",
                       "check the track data, mirror options and the t_Y range");
    return M;
  };
  std::vector<Main> mains(nt);
  G.main_strip.resize(nt);
  G.z_contact.resize(nt);
  for (std::size_t k = 0; k < nt; ++k) {
    mains[k] = locate(G.tY[k]);
    G.main_strip[k] = mains[k].strip;
    G.z_contact[k] = mains[k].gmin;
  }

  // Jumps of the CAF cut the t_Y axis into potential ellipses (method.md §3.5). A jump is a
  // discontinuity of the contact point, a property of the profiles and not of the grid: every
  // grid interval where the contact point moves by more than jump_distance is bisected (halves
  // that still move by more than jump_distance, down to kJumpBracket); a jump is a final bracket
  // across which the point still moves by more than jump_distance and γ by more than
  // jump_threshold. Continuous motion, however fast, moves the point by ~0 over such a bracket.
  auto gamma_at = [&](double y) { double d; R.z(y, &d); return std::atan(d); };
  constexpr double kJumpBracket = 1e-8;  // [m] 0.01 µm
  std::vector<double> jumps;              // t_Y of each jump, increasing
  auto split = [&](auto&& self, double ta, const Main& ma, double tb, const Main& mb) -> void {
    if (!(std::fabs(mb.y_r - ma.y_r) > opt.jump_distance)) return;
    if (tb - ta <= kJumpBracket) {
      if (std::fabs(gamma_at(mb.y_r) - gamma_at(ma.y_r)) > opt.jump_threshold) jumps.push_back(0.5 * (ta + tb));
      return;
    }
    const double tm = 0.5 * (ta + tb);
    const Main mm = locate(tm);
    self(self, ta, ma, tm, mm);
    self(self, tm, mm, tb, mb);
  };
  for (std::size_t k = 1; k < nt; ++k) split(split, G.tY[k - 1], mains[k - 1], G.tY[k], mains[k]);

  // Slivers: an ellipse narrower than min_ellipse_width, or without a grid point (it would have no
  // candidate data), is merged into the neighbour whose contact point at the shared jump is
  // closer on the rail; i.e. the jump between them is dropped. Repeated until none is left.
  for (bool changed = true; changed && !jumps.empty();) {
    changed = false;
    const std::size_t nj = jumps.size();
    for (std::size_t i = 0; i <= nj; ++i) {  // ellipse i lies between jumps[i-1] and jumps[i]
      const double lo = i == 0 ? G.tY.front() : jumps[i - 1];
      const double hi = i == nj ? G.tY.back() : jumps[i];
      bool has_point = false;
      for (std::size_t k = 0; k < nt && !has_point; ++k) has_point = G.tY[k] > lo && G.tY[k] < hi;
      if (i == 0) has_point = has_point || lo == G.tY.front();
      const bool interior = i > 0 && i < nj;
      if (has_point && (!interior || hi - lo >= opt.min_ellipse_width)) continue;
      std::size_t drop;
      if (i == 0) drop = 0;
      else if (i == nj) drop = nj - 1;
      else {
        const double y = locate(0.5 * (lo + hi)).y_r;
        const double yl = locate(lo - kJumpBracket).y_r, yh = locate(hi + kJumpBracket).y_r;
        drop = std::fabs(y - yl) <= std::fabs(y - yh) ? i - 1 : i;
      }
      jumps.erase(jumps.begin() + static_cast<std::ptrdiff_t>(drop));
      changed = true;
      break;
    }
  }

  G.main_ellipse.resize(nt);
  G.jumps = jumps;
  {
    std::size_t e = 0;
    for (std::size_t k = 0; k < nt; ++k) {
      while (e < jumps.size() && G.tY[k] > jumps[e]) ++e;
      G.main_ellipse[k] = static_cast<int>(e);
    }
  }
  for (std::size_t e = 0; e <= jumps.size(); ++e) {
    PotentialEllipse P;
    P.index = static_cast<int>(e) + 1;
    std::size_t first = nt, last = 0;
    for (std::size_t k = 0; k < nt; ++k)
      if (G.main_ellipse[k] == static_cast<int>(e)) { first = std::min(first, k); last = k; }
    if (first == nt) continue;  // cannot happen after the sliver rule
    P.k_first = first;
    P.k_last = last;
    P.tY_min = G.tY[first];
    P.tY_max = G.tY[last];
    P.y_r_min = P.y_r_max = mains[first].y_r;
    P.y_w_min = P.y_w_max = mains[first].y_r - G.y_offset - G.tY[first];
    for (std::size_t k = first; k <= last; ++k) {
      const double yr = mains[k].y_r, yw = yr - G.y_offset - G.tY[k];
      P.y_r_min = std::min(P.y_r_min, yr); P.y_r_max = std::max(P.y_r_max, yr);
      P.y_w_min = std::min(P.y_w_min, yw); P.y_w_max = std::max(P.y_w_max, yw);
    }
    G.ellipses.push_back(P);
  }

  // Each strip's ellipse for the rolled candidates: the one whose rail range is nearest.
  G.strip_ellipse.assign(ns, 0);
  for (std::size_t j = 0; j < ns; ++j) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t e = 0; e < G.ellipses.size(); ++e) {
      const PotentialEllipse& P = G.ellipses[e];
      const double d = std::max({0.0, P.y_r_min - G.strip_y[j], G.strip_y[j] - P.y_r_max});
      if (d < best) best = d, G.strip_ellipse[j] = static_cast<int>(e);
    }
  }

  // Candidate table: for every grid point and ellipse, the ellipse's own main strip when it is
  // the main one, else the main strip of the ellipse's t_Y nearest to this t_Y (method.md §3.6).
  // The wheel's steepest flange section (method.md §3.7): the largest slope of the smoothed wheel
  // between its lowest point (the flange tip) and the taping line, and the tip-side end of the part
  // of the face within flange_angle_tolerance of it.
  {
    std::size_t i_tip = 0;
    for (std::size_t i = 0; i < W.nodes(); ++i) if (W.z(W.node_y(i)) < W.z(W.node_y(i_tip))) i_tip = i;
    const double y_tip = W.node_y(i_tip);
    if (y_tip < 0 && W.contains(0.0) && W.z(0.0) - W.z(y_tip) >= opt.flange_min_height) {
      double smax = 0;
      std::size_t i_max = i_tip;
      for (std::size_t i = i_tip; i < W.nodes() && W.node_y(i) <= 0; ++i) {
        double d;
        W.z(W.node_y(i), &d);
        if (d > smax) { smax = d; i_max = i; }
      }
      const double gmax = std::atan(smax);
      std::size_t i_lo = i_max;
      while (i_lo > i_tip) {
        double d;
        W.z(W.node_y(i_lo - 1), &d);
        if (std::atan(d) < gmax - opt.flange_angle_tolerance) break;
        --i_lo;
      }
      G.has_flange = true;
      G.flange_gamma_max = gmax;
      G.flange_y_steepest = W.node_y(i_lo);
      G.flange_y_tip = y_tip;
      G.flange_r_tip = G.nominal_radius - (W.z(y_tip) - G.wheel_z0);
    }
  }
  if (!G.has_flange && track.positioning == TrackSetup::Positioning::Gauge)
    G.warnings.push_back("the wheel has no flange (no lowest point " + format_number(opt.flange_min_height * units::per_mm) +
                         " mm below its taping line on the gauge side): gauge positioning places it by a flange back it "
                         "does not have (track.flange_back_position_mm from its origin); for a roller, a test wheel or "
                         "a section without a flange place it yourself: track.positioning \"explicit\" with "
                         "track.lateral_offset_mm");
  const std::size_t ne = G.ellipses.size();
  G.table.resize(nt * ne);
  // Outside its own t_Y interval an ellipse's candidate is its main strip at the nearer end of
  // that interval (method.md §3.6): the contact point just inside the bisected jump, so that the
  // table does not depend on where the grid points fall.
  for (std::size_t ie = 0; ie < ne; ++ie) {
    if (ie > 0) G.ellipses[ie].y_r_below = locate(jumps[ie - 1] + kJumpBracket).y_r;
    if (ie + 1 < ne) G.ellipses[ie].y_r_above = locate(jumps[ie] - kJumpBracket).y_r;
  }
  for (std::size_t k = 0; k < nt; ++k) {
    const std::size_t em = static_cast<std::size_t>(G.main_ellipse[k]);
    for (std::size_t ie = 0; ie < ne; ++ie) {
      const double y_r = ie == em ? mains[k].y_r : em < ie ? G.ellipses[ie].y_r_below : G.ellipses[ie].y_r_above;
      G.fill_candidate(G.tY[k], y_r, ie == em, mains[k].gmin, G.table[k * ne + ie]);
    }
  }
  return G;
}

}  // namespace mh
