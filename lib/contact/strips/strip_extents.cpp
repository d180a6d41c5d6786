// Strip extents from a virtual interpenetration; see strip_extents.hpp.
//
// Sources:
//  - Johnson, Contact Mechanics (1985) §4.2 (Hertz elliptic contact: contact/ellipse/hertz.hpp).
//  - Kik & Piotrowski 1996; Piotrowski & Kik 2008 (KPEC: equivalent ellipse,
//    virtual penetration, strip extents from a reduced interpenetration).
//  - Sichani, Enblom, Berg 2014 (ANALYN: local Hertz solution per strip).
#include "contact/strips/strip_extents.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include "contact/ellipse/hertz.hpp"
#include "core/roots.hpp"
#include "core/units.hpp"

namespace mh {
namespace strips_detail {

namespace {


/// Hertz shape for h = A x^2 + B y^2, A, B > 0: a/sqrt(delta) along x, b/sqrt(delta) along y
/// (the project's one Hertz, contact/ellipse/hertz.hpp).
void hertz_shape(double A, double B, double* ka, double* kb) {
  const HertzShape h = mh::hertz_shape(A, B);
  *ka = h.ka;
  *kb = h.kb;
}

/// Root of the quadratic through (s_k, g_k), k = 0..2, equal to `level` in
/// [lo, hi] (the interpolant changes sign there by construction).
double crossing(const double* sv, const double* gv, double level, double lo, double hi) {
  auto q = [&](double x) {
    double r = 0.0;
    for (int i = 0; i < 3; ++i) {
      double li = 1.0;
      for (int j = 0; j < 3; ++j)
        if (j != i) li *= (x - sv[j]) / (sv[i] - sv[j]);
      r += li * gv[i];
    }
    return r - level;
  };
  return bracketed_root(q, lo, hi, q(lo), q(hi)).x;
}

}  // namespace

StripExtents::StripExtents(const StripGeometry& g) : geo(g), n(static_cast<int>(g.s.size())) { init(); }

void StripExtents::init() {
  n = static_cast<int>(geo.s.size());
  Bloc.assign(n, 0.0);
  ka.assign(n, 0.0);
  kb.assign(n, 0.0);
  const double ds2 = geo.ds * geo.ds;
  for (int i = 0; i < n; ++i) {
    // ANALYN (Sichani et al. 2014): B(s) from the second difference of g;
    // end strips borrow the neighbour's difference.
    int c = std::min(std::max(i, 1), n - 2);
    if (n >= 3) Bloc[i] = (geo.g[c + 1] - 2.0 * geo.g[c] + geo.g[c - 1]) / (2.0 * ds2);
    if (Bloc[i] > 0.0) hertz_shape(geo.A[i], Bloc[i], &ka[i], &kb[i]);
  }
  imin = static_cast<int>(std::min_element(geo.g.begin(), geo.g.end()) - geo.g.begin());
  gmin = geo.g[imin];
}

/// Bands at approach delta: runs of g < delta split at interior local maxima.
/// Returns band id per strip (-1 outside), sets nb.
void StripExtents::bands(double delta, int* nb, std::vector<int>& band) const {
  band.assign(static_cast<std::size_t>(n), -1);
  int id = -1;
  bool in = false;
  for (int i = 0; i < n; ++i) {
    if (!(geo.g[i] < delta)) { in = false; continue; }
    if (!in) { ++id; in = true; band[i] = id; continue; }
    band[i] = id;
    // saddle at i-1 (strict local maximum, inside the run): start a new band
    // at i if i-1 is a maximum; the saddle strip stays with the side whose
    // neighbour is deeper.
    if (i >= 2 && band[i - 2] == id && geo.g[i - 1] > geo.g[i - 2] && geo.g[i - 1] > geo.g[i]) {
      ++id;
      band[i] = id;
      if (geo.g[i] < geo.g[i - 2]) band[i - 1] = id;
    }
  }
  *nb = id + 1;
}

/// Strip half-lengths at approach delta: union of KPEC and ANALYN estimates.
/// Within a band the approach is measured from the band's deepest gap g0:
/// delta_b = delta - g0 and g - g0 (identical to the spec for g0 = 0 and
/// exact for an elliptic patch whose minimum gap is g0).
void StripExtents::extents(double delta, const std::vector<int>& band, int nb, std::vector<double>& a) const {
  a.assign(static_cast<std::size_t>(n), 0.0);
  for (int b = 0; b < nb; ++b) {
    int first = -1, last = -1;
    for (int i = 0; i < n; ++i)
      if (band[i] == b) { if (first < 0) first = i; last = i; }
    int i0 = first;
    for (int i = first; i <= last; ++i)
      if (geo.g[i] < geo.g[i0]) i0 = i;
    // deepest point: vertex of the parabola through the three rows around i0
    double s0 = geo.s[i0], g0 = geo.g[i0];
    if (i0 > 0 && i0 < n - 1) {
      const double d2 = geo.g[i0 + 1] - 2.0 * geo.g[i0] + geo.g[i0 - 1];
      if (d2 > 0.0) {
        const double d1 = 0.5 * (geo.g[i0 + 1] - geo.g[i0 - 1]);
        const double u = -d1 / d2;  // in strip widths, |u| <= 1/2
        s0 = geo.s[i0] + u * geo.ds;
        g0 = geo.g[i0] + 0.5 * d1 * u;
      }
    }
    g0 = std::min(g0, geo.g[i0]);
    const double db = delta - g0;
    if (!(db > 0.0)) continue;
    const double half = 0.5 * db;

    // ---- KPEC-type (Kik & Piotrowski 1996): equivalent ellipse of the band.
    // Lateral extent of h < delta/2 around i0 within the band.
    auto edge = [&](int dir) {
      int k = i0;
      while (true) {
        const int nx = k + dir;
        if (nx < first || nx > last) return geo.s[k] + dir * 0.5 * geo.ds;  // band ends first
        if (!(geo.g[nx] - g0 < half)) {
          // crossing between k (inside) and nx (outside); quadratic through
          // k - dir, k, nx where available
          const int o = (k - dir >= 0 && k - dir < n) ? k - dir : nx + dir;
          if (o < 0 || o >= n) {
            const double t = (half - (geo.g[k] - g0)) / (geo.g[nx] - geo.g[k]);
            return geo.s[k] + t * (geo.s[nx] - geo.s[k]);
          }
          const double sv[3] = {geo.s[o], geo.s[k], geo.s[nx]};
          const double gv[3] = {geo.g[o] - g0, geo.g[k] - g0, geo.g[nx] - g0};
          return crossing(sv, gv, half, std::min(geo.s[k], geo.s[nx]), std::max(geo.s[k], geo.s[nx]));
        }
        k = nx;
      }
    };
    const double sL = edge(-1), sR = edge(+1);
    const double w = 0.5 * (sR - sL);
    const double Ab = geo.A[i0];
    if (w > 0.0) {
      const double Bb = half / (w * w);
      double kA, kB;
      hertz_shape(Ab, Bb, &kA, &kB);
      const double ae = kA * std::sqrt(db), be = kB * std::sqrt(db);
      const double Aa2 = Ab * ae * ae, Bb2 = Bb * be * be;
      for (int i = first; i <= last; ++i) {
        const double y = (geo.s[i] - s0) / be;
        // reduced interpenetration eps(s) delta_b, clipped to [0, delta_b]
        const double ed = std::min(std::max(Aa2 - (Aa2 - Bb2) * y * y, 0.0), db);
        const double pen = ed - (geo.g[i] - g0);
        if (pen > 0.0) a[i] = std::max(a[i], std::sqrt(pen / geo.A[i]));
      }
    }
    // ---- ANALYN-type (Sichani et al. 2014): local Hertz solution per strip,
    // a_i = a* sqrt(1 - (g_i - g0)/(B b*^2)).
    for (int i = first; i <= last; ++i) {
      if (!(Bloc[i] > 0.0)) continue;
      const double as = ka[i] * std::sqrt(db), bs = kb[i] * std::sqrt(db);
      const double arg = 1.0 - (geo.g[i] - g0) / (Bloc[i] * bs * bs);
      if (arg > 0.0) a[i] = std::max(a[i], as * std::sqrt(arg));
    }
  }
}

bool hertz_axes(double A, double B, double delta, double* a, double* b) {
  if (!(A > 0.0) || !(B > 0.0) || !(delta > 0.0)) return false;
  double ka, kb;
  hertz_shape(A, B, &ka, &kb);
  *a = ka * std::sqrt(delta);
  *b = kb * std::sqrt(delta);
  return true;
}

}  // namespace strips_detail
}  // namespace mh
