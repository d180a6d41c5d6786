// The subsurface stresses of one solved contact (contact_stresses.hpp).
#include "contact/rcf/contact_stresses.hpp"

#include <algorithm>
#include <utility>

#include "core/units.hpp"

namespace mh {

namespace {

// The stresses below the contact's elastic Hertz ellipse with full-slip traction f (subsurface.hpp)
// on the rail, against the creep force on the wheel (along x without one).
SubsurfacePeaks ellipse_peaks(const RcfOptions& o, double N, double a_el, double b_el, const TangentialResult& t,
                              double f) {
  if (!(N > 0 && a_el > 0 && b_el > 0 && f >= 0)) return {};
  HertzLoad L;
  L.a = a_el, L.b = b_el, L.p0 = 1.5 * N / (units::pi * a_el * b_el), L.nu = o.nu;
  const double F = std::hypot(t.Fx, t.Fy);
  // On the rail, against the force on the wheel (as a grid patch's, patch_stress_load). The peaks
  // are those of the mirrored load along +F too (the ellipse is symmetric about its centre).
  if (o.actual && F > 0) L.fx = -f * t.Fx / F, L.fy = -f * t.Fy / F;
  else L.fx = f;
  struct Memo { HertzLoad L; SubsurfacePeaks P; bool used = false; };
  static thread_local Memo memo[8];
  static thread_local int next = 0;
  for (const Memo& m : memo)
    if (m.used && m.L.a == L.a && m.L.b == L.b && m.L.p0 == L.p0 && m.L.fx == L.fx && m.L.fy == L.fy && m.L.nu == L.nu)
      return m.P;
  Memo& m = memo[next];
  next = (next + 1) % 8;
  m.L = L, m.P = subsurface_peaks(L), m.used = true;
  return m.P;
}

// The pressure of a grid patch as uniform elements: the half-space method's own grid, or the
// strips' semi-ellipses q √(1 − ((x − c)/a)²) at the centres of elements of the strip width
// across and at least 32 along (as the strips' tangential step lays them, solve.cpp), scaled to
// carry the patch's N. Empty when the patch kept neither.
GridLoad patch_pressure(const PatchResult& P) {
  GridLoad G;
  if (!P.p.empty() && P.nx > 0 && P.ns > 0) {
    G.nx = P.nx, G.ny = P.ns, G.dx = P.dx, G.dy = P.ds, G.x0 = P.x0, G.y0 = P.s0;
    G.p = P.p;
    return G;
  }
  if (P.strips.empty() || !(P.element > 0) || !(P.N > 0)) return G;
  double s_lo = INFINITY, s_hi = -INFINITY, x_lo = INFINITY, x_hi = -INFINITY;
  for (const StripOut& S : P.strips) {
    s_lo = std::min(s_lo, S.s), s_hi = std::max(s_hi, S.s);
    x_lo = std::min(x_lo, S.c - S.a), x_hi = std::max(x_hi, S.c + S.a);
  }
  const double ds = P.element, dx = std::min(ds, (x_hi - x_lo) / 32);
  G.nx = std::max(1, static_cast<int>(std::ceil((x_hi - x_lo) / dx)));
  G.ny = static_cast<int>(std::lround((s_hi - s_lo) / ds)) + 1;
  G.dx = dx, G.dy = ds, G.x0 = x_lo + 0.5 * dx, G.y0 = s_lo;
  G.p.assign(static_cast<std::size_t>(G.nx * G.ny), 0.0);
  double sum = 0;
  for (const StripOut& S : P.strips) {
    const int j = static_cast<int>(std::lround((S.s - s_lo) / ds));
    for (int i = 0; i < G.nx; ++i) {
      const double t = (G.x0 + i * dx - S.c) / S.a;
      if (std::fabs(t) >= 1) continue;
      const double p = S.q * std::sqrt(1 - t * t);
      G.p[static_cast<std::size_t>(i + G.nx * j)] = p;
      sum += p * dx * ds;
    }
  }
  if (sum > 0)
    for (double& p : G.p) p *= P.N / sum;
  return G;
}

// The grid patch's peaks, searched once for the CSV and JSON records of the same patch.
SubsurfacePeaks grid_peaks(GridLoad G) {
  struct Memo { GridLoad G; SubsurfacePeaks P; bool used = false; };
  static thread_local Memo memo[4];
  static thread_local int next = 0;
  auto same = [](const GridLoad& a, const GridLoad& b) {
    return a.nx == b.nx && a.ny == b.ny && a.dx == b.dx && a.dy == b.dy && a.x0 == b.x0 && a.y0 == b.y0 &&
           a.nu == b.nu && a.p == b.p && a.qx == b.qx && a.qy == b.qy;
  };
  for (const Memo& m : memo)
    if (m.used && same(m.G, G)) return m.P;
  Memo& m = memo[next];
  next = (next + 1) % 4;
  m.P = grid_subsurface_peaks(G);
  m.G = std::move(G), m.used = true;
  return m.P;
}

}  // namespace

GridLoad patch_stress_load(const RcfOptions& o, const PatchResult& patch, double f, bool solved, bool* solved_used) {
  if (solved_used) *solved_used = false;
  const PatchTraction& T = patch.traction;
  const std::size_t n = static_cast<std::size_t>(T.nx) * static_cast<std::size_t>(T.ns);
  GridLoad G;
  if (solved && patch.t.solved && !T.empty() && T.pn.size() == n && T.px.size() == n && T.py.size() == n) {
    // The solved traction on the grid it was solved on, with that grid's pressure (traction_grid.hpp:
    // half-space, PatchResult::p; strips, their pressure laid on elements). The files and the
    // stresses are the rail's: the traction on the wheel reversed.
    G.nx = T.nx, G.ny = T.ns, G.dx = T.dx, G.dy = T.ds, G.x0 = T.x0, G.y0 = T.s0;
    G.p.resize(n), G.qx.resize(n), G.qy.resize(n);
    for (std::size_t e = 0; e < n; ++e) {
      const bool in = T.pn[e] > 0;
      G.p[e] = in ? T.pn[e] : 0.0;
      G.qx[e] = in ? -T.px[e] : 0.0, G.qy[e] = in ? -T.py[e] : 0.0;
    }
    G.nu = o.nu;
    if (solved_used) *solved_used = true;
    return G;
  }
  G = patch_pressure(patch);
  if (G.p.empty()) return G;
  G.nu = o.nu;
  if (f > 0) {
    // Full slip f p on the rail, against the force on the wheel (along x without one).
    const double F = std::hypot(patch.t.Fx, patch.t.Fy);
    const double ux = o.actual && F > 0 ? -patch.t.Fx / F : 1.0, uy = o.actual && F > 0 ? -patch.t.Fy / F : 0.0;
    G.qx.resize(G.p.size()), G.qy.resize(G.p.size());
    for (std::size_t e = 0; e < G.p.size(); ++e) G.qx[e] = f * ux * G.p[e], G.qy[e] = f * uy * G.p[e];
  }
  return G;
}

GridLoad ellipse_fastsim_load(const RcfOptions& o, double N, double a_el, double b_el, double mu,
                              const EllipseCells& cells) {
  GridLoad G;
  if (!cells.traction || cells.traction->empty() || !(N > 0 && a_el > 0 && b_el > 0 && mu > 0)) return G;
  // Only FASTSIM's traction of the elastic ellipse itself: a plastic patch's cells are of another
  // pressure (contact_stresses.hpp).
  if (!(std::fabs(cells.a - a_el) <= 1e-9 * a_el && std::fabs(cells.b - b_el) <= 1e-9 * b_el)) return G;
  const double h = std::min(a_el, b_el) / kEllipseElements;
  G.nx = 2 * static_cast<int>(std::ceil(a_el / h)), G.ny = 2 * static_cast<int>(std::ceil(b_el / h));
  G.dx = 2 * a_el / G.nx, G.dy = 2 * b_el / G.ny;
  G.x0 = -a_el + 0.5 * G.dx, G.y0 = -b_el + 0.5 * G.dy;
  G.nu = o.nu;
  const std::size_t n = static_cast<std::size_t>(G.nx) * static_cast<std::size_t>(G.ny);
  G.p.assign(n, 0.0), G.qx.assign(n, 0.0), G.qy.assign(n, 0.0);
  const double p0 = 1.5 * N / (units::pi * a_el * b_el);
  for (int j = 0; j < G.ny; ++j)
    for (int i = 0; i < G.nx; ++i) {
      const double x = G.x0 + i * G.dx, y = G.y0 + j * G.dy, q = 1 - x * x / (a_el * a_el) - y * y / (b_el * b_el);
      if (!(q > 0)) continue;
      const std::size_t e = static_cast<std::size_t>(i) + static_cast<std::size_t>(G.nx) * static_cast<std::size_t>(j);
      G.p[e] = p0 * std::sqrt(q);
      // FASTSIM's traction on the wheel at the element centre; the rail's is its reverse.
      const TractionSample s = fastsim_traction_at(*cells.traction, a_el, b_el, mu, x, y);
      G.qx[e] = -s.px, G.qy[e] = -s.py;
    }
  return G;
}

ContactStresses contact_stresses(const RcfOptions& o, double N, double a_el, double b_el, const TangentialResult& t,
                                 double f, const PatchResult* patch, const EllipseCells& cells) {
  ContactStresses S;
  if (!std::isfinite(f)) return S;
  // The grid: asked, a patch, elastic (no element at the plastic cap), its pressure kept.
  if (patch && o.subsurface_grid && !(patch->plastic_area > 0) && f >= 0) {
    bool solved = false;
    GridLoad G = patch_stress_load(o, *patch, f, o.actual, &solved);
    if (!G.p.empty()) {
      S.peaks = grid_peaks(std::move(G));
      S.source = solved ? ContactStressSource::GridPatchSolvedTraction : ContactStressSource::GridPatch;
    }
  }
  // An ellipse row: FASTSIM's traction of its elastic ellipse, with friction given and its cells kept.
  if (!patch && o.actual && t.solved && f >= 0) {
    GridLoad G = ellipse_fastsim_load(o, N, a_el, b_el, t.mu, cells);
    if (!G.p.empty()) {
      S.peaks = grid_peaks(std::move(G));
      S.source = ContactStressSource::HertzEllipseFastsim;
    }
  }
  if (S.source == ContactStressSource::None) {
    S.peaks = ellipse_peaks(o, N, a_el, b_el, t, f);
    if (std::isfinite(S.peaks.vm_max)) S.source = ContactStressSource::HertzEllipse;
  }
  S.fi_sub = fi_sub(S.peaks, o.dang_van_c);
  return S;
}

}  // namespace mh
