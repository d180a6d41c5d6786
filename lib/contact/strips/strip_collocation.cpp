// Collocation solve of the coupled strips at a fixed approach; see strip_collocation.hpp.
//
// Sources:
//  - Johnson, Contact Mechanics (1985) §3.2 (Boussinesq point load, pressure on
//    a rectangle).
#include "contact/strips/strip_collocation.hpp"

#include "contact/strips/strip_influence.hpp"
#include "contact/strips/strip_kernel.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include "core/units.hpp"

namespace mh {
namespace strips_detail {

namespace {

constexpr double kPi = units::pi;
constexpr int kMaxWiden = 12;         // widening passes per approach (docs/method.md §9 item 7; 7 at most measured on the Manchester sweeps)
constexpr double kWidenRtol = 1e-6;   // a strip is widened when it gains more than this (relative)
constexpr double kPenetrationRtol = 1e-9;  // an unloaded strip counts as penetrated beyond this × (delta − g_min)

/// The amplitudes q >= 0 of the strips E (K = Kc_EE, lu its factorisation) with K q = rhs where q > 0 and K q >= rhs where q = 0
/// (no strip penetrated; a linear complementarity problem), by an active set: solve on the
/// active strips, drop those with q < 0; once none is negative, add back every inactive strip
/// that is penetrated (K q < rhs - tol); repeat until neither happens. `in_act` holds the
/// starting set (a warm start) and returns the final one. K is factorised once: with R the
/// inactive strips, q = K⁻¹(z + E_R mu), z = rhs with z_R = 0, and mu from q_R = 0,
/// (K⁻¹)_RR mu = −(K⁻¹ z)_R: a |R|×|R| system and one back-substitution per strip of R (the
/// capacitance matrix method); (K q)_R = mu is the displacement the add-back test needs.
/// A large R (over a third of E) is solved directly on the active strips instead. The columns
/// K⁻¹ e_r taken so far are kept with the factorisation: the collocations that reuse a
/// factorisation reuse them. `rhs` and `q` have E's size; `s` the buffers.
bool solve_active_set(const DenseMatrix& Kc, Collocation::Factorisation& f, const double* rhs, double tol,
                      int max_iter, std::vector<char>& in_act, double* q, StripScratch& s) {
  const std::vector<int>& E = f.of;
  const int e = static_cast<int>(E.size());
  auto K = [&](int r, int c) { return Kc(E[r], E[c]); };  // K = Kc restricted to E, read in place
  using Vec = Eigen::Map<Eigen::VectorXd>;
  // The factorisation of K, on first use (a solve that goes directly to the active strips needs none).
  auto lu = [&]() -> const DenseLU& {
    if (!f.factorised) {
      double* KE = f.lu.matrix(e);
      for (int cc = 0; cc < e; ++cc)
        for (int r = 0; r < e; ++r) KE[r + cc * e] = K(r, cc);
      f.lu.factorise();
      f.factorised = true;
    }
    return f.lu;
  };
  std::vector<int>& R = s.R;
  std::vector<int>& A = s.A;
  std::vector<double>& KqR = s.KqR;
  Vec qv(q, e);
  for (int it = 0; it < max_iter; ++it) {
    R.clear();
    A.clear();
    for (int r = 0; r < e; ++r) (in_act[r] ? A : R).push_back(r);
    const int nR = static_cast<int>(R.size()), nA = static_cast<int>(A.size());
    if (nR == 0) {
      std::copy(rhs, rhs + e, q);
      lu().solve_in_place(q);
    } else if (3 * nR <= e) {
      std::vector<double>& w = s.w;
      w.assign(rhs, rhs + e);
      for (int r : R) w[static_cast<std::size_t>(r)] = 0.0;  // z
      lu().solve_in_place(w.data());
      double* C = s.small.matrix(nR);
      s.wR.resize(static_cast<std::size_t>(nR));
      for (int b = 0; b < nR; ++b) {
        const std::size_t rb = static_cast<std::size_t>(R[b]);
        double* x = f.inv_col.data() + rb * e;
        if (!f.has_col[rb]) {
          std::fill(x, x + e, 0.0);
          x[rb] = 1.0;
          f.lu.solve_in_place(x);
          f.has_col[rb] = 1;
        }
        for (int a = 0; a < nR; ++a) C[a + b * nR] = x[R[a]];
        s.wR[static_cast<std::size_t>(b)] = w[rb];
      }
      s.small.factorise();
      KqR.assign(s.wR.begin(), s.wR.end());
      s.small.solve_in_place(KqR.data());
      for (double& v : KqR) v = -v;
      qv = Vec(w.data(), e);
      for (int b = 0; b < nR; ++b)
        qv += Vec(f.inv_col.data() + static_cast<std::size_t>(R[b]) * e, e) * KqR[static_cast<std::size_t>(b)];
      for (int r : R) q[r] = 0.0;
    } else {
      qv.setZero();
      if (nA > 0) {
        double* Kaa = s.small.matrix(nA);
        s.qa.resize(static_cast<std::size_t>(nA));
        for (int c = 0; c < nA; ++c) {
          for (int r = 0; r < nA; ++r) Kaa[r + c * nA] = K(A[r], A[c]);
          s.qa[static_cast<std::size_t>(c)] = rhs[A[c]];
        }
        s.small.factorise();
        s.small.solve_in_place(s.qa.data());
        for (int c = 0; c < nA; ++c) q[A[c]] = s.qa[static_cast<std::size_t>(c)];
      }
      KqR.assign(static_cast<std::size_t>(nR), 0.0);
      for (int a = 0; a < nR; ++a)
        for (int c = 0; c < nA; ++c) KqR[static_cast<std::size_t>(a)] += K(R[a], A[c]) * q[A[c]];
    }
    bool dropped = false;
    for (int r : A)
      if (q[r] < 0.0) { in_act[r] = 0; q[r] = 0.0; dropped = true; }
    if (dropped) continue;
    bool added = false;
    for (int a = 0; a < nR; ++a)
      if (KqR[static_cast<std::size_t>(a)] < rhs[R[a]] - tol) { in_act[R[a]] = 1; added = true; }
    if (!added) return true;
  }
  return false;
}

/// Column jj of the elastic influence matrix among the strips `cand` (unit amplitude), strip
/// cand[jj] of half-length aj; zero for aj = 0 (a strip without extent carries no load).
void elastic_column(const Solver& S, const std::vector<int>& cand, int jj, double aj, DenseMatrix& K) {
  const int m = static_cast<int>(cand.size()), j = cand[jj];
  std::fill(K.col(jj), K.col(jj) + m, 0.0);
  if (!(aj > 0.0)) return;
  if (S.same_xc && S.opt.coupling) {
    // K_ij = H a_j [g((j − i + ½) ds / a_j) − g((j − i − ½) ds / a_j)] (strip_kernel.hpp) with
    // g odd: with h_k = g((k + ½) ds / a_j), K_ij = H a_j (h_d − h_{d−1}), d = |i − j| ≥ 1, and
    // 2 H a_j h_0 on the diagonal. One kernel lookup per distance instead of two per entry.
    const int dmax = std::max(j - cand.front(), cand.back() - j);
    thread_local std::vector<double> h;
    h.resize(static_cast<std::size_t>(dmax) + 1);
    for (int k = 0; k <= dmax; ++k) h[k] = strip_kernel_g((k + 0.5) * S.geo.ds / aj);
    for (int ii = 0; ii < m; ++ii) {
      const int d = std::abs(cand[ii] - j);
      K(ii, jj) = S.H * aj * (d == 0 ? 2.0 * h[0] : h[d] - h[d - 1]);
    }
  } else {
    for (int ii = 0; ii < m; ++ii)
      if (S.opt.coupling || ii == jj) K(ii, jj) = S.K_elastic(cand[ii], j, aj);
  }
}

}  // namespace

double strip_load(const Collocation& c, int ii, double ds) {
  if (!(c.q[ii] > 0.0)) return 0.0;
  return (c.capped[ii] ? c.q[ii] * c.aeff[ii] * Phi(c.rcap[ii]) : 0.5 * kPi * c.q[ii] * c.aeff[ii]) * ds;
}

Collocation::Factorisation& Collocation::factorisation_of(const std::vector<int>& E) {
  for (int k = 0; k < n_lus; ++k) {
    Factorisation& f = lus[static_cast<std::size_t>((oldest + k) % kMaxFactorisations)];
    if (f.of == E) return f;
  }
  int slot;
  if (n_lus < kMaxFactorisations) {
    slot = (oldest + n_lus) % kMaxFactorisations;
    ++n_lus;
  } else {  // full: the oldest goes
    slot = oldest;
    oldest = (oldest + 1) % kMaxFactorisations;
  }
  if (lus.size() <= static_cast<std::size_t>(slot)) lus.resize(static_cast<std::size_t>(slot) + 1);
  Factorisation& f = lus[static_cast<std::size_t>(slot)];
  f.of = E;
  f.factorised = false;
  const std::size_t e = E.size();
  f.inv_col.resize(e * e);
  f.has_col.assign(e, 0);
  return f;
}

void Collocation::reset() {
  cand.clear();
  a.clear();
  K.resize(0, 0);
  q.clear();
  aeff.clear();
  rcap.clear();
  capped.clear();
  Ucap.resize(0, 0);
  as_ok = settled = true;
  newly_capped = 0;
  n_lus = oldest = 0;
}

double Phi(double r) {
  if (r >= 1.0) return 0.5 * kPi;
  return r * std::sqrt(1.0 - r * r) + std::asin(r);
}

Solver::Solver(const StripGeometry& g, double Hc, const StripOptions& o) : StripExtents(g), H(Hc), opt(o) {
  set(Hc, o);
}

void Solver::reinit(double Hc, const StripOptions& o) {
  StripExtents::init();
  set(Hc, o);
}

void Solver::set(double Hc, const StripOptions& o) {
  H = Hc;
  opt = o;
  gauss_legendre(opt.gauss_points / 2, &gx, &gw);
  same_xc = true;
  for (double x : geo.xc) same_xc = same_xc && x == geo.xc.front();
  log2_edge.clear();
  for (int k = -n; k <= n + 1; ++k) log2_edge.push_back(std::log2(std::fabs((k - 0.5) * geo.ds)));
}

double Solver::K_elastic(int i, int j, double aj) const {
  const double e1 = geo.s[j] - 0.5 * geo.ds - geo.s[i], e2 = geo.s[j] + 0.5 * geo.ds - geo.s[i];
  if (geo.xc[i] == geo.xc[j] && aj > 0.0)  // X0 = 0, uncapped: the tabulated kernel, exact
    return H * aj * (strip_kernel_g(e2 / aj) - strip_kernel_g(e1 / aj));
  return H * influence(geo.xc[i] - geo.xc[j], aj, geo.s[j] - 0.5 * geo.ds - geo.s[i],
                       geo.s[j] + 0.5 * geo.ds - geo.s[i], 1.0, gx, gw);
}

double Solver::K_end(int i, double ai, int j, double aj, double rcap) const {
  if (!(aj > 0.0)) return 0.0;
  const double e1 = geo.s[j] - 0.5 * geo.ds - geo.s[i], e2 = e1 + geo.ds;
  const double X = geo.xc[i] - geo.xc[j];
  if (ai == 0.0) return H * influence(X, aj, e1, e2, rcap, gx, gw);  // the centre: one quadrature, not two
  if (X == 0.0) return H * influence(ai, aj, e1, e2, rcap, gx, gw);   // both ends alike (the pressure is even)
  return 0.5 * H * (influence(X + ai, aj, e1, e2, rcap, gx, gw) + influence(X - ai, aj, e1, e2, rcap, gx, gw));
}

void Solver::capped_column(Collocation& c, int jj) const {
  const int m = static_cast<int>(c.cand.size()), j = c.cand[jj];
  const double f = H * c.q[jj];
  std::fill(c.Ucap.col(jj), c.Ucap.col(jj) + m, 0.0);
  if (same_xc) {  // on the centre lines: a function of the distance |i − j| only
    int dmax = 0;
    for (int r = 0; r < m; ++r)
      if (!c.capped[r] && (opt.coupling || r == jj)) dmax = std::max(dmax, std::abs(c.cand[r] - j));
    thread_local std::vector<double> col;
    thread_local std::vector<char> need;  // the distances of the elastic strips (few on a mostly capped patch)
    need.assign(static_cast<std::size_t>(dmax) + 1, 0);
    for (int r = 0; r < m; ++r)
      if (!c.capped[r] && (opt.coupling || r == jj)) need[static_cast<std::size_t>(std::abs(c.cand[r] - j))] = 1;
    capped_centre_line(c.aeff[jj], geo.ds, c.rcap[jj], dmax, gx, gw, col, &need, log2_edge.data() + n + 1);
    for (int r = 0; r < m; ++r)
      if (!c.capped[r] && (opt.coupling || r == jj)) c.Ucap(r, jj) = f * col[std::abs(c.cand[r] - j)];
    return;
  }
  for (int r = 0; r < m; ++r) {
    if (c.capped[r] || (!opt.coupling && r != jj)) continue;
    const int i = c.cand[r];
    c.Ucap(r, jj) = f * influence(geo.xc[i] - geo.xc[j], c.aeff[jj], geo.s[j] - 0.5 * geo.ds - geo.s[i],
                                  geo.s[j] + 0.5 * geo.ds - geo.s[i], c.rcap[jj], gx, gw);
  }
}

void Solver::build_K(Collocation& c, std::vector<double>& built) const {
  const int m = static_cast<int>(c.cand.size());
  if (c.K.rows != m || static_cast<int>(built.size()) != m) {
    c.K.zero(m, m);
    built.assign(m, -1.0);
  }
  for (int jj = 0; jj < m; ++jj)
    if (built[jj] != c.a[jj]) {
      elastic_column(*this, c.cand, jj, c.a[jj], c.K);
      built[jj] = c.a[jj];
      c.n_lus = c.oldest = 0;
    }
}

void Solver::collocate(double delta, double p_lim, Collocation& c, std::vector<char>& start) const {
  const int m = static_cast<int>(c.cand.size());
  // Plastic bookkeeping. A capped strip keeps the ELASTIC amplitude q_j at
  // which it was capped and is lengthened to a'_j = a_j (pi/2)/Phi(r_j),
  // r_j = p_lim/q_j; its pressure is min(q_j sqrt(1 - ((x-c)/a'_j)^2), p_lim):
  // flat top at p_lim, load q_j a'_j Phi(r_j) ds = (pi/2) q_j a_j ds (the
  // elastic strip's load). Its displacement equation is dropped. The length
  // never exceeds the strip's overlap, a'_j <= sqrt((delta - g_j)/A_j): the
  // displacements are compressive, so the surfaces touch only where they
  // interpenetrate rigidly (docs/method.md §9 item 6). A strip held there
  // carries q_j a'_j Phi(r_j) ds, less than its elastic load; the approach
  // rises until the patch carries its load, as in the rigid-plastic limit.
  c.capped.assign(m, 0);
  c.q.assign(m, 0.0);
  c.aeff = c.a;
  c.rcap.assign(m, 1.0);
  // Column j: displacement from capped strip j, zeroed when j is capped (capped_column); only
  // capped strips' columns are read.
  if (std::isfinite(p_lim) && (c.Ucap.rows != m || c.Ucap.cols != m)) c.Ucap.resize(m, m);
  c.settled = false;
  c.as_ok = true;
  StripScratch& s = scratch;
  std::vector<int>& act = s.act;
  std::vector<int>& E = s.E;
  std::vector<int>& newly = s.newly;
  using Vec = Eigen::Map<Eigen::VectorXd>;
  for (int pass = 0; pass < opt.max_active_set && !c.settled; ++pass) {
    // The elastic strips E of this pass (each plastic pass drops the newly capped ones) and
    // their equations K_EE q_E = delta - g - u_cap, solved for q >= 0 from the previous pass's
    // active set.
    E.clear();
    for (int ii = 0; ii < m; ++ii)
      if (!c.capped[ii] && c.a[ii] > 0.0) E.push_back(ii);
    const int e = static_cast<int>(E.size());
    s.ucap.assign(static_cast<std::size_t>(m), 0.0);
    Vec ucap(s.ucap.data(), m);
    for (int jj = 0; jj < m; ++jj)
      if (c.capped[jj]) ucap += Eigen::Map<const Eigen::VectorXd>(c.Ucap.col(jj), m);
    s.rhs.resize(static_cast<std::size_t>(e));
    s.qE.assign(static_cast<std::size_t>(e), 0.0);
    std::vector<char>& in_act = s.in_act;
    in_act.resize(static_cast<std::size_t>(e));
    for (int cc = 0; cc < e; ++cc) {
      s.rhs[static_cast<std::size_t>(cc)] = delta - geo.g[c.cand[E[cc]]] - ucap(E[cc]);
      in_act[cc] = start[E[cc]];
    }
    // The factorisation of K_EE: one of an earlier pass or collocation on the same set and K, else a
    // new one (factorised when the active-set solve first needs it).
    c.as_ok = e == 0 || solve_active_set(c.K, c.factorisation_of(E), s.rhs.data(), kPenetrationRtol * (delta - gmin),
                                         opt.max_active_set, in_act, s.qE.data(), s);
    if (!c.as_ok) break;
    const std::vector<double>& qE = s.qE;
    act.clear();
    for (int cc = 0; cc < e; ++cc) {
      c.q[E[cc]] = qE[static_cast<std::size_t>(cc)];
      if (in_act[cc]) act.push_back(E[cc]);
    }
    std::fill(start.begin(), start.end(), 0);
    for (int ii : act) start[ii] = 1;
    // Newly capped strips.
    bool any = false;
    if (std::isfinite(p_lim)) {
      newly.clear();
      for (int ii : act) {
        if (c.q[ii] > p_lim) {
          c.capped[ii] = 1;
          any = true;
          newly.push_back(ii);
          c.rcap[ii] = p_lim / c.q[ii];
          const int j = c.cand[ii];
          const double pen = delta - geo.g[j];
          c.aeff[ii] = std::min(c.a[ii] * (0.5 * kPi) / Phi(c.rcap[ii]), std::sqrt(std::max(pen, 0.0) / geo.A[j]));
          c.aeff[ii] = std::max(c.aeff[ii], c.a[ii]);  // never shorter than its elastic extent
        }
      }
      for (int ii : newly) capped_column(c, ii);
      c.newly_capped = static_cast<int>(newly.size());
    }
    if (!any) c.settled = true;
  }
}

/// A result reset to a new one's fields, its vectors and message keeping their capacity.
void clear_result(StripResult& r) {
  r.status = StripStatus::NoContact;
  r.message.clear();
  r.failure = Warning();
  r.iterations = 0;
  r.delta = r.N = r.pmax = r.area = 0.0;
  r.n_bands = 0;
  r.end_gap_error = NAN;
  r.refined = false;
  r.n_outliers = 0;
  r.worst_outlier = -1;
  r.strips.clear();
}

/// Solve at fixed approach.
void Solver::evaluate(double delta, double p_lim, const std::vector<int>* warm, StripResult& res) const {
  clear_result(res);
  res.delta = delta;
  if (!(delta > gmin)) {
    res.status = StripStatus::NoContact;
    res.message = "approach does not exceed the minimum gap";
    return;
  }
  StripScratch& s = scratch;
  int nb = 0;
  bands(delta, &nb, s.band);
  std::vector<double>& a = s.a;
  extents(delta, s.band, nb, a);

  // The interpenetrated strips (g < delta): those with a positive extent carry load; the others
  // are checked for the interpenetration the loaded strips leave at their centres (widening).
  Collocation& c = s.eval;
  c.reset();
  bool any_extent = false;
  for (int i = 0; i < n; ++i)
    if (s.band[i] >= 0) { c.cand.push_back(i); any_extent = any_extent || a[i] > 0.0; }
  const int m = static_cast<int>(c.cand.size());
  if (!any_extent) {
    res.status = StripStatus::NoContact;
    res.message = "no strip has a positive extent";
    return;
  }
  std::vector<char>& start = s.start;
  start.assign(static_cast<std::size_t>(m), 1);
  std::vector<double>& built = s.built;  // the extent each column of K was built for
  built.clear();
  std::vector<double>& a_prev = s.a_prev;  // per strip: the last widening pass's extent and phi there
  std::vector<double>& phi_prev = s.phi_prev;
  a_prev.assign(static_cast<std::size_t>(n), NAN);
  phi_prev.assign(static_cast<std::size_t>(n), NAN);
  c.a.resize(m);
  for (int widen = 0;; ++widen) {
    for (int ii = 0; ii < m; ++ii) c.a[ii] = a[c.cand[ii]];
    // Elastic influence matrix among the candidates (unit amplitude): the columns whose extent
    // changed (all of them on the first pass).
    build_K(c, built);
    // The starting active set: the strips of a previous solve that are still candidates (warm
    // start: along an approach iteration the set changes by a few strips), else every candidate.
    if (widen == 0 && warm && !warm->empty()) {
      std::fill(start.begin(), start.end(), 0);
      int found = 0;
      for (int ii = 0, w = 0; ii < m; ++ii) {
        while (w < static_cast<int>(warm->size()) && (*warm)[w] < c.cand[ii]) ++w;
        if (w < static_cast<int>(warm->size()) && (*warm)[w] == c.cand[ii]) { start[ii] = 1; ++found; }
      }
      if (found == 0) std::fill(start.begin(), start.end(), 1);
    }
    collocate(delta, p_lim, c, start);
    if (!c.as_ok || !c.settled || widen >= kMaxWiden) break;
    // Widening (the remedy of docs/method.md §9 item 7 for thin tails). The interpenetration the
    // other strips leave at a strip's centre, r_i = delta − g_i − sum_{j≠i} K_ij q_j, is what its
    // own pressure must take up; the strip is given at least the length over which that residual
    // interpenetration exists, a_i ≥ sqrt(r_i / A_i). Inside a patch r_i is the strip's own
    // displacement, far below A_i a_i²; at a tail whose extent rule gave a strip too short a
    // length it is not, and without this the amplitude there grows like 1/(a ln(1/a)) and the
    // load jumps when a strip enters (docs/strips.md "Load jumps").
    bool widened = false;
    const bool any_capped = std::find(c.capped.begin(), c.capped.end(), 1) != c.capped.end();
    for (int ii = 0; ii < m; ++ii) {
      const int i = c.cand[ii];
      if (c.capped[ii]) continue;
      double u = 0.0;
      for (int jj = 0; jj < m; ++jj) {
        if (jj == ii) continue;
        u += c.capped[jj] ? c.Ucap(ii, jj) : c.K(ii, jj) * c.q[jj];
      }
      const double r = delta - geo.g[i] - u;
      const double aw = r > 0.0 ? std::sqrt(r / geo.A[i]) : 0.0;
      if (!(aw > a[i] * (1.0 + kWidenRtol))) {
        a_prev[i] = NAN;
        continue;
      }
      // The strip's extent is the fixed point a = phi(a), phi(a) = aw at a. The plain iteration
      // contracts by about 0.1 per pass at a tail strip (Manchester plastic sweep: 7-8 passes at
      // t_Y = 1.5 mm), and with capped strips each pass is a whole collocation with their columns
      // (their elastic amplitudes move with every widening); there a secant step on the last two
      // passes settles it in about half the passes (its slope in [0, 0.5): a contraction). It may
      // overshoot the fixed point by its second-order error, so it is kept to the plastic model:
      // elastic patches widen as before, in passes that cost one column of K each.
      double next = aw;
      if (any_capped && std::isfinite(a_prev[i]) && a[i] != a_prev[i]) {
        const double slope = (aw - phi_prev[i]) / (a[i] - a_prev[i]);
        if (slope >= 0.0 && slope < 0.5) next = a[i] + (aw - a[i]) / (1.0 - slope);
      }
      a_prev[i] = a[i];
      phi_prev[i] = aw;
      a[i] = next;
      widened = true;
    }
    if (!widened) break;
    for (int ii = 0; ii < m; ++ii) start[ii] = c.q[ii] > 0.0 || c.capped[ii];
  }
  assemble(delta, p_lim, c, res);
}

void Solver::assemble(double delta, double p_lim, const Collocation& c, StripResult& res) const {
  clear_result(res);
  res.delta = delta;
  int nb = 0;
  std::vector<int>& band = scratch.band;
  bands(delta, &nb, band);
  res.n_bands = nb;
  res.status = StripStatus::Ok;
  if (!c.as_ok || !c.settled) {
    res.status = StripStatus::NotConverged;
    res.message = !c.as_ok ? "active set (q >= 0) did not settle within max_active_set passes"
                           : "plastic set did not settle within max_active_set passes";
    res.failure = Warning(!c.as_ok ? WarningClass::NotConvergedActiveSet : WarningClass::NotConvergedPlasticSet);
    res.failure.add(Quantity::Passes, opt.max_active_set);
    if (c.as_ok) res.failure.add(Quantity::StripsCapped, c.newly_capped, '>', 0);
  }
  const int m = static_cast<int>(c.cand.size());
  double qmax = 0.0;
  for (int ii = 0; ii < m; ++ii) {
    if (!(c.q[ii] > 0.0)) continue;
    StripState st;
    st.index = c.cand[ii];
    st.s = geo.s[st.index];
    st.c = geo.xc[st.index];
    st.a = c.aeff[ii];
    st.a_elastic = c.a[ii];
    st.q = c.q[ii];
    st.plastic = c.capped[ii] != 0;
    st.band = std::max(band[st.index], 0);
    st.load = strip_load(c, ii, geo.ds);
    res.N += st.load;
    res.area += 2.0 * st.a * geo.ds;
    qmax = std::max(qmax, c.q[ii]);
    res.strips.push_back(st);
  }
  res.pmax = std::min(qmax, p_lim);
  if (res.strips.empty() && res.status == StripStatus::Ok) {
    res.status = StripStatus::NoContact;
    res.message = "all amplitudes non-positive";
  }
  // Outliers: peak pressure above every neighbour's (same band, adjacent strip)
  // by more than outlier_factor — the thin-tail failure mode of short strips.
  // The peak of a capped strip is p_lim, not its elastic amplitude: the
  // amplitude of a strongly capped strip sets neither its pressure nor, held
  // at its overlap, much of its load.
  double worst = 0.0;
  const int L = static_cast<int>(res.strips.size());
  auto peak = [&](int k) { return std::min(res.strips[k].q, p_lim); };
  for (int k = 0; k < L; ++k) {
    double qn = -1.0;
    for (int d : {-1, 1}) {
      const int o = k + d;
      if (o < 0 || o >= L) continue;
      if (res.strips[o].band != res.strips[k].band || std::abs(res.strips[o].index - res.strips[k].index) != 1)
        continue;
      qn = std::max(qn, peak(o));
    }
    if (qn < 0.0) continue;
    if (peak(k) > opt.outlier_factor * qn) {
      ++res.n_outliers;
      const double ratio = peak(k) / std::max(qn, std::numeric_limits<double>::min());
      if (ratio > worst) { worst = ratio; res.worst_outlier = k; }
    }
  }
}

}  // namespace strips_detail
}  // namespace mh
