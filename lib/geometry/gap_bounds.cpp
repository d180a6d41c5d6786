// The gap-corner bounds of geometry/gap.hpp (gap_kink_bound, gap_curvature_bound): the profiles'
// node polylines tabulated per curve and level, and the bounds they give a patch plane's samples.
#include "geometry/gap.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <vector>

#include "geometry/normal_hits.hpp"

namespace mh {

using detail::NormalHits;
using detail::normal_hits;

namespace {

// The kinks of both polylines seen from the plane (gap_kink_bound), summed into bins of width
// h/2 whose edges are the centres' grid g_j = s_first − h + (h/2) j: on each bin every centre's
// weight (1 − |s_k − s_i|/h)₊ is linear in the kink's place u = (s_k − g_j)/(h/2) ∈ [0, 1), so
// the bin's Σ J and Σ J u give each centre's sum exactly. A_abs: Σ |J| (for the rounding).
struct KinkBins {
  std::vector<double> A, U;
  double g0 = 0, inv_half_h = 0, A_abs = 0, coord = 0;
  int kinks = 0;
  void reset(double g0_, double h, int nb) {
    A.assign(static_cast<std::size_t>(nb), 0.0);
    U.assign(static_cast<std::size_t>(nb), 0.0);
    g0 = g0_;
    inv_half_h = 2 / h;
    A_abs = coord = 0;
    kinks = 0;
  }
};
// One curve's polyline seen from the plane: the largest Hermite deviation from it E and the
// least D over its intervals (its kinks go into KinkBins).
struct PlanePolyline {
  double E = 0, D_min = INFINITY;
};

// A curve's nodes as z(y) gives them (z(node_y(k)), within ~1e-19 m of the node's z: node_y
// rounds by an ulp of y, covered by the 1e-15 m added to e), seen as polylines through every
// 2^l-th node (level l): the chord slope m_k of coarse interval k, the bound dev_k of |z' − m_k| on
// it and e_k of |z − chord| on it. On a fine interval the Hermite's slope basis is within ±1 on
// [0, 1], so |z' − m| ≤ |z'_k − m| + |z'_k+1 − m|, and |z − chord| ≤ (4/27) Δy that (|h10|, |h11|
// ≤ 4/27); a coarse interval adds the largest distance of its fine nodes from its chord (both
// polylines are linear between fine nodes). Made once per geometry (ContactGeometry::build_id),
// curve and thread.
// For gap_curvature_bound each level also keeps the range of the curve's slope z' on each of its
// intervals (plo, phi: m ± dev on each fine interval, the least and largest over the interval's
// fine ones) and at each inner node k the polyline's kink per length in y, q_k = (m_k − m_k−1)/Δy
// (the level's nodes are equally spaced), independent of the plane.
struct NodeLevel {
  std::vector<double> y, z, m, dev, e;
  std::vector<double> plo, phi, q;
  // The same per block of kBlock intervals (plo, phi, e) or nodes (q): a range's scan takes whole
  // blocks where it can.
  static constexpr std::size_t kBlock = 16;
  std::vector<double> bplo, bphi, be, bqlo, bqhi;
  double abs_max = 0;  // [m] max |y| + max |z| over the nodes (the rounding of their plane coordinates)
};
struct NodeTable {
  static constexpr int kLevels = 8;  // coarse spacing up to 128 nodes (1.28 mm at 0.01 mm)
  static void kinks(NodeLevel& L) {
    L.q.assign(L.y.size(), 0.0);
    for (std::size_t k = 1; k < L.m.size(); ++k) L.q[k] = (L.m[k] - L.m[k - 1]) / (L.y[1] - L.y[0]);
    constexpr std::size_t K = NodeLevel::kBlock;
    const std::size_t ni = L.m.size() / K, nn = L.q.size() / K;  // whole blocks only
    L.bplo.assign(ni, INFINITY); L.bphi.assign(ni, -INFINITY); L.be.assign(ni, 0.0);
    L.bqlo.assign(nn, INFINITY); L.bqhi.assign(nn, -INFINITY);
    for (std::size_t k = 0; k < ni * K; ++k) {
      L.bplo[k / K] = std::min(L.bplo[k / K], L.plo[k]);
      L.bphi[k / K] = std::max(L.bphi[k / K], L.phi[k]);
      L.be[k / K] = std::max(L.be[k / K], L.e[k]);
    }
    for (std::size_t k = 0; k < nn * K; ++k) {
      L.bqlo[k / K] = std::min(L.bqlo[k / K], L.q[k]);
      L.bqhi[k / K] = std::max(L.bqhi[k / K], L.q[k]);
    }
  }
  std::uint64_t id = 0;
  const ProfileCurve* curve = nullptr;
  NodeLevel level[kLevels];
  void make(const ProfileCurve& C, std::uint64_t build_id) {
    id = build_id;
    curve = &C;
    const std::size_t n = C.nodes();
    NodeLevel& f = level[0];
    f.y.resize(n); f.z.resize(n);
    std::vector<double> dz(n);
    for (std::size_t k = 0; k < n; ++k) {
      f.y[k] = C.node_y(k);
      f.z[k] = C.z(f.y[k], &dz[k]);
    }
    f.m.assign(n ? n - 1 : 0, 0); f.dev.assign(f.m.size(), 0); f.e.assign(f.m.size(), 0);
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const double dy = f.y[k + 1] - f.y[k];
      f.m[k] = (f.z[k + 1] - f.z[k]) / dy;
      f.dev[k] = std::fabs(dz[k] - f.m[k]) + std::fabs(dz[k + 1] - f.m[k]);
      f.e[k] = 4.0 / 27.0 * dy * f.dev[k] + 1e-15;
    }
    f.plo.resize(f.m.size()); f.phi.resize(f.m.size());
    for (std::size_t k = 0; k < f.m.size(); ++k) {
      f.plo[k] = f.m[k] - f.dev[k];
      f.phi[k] = f.m[k] + f.dev[k];
    }
    kinks(f);
    double ay = 0, az = 0;
    for (std::size_t k = 0; k < n; ++k) { ay = std::max(ay, std::fabs(f.y[k])); az = std::max(az, std::fabs(f.z[k])); }
    f.abs_max = ay + az;
    for (int l = 1; l < kLevels; ++l) {
      const std::size_t step = std::size_t{1} << l;
      NodeLevel& L = level[l];
      const std::size_t nc = n ? (n - 1) / step + 1 : 0;
      L.y.resize(nc); L.z.resize(nc);
      for (std::size_t k = 0; k < nc; ++k) { L.y[k] = f.y[k * step]; L.z[k] = f.z[k * step]; }
      L.m.assign(nc ? nc - 1 : 0, 0); L.dev.assign(L.m.size(), 0); L.e.assign(L.m.size(), 0);
      L.abs_max = f.abs_max;
      for (std::size_t k = 0; k + 1 < nc; ++k) {
        const std::size_t j0 = k * step, j1 = j0 + step;
        const double m = (f.z[j1] - f.z[j0]) / (f.y[j1] - f.y[j0]);
        double dev = 0, e = 0, off = 0;
        for (std::size_t i = j0; i < j1; ++i) {
          dev = std::max(dev, std::fabs(f.m[i] - m) + f.dev[i]);
          e = std::max(e, f.e[i]);
          off = std::max(off, std::fabs(f.z[i] - (f.z[j0] + m * (f.y[i] - f.y[j0]))));
        }
        L.m[k] = m;
        L.dev[k] = dev;
        L.e[k] = e + off + 1e-15;
      }
      // The slope ranges from the level below (its intervals 2k and 2k + 1 make up interval k).
      const NodeLevel& B = level[l - 1];
      L.plo.resize(L.m.size()); L.phi.resize(L.m.size());
      for (std::size_t k = 0; k < L.m.size(); ++k) {
        L.plo[k] = std::min(B.plo[2 * k], B.plo[2 * k + 1]);
        L.phi[k] = std::max(B.phi[2 * k], B.phi[2 * k + 1]);
      }
      kinks(L);
    }
  }
};

const NodeTable& node_table(const ProfileCurve& C, std::uint64_t build_id, int which) {
  // A few tables per thread and kind, the least recently used replaced: a caller alternating
  // between pairs (the two wheels of a wheelset step) finds both made, instead of remaking one
  // (and allocating) at every call.
  constexpr int kSlots = 4;
  thread_local NodeTable t[2][kSlots];
  thread_local std::uint64_t used[2][kSlots] = {};
  thread_local std::uint64_t clock = 0;
  ++clock;
  int lru = 0;
  for (int i = 0; i < kSlots; ++i) {
    NodeTable& T = t[which][i];
    if (T.id == build_id && T.curve == &C) {
      used[which][i] = clock;
      return T;
    }
    if (used[which][i] < used[which][lru]) lru = i;
  }
  NodeTable& T = t[which][lru];
  T.make(C, build_id);
  used[which][lru] = clock;
  return T;
}

// The nodes k0 < k1 of level T whose intervals cover [ya, yb] with one more on each side; false
// when that reaches beyond the nodes (or the level has fewer than 3).
bool node_range(const NodeLevel& T, double ya, double yb, std::size_t& k0, std::size_t& k1) {
  const std::size_t n = T.y.size();
  if (n < 3) return false;
  const double hg = T.y[1] - T.y[0];
  const double ka = std::floor((std::min(ya, yb) - T.y[0]) / hg) - 1, kb = std::ceil((std::max(ya, yb) - T.y[0]) / hg) + 1;
  if (!(ka >= 0) || !(kb <= static_cast<double>(n - 1))) return false;
  k0 = static_cast<std::size_t>(ka);
  k1 = static_cast<std::size_t>(kb);
  return true;
}

// The nodes whose intervals cover [ya, yb] (the curve's own y) with one more on each side,
// placed in the rail frame at y + dy, z + dzv, seen from plane P (c, sn); `sign` +1 the wheel,
// −1 the rail (G = h_w − h_r): their kinks into `bins`. False when the range reaches beyond the
// nodes or D < kMinSlopeFactor.
bool plane_polyline(const NodeLevel& T, double ya, double yb, double dy, double dzv, const PatchPlane& P, double c,
                    double sn, double sign, PlanePolyline& out, KinkBins& bins) {
  std::size_t k0, k1;
  if (!node_range(T, ya, yb, k0, k1)) return false;
  const double asn = std::fabs(sn);
  const double ys = dy - P.y_ref, zs = dzv - P.z_ref;
  const double g0 = bins.g0, ih = bins.inv_half_h;
  const double nb = static_cast<double>(bins.A.size());
  double* A = bins.A.data();
  double* U = bins.U.data();
  // Plain pointers and signed indices: the loop's loads stay in registers, and int ↔ double
  // conversions are single instructions (size_t's are not).
  const double *Ty = T.y.data(), *Tz = T.z.data(), *Tm = T.m.data(), *Tdev = T.dev.data(), *Te = T.e.data();
  const int i0 = static_cast<int>(k0), i1 = static_cast<int>(k1);
  double prev_D = c + Tm[i0] * sn, D_min = prev_D, E = Te[i0], A_abs = 0;
  if (!(prev_D - asn * Tdev[i0] >= KinkBound::kMinSlopeFactor)) return false;
  for (int k = i0 + 1; k < i1; ++k) {  // interval k: nodes k, k + 1; the kink at node k
    const double D = c + Tm[k] * sn;
    if (!(D - asn * Tdev[k] >= KinkBound::kMinSlopeFactor)) return false;
    D_min = std::min(D_min, D);
    E = std::max(E, Te[k]);
    const double J = sign * (Tm[k] - Tm[k - 1]) / (D * prev_D);
    A_abs += std::fabs(J);
    const double t = ((Ty[k] + ys) * c + (Tz[k] + zs) * sn - g0) * ih;
    if (t >= 0 && t < nb) {  // a kink outside the bins weighs nothing at every centre
      const int j = static_cast<int>(t);
      A[j] += J;
      U[j] += J * (t - static_cast<double>(j));
    }
    prev_D = D;
  }
  out.D_min = D_min;
  out.E = E;
  bins.A_abs += A_abs;
  bins.kinks += static_cast<int>(k1 - k0 - 1);
  bins.coord = std::max(bins.coord, T.abs_max + std::fabs(dy) + std::fabs(dzv) + std::fabs(P.y_ref) + std::fabs(P.z_ref));
  return true;
}

// One curve's polyline at level L over the nodes covering [ya, yb] (one more each side), seen from
// the plane (gap_curvature_bound): the range of its kinks per plane length c_k = J_k / δ_k (J_k as
// in plane_polyline, δ_k = (Δs_k−1 + Δs_k)/2 the kink's trapezoid weight, Δs = Δy D), the largest
// plane spacing, the largest deviation E and the least D. With D_k ∈ [D_lo, D_hi] on the span
// (from the range of z'), c_k = 2 q_k / (D_k D_k−1 (D_k + D_k−1)) lies between q_k / D_hi³ and
// q_k / D_lo³. False as plane_polyline.
struct PolylineRange {
  double cmin = 0, cmax = 0, ds_max = 0, E = 0, D_min = 0;
};
bool polyline_range(const NodeLevel& T, double ya, double yb, double c, double sn, PolylineRange& out) {
  std::size_t i0, i1;
  if (!node_range(T, ya, yb, i0, i1)) return false;
  const double hg = T.y[1] - T.y[0];
  // Intervals i0 … i1 − 1, kinks at nodes i0 + 1 … i1 − 1: min/max scans, whole blocks where
  // they fit.
  constexpr std::size_t K = NodeLevel::kBlock;
  auto scan = [](std::size_t a, std::size_t b, auto&& one, auto&& block) {
    std::size_t k = a;
    for (; k < b && k % K != 0; ++k) one(k);
    for (; k + K <= b; k += K) block(k / K);
    for (; k < b; ++k) one(k);
  };
  double plo = INFINITY, phi = -INFINITY, E = 0;
  scan(
      i0, i1,
      [&](std::size_t k) { plo = std::min(plo, T.plo[k]); phi = std::max(phi, T.phi[k]); E = std::max(E, T.e[k]); },
      [&](std::size_t j) { plo = std::min(plo, T.bplo[j]); phi = std::max(phi, T.bphi[j]); E = std::max(E, T.be[j]); });
  double qmin = INFINITY, qmax = -INFINITY;
  scan(
      i0 + 1, i1, [&](std::size_t k) { qmin = std::min(qmin, T.q[k]); qmax = std::max(qmax, T.q[k]); },
      [&](std::size_t j) { qmin = std::min(qmin, T.bqlo[j]); qmax = std::max(qmax, T.bqhi[j]); });
  const double D_lo = c + (sn >= 0 ? sn * plo : sn * phi), D_hi = c + (sn >= 0 ? sn * phi : sn * plo);
  if (!(D_lo >= KinkBound::kMinSlopeFactor)) return false;
  const double lo3 = D_lo * D_lo * D_lo, hi3 = D_hi * D_hi * D_hi;
  out.cmax = qmax > 0 ? qmax / lo3 : qmax / hi3;
  out.cmin = qmin < 0 ? qmin / lo3 : qmin / hi3;
  out.ds_max = hg * D_hi;
  out.E = E;
  out.D_min = D_lo;
  return true;
}

// The span of the samples, [s_first − h, s_last + h], and where its end normals meet the curves:
// the rail's y and the wheel's own y at both ends (gap_kink_bound, gap_curvature_bound). False
// (no bound) for a rolled wheel (no node tables), no centres, or a normal on the rail's gauge
// face (the face is met by the normals below some s: qz + (qy − y_f) cos γ / sin γ grows with s
// at rate 1/sin γ, so none on the span if none at its start).
struct SpanEnds {
  double c = 1, sn = 0, sa = 0;
  NormalHits a, b;
  double yr_a = 0, yr_b = 0, yw_a = 0, yw_b = 0;
};
bool span_ends(const WheelRailGap& gap, const PatchPlane& P, double s_first, double h, int n, double dz, SpanEnds& e) {
  if (gap.build_id() == 0 || n < 1) return false;
  e.c = std::cos(P.gamma);
  e.sn = std::sin(P.gamma);
  e.sa = s_first - h;
  const double sb = s_first + 0.5 * h * (n - 1) + h;
  e.a = normal_hits(gap, P, e.c, e.sn, 0, e.sa, dz);
  e.b = normal_hits(gap, P, e.c, e.sn, 0, sb, dz);
  if (e.a.on_face || e.b.on_face) return false;
  e.yr_a = e.a.qy - e.a.h_r * e.sn;
  e.yr_b = e.b.qy - e.b.h_r * e.sn;
  e.yw_a = gap.y_wheel(e.a.qy - e.a.h_w * e.sn);
  e.yw_b = gap.y_wheel(e.b.qy - e.b.h_w * e.sn);
  return true;
}

// The polyline through every 2^l-th node with the largest l whose spacing is at most `spacing`.
const NodeLevel& level_at_most(const NodeTable& T, double spacing) {
  const NodeLevel& f = T.level[0];
  if (f.y.size() < 2) return f;
  int l = 0;
  while (l + 1 < NodeTable::kLevels && (f.y[1] - f.y[0]) * static_cast<double>(std::size_t{1} << (l + 1)) <= spacing) ++l;
  return T.level[l];
}

}  // namespace

KinkBound gap_curvature_bound(const WheelRailGap& gap, const PatchPlane& P, double s_first, double h, int n, double B,
                              double dz) {
  KinkBound out;
  SpanEnds e;
  if (!span_ends(gap, P, s_first, h, n, dz, e)) return out;
  // The polylines through every 2^l-th node, spaced at most 0.75 h: finer ones see the nodes'
  // height noise in their kinks per length (∝ 1/Δ²), coarser ones a larger trapezoid error
  // (∝ Δ²). Of the 297 Manchester patches of test_gap_kink_bound.cpp the bound passes 222 at
  // 0.5 h, 236 at 0.75 h, 222 at h.
  const double spacing = 0.75 * h;
  PolylineRange rr, wr;
  if (!polyline_range(level_at_most(node_table(gap.rail_curve(), gap.build_id(), 0), spacing), e.yr_a, e.yr_b, e.c,
                      e.sn, rr))
    return out;
  if (!polyline_range(level_at_most(node_table(gap.wheel_curve(), gap.build_id(), 1), spacing), e.yw_a, e.yw_b, e.c,
                      e.sn, wr))
    return out;
  // G_L = wheel − rail polylines: S_i = Σ_w J w_i − Σ_r J w_i (w_i = (1 − |s_k − s_i|/h)₊), and
  // with J = c δ and any κ̄ per curve, Σ c δ w_i = Σ (c − κ̄) δ w_i + κ̄ W_i, W_i = Σ δ w_i the
  // trapezoid rule of ∫ w_i ds = h on the polyline's nodes (w_i vanishes at the range's ends),
  // exact but on the three intervals holding w_i's kinks (slope jumps 1/h, 2/h, 1/h): |W_i − h| ≤
  // (4/h) Δs²/8. So |S_i − 2Bh| ≤ Σ_curves [r (h + err) + |κ̄| err] + |κ̄_w − κ̄_r − 2B| h with
  // κ̄ the middle of the curve's c range, r its half width, err = Δs_max²/(2h); plus, as in
  // gap_kink_bound, 4 (η + ε)/h for the curves' deviation from the polylines and the samples' error.
  auto part = [&](const PolylineRange& R, double& mid) {
    mid = 0.5 * (R.cmin + R.cmax);
    const double err = R.ds_max * R.ds_max / (2 * h);
    return 0.5 * (R.cmax - R.cmin) * (h + err) + std::fabs(mid) * err;
  };
  double kw, kr;
  const double pw = part(wr, kw), pr = part(rr, kr);
  const double eta = wr.E / wr.D_min + rr.E / rr.D_min;
  out.dtheta = (pw + pr + std::fabs(kw - kr - 2 * B) * h) * (1 + 1e-9) + 4 * (eta + kGapError) / h;
  out.found = std::isfinite(out.dtheta);
  return out;
}

KinkBound gap_kink_bound(const WheelRailGap& gap, const PatchPlane& P, double s_first, double h, int n, double B,
                         double dz, double spacing, double* centre_bound) {
  KinkBound out;
  SpanEnds e;
  if (!span_ends(gap, P, s_first, h, n, dz, e)) return out;
  const double c = e.c, sn = e.sn;
  // Bins j = 0 … n + 2 of width h/2 from g_0 = s_first − h (KinkBins): centre i is g_{i+2}.
  thread_local KinkBins bins;
  bins.reset(e.sa, h, n + 3);
  PlanePolyline rail, wheel;
  // The polylines through every 2^l-th node, spaced at most `spacing`: the coarser, the fewer
  // kinks to sum and the larger their distance from the curve (about κ Δ²/8 at spacing Δ).
  const NodeLevel& Tr = level_at_most(node_table(gap.rail_curve(), gap.build_id(), 0), spacing);
  const NodeLevel& Tw = level_at_most(node_table(gap.wheel_curve(), gap.build_id(), 1), spacing);
  if (!plane_polyline(Tr, e.yr_a, e.yr_b, 0, 0, P, c, sn, -1, rail, bins)) return out;
  if (!plane_polyline(Tw, e.yw_a, e.yw_b, e.a.qy - gap.y_wheel(e.a.qy), -gap.wheel_lift() - dz, P, c, sn, 1, wheel, bins))
    return out;
  const double eta = wheel.E / wheel.D_min + rail.E / rail.D_min;
  // Σ_k J_k (1 − |s_k − s_i|/h)₊ for centre i from bins i … i + 3 (offsets −2 … 1 from the
  // centre's edge g_{i+2}): weights u/2, (1 + u)/2, 1 − u/2, (1 − u)/2.
  const double* A = bins.A.data();
  const double* U = bins.U.data();
  const double twoBh = 2 * B * h;
  double worst = 0;
  for (int i = 0; i < n; ++i) {
    const double S = 0.5 * U[i] + 0.5 * (A[i + 1] + U[i + 1]) + (A[i + 2] - 0.5 * U[i + 2]) + 0.5 * (A[i + 3] - U[i + 3]);
    const double d = std::fabs(S - twoBh);
    if (centre_bound) centre_bound[i] = d;
    worst = std::max(worst, d);
  }
  // The rounding: a kink's plane coordinate is within δ = 8 ε (its coordinates' magnitudes) of
  // the exact one, and so is a centre's, which moves its weights by at most 2 δ / (h/2) plus
  // ε t (t < n + 3, its place in bins); each bin sum and a centre's eight terms add at most
  // (kinks + 8) ε Σ |J| (|J u| ≤ |J|). Doubled.
  const double delta = 8 * DBL_EPSILON * (bins.coord + std::fabs(s_first) + 2 * h);
  const double rounding = 2 * bins.A_abs * (4 * delta / h + DBL_EPSILON * (n + 3) + DBL_EPSILON * (bins.kinks + 8));
  const double deviation = 4 * (eta + kGapError) / h;
  out.dtheta = (worst + rounding) * (1 + 1e-9) + deviation;
  out.found = std::isfinite(out.dtheta);
  if (centre_bound && out.found)
    for (int i = 0; i < n; ++i) centre_bound[i] = (centre_bound[i] + rounding) * (1 + 1e-9) + deviation;
  return out;
}

}  // namespace mh
