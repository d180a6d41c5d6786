// The candidates of a wheel rolled by δ against its rail (method.md §3.8, eq. 3.8.1):
// ContactGeometry::rolled_wheel_at, ContactGeometry::candidates_at(t, δ), and the tabulated rolled
// minima (RolledMinima, build_rolled_minima) with their build on demand.
#include "geometry/rolled_candidates.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

#include "geometry/gap_minimum.hpp"

namespace mh {

namespace {

/// The wheel point facing a rail point, rolled by δ: y_w with y_w cos δ − z_w(y_w) sin δ = y0
/// (eq. 3.8.1, y0 = y_r − y_offset − t_Y), its height z_w and slope z_w'. Newton from y_w = y0 on
/// that condition (derivative cos δ − z_w' sin δ), each step one profile evaluation, until a step
/// is below kLast; the last step's height and slope are then taken from the tangent (their errors
/// κ (1 + z'²)^{3/2} kLast² / 2 and κ (1 + z'²)^{3/2} kLast: below 1e-14 m and 3e-6 on the S1002
/// flange's R13 arc). The steps shrink quadratically: z sin δ first (0.75 mm at 25 mrad on a 30 mm
/// flange), then about z'' sin δ / 2 times its square (30 µm, 30 nm): 2 evaluations on a tread,
/// up to 4 on a flange at 25 mrad. Why not the first-order point y0 + z_w(y0) sin δ alone: it
/// misses O(δ² (|y_w| + |z_w|) z_w') of separation, 12 µm at 10 mrad and 52 µm at 25 mrad on the
/// S1002 flange against the exact rotation (test_rolled_gap.cpp).
struct Facing { double y, z, dz; };
Facing facing_point(const ProfileCurve& W, double y0, double sn, double c) {
  constexpr double kLast = 1e-9;  // [m]
  double y = y0, d;
  double z = W.z(y, &d);
  for (int it = 0; it < 8; ++it) {
    const double step = (y * c - z * sn - y0) / (c - d * sn);
    y -= step;
    if (std::fabs(step) <= kLast) {
      z -= d * step;
      break;
    }
    z = W.z(y, &d);
  }
  return {y, z, d};
}

}  // namespace

void ContactGeometry::rolled_wheel_at(double t, double roll, double y_r, double* y_w, double* z_w) const {
  // The wheel point (y_w, z_w) rotated by δ about the wheel's origin lies at rail
  // (s + y_w cos δ − z_w sin δ, y_w sin δ + z_w cos δ), s = y_offset + t (eq. 3.8.1): the point
  // facing y_r exactly (facing_point), its rotated height.
  const double sn = std::sin(roll), c = std::cos(roll);
  const Facing f = facing_point(*wheel_curve, y_r - (y_offset + t), sn, c);
  *y_w = f.y;
  *z_w = f.y * sn + f.z * c;
}

namespace {

// candidates_at(t, δ) of G evaluated every time (no cache).
bool rolled_candidates(const ContactGeometry& G, double t, double roll, CandidateGeom* out, int* main) {
  const auto& wheel_curve = G.wheel_curve;
  const auto& rail_curve = G.rail_curve;
  const auto& strip_y = G.strip_y;
  const auto& strip_zr = G.strip_zr;
  const auto& strip_ellipse = G.strip_ellipse;
  const auto& ellipses = G.ellipses;
  const double y_offset = G.y_offset, nominal_radius = G.nominal_radius, wheel_z0 = G.wheel_z0,
               flange_y_steepest = G.flange_y_steepest;
  const bool has_flange = G.has_flange;
  G.candidates_at(t, out, main);  // the upright candidates: their points, and the answer if no overlap
  if (roll == 0.0 || !wheel_curve || !rail_curve || strip_y.empty() || strip_ellipse.size() != strip_y.size())
    return true;
  const ProfileCurve& W = *wheel_curve;
  const ProfileCurve& R = *rail_curve;
  const std::size_t ns = strip_y.size(), ne = ellipses.size();
  const double s = y_offset + t, sn = std::sin(roll), tn = std::tan(roll);
  // The rolled separation at strip j to first order in δ, for the scan only (one wheel evaluation):
  // z_w(y − s) + δ (y − s) + δ z_w z_w' − z_r.
  auto sep1 = [&](std::size_t j) {
    const double yw = strip_y[j] - s;
    double d;
    const double zw = W.z(yw, &d);
    return zw + sn * (yw + zw * d) - strip_zr[j];
  };
  // The smallest rolled separation over the strips: every 5th strip, then those around the best.
  constexpr std::size_t kStride = 5;
  std::size_t jb = ns;
  double gb = std::numeric_limits<double>::infinity();
  auto consider = [&](std::size_t j) {
    if (!W.contains(strip_y[j] - s)) return;
    const double g = sep1(j);
    if (g < gb) gb = g, jb = j;
  };
  const RolledMinima* E = G.rolled_minima.get();
  if (!E && G.rolled_minima_on_demand && std::fabs(sn) <= G.rolled_minima_on_demand->sigma_max())
    E = G.rolled_minima_on_demand->get(G);
  const std::size_t n = G.tY.size();
  if (E && n > 1 && E->first.size() == n + 1 && std::fabs(sn) <= E->sigma_max) {
    // The envelopes' minima at the grid points around t, and the strips beside them: at a grid
    // point the strip of the full scan; between two the wheel moves 0.1 strip against the rail.
    const double step = (G.tY.back() - G.tY.front()) / static_cast<double>(n - 1);
    const std::size_t k = std::min(static_cast<std::size_t>(std::clamp((t - G.tY.front()) / step, 0.0, static_cast<double>(n - 1))), n - 2);
    for (std::size_t kk : {k, k + 1}) {
      const std::size_t j0 = E->at(kk, sn);
      if (j0 >= ns) continue;
      for (std::size_t j = j0 > 2 ? j0 - 2 : 0; j <= std::min(j0 + 2, ns - 1); ++j) consider(j);
    }
  } else {
    for (std::size_t j = 0; j < ns; j += kStride) consider(j);
    consider(ns - 1);
    if (jb == ns) return false;
    const std::size_t j0 = jb;
    for (std::size_t j = j0 > kStride ? j0 - kStride : 0; j <= std::min(j0 + kStride, ns - 1); ++j) consider(j);
  }
  if (jb == ns) return false;
  // Refined between the neighbouring strips to the root of the rolled gap's slope,
  // tan(θ_w + δ) − z_r'(y) with tan θ_w = z_w'(y_w) (as refine_minimum: sign changes over
  // sub-intervals, each to 1 nm by TOMS 748; gap_minimum.hpp).
  const double cs = std::cos(roll);
  auto slope = [&](double y) {
    double dr;
    const double dw = facing_point(W, y - s, sn, cs).dz;  // the wheel's slope at the point facing y
    R.z(y, &dr);
    return (dw + tn) / (1 - dw * tn) - dr;
  };
  auto sep = [&](double y) {
    double yw, zw;
    G.rolled_wheel_at(t, roll, y, &yw, &zw);
    return zw - R.z(y);
  };
  const std::size_t j = jb;
  const double a = std::max(strip_y[j > 2 ? j - 3 : 0], W.y_min() + s),
               b = std::min(strip_y[std::min(j + 3, ns - 1)], W.y_max() + s);
  double ym_best = strip_y[j], gm_best = sep(ym_best);
  lowest_gap_minimum(slope, sep, a, b, GapMinimumScan{6, 1e-9, false}, ym_best, gm_best);
  // The rolled minimum is the candidate of the ellipse whose part of the rail holds it; every
  // other ellipse keeps its upright candidate's point (method.md §3.6), its separation that of the
  // rolled wheel there: so δ → 0 gives the upright candidates back (continuous in δ).
  const std::size_t em = static_cast<std::size_t>(strip_ellipse[j]);
  thread_local std::vector<double> y_c, g_c;
  y_c.resize(ne);
  g_c.resize(ne);
  for (std::size_t e = 0; e < ne; ++e) {
    y_c[e] = e == em ? ym_best : out[e].y_r;
    g_c[e] = e == em ? gm_best : sep(y_c[e]);
  }
  std::size_t m = em;
  for (std::size_t e = 0; e < ne; ++e)
    if (g_c[e] < g_c[m]) m = e;
  for (std::size_t e = 0; e < ne; ++e) {
    CandidateGeom& c = out[e];
    G.fill_candidate(t, y_c[e], e == m, g_c[m], c);
    double yw, zw;
    G.rolled_wheel_at(t, roll, y_c[e], &yw, &zw);
    const double z_w = W.z(yw);
    c.y_w = yw;
    c.k_wxx = W.kappa(yw);
    c.sep = g_c[e];
    c.gap = e == m ? 0.0 : std::max(0.0, g_c[e] - g_c[m]);
    c.r_roll = nominal_radius - (z_w - wheel_z0);
    c.flange_climb = has_flange && yw < flange_y_steepest;
  }
  if (main) *main = static_cast<int>(m);
  return true;
}

}  // namespace

bool ContactGeometry::candidates_at(double t, double roll, CandidateGeom* out, int* main) const {
  if (roll == 0.0 || !wheel_curve || !rail_curve || strip_y.empty() || strip_ellipse.size() != strip_y.size()) {
    candidates_at(t, out, main);  // the upright candidates, the answer at δ = 0
    return true;
  }
  // A solve asks for the same (t, δ) several times (the wheelset's first-contact height, then the
  // normal solves of the creep forces' vertical equilibrium): the last few answers are kept per
  // thread, keyed by the geometry's build_id, t and δ (the same bits as evaluating again).
  struct Entry { std::uint64_t id = 0; double t = 0, roll = 0; bool ok = false; int main = 0; std::vector<CandidateGeom> c; };
  constexpr std::size_t kEntries = 4;  // both wheels of a wheelset, at two rolls of a root search
  thread_local Entry cache[kEntries];
  thread_local std::size_t next = 0;
  const std::size_t ne = ellipses.size();
  if (build_id != 0)
    for (const Entry& e : cache)
      if (e.id == build_id && e.t == t && e.roll == roll && e.c.size() == ne) {
        std::copy(e.c.begin(), e.c.end(), out);
        if (main) *main = e.main;
        return e.ok;
      }
  int m = 0;
  const bool ok = rolled_candidates(*this, t, roll, out, &m);
  if (main) *main = m;
  if (build_id != 0) {
    Entry& e = cache[next];
    next = (next + 1) % kEntries;
    e.id = build_id;
    e.t = t;
    e.roll = roll;
    e.ok = ok;
    e.main = m;
    e.c.assign(out, out + ne);
  }
  return ok;
}

std::uint32_t RolledMinima::at(std::size_t k, double sigma) const {
  const auto b = sigma_from.begin() + first[k], e = sigma_from.begin() + first[k + 1];
  if (b == e) return std::numeric_limits<std::uint32_t>::max();
  const auto it = std::upper_bound(b + 1, e, sigma);  // the last piece starting at or below σ
  return strip[static_cast<std::size_t>(it - sigma_from.begin()) - 1];
}

namespace {

std::shared_ptr<const RolledMinima> tabulate_rolled_minima(const ContactGeometry& G, double roll_max) {
  if (!G.wheel_curve || G.strip_y.empty() || G.tY.size() < 2 || !(roll_max > 0)) return nullptr;
  const ProfileCurve& W = *G.wheel_curve;
  const std::size_t ns = G.strip_y.size(), n = G.tY.size();
  auto E = std::make_shared<RolledMinima>();
  const double sm = std::sin(roll_max);
  E->sigma_max = sm;
  E->first.reserve(n + 1);
  struct Line { double h, g; std::uint32_t j; };
  std::vector<Line> lines, hull;
  std::vector<double> x;  // hull[i] is the minimum from x[i] on
  for (std::size_t k = 0; k < n; ++k) {
    E->first.push_back(static_cast<std::uint32_t>(E->strip.size()));
    // Strip j's rolled separation to first order, g + σ h (the scan's sep1 in rolled_candidates).
    const double s = G.y_offset + G.tY[k];
    lines.clear();
    double U = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < ns; ++j) {
      const double yw = G.strip_y[j] - s;
      if (!W.contains(yw)) continue;
      double d;
      const double zw = W.z(yw, &d);
      const Line L{yw + zw * d, zw - G.strip_zr[j], static_cast<std::uint32_t>(j)};
      lines.push_back(L);
      // The envelope stays below every line's larger end value on |σ| ≤ sm.
      U = std::min(U, L.g + sm * std::fabs(L.h));
    }
    // Only a line whose smaller end value is not above U can be the minimum somewhere there.
    lines.erase(std::remove_if(lines.begin(), lines.end(), [&](const Line& L) { return L.g - sm * std::fabs(L.h) > U; }),
                lines.end());
    // The lower envelope in increasing σ passes the lines in decreasing slope h; of equal slopes the
    // lower (then the first strip, as the scan keeps the first of equal values).
    // h = y_w + z_w z_w' grows with the strip but on the flange: reversed, the lines are nearly in
    // order, and an insertion sort costs about one pass.
    auto before = [](const Line& a, const Line& b) { return a.h != b.h ? a.h > b.h : a.g != b.g ? a.g < b.g : a.j < b.j; };
    std::reverse(lines.begin(), lines.end());
    for (std::size_t i = 1; i < lines.size(); ++i) {
      const Line L = lines[i];
      std::size_t p = i;
      for (; p > 0 && before(L, lines[p - 1]); --p) lines[p] = lines[p - 1];
      lines[p] = L;
    }
    hull.clear();
    x.clear();
    for (const Line& L : lines) {
      if (!hull.empty() && hull.back().h == L.h) continue;
      double xs = -std::numeric_limits<double>::infinity();
      while (!hull.empty()) {
        const Line& B = hull.back();
        xs = (L.g - B.g) / (B.h - L.h);  // where L falls below B
        if (xs <= x.back()) {
          hull.pop_back();
          x.pop_back();
          xs = -std::numeric_limits<double>::infinity();
        } else {
          break;
        }
      }
      hull.push_back(L);
      x.push_back(xs);
    }
    for (std::size_t i = 0; i < hull.size(); ++i) {
      const double to = i + 1 < hull.size() ? x[i + 1] : std::numeric_limits<double>::infinity();
      if (to < -sm || x[i] > sm) continue;  // a piece outside |σ| ≤ sm
      E->sigma_from.push_back(x[i]);
      E->strip.push_back(hull[i].j);
    }
  }
  E->first.push_back(static_cast<std::uint32_t>(E->strip.size()));
  E->sigma_from.shrink_to_fit();
  E->strip.shrink_to_fit();
  return E;
}

}  // namespace

void build_rolled_minima(ContactGeometry& G, double roll_max) { G.rolled_minima = tabulate_rolled_minima(G, roll_max); }

RolledMinimaOnDemand::RolledMinimaOnDemand(double roll_max) : roll_max_(roll_max), sigma_max_(std::sin(roll_max)) {}

const RolledMinima* RolledMinimaOnDemand::get(const ContactGeometry& G) const {
  std::call_once(once_, [&] {
    table_ = tabulate_rolled_minima(G, roll_max_);
    built_.store(true, std::memory_order_release);
  });
  return table_.get();
}

bool RolledMinimaOnDemand::built() const { return built_.load(std::memory_order_acquire); }

void tabulate_rolled_minima_on_demand(ContactGeometry& G, double roll_max) {
  if (G.rolled_minima || !(roll_max > 0)) return;
  G.rolled_minima_on_demand = std::make_shared<const RolledMinimaOnDemand>(roll_max);
}

}  // namespace mh
