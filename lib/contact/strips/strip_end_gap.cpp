// Strip extents that close the deformed gap at the strip ends (docs/method.md §9 item 3, "end
// gap"); see strip_collocation.hpp.
//
// At a strip's end x = c_i ± a_i the pressure falls to zero and the surfaces just meet:
//   g_i + A_i a_i² + u(c_i ± a_i, s_i) = δ.
// With the collocation at the centre, u(c_i, s_i) = δ − g_i, this reads A_i a_i² = D_i: the rise
// of the rigid gap over the half-length equals the drop of the elastic displacement from the
// centre to the end, D_i = Σ_j q_j [K_ij − K_end,ij] (contact/strips/strip_kernel.hpp, the drop E(t, r)).
// For a Hertz ellipse the semi-elliptic strips satisfy it exactly; for any other patch it replaces
// the rigid-geometry rules of contact/strips/strip_extents.hpp, which guess the extent from the
// undeformed gap alone and miss where the pressure has two lobes over a concave gap (docs/strips.md).
//
// The extents and the amplitudes are found together: the extents are a fixed point
// a ↦ sqrt((δ − g − u_end(a, q(a))) / A), q(a) the collocation at those extents, iterated from
// the estimate with Anderson acceleration (Walker & Ni, SIAM J. Numer. Anal. 49 (2011) 1715–1735;
// the plain iteration contracts by only about 0.75–0.85 per pass at a strip shorter than its
// neighbours: its end lies where they keep the surfaces together, and the condition barely moves it). With the load given, each pass also solves for the
// approach at its extents (N is piecewise linear in δ at fixed extents: a secant on one
// factorisation), so that every pass carries the load exactly.
#include "contact/strips/strip_end_gap.hpp"

#include "contact/strips/strip_influence.hpp"
#include "core/numfmt.hpp"
#include "contact/strips/strip_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mh {
namespace strips_detail {

namespace {

constexpr int kMaxPasses = 60;             // fixed-point passes of the extents
constexpr int kDepth = 5;                  // Anderson acceleration: the last kDepth passes
constexpr double kAreaRtolLoad = 1e-3;     // settled when the extents move by less than this of their sum
                                           //   (the area within about 0.1 % of the fixed point, far inside
                                           //   the method's accuracy; 1e-4 cost 1.5 times as much and moved
                                           //   the Manchester sweep by <= 0.2 % in area) …
constexpr double kAreaRtolApproach = 1e-6; // … tighter with the approach given: N(δ) must be smooth for the
                                           //   force balance across patches (contact/grid/patch_driver.hpp)
constexpr int kMaxLoadSteps = 40;          // secant steps on the approach at fixed extents

/// The load of a collocation [N].
double load(const Collocation& c, double ds) {
  double N = 0;
  for (int ii = 0; ii < static_cast<int>(c.cand.size()); ++ii) N += strip_load(c, ii, ds);
  return N;
}

using Source = StripEndGapScratch::Source;

/// The drop of the displacement from the centre of each field strip (geometry index `field[k]`)
/// to its end (half-length `end[k]`), D_k = Σ_j q_j [K(centre) − K(end)] over the sources [m].
void drops(const Solver& S, const std::vector<int>& field, const std::vector<double>& end,
           const std::vector<Source>& src, std::vector<double>& D) {
  const StripGeometry& geo = S.geo;
  const int nf = static_cast<int>(field.size());
  D.assign(nf, 0.0);
  if (nf == 0) return;
  StripEndGapScratch& w = S.end_gap;
  std::vector<StripDropR>& R = w.R;
  std::vector<double>& centre = w.centre;
  std::vector<char>& need = w.need;
  CappedSource& cs = w.cs;
  std::vector<int>& kk = w.kk;
  std::vector<double>& t = w.t;
  kk.resize(static_cast<std::size_t>(nf));
  t.resize(static_cast<std::size_t>(nf));
  for (const Source& sj : src) {
    if (!(sj.a > 0) || !(sj.q > 0)) continue;
    if (!S.same_xc) {
      for (int k = 0; k < nf; ++k)
        D[k] += sj.q * (S.K_end(field[k], 0.0, sj.j, sj.a, sj.rcap) - S.K_end(field[k], end[k], sj.j, sj.a, sj.rcap));
      continue;
    }
    if (sj.rcap < 1.0) {
      // A capped source (no table for its flat top): the centres by distance, one column, the
      // ends by quadrature on its prepared nodes (strip_influence.hpp).
      const int dmax = std::max(std::abs(sj.j - field.front()), std::abs(sj.j - field.back()));
      // Only the field strips' distances: capped strips are no field points, and the field of a
      // mostly capped patch is a few tail strips either side.
      need.assign(static_cast<std::size_t>(dmax) + 1, 0);
      for (int k = 0; k < nf; ++k) need[static_cast<std::size_t>(std::abs(sj.j - field[k]))] = 1;
      capped_centre_line(sj.a, geo.ds, sj.rcap, dmax, S.gx, S.gw, centre, &need, S.log2_edge.data() + S.n + 1);
      capped_source(sj.a, sj.rcap, S.gx, S.gw, cs);
      for (int k = 0; k < nf; ++k) {
        const double e1 = geo.s[sj.j] - 0.5 * geo.ds - geo.s[field[k]];
        const double uend = S.H * capped_source_influence(cs, end[k], e1, e1 + geo.ds);
        D[k] += sj.q * (S.H * centre[std::abs(sj.j - field[k])] - uend);
      }
      continue;
    }
    // Uniform strips: the field strip i sees the source's edges at (j − i ∓ ½) ds; each edge
    // value is prepared once for all field strips (strip_kernel.hpp).
    const int kmin = sj.j - field.back(), kmax = sj.j - field.front();
    R.resize(static_cast<std::size_t>(kmax - kmin + 2));
    const double la = std::log2(sj.a);
    for (int k = kmin; k <= kmax + 1; ++k)
      R[k - kmin] = strip_kernel_drop_prepare((k - 0.5) * geo.ds / sj.a, S.log2_edge[k + S.n] - la);
    for (int i = 0; i < nf; ++i) {
      kk[i] = sj.j - field[i] - kmin;
      t[i] = end[i] / sj.a;
    }
    strip_kernel_drop_diffs(R.data(), kk.data(), t.data(), nf, S.H * sj.q * sj.a, D.data());
  }
}

/// The end-gap extents of a collocation's strips (per geometry strip, zero outside the contact):
/// loaded elastic strips from A a² = δ − g − u_end at their ends; capped strips keep theirs (the
/// plastic law sets a capped strip's length from its load and its overlap, §9 item 6); unloaded strips the length
/// over which their centre is still interpenetrated (zero when it is not: the widening rule of
/// item 7, the limit of the end rule for a strip entering the patch).
void end_extents(const Solver& S, double delta, const Collocation& c, std::vector<double>& anew) {
  const StripGeometry& geo = S.geo;
  const int m = static_cast<int>(c.cand.size());
  std::fill(anew.begin(), anew.end(), 0.0);
  StripEndGapScratch& w = S.end_gap;
  // Displacement at every centre.
  w.qv.assign(c.q.begin(), c.q.begin() + m);
  std::vector<double>& qv = w.qv;
  std::vector<Source>& src = w.src;
  src.clear();
  for (int jj = 0; jj < m; ++jj) {
    if (c.capped[jj]) { qv[jj] = 0; src.push_back({c.cand[jj], c.aeff[jj], c.q[jj], c.rcap[jj]}); continue; }
    if (c.q[jj] > 0) src.push_back({c.cand[jj], c.a[jj], c.q[jj], 1.0});
    else qv[jj] = 0;
  }
  w.u.resize(static_cast<std::size_t>(m));
  Eigen::Map<Eigen::VectorXd> u(w.u.data(), m);
  u.noalias() = c.K.map() * Eigen::Map<const Eigen::VectorXd>(qv.data(), m);
  if (c.Ucap.rows == m)
    for (int jj = 0; jj < m; ++jj)
      if (c.capped[jj]) u += Eigen::Map<const Eigen::VectorXd>(c.Ucap.col(jj), m);
  std::vector<int>& field = w.field;
  std::vector<double>& end = w.end;
  std::vector<double>& D = w.D;
  field.clear();
  end.clear();
  for (int ii = 0; ii < m; ++ii)
    if (c.q[ii] > 0 && !c.capped[ii]) { field.push_back(c.cand[ii]); end.push_back(c.a[ii]); }
  drops(S, field, end, src, D);
  for (int ii = 0, k = 0; ii < m; ++ii) {
    const int i = c.cand[ii];
    if (c.capped[ii]) {  // kept
      anew[i] = c.a[ii];
      continue;
    }
    const double drop = c.q[ii] > 0 ? D[k++] : 0.0;  // none for an unloaded strip: its centre decides
    if (!(geo.g[i] < delta)) continue;
    const double pen = delta - geo.g[i] - u(ii) + drop;
    anew[i] = pen > 0 ? std::sqrt(pen / geo.A[i]) : 0.0;
  }
}

}  // namespace

double end_gap_error(const Solver& S, const StripResult& r, double p_lim) {
  StripEndGapScratch& w = S.end_gap;
  std::vector<int>& field = w.field;
  std::vector<double>& end = w.end;
  std::vector<double>& D = w.D;
  std::vector<Source>& src = w.src;
  field.clear();
  end.clear();
  src.clear();
  for (const StripState& st : r.strips) {
    src.push_back({st.index, st.a, st.q, st.plastic ? p_lim / st.q : 1.0});
    if (st.plastic) continue;  // a capped strip's length follows from its load and overlap, not its end gap
    field.push_back(st.index);
    end.push_back(st.a);
  }
  drops(S, field, end, src, D);
  double wsum = 0, werr = 0;
  for (std::size_t k = 0, f = 0; k < r.strips.size(); ++k) {
    const StripState& st = r.strips[k];
    if (st.plastic) continue;
    // The centre's collocation holds (δ − g_i = u_centre), so the end's interpenetration is the drop.
    const double err = std::fabs(1.0 - D[f++] / (S.geo.A[st.index] * st.a * st.a));
    wsum += st.load;
    werr += st.load * err;
  }
  return wsum > 0 ? werr / wsum : 0.0;
}

void refine_extents(const Solver& S, bool load_given, double target, double p_lim, const StripResult& start,
                    StripResult& res) {
  const int n = S.n;
  const StripGeometry& geo = S.geo;
  const double gmin = S.gmin;
  StripEndGapScratch& w = S.end_gap;
  std::vector<double>& a = w.a;
  std::vector<double>& anew = w.anew;
  a.assign(static_cast<std::size_t>(n), 0.0);
  anew.assign(static_cast<std::size_t>(n), 0.0);
  for (const StripState& st : start.strips)
    a[st.index] = st.plastic ? st.a_elastic : st.a;  // a capped strip: its extent before lengthening
  double delta = load_given ? start.delta : target;
  if (!(delta > gmin)) delta = gmin + 1e-3 * std::fabs(gmin) + 1e-9;  // load control starts inside the contact
  std::vector<char>& was_loaded = w.was_loaded;
  was_loaded.assign(static_cast<std::size_t>(n), 0);
  for (const StripState& st : start.strips) was_loaded[st.index] = 1;
  const double rtol = load_given ? kAreaRtolLoad : kAreaRtolApproach;

  // Anderson acceleration on x = a (all strips), f = anew − a: the last kDepth differences in
  // w.dX, w.dF (columns in a ring from w.oldest).
  w.dX.resize(n, kDepth);
  w.dF.resize(n, kDepth);
  w.n_diff = w.oldest = 0;
  bool have_prev = false;
  w.x_prev.resize(static_cast<std::size_t>(n));
  w.f_prev.resize(static_cast<std::size_t>(n));
  using Vec = Eigen::Map<Eigen::VectorXd>;
  Vec x_prev(w.x_prev.data(), n), f_prev(w.f_prev.data(), n);
  double slope = NAN;  // dN/dδ at fixed extents, from the previous pass's secant
  Collocation& c = S.scratch.refine;
  c.reset();
  std::vector<double>& built = w.built;  // the extent each column of c.K was built for
  built.clear();
  std::vector<int>& cand = w.cand;
  for (int pass = 1;; ++pass) {
    // The strips taking part: those with an extent, and those interpenetrated (they may enter).
    // With the same strips as the last pass, K keeps the columns whose extent did not move (the
    // capped strips keep theirs through the refinement); else it is built anew.
    cand.clear();
    for (int i = 0; i < n; ++i)
      if (a[i] > 0 || geo.g[i] < delta) cand.push_back(i);
    if (cand != c.cand) {
      c.reset();
      c.cand = cand;
      built.clear();
    }
    c.a.clear();
    for (int i : c.cand) c.a.push_back(a[i]);
    if (c.cand.empty()) {
      clear_result(res);
      res.status = StripStatus::NoContact;
      res.message = "end-gap extents: no strip keeps a positive extent";
      res.delta = delta;
      return;
    }
    const int m = static_cast<int>(c.cand.size());
    S.build_K(c, built);
    std::vector<char>& act = w.act;
    act.resize(static_cast<std::size_t>(m));
    for (int ii = 0; ii < m; ++ii) act[ii] = was_loaded[c.cand[ii]];
    S.collocate(delta, p_lim, c, act);
    if (load_given) {
      // The approach that carries the load at these extents: secant on N(δ) (linear while the
      // active and plastic sets stay, one factorisation), bracketed, from the previous approach.
      const double Nt = target;
      double N = load(c, geo.ds);
      double lo = gmin, hi = std::numeric_limits<double>::infinity(), d_prev = NAN, N_prev = NAN;
      for (int it = 0; it < kMaxLoadSteps && std::fabs(N - Nt) > S.opt.load_rtol * Nt && c.as_ok && c.settled; ++it) {
        (N < Nt ? lo : hi) = delta;
        double next;
        if (std::isfinite(d_prev) && N != N_prev) next = delta - (N - Nt) * (delta - d_prev) / (N - N_prev);
        else if (std::isfinite(slope) && slope > 0) next = delta - (N - Nt) / slope;
        else next = delta - (N - Nt) * (delta - gmin) / (1.5 * std::max(N, 1e-3 * Nt));  // Hertz: N ∝ (δ − g)^{3/2}
        if (!(next > lo && next < hi)) next = std::isfinite(hi) ? 0.5 * (lo + hi) : gmin + 2 * (delta - gmin);
        if (std::isfinite(d_prev) && N != N_prev) slope = (N - N_prev) / (delta - d_prev);
        d_prev = delta;
        N_prev = N;
        delta = next;
        S.collocate(delta, p_lim, c, act);
        N = load(c, geo.ds);
      }
      if (std::isfinite(d_prev) && N != N_prev && delta != d_prev) slope = (N - N_prev) / (delta - d_prev);
    }
    if (!c.as_ok || !c.settled) {
      S.assemble(delta, p_lim, c, res);
      res.iterations = pass;
      return;  // NotConverged, with assemble's message
    }
    for (int ii = 0; ii < m; ++ii) was_loaded[c.cand[ii]] = c.q[ii] > 0 || c.capped[ii];
    end_extents(S, delta, c, anew);
    // Settled when the extents move by less than rtol of their sum (the contact area): the
    // slowest modes of the iteration (a strip shorter than its neighbours, whose end lies where
    // they keep the surfaces together) barely move the pressure, the load or the area.
    double moved = 0, total = 0;
    for (int i = 0; i < n; ++i) {
      moved += std::fabs(anew[i] - a[i]);
      total += a[i];
    }
    if (moved <= rtol * total) {  // c holds the solution at extents a
      S.assemble(delta, p_lim, c, res);
      res.iterations = pass;
      return;
    }
    if (pass >= kMaxPasses) {
      S.assemble(delta, p_lim, c, res);
      res.status = StripStatus::NotConverged;
      assign_format(res.message, "end-gap extents did not settle in %d passes (the last moved the extents by %g of their sum)",
                    kMaxPasses, moved / total);
      res.failure = Warning(WarningClass::NotConvergedEndGap)
                        .add(Quantity::Passes, kMaxPasses)
                        .add(Quantity::ExtentsMoved, moved / total, '>', rtol);
      res.iterations = pass;
      return;
    }
    // Anderson step (type II): x+ = x + f − (ΔX + ΔF) γ, γ = argmin |f − ΔF γ|.
    w.x.assign(a.begin(), a.end());
    w.f.resize(static_cast<std::size_t>(n));
    const Vec x(w.x.data(), n);
    Vec f(w.f.data(), n);
    f = Vec(anew.data(), n) - x;
    if (have_prev) {
      int slot;
      if (w.n_diff < kDepth) {
        slot = (w.oldest + w.n_diff) % kDepth;
        ++w.n_diff;
      } else {  // full: the oldest goes
        slot = w.oldest;
        w.oldest = (w.oldest + 1) % kDepth;
      }
      Vec(w.dX.col(slot), n) = x - x_prev;
      Vec(w.dF.col(slot), n) = f - f_prev;
    }
    x_prev = x;
    f_prev = f;
    have_prev = true;
    w.xn.resize(static_cast<std::size_t>(n));
    Vec xn(w.xn.data(), n);
    xn = x + f;
    if (w.n_diff > 0) {
      const int k = w.n_diff;
      w.Fm.resize(n, k);
      w.XF.resize(n, k);
      for (int cc = 0; cc < k; ++cc) {  // in age order, as the columns were appended
        const int col = (w.oldest + cc) % kDepth;
        Vec(w.Fm.col(cc), n) = Vec(w.dF.col(col), n);
        Vec(w.XF.col(cc), n) = Vec(w.dX.col(col), n) + Vec(w.dF.col(col), n);
      }
      // γ by Eigen's column-pivoting Householder QR, kept per shape, and its solve (the steps of
      // ColPivHouseholderQR::solve, whose copy of the right-hand side would allocate).
      auto& qr = w.qrs.get({n, k}, [&] { return Eigen::ColPivHouseholderQR<Eigen::MatrixXd>(n, k); });
      qr.compute(w.Fm.map());
      w.gam.assign(static_cast<std::size_t>(k), 0.0);
      const Eigen::Index nz = qr.nonzeroPivots();
      if (nz > 0) {
        w.c.assign(w.f.begin(), w.f.end());
        Vec cv(w.c.data(), n);
        // Qᵀ f: the reflectors H_0 … H_{nz−1} in turn (householderQ().adjoint() applied on the left),
        // each on the vector block it acts on (Eigen's sequence applies them to a block of dynamic
        // width, whose scaled reflector it evaluates into a new vector each time).
        double ws = 0;
        for (Eigen::Index k = 0; k < nz; ++k)
          cv.tail(n - k).applyHouseholderOnTheLeft(qr.matrixQR().col(k).tail(n - k - 1), qr.hCoeffs()(k), &ws);
        qr.matrixQR().topLeftCorner(nz, nz).triangularView<Eigen::Upper>().solveInPlace(cv.head(nz));
        for (Eigen::Index i = 0; i < nz; ++i) w.gam[static_cast<std::size_t>(qr.colsPermutation().indices()(i))] = cv(i);
      }
      // xn −= (ΔX + ΔF) γ, the product evaluated first as Eigen does (a temporary, then subtracted).
      w.sum_col.resize(static_cast<std::size_t>(n));
      Vec tmp(w.sum_col.data(), n);
      tmp.noalias() = w.XF.map() * Eigen::Map<const Eigen::VectorXd>(w.gam.data(), k);
      xn -= tmp;
    }
    for (int i = 0; i < n; ++i) a[i] = anew[i] > 0 ? std::max(0.0, xn(i)) : 0.0;
  }
}

}  // namespace strips_detail
}  // namespace mh
