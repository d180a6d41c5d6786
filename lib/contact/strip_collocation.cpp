// Collocation solve of the coupled strips at a fixed approach; see strip_collocation.hpp.
//
// Sources:
//  - Johnson, Contact Mechanics (1985) §3.2 (Boussinesq point load, pressure on
//    a rectangle).
#include "contact/strip_collocation.hpp"

#include "contact/strip_influence.hpp"
#include "contact/strip_kernel.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include "core/units.hpp"

namespace mh {
namespace strips_detail {

namespace {

constexpr double kPi = units::pi;

/// Phi(r) = r sqrt(1 - r^2) + asin r: load of a capped semi-ellipse
/// min(q sqrt(1-t^2), r q) over t in [-1, 1] is q a Phi(r); Phi(1) = pi/2.
double Phi(double r) {
  if (r >= 1.0) return 0.5 * kPi;
  return r * std::sqrt(1.0 - r * r) + std::asin(r);
}

}  // namespace

Solver::Solver(const StripGeometry& g, double Hc, const StripOptions& o) : StripExtents(g), H(Hc), opt(o) {
  gauss_legendre(opt.gauss_points / 2, &gx, &gw);
}

double Solver::K_elastic(int i, int j, double aj) const {
  const double e1 = geo.s[j] - 0.5 * geo.ds - geo.s[i], e2 = geo.s[j] + 0.5 * geo.ds - geo.s[i];
  if (geo.xc[i] == geo.xc[j] && aj > 0.0)  // X0 = 0, uncapped: the tabulated kernel, exact
    return H * aj * (strip_kernel_g(e2 / aj) - strip_kernel_g(e1 / aj));
  return H * influence(geo.xc[i] - geo.xc[j], aj, geo.s[j] - 0.5 * geo.ds - geo.s[i],
                       geo.s[j] + 0.5 * geo.ds - geo.s[i], 1.0, gx, gw);
}

/// Solve at fixed approach.
StripResult Solver::evaluate(double delta, double p_lim) const {
  StripResult res;
  res.delta = delta;
  if (!(delta > gmin)) {
    res.status = StripStatus::NoContact;
    res.message = "approach does not exceed the minimum gap";
    return res;
  }
  int nb = 0;
  const std::vector<int> band = bands(delta, &nb);
  const std::vector<double> a = extents(delta, band, nb);
  res.n_bands = nb;

  std::vector<int> cand;
  for (int i = 0; i < n; ++i)
    if (a[i] > 0.0) cand.push_back(i);
  const int m = static_cast<int>(cand.size());
  if (m == 0) {
    res.status = StripStatus::NoContact;
    res.message = "no strip has a positive extent";
    return res;
  }
  // Elastic influence matrix among candidates (unit amplitude).
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(m, m);
  for (int jj = 0; jj < m; ++jj)
    for (int ii = 0; ii < m; ++ii)
      if (opt.coupling || ii == jj) K(ii, jj) = K_elastic(cand[ii], cand[jj], a[cand[jj]]);

  // Plastic bookkeeping. A capped strip keeps the ELASTIC amplitude q_j at
  // which it was capped and is lengthened to a'_j = a_j (pi/2)/Phi(r_j),
  // r_j = p_lim/q_j; its pressure is min(q_j sqrt(1 - ((x-c)/a'_j)^2), p_lim):
  // flat top at p_lim, load q_j a'_j Phi(r_j) ds = (pi/2) q_j a_j ds (the
  // elastic strip's load). Its displacement equation is dropped.
  std::vector<char> capped(m, 0);
  std::vector<double> q(m, 0.0), aeff(m, 0.0), rcap(m, 1.0);
  Eigen::MatrixXd Ucap = Eigen::MatrixXd::Zero(m, m);  // column j: displacement from capped strip j
  for (int ii = 0; ii < m; ++ii) aeff[ii] = a[cand[ii]];

  bool settled = false;
  bool as_ok = true;
  for (int pass = 0; pass < opt.max_active_set && !settled; ++pass) {
    std::vector<int> act;
    for (int ii = 0; ii < m; ++ii)
      if (!capped[ii]) act.push_back(ii);
    Eigen::VectorXd ucap = Eigen::VectorXd::Zero(m);
    for (int jj = 0; jj < m; ++jj)
      if (capped[jj]) ucap += Ucap.col(jj);
    // Active set for q >= 0 among elastic strips.
    as_ok = false;
    for (int it = 0; it < opt.max_active_set; ++it) {
      const int k = static_cast<int>(act.size());
      if (k == 0) { as_ok = true; break; }
      Eigen::MatrixXd Kaa(k, k);
      Eigen::VectorXd rhs(k);
      for (int r = 0; r < k; ++r) {
        rhs(r) = delta - geo.g[cand[act[r]]] - ucap(act[r]);
        for (int c = 0; c < k; ++c) Kaa(r, c) = K(act[r], act[c]);
      }
      const Eigen::VectorXd sol = Kaa.partialPivLu().solve(rhs);
      std::vector<int> keep;
      for (int r = 0; r < k; ++r) {
        q[act[r]] = sol(r);
        if (sol(r) >= 0.0) keep.push_back(act[r]);
      }
      for (int ii = 0; ii < m; ++ii)
        if (!capped[ii] && std::find(keep.begin(), keep.end(), ii) == keep.end()) q[ii] = 0.0;
      if (keep.size() == act.size()) { as_ok = true; break; }
      act.swap(keep);
    }
    if (!as_ok) break;
    // Newly capped strips.
    bool any = false;
    if (std::isfinite(p_lim)) {
      for (int ii : act) {
        if (q[ii] > p_lim) {
          capped[ii] = 1;
          any = true;
          rcap[ii] = p_lim / q[ii];
          aeff[ii] = a[cand[ii]] * (0.5 * kPi) / Phi(rcap[ii]);
          const int j = cand[ii];
          for (int r = 0; r < m; ++r) {
            if (!opt.coupling && r != ii) continue;
            const int i = cand[r];
            Ucap(r, ii) = H * q[ii] *
                          influence(geo.xc[i] - geo.xc[j], aeff[ii], geo.s[j] - 0.5 * geo.ds - geo.s[i],
                                    geo.s[j] + 0.5 * geo.ds - geo.s[i], rcap[ii], gx, gw);
          }
        }
      }
    }
    if (!any) settled = true;
  }

  res.status = StripStatus::Ok;
  if (!as_ok || !settled) {
    res.status = StripStatus::NotConverged;
    res.message = !as_ok ? "active set (q >= 0) did not settle within max_active_set passes"
                         : "plastic set did not settle within max_active_set passes";
  }
  double qmax = 0.0;
  for (int ii = 0; ii < m; ++ii) {
    if (!(q[ii] > 0.0)) continue;
    StripState st;
    st.index = cand[ii];
    st.s = geo.s[cand[ii]];
    st.c = geo.xc[cand[ii]];
    st.a = aeff[ii];
    st.q = q[ii];
    st.plastic = capped[ii] != 0;
    st.band = band[cand[ii]];
    st.load = (st.plastic ? q[ii] * aeff[ii] * Phi(rcap[ii]) : 0.5 * kPi * q[ii] * aeff[ii]) * geo.ds;
    res.N += st.load;
    res.area += 2.0 * st.a * geo.ds;
    qmax = std::max(qmax, q[ii]);
    res.strips.push_back(st);
  }
  res.pmax = std::min(qmax, p_lim);
  if (res.strips.empty() && res.status == StripStatus::Ok) {
    res.status = StripStatus::NoContact;
    res.message = "all amplitudes non-positive";
  }
  // Outliers: amplitude above every neighbour's (same band, adjacent strip)
  // by more than outlier_factor — the thin-tail failure mode of short strips.
  double worst = 0.0;
  const int L = static_cast<int>(res.strips.size());
  for (int k = 0; k < L; ++k) {
    double qn = -1.0;
    for (int d : {-1, 1}) {
      const int o = k + d;
      if (o < 0 || o >= L) continue;
      if (res.strips[o].band != res.strips[k].band || std::abs(res.strips[o].index - res.strips[k].index) != 1)
        continue;
      qn = std::max(qn, res.strips[o].q);
    }
    if (qn < 0.0) continue;
    if (res.strips[k].q > opt.outlier_factor * qn) {
      ++res.n_outliers;
      const double ratio = res.strips[k].q / std::max(qn, std::numeric_limits<double>::min());
      if (ratio > worst) { worst = ratio; res.worst_outlier = k; }
    }
  }
  return res;
}

}  // namespace strips_detail
}  // namespace mh
