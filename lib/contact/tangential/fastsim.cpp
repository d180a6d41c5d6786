// FASTSIM on one ellipse (fastsim.hpp).
#include "contact/tangential/fastsim.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
// MHC_FASTSIM_SCALAR: the plain C++ march on any host (tests/fastsim_paths compares the two).
#if defined(__SSE2__) && !defined(MHC_FASTSIM_SCALAR)
#define MHC_FASTSIM_SSE2 1
#include <emmintrin.h>
#endif

#include "contact/tangential/kalker.hpp"

namespace mh {

FastsimFlexibilities fastsim_flexibilities(double a, double b, double G, double nu) {
  const KalkerCoefficients k = kalker_coefficients(a / b, nu);
  // Kalker 1982 (fastsim.hpp): chosen so that the traction of the linear limit integrates to
  // Kalker's linear-theory forces (checked by tests/unit/contact/test_fastsim.cpp).
  return {8.0 * a / (3.0 * k.C11 * G), 8.0 * a / (3.0 * k.C22 * G),
          M_PI * a * std::sqrt(a / b) / (4.0 * k.C23 * G)};
}

namespace {

// Vollebregt & Voltr 2023 as CONTACT 25.2 applies it (m_hertz.f90, simpflex; the paper itself not
// read here): one combined flexibility L_c, the mean of L1, L2, L3 weighted by the creepages'
// squares in harmonic form (the spin scaled by (πa²/4) / (8a/3)), blended in with the weight
// min(1, f/3), f the translational creepage relative to the one that saturates linear theory.
void blend(FastsimFlexibilities& L, const Creepages& cr, double a, double b, double N, double mu,
           double G, double nu) {
  const KalkerCoefficients k = kalker_coefficients(a / b, nu);
  const double c2 = a * b;
  const double ch_xi = mu * N / (c2 * G * k.C11), ch_eta = mu * N / (c2 * G * k.C22);
  const double sp = cr.phi * (M_PI * a * a / 4.0) / (8.0 * a / 3.0);
  const double num = cr.xi * cr.xi + cr.eta * cr.eta + sp * sp;
  double den = cr.xi * cr.xi / L.L1 + cr.eta * cr.eta / L.L2 + sp * sp / L.L3;
  if (std::abs(den) < 1e-14) den = 1e-14;
  const double Lc = num / den;
  const double f = std::max(1e-10, std::sqrt((cr.xi * cr.xi + cr.eta * cr.eta) / (ch_xi * ch_xi + ch_eta * ch_eta)));
  const double w = std::min(1.0, f / 3.0);
  L.L1 = (1 - w) * L.L1 + w * Lc;
  L.L2 = (1 - w) * L.L2 + w * Lc;
  L.L3 = (1 - w) * L.L3 + w * Lc;
}

}  // namespace

namespace {

// The march (fastsim() below); kSlope: also the derivative of the tractions in λ, the creepages
// ξ, η scaled by λ (fastsim.hpp, load_slope), beside the same arithmetic.
template <bool kSlope>
TangentialResult march(const Creepages& cr, double a, double b, double N, double mu, double G, double nu,
                       const FastsimOptions& o, FastsimGrid* grid) {
  assert(a > 0 && b > 0 && N >= 0 && mu >= 0 && G > 0 && o.nx >= 1 && o.ny >= 1 && o.nx <= kFastsimMaxN);
  const int nx = o.nx, ny = o.ny;
  FastsimFlexibilities L = fastsim_flexibilities(a, b, G, nu);
  if (o.blend) blend(L, cr, a, b, N, mu, G, nu);
  const bool ell = o.bound == TractionBound::Elliptical;
  if (grid) {
    const size_t n = static_cast<size_t>(nx) * ny;
    grid->nx = nx;
    grid->ny = ny;
    for (auto* v : {&grid->x, &grid->y, &grid->px, &grid->py, &grid->pn}) v->assign(n, 0.0);
    grid->slip.assign(n, 0);
  }

  // The bound's shape factorises: p_n = P q(y_j) f(s_k), s = x / a(y_j) the cell centre's place on
  // its strip. Its discrete integral Σ_j dy a_j q_j Σ_k ds f(s_k) fixes P. f(s_k) is the same on
  // every strip: tabulated once (on the stack: no allocation).
  const double dy = 2.0 * b / ny, ds = 2.0 / nx;
  double f[kFastsimMaxN];
  double rf[kSlope ? kFastsimMaxN : 1];  // kSlope: 1/f(s_k), the bound's reciprocal without a division per cell
  double Rs = 0;
  for (int k = 0; k < nx; ++k) {
    const double s = 1.0 - (k + 0.5) * ds, u = 1.0 - s * s;
    f[k] = ell ? std::sqrt(u) : u;
    if (kSlope) rf[k] = 1.0 / f[k];
    Rs += ds * f[k];
  }
  double Ry = 0;
  for (int j = 0; j < ny; ++j) {
    const double yb = -1.0 + (j + 0.5) * (2.0 / ny), u = 1.0 - yb * yb;
    Ry += dy * a * std::sqrt(u) * (ell ? std::sqrt(u) : u);
  }
  const double P = (Rs * Ry > 0) ? N / (Rs * Ry) : 0.0;

  // Cell-centred marching: the traction at the centre x_k = a_j − (k + ½) h is the previous
  // centre's (after the bound) plus the exact integral of the gradient between the two (half a
  // step from the leading edge for the first); the midpoint rule integrates it. The bound is
  // never 0 at a centre, so the linear limit is reproduced to the midpoint rule's accuracy.
  //
  // Speed: each cell's traction depends on the previous one through a square root and a division
  // where it slips, so one strip alone runs at the latency of that chain. kLanes strips are
  // marched side by side, independent chains the processor overlaps (with SSE2 two to a register,
  // the projection on every lane: 8 lanes, four registers of chains, measured fastest of 4, 8, 16
  // on the 16-strip wheelset step, docs/performance.md). Each strip's arithmetic and the order of
  // the sums are those of a strip-by-strip march, so the results do not depend on kLanes or on
  // the vector path. Lanes past the last strip run with a = 0 and are not summed.
  constexpr int kLanes = 8;
  const double gx = cr.xi / L.L1, gy = cr.eta / L.L2, gs = cr.phi / L.L3;
  double Fx = 0, Fy = 0, Mz = 0, n_adh = 0, n_all = 0, dFx = 0, dFy = 0;
  for (int j0 = 0; j0 < ny; j0 += kLanes) {
    double aj[kLanes], h[kLanes], y[kLanes], brow[kLanes], gxy[kLanes], pnr[kLanes];
    double px[kLanes], py[kLanes], x[kLanes], rFx[kLanes], rFy[kLanes], rM[kLanes];
    double dpx[kLanes], dpy[kLanes], rdFx[kLanes], rdFy[kLanes], rbrow[kLanes];  // kSlope: d/dλ
    double rA[kLanes];  // adhesion cells (counts, exact in a double)
    bool slip[kLanes];
    for (int l = 0; l < kLanes; ++l) {
      const int j = std::min(j0 + l, ny - 1);
      const double yb = -1.0 + (j + 0.5) * (2.0 / ny), u = 1.0 - yb * yb;
      const bool real = j0 + l < ny;
      y[l] = b * yb;
      aj[l] = real ? a * std::sqrt(u) : 0.0;
      h[l] = aj[l] * ds;
      pnr[l] = P * (ell ? std::sqrt(u) : u);
      brow[l] = mu * P * (ell ? std::sqrt(u) : u);
      gxy[l] = gx - gs * y[l];  // ∂px/∂x on this strip
      px[l] = py[l] = 0;
      x[l] = aj[l];
      rFx[l] = rFy[l] = rM[l] = 0;
      dpx[l] = dpy[l] = rdFx[l] = rdFy[l] = 0;
      rbrow[l] = brow[l] > 0 ? 1.0 / brow[l] : 0.0;
      rA[l] = 0;
    }
    // The lanes' cells of column k into the grid.
    auto keep_cells = [&](int k) {
      for (int l = 0; l < kLanes && j0 + l < ny; ++l) {
        const size_t i = static_cast<size_t>(j0 + l) * nx + k;
        grid->x[i] = x[l];
        grid->y[i] = y[l];
        grid->px[i] = px[l];
        grid->py[i] = py[l];
        grid->pn[i] = pnr[l] * f[k];
        grid->slip[i] = slip[l];
      }
    };
#if defined(MHC_FASTSIM_SSE2)
    // The same arithmetic, two lanes to a register (IEEE operations lane by lane: the same bits);
    // the projection computed on every lane and selected where it slips (no branch; where it
    // sticks the quotient is not used, pt2 may be 0).
    {
      constexpr int kPairs = kLanes / 2;
      __m128d vaj[kPairs], vh[kPairs], vy[kPairs], vbrow[kPairs], vgxy[kPairs], vrbrow[kPairs];
      __m128d vpx[kPairs], vpy[kPairs], vx[kPairs], vrFx[kPairs], vrFy[kPairs], vrM[kPairs], vrA[kPairs];
      __m128d vdpx[kPairs], vdpy[kPairs], vrdFx[kPairs], vrdFy[kPairs];
      for (int p = 0; p < kPairs; ++p) {
        vaj[p] = _mm_loadu_pd(aj + 2 * p); vh[p] = _mm_loadu_pd(h + 2 * p); vy[p] = _mm_loadu_pd(y + 2 * p);
        vbrow[p] = _mm_loadu_pd(brow + 2 * p); vgxy[p] = _mm_loadu_pd(gxy + 2 * p); vrbrow[p] = _mm_loadu_pd(rbrow + 2 * p);
        vpx[p] = _mm_loadu_pd(px + 2 * p); vpy[p] = _mm_loadu_pd(py + 2 * p);
        vdpx[p] = _mm_loadu_pd(dpx + 2 * p); vdpy[p] = _mm_loadu_pd(dpy + 2 * p);
        vrFx[p] = vrFy[p] = vrM[p] = vrA[p] = vrdFx[p] = vrdFy[p] = _mm_setzero_pd();
        vx[p] = vaj[p];
      }
      const __m128d vgx = _mm_set1_pd(gx), vgy = _mm_set1_pd(gy), vhgs = _mm_set1_pd(0.5 * gs), one = _mm_set1_pd(1.0);
      for (int k = 0; k < nx; ++k) {
        const __m128d vfk = _mm_set1_pd(f[k]), vkc = _mm_set1_pd(k + 0.5);
        const __m128d vrf = _mm_set1_pd(kSlope ? rf[k] : 0.0);
        for (int p = 0; p < kPairs; ++p) {
          const __m128d xn = _mm_sub_pd(vaj[p], _mm_mul_pd(vkc, vh[p]));
          const __m128d d = _mm_sub_pd(vx[p], xn);
          if (kSlope) {
            vdpx[p] = _mm_sub_pd(vdpx[p], _mm_mul_pd(vgx, d));
            vdpy[p] = _mm_sub_pd(vdpy[p], _mm_mul_pd(vgy, d));
          }
          __m128d tx = _mm_sub_pd(vpx[p], _mm_mul_pd(vgxy[p], d));
          const __m128d sq = _mm_sub_pd(_mm_mul_pd(vx[p], vx[p]), _mm_mul_pd(xn, xn));
          __m128d ty = _mm_sub_pd(vpy[p], _mm_add_pd(_mm_mul_pd(vgy, d), _mm_mul_pd(vhgs, sq)));
          vx[p] = xn;
          const __m128d bound = _mm_mul_pd(vbrow[p], vfk);
          const __m128d pt2 = _mm_add_pd(_mm_mul_pd(tx, tx), _mm_mul_pd(ty, ty));
          const __m128d sl = _mm_cmpgt_pd(pt2, _mm_mul_pd(bound, bound));
          const __m128d scale = _mm_div_pd(bound, _mm_sqrt_pd(pt2));
          if (kSlope) {
            const __m128d ip = _mm_mul_pd(_mm_mul_pd(scale, vrbrow[p]), vrf);
            const __m128d pd =
                _mm_mul_pd(_mm_mul_pd(_mm_add_pd(_mm_mul_pd(tx, vdpx[p]), _mm_mul_pd(ty, vdpy[p])), ip), ip);
            const __m128d ex = _mm_mul_pd(scale, _mm_sub_pd(vdpx[p], _mm_mul_pd(tx, pd)));
            const __m128d ey = _mm_mul_pd(scale, _mm_sub_pd(vdpy[p], _mm_mul_pd(ty, pd)));
            vdpx[p] = _mm_or_pd(_mm_and_pd(sl, ex), _mm_andnot_pd(sl, vdpx[p]));
            vdpy[p] = _mm_or_pd(_mm_and_pd(sl, ey), _mm_andnot_pd(sl, vdpy[p]));
            vrdFx[p] = _mm_add_pd(vrdFx[p], vdpx[p]);
            vrdFy[p] = _mm_add_pd(vrdFy[p], vdpy[p]);
          }
          tx = _mm_or_pd(_mm_and_pd(sl, _mm_mul_pd(tx, scale)), _mm_andnot_pd(sl, tx));
          ty = _mm_or_pd(_mm_and_pd(sl, _mm_mul_pd(ty, scale)), _mm_andnot_pd(sl, ty));
          vpx[p] = tx;
          vpy[p] = ty;
          vrA[p] = _mm_add_pd(vrA[p], _mm_andnot_pd(sl, one));
          vrFx[p] = _mm_add_pd(vrFx[p], tx);
          vrFy[p] = _mm_add_pd(vrFy[p], ty);
          vrM[p] = _mm_add_pd(vrM[p], _mm_sub_pd(_mm_mul_pd(xn, ty), _mm_mul_pd(vy[p], tx)));
          if (grid) {
            const int m = _mm_movemask_pd(sl);
            slip[2 * p] = (m & 1) != 0;
            slip[2 * p + 1] = (m & 2) != 0;
            _mm_storeu_pd(x + 2 * p, xn);
            _mm_storeu_pd(px + 2 * p, vpx[p]);
            _mm_storeu_pd(py + 2 * p, vpy[p]);
          }
        }
        if (grid) keep_cells(k);
      }
      for (int p = 0; p < kPairs; ++p) {
        _mm_storeu_pd(rFx + 2 * p, vrFx[p]); _mm_storeu_pd(rFy + 2 * p, vrFy[p]); _mm_storeu_pd(rM + 2 * p, vrM[p]);
        _mm_storeu_pd(rdFx + 2 * p, vrdFx[p]); _mm_storeu_pd(rdFy + 2 * p, vrdFy[p]); _mm_storeu_pd(rA + 2 * p, vrA[p]);
      }
    }
#else
    for (int k = 0; k < nx; ++k) {
      const double fk = f[k], kc = k + 0.5;
      for (int l = 0; l < kLanes; ++l) {
        const double xn = aj[l] - kc * h[l];
        if (kSlope) {
          dpx[l] -= gx * (x[l] - xn);
          dpy[l] -= gy * (x[l] - xn);
        }
        px[l] -= gxy[l] * (x[l] - xn);
        py[l] -= gy * (x[l] - xn) + 0.5 * gs * (x[l] * x[l] - xn * xn);  // ∫_{xn}^{x} (η/L2 + φ x'/L3) dx'
        x[l] = xn;
        const double bound = brow[l] * fk;
        const double pt2 = px[l] * px[l] + py[l] * py[l];
        const bool sl = pt2 > bound * bound;
        // Onto the bound, in the direction of the adhesion traction (Kalker 1982).
        if (sl) {
          const double scale = bound / std::sqrt(pt2);
          if (kSlope) {  // the projection's derivative: scale (dp − p (p·dp)/|p|²), 1/|p| = scale/bound
            const double ip = scale * rbrow[l] * rf[k];
            const double pd = (px[l] * dpx[l] + py[l] * dpy[l]) * ip * ip;
            dpx[l] = scale * (dpx[l] - px[l] * pd);
            dpy[l] = scale * (dpy[l] - py[l] * pd);
          }
          px[l] *= scale;
          py[l] *= scale;
        }
        if (kSlope) {
          rdFx[l] += dpx[l];
          rdFy[l] += dpy[l];
        }
        rA[l] += sl ? 0 : 1;
        slip[l] = sl;
        rFx[l] += px[l];
        rFy[l] += py[l];
        rM[l] += xn * py[l] - y[l] * px[l];
      }
      if (grid) keep_cells(k);
    }
#endif
    for (int l = 0; l < kLanes && j0 + l < ny; ++l) {
      const double wA = h[l] * dy;
      Fx += wA * rFx[l];
      Fy += wA * rFy[l];
      Mz += wA * rM[l];
      if (kSlope) {
        dFx += wA * rdFx[l];
        dFy += wA * rdFy[l];
      }
      n_adh += wA * rA[l];
      n_all += wA * nx;
    }
  }

  TangentialResult r;
  r.c = cr;
  r.mu = mu;
  r.Fx = Fx;
  r.Fy = Fy;
  r.Mz = Mz;
  r.adhesion_fraction = n_all > 0 ? n_adh / n_all : NAN;
  r.Tgamma = -(Fx * cr.xi + Fy * cr.eta);
  r.Tgamma_spin = -Mz * cr.phi;
  r.iterations = 0;
  r.solved = true;
  if (kSlope && N > 0) {
    // Kalker's similarity (fastsim.hpp): dF/dN = F/N − (ξ ∂F/∂ξ + η ∂F/∂η)/(3N).
    r.dFx_dN = (Fx - dFx / 3.0) / N;
    r.dFy_dN = (Fy - dFy / 3.0) / N;
  }
  return r;
}

}  // namespace

TangentialResult fastsim(const Creepages& cr, double a, double b, double N, double mu, double G,
                         double nu, const FastsimOptions& o, FastsimGrid* grid) {
  return o.load_slope ? march<true>(cr, a, b, N, mu, G, nu, o, grid) : march<false>(cr, a, b, N, mu, G, nu, o, grid);
}

}  // namespace mh
