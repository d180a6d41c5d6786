// Making a contact table (contact_table_make.hpp; docs/tables.md).
#include "jobs/contact_table_make.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <iomanip>
#include <numeric>
#include <ostream>
#include <sstream>
#include <thread>
#include <utility>

#include "contact/solve.hpp"
#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "core/units.hpp"
#include "core/parallel.hpp"
#include "jobs/contact_table_shards.hpp"
#include "jobs/contact_table_solves.hpp"
#include "jobs/run.hpp"
#include "output/output_file.hpp"
#include "output/pair_tables.hpp"

namespace mh {
namespace {

/// Overlap of two contacts' rail extents, widened by `margin` [m] (> 0: they may be one contact).
double overlap(const NodeContact& a, const NodeContact& b, double margin) {
  return std::min(a.y_hi, b.y_hi) - std::max(a.y_lo, b.y_lo) + margin;
}

struct UnionFind {
  std::vector<std::size_t> p;
  explicit UnionFind(std::size_t n) : p(n) { std::iota(p.begin(), p.end(), 0); }
  std::size_t find(std::size_t x) {
    while (p[x] != x) x = p[x] = p[p[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a), b = find(b);
    if (a != b) p[std::max(a, b)] = std::min(a, b);
  }
};

/// Contacts across nodes (docs/tables.md "Contacts across nodes"): two contacts of neighbouring
/// nodes (in t_Y or in Q) are one track when their rail extents overlap (within 0.5 mm) and each
/// is the other's best overlap; a track holding two contacts of one node keeps the larger and
/// the other starts a track of its own. Absent nodes: N, pressure and sizes 0, the positions,
/// angle, radius and Kalker coefficients of the nearest node with the contact (same Q first).
ContactTableData build_table(const std::vector<double>& tY, const std::vector<double>& Q,
                             const std::vector<const NodeSolve*>& nodes) {
  const std::size_t nT = tY.size(), nQ = Q.size();
  constexpr double kMargin = 0.5e-3;
  std::vector<std::size_t> first(nT * nQ + 1, 0);
  for (std::size_t n = 0; n < nT * nQ; ++n) first[n + 1] = first[n] + nodes[n]->contacts.size();
  const std::size_t total = first.back();
  UnionFind uf(total);
  auto link = [&](std::size_t na, std::size_t nb) {
    const auto& A = nodes[na]->contacts;
    const auto& B = nodes[nb]->contacts;
    auto best = [](const std::vector<NodeContact>& X, const NodeContact& c) {
      std::size_t b = X.size();
      double o = 0;
      for (std::size_t k = 0; k < X.size(); ++k) {
        const double ok = overlap(X[k], c, kMargin);
        if (ok > o) o = ok, b = k;
      }
      return b;
    };
    for (std::size_t a = 0; a < A.size(); ++a) {
      const std::size_t b = best(B, A[a]);
      if (b < B.size() && best(A, B[b]) == a) uf.unite(first[na] + a, first[nb] + b);
    }
  };
  for (std::size_t i = 0; i < nT; ++i)
    for (std::size_t j = 0; j < nQ; ++j) {
      if (i + 1 < nT) link(i * nQ + j, (i + 1) * nQ + j);
      if (j + 1 < nQ) link(i * nQ + j, i * nQ + j + 1);
    }
  // Components → tracks; a second contact of one node in a component starts its own track.
  std::map<std::size_t, std::size_t> root_track;
  std::vector<std::size_t> track_of(total);
  std::vector<std::map<std::size_t, std::size_t>> track_nodes;  // node → contact (global index)
  for (std::size_t n = 0; n < nT * nQ; ++n) {
    // Larger N first, so that the larger keeps the track.
    std::vector<std::size_t> order(nodes[n]->contacts.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return nodes[n]->contacts[a].v[kTabN] > nodes[n]->contacts[b].v[kTabN];
    });
    for (std::size_t c : order) {
      const std::size_t g = first[n] + c, root = uf.find(g);
      auto it = root_track.find(root);
      std::size_t t;
      if (it == root_track.end() || track_nodes[it->second].count(n)) {
        t = track_nodes.size();
        track_nodes.emplace_back();
        if (it == root_track.end()) root_track[root] = t;
      } else {
        t = it->second;
      }
      track_nodes[t][n] = g;
      track_of[g] = t;
    }
  }
  // Tracks in increasing mean rail y.
  const std::size_t nk0 = track_nodes.size();
  std::vector<double> mean_y(nk0, 0);
  auto contact_at = [&](std::size_t g) -> const NodeContact& {
    const std::size_t n = static_cast<std::size_t>(std::upper_bound(first.begin(), first.end(), g) - first.begin()) - 1;
    return nodes[n]->contacts[g - first[n]];
  };
  for (std::size_t t = 0; t < nk0; ++t) {
    for (const auto& [n, g] : track_nodes[t]) mean_y[t] += contact_at(g).v[kTabYRail];
    mean_y[t] /= static_cast<double>(track_nodes[t].size());
  }
  std::vector<std::size_t> order(nk0);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return mean_y[a] < mean_y[b]; });

  ContactTableData d;
  d.tY = tY;
  d.Q = Q;
  d.n_tracks = static_cast<int>(std::max<std::size_t>(nk0, 1));
  const std::size_t nk = static_cast<std::size_t>(d.n_tracks);
  d.node_status.resize(nT * nQ);
  for (std::size_t n = 0; n < nT * nQ; ++n) d.node_status[n] = nodes[n]->status;
  d.present.assign(nT * nQ * nk, 0);
  d.v.assign(nT * nQ * nk * kTableQuantities, 0.0);
  d.cell_coarse.assign((nT - 1) * (nQ - 1), 0);
  for (std::size_t kk = 0; kk < nk0; ++kk) {
    const auto& tn = track_nodes[order[kk]];
    for (std::size_t i = 0; i < nT; ++i)
      for (std::size_t j = 0; j < nQ; ++j) {
        const std::size_t n = i * nQ + j;
        double* v = &d.v[d.at(i, j, static_cast<int>(kk))];
        auto it = tn.find(n);
        if (it != tn.end()) {
          d.present[n * nk + kk] = 1;
          const auto& c = contact_at(it->second);
          std::copy(c.v.begin(), c.v.end(), v);
          continue;
        }
        // Absent: the nearest node with the contact, same Q row first, then the nearest rows.
        std::size_t src = tn.begin()->first;
        bool found = false;
        for (std::size_t dj = 0; dj < nQ && !found; ++dj)
          for (int sgn : {-1, 1}) {
            if (found || (dj == 0 && sgn > 0)) continue;
            const long jj = static_cast<long>(j) + sgn * static_cast<long>(dj);
            if (jj < 0 || jj >= static_cast<long>(nQ)) continue;
            std::size_t bestd = nT + 1;
            for (const auto& [m, g] : tn)
              if (m % nQ == static_cast<std::size_t>(jj)) {
                const std::size_t di = m / nQ > i ? m / nQ - i : i - m / nQ;
                if (di < bestd) bestd = di, src = m;
              }
            if (bestd <= nT) found = true;
          }
        const auto& c = contact_at(tn.at(src));
        for (int q = 0; q < kTableQuantities; ++q) v[q] = kTableColumns[q].fades ? 0.0 : c.v[q];
      }
  }
  return d;
}

/// The interpolant against a direct solve at one point.
TableCheckError compare(const TableAnswer& T, const NodeSolve& D, double tY, double Q) {
  TableCheckError e;
  e.tY = tY;
  e.Q = Q;
  e.direct = D.status;
  e.table = T.status;
  if (is_failure(D.status) || is_failure(T.status)) return e;
  e.compared = true;
  const int nt = std::min(T.n_contacts, kTableMaxContacts);
  std::vector<bool> used(static_cast<std::size_t>(nt), false);
  double pmax = 0, area = 0;
  for (int k = 0; k < nt; ++k) {
    pmax = std::max(pmax, T.c[static_cast<std::size_t>(k)].v[kTabPmax]);
    area += T.c[static_cast<std::size_t>(k)].v[kTabArea];
  }
  // Each direct contact against the nearest unused table contact in rail y (larger N first).
  std::vector<std::size_t> order(D.contacts.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return D.contacts[a].v[kTabN] > D.contacts[b].v[kTabN]; });
  for (std::size_t di : order) {
    const NodeContact& c = D.contacts[di];
    int best = -1;
    double bd = INFINITY;
    for (int k = 0; k < nt; ++k) {
      const double dy = std::fabs(T.c[static_cast<std::size_t>(k)].v[kTabYRail] - c.v[kTabYRail]);
      if (!used[static_cast<std::size_t>(k)] && dy < bd) bd = dy, best = k;
    }
    // A table contact further than its own width plus 2 mm is another contact.
    if (best >= 0 && bd > c.y_hi - c.y_lo + 2e-3) best = -1;
    const double Nt = best >= 0 ? T.c[static_cast<std::size_t>(best)].v[kTabN] : 0.0;
    e.e_N = std::max(e.e_N, std::fabs(Nt - c.v[kTabN]) / Q);
    if (best >= 0) {
      used[static_cast<std::size_t>(best)] = true;
      if (c.v[kTabN] >= 0.05 * Q) e.e_position = std::max(e.e_position, bd);
    }
  }
  for (int k = 0; k < nt; ++k)
    if (!used[static_cast<std::size_t>(k)]) e.e_N = std::max(e.e_N, T.c[static_cast<std::size_t>(k)].v[kTabN] / Q);
  e.e_pmax = D.pmax > 0 ? std::fabs(pmax - D.pmax) / D.pmax : 0;
  e.e_area = D.area > 0 ? std::fabs(area - D.area) / D.area : 0;
  e.e_Fy = std::fabs(T.Fy - D.Fy) / Q;
  return e;
}

std::string fmt3(double v) {
  std::ostringstream o;
  o << std::setprecision(3) << v;
  return o.str();
}

double rounded_mm(double mm) { return std::round(mm * 1e9) / 1e9; }

nlohmann::json error_summary(const std::vector<TableCheckError>& checks, const TableMakeOptions& opt) {
  auto stats = [&](double TableCheckError::*f, double tol, double scale, const char* unit) {
    std::vector<double> v;
    for (const auto& e : checks)
      if (e.compared) v.push_back(e.*f * scale);
    std::sort(v.begin(), v.end());
    std::size_t beyond = 0;
    for (double x : v) beyond += x > tol;
    nlohmann::json j = {{"unit", unit}, {"tolerance", tol}, {"checked", v.size()}, {"beyond", beyond}};
    j["max"] = v.empty() ? 0.0 : v.back();
    j["p95"] = v.empty() ? 0.0 : v[std::min(v.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(v.size())))];
    j["median"] = v.empty() ? 0.0 : v[v.size() / 2];
    return j;
  };
  nlohmann::json j;
  j["where"] = "the centre of every cell, against a direct solve by the table's method";
  j["N"] = stats(&TableCheckError::e_N, opt.tol_N, 1, "fraction of Q");
  j["pmax"] = stats(&TableCheckError::e_pmax, opt.tol_pmax, 1, "fraction");
  j["area"] = stats(&TableCheckError::e_area, opt.tol_area, 1, "fraction");
  j["position"] = stats(&TableCheckError::e_position, opt.tol_position_mm, 1e3, "mm");
  j["Fy"] = stats(&TableCheckError::e_Fy, opt.tol_N, 1, "fraction of Q");
  std::size_t ok_direct = 0, ok_both = 0, unanswered = 0;
  for (const auto& e : checks) {
    if (e.direct == CaseStatus::Ok) {
      ++ok_direct;
      ok_both += e.table == CaseStatus::Ok;
    }
    unanswered += !e.compared;
  }
  j["status"] = {{"direct_ok", ok_direct}, {"direct_ok_table_ok", ok_both}, {"not_compared", unanswered}};
  return j;
}

}  // namespace

void table_initial_nodes(const CaseFile& cf, std::vector<double>& tY_mm, std::vector<double>& Q_kN) {
  const std::string where = cf.path + ": /sweep";
  if (!cf.cases.empty() || cf.sweep_tY_mm.size() < 2 || cf.sweep_Q_kN.size() < 2)
    throw InputError(where, "", "a table needs a sweep with at least two t_Y and two Q values (its nodes)",
                     "e.g. \"sweep\": {\"tY_mm\": {\"from\": -8, \"to\": 10, \"step\": 0.5}, \"Q_kN\": [20, 40, 60, 80, 100, 120, 140]}");
  if (cf.method == Method::MultiHertzian)
    throw InputError(cf.path + ": /method", "multi-hertzian", "a table is made by a grid method: strips, half-space or auto",
                     "the multi-Hertzian method is as fast as a table lookup: call it directly");
  tY_mm.clear();
  Q_kN.clear();
  for (std::uint64_t i = 0; i < cf.sweep_tY_mm.size(); ++i) tY_mm.push_back(cf.sweep_tY_mm.at(i));
  for (std::uint64_t i = 0; i < cf.sweep_Q_kN.size(); ++i) Q_kN.push_back(cf.sweep_Q_kN.at(i));
  std::sort(tY_mm.begin(), tY_mm.end());
  std::sort(Q_kN.begin(), Q_kN.end());
  tY_mm.erase(std::unique(tY_mm.begin(), tY_mm.end()), tY_mm.end());
  Q_kN.erase(std::unique(Q_kN.begin(), Q_kN.end()), Q_kN.end());
  if (tY_mm.size() < 2 || Q_kN.size() < 2 || !(Q_kN.front() > 0))
    throw InputError(where, "", "a table needs two distinct t_Y values and two distinct loads Q > 0");
}

std::vector<std::pair<double, double>> table_first_points(const CaseFile& cf, const TableMakeOptions& opt) {
  std::vector<double> tY_mm, Q_kN;
  table_initial_nodes(cf, tY_mm, Q_kN);
  std::vector<std::pair<double, double>> pts;
  for (double t : tY_mm)
    for (double q : Q_kN) pts.emplace_back(t, q);
  if (opt.check)
    for (std::size_t i = 0; i + 1 < tY_mm.size(); ++i)
      for (std::size_t j = 0; j + 1 < Q_kN.size(); ++j)
        pts.emplace_back(rounded_mm(0.5 * (tY_mm[i] + tY_mm[i + 1])), 0.5 * (Q_kN[j] + Q_kN[j + 1]));
  return pts;
}

TableMade make_contact_table(const CaseFile& cf, const PairGeometry& pg, const TableMakeOptions& opt, std::ostream& err,
                             const TableSolves* presolved, bool defer) {
  std::vector<double> tY_mm, Q_kN;
  table_initial_nodes(cf, tY_mm, Q_kN);

  const unsigned nt = std::max(1u, opt.threads ? opt.threads : std::thread::hardware_concurrency());
  Pool pool(nt);
  TableMade made;
  TableSolves solved;  // (tY mm, Q kN) → solve
  if (presolved) solved = *presolved;
  // Solve the points not solved yet; false when deferred (they are then made.pending).
  auto solve_missing = [&](const std::vector<std::pair<double, double>>& pts_mm) {
    std::vector<std::pair<double, double>> todo, si;
    for (const auto& p : pts_mm)
      if (!solved.count(p)) todo.push_back(p);
    std::sort(todo.begin(), todo.end());
    todo.erase(std::unique(todo.begin(), todo.end()), todo.end());
    if (defer && !todo.empty()) {
      made.pending = std::move(todo);
      return false;
    }
    for (const auto& p : todo) si.emplace_back(p.first * units::mm, p.second * 1e3);
    const auto res = solve_points(cf, pg, si, pool);
    for (std::size_t k = 0; k < todo.size(); ++k) solved[todo[k]] = res[k];
    made.solves += todo.size();
    return true;
  };

  ContactTableData data;
  std::vector<TableCheckError> checks;
  std::vector<std::uint8_t> cell_fail;
  // The centres (t_Y [mm], Q [kN]) of the cells of the grid tY_mm × Q_kN, cell by cell (t_Y outer).
  auto cell_centres = [&] {
    std::vector<std::pair<double, double>> centres;
    for (std::size_t i = 0; i + 1 < tY_mm.size(); ++i)
      for (std::size_t j = 0; j + 1 < Q_kN.size(); ++j)
        centres.emplace_back(rounded_mm(0.5 * (tY_mm[i] + tY_mm[i + 1])), 0.5 * (Q_kN[j] + Q_kN[j + 1]));
    return centres;
  };
  // The table `data` against the direct solves at its cells' centres (solved already): `checks`,
  // and the cells beyond a tolerance marked in `cell_fail`.
  auto check_cells = [&](const std::vector<std::pair<double, double>>& centres) {
    const ContactTableLookup look(data);
    TableAnswer ans;
    checks.clear();
    for (std::size_t c = 0; c < centres.size(); ++c) {
      const double ty = centres[c].first * units::mm, q = centres[c].second * 1e3;
      look.lookup(ty, q, ans);
      checks.push_back(compare(ans, solved.at(centres[c]), ty, q));
      const TableCheckError& e = checks.back();
      cell_fail[c] |= e.compared && (e.e_N > opt.tol_N || e.e_pmax > opt.tol_pmax || e.e_area > opt.tol_area);
    }
  };
  for (int round = 0;; ++round) {
    std::vector<std::pair<double, double>> pts;
    for (double t : tY_mm)
      for (double q : Q_kN) pts.emplace_back(t, q);
    std::vector<std::pair<double, double>> centres;
    if (opt.check) centres = cell_centres();
    // The nodes and the centres of their cells in one batch (one pass of shards).
    std::vector<std::pair<double, double>> batch = pts;
    batch.insert(batch.end(), centres.begin(), centres.end());
    if (!solve_missing(batch)) return made;
    std::vector<const NodeSolve*> nodes;
    for (const auto& p : pts) nodes.push_back(&solved.at(p));
    std::vector<double> tY, Q;
    for (double t : tY_mm) tY.push_back(t * units::mm);
    for (double q : Q_kN) Q.push_back(q * 1e3);
    data = build_table(tY, Q, nodes);
    checks.clear();
    cell_fail.assign((tY_mm.size() - 1) * (Q_kN.size() - 1), 0);
    if (!opt.check) break;
    check_cells(centres);
    if (round >= opt.refine) break;
    const ContactTableLookup look(data);
    TableAnswer ans;
    // Which way to halve a failing cell (docs/tables.md "Check and refinement"): its edges'
    // midpoints measure the interpolation along one axis alone, (t_Y midpoint, Q node) along t_Y
    // and (t_Y node, Q midpoint) along Q. Q is halved when the edges along t_Y hold their
    // tolerances and those along Q come nearer to missing theirs; else t_Y. Where both miss
    // (flange onset, a contact appearing) t_Y, along which contacts jump: a halved Q interval
    // adds a row of nodes across the whole t_Y range.
    const std::size_t nQc = Q_kN.size() - 1;
    std::vector<std::pair<double, double>> edges;
    for (std::size_t c = 0; c < cell_fail.size(); ++c)
      if (cell_fail[c]) {
        const std::size_t i = c / nQc, j = c % nQc;
        const double tm = rounded_mm(0.5 * (tY_mm[i] + tY_mm[i + 1])), qm = 0.5 * (Q_kN[j] + Q_kN[j + 1]);
        edges.insert(edges.end(), {{tm, Q_kN[j]}, {tm, Q_kN[j + 1]}, {tY_mm[i], qm}, {tY_mm[i + 1], qm}});
      }
    if (!solve_missing(edges)) return made;
    // An edge midpoint's error in units of its tolerances (> 1: missed; 0 where not compared).
    auto score = [&](const std::pair<double, double>& p) {
      look.lookup(p.first * units::mm, p.second * 1e3, ans);
      const TableCheckError e = compare(ans, solved.at(p), p.first * units::mm, p.second * 1e3);
      if (!e.compared) return 0.0;
      return std::max({e.e_N / opt.tol_N, e.e_pmax / opt.tol_pmax, e.e_area / opt.tol_area});
    };
    std::vector<std::uint8_t> split_t(tY_mm.size() - 1, 0), split_q(nQc, 0);
    for (std::size_t c = 0, k = 0; c < cell_fail.size(); ++c)
      if (cell_fail[c]) {
        const double sT = std::max(score(edges[k]), score(edges[k + 1]));
        const double sQ = std::max(score(edges[k + 2]), score(edges[k + 3]));
        k += 4;
        const std::size_t j = c % nQc;
        const bool q_can = Q_kN[j + 1] - Q_kN[j] >= 2 * opt.min_Q_step_kN - 1e-12;  // else t_Y is all that is left
        const bool q = q_can && sT <= 1 && sQ > sT;
        split_q[j] |= q;
        split_t[c / nQc] |= !q;
      }
    // A node without an answer leaves its cells without one: halving its t_Y intervals narrows
    // that band.
    for (std::size_t i = 0; i + 1 < tY_mm.size(); ++i)
      for (std::size_t j = 0; j < Q_kN.size(); ++j)
        split_t[i] |= is_failure(nodes[i * Q_kN.size() + j]->status) || is_failure(nodes[(i + 1) * Q_kN.size() + j]->status);
    // Halve the marked intervals (not below min_step_mm, min_Q_step_kN).
    auto halve = [](const std::vector<double>& x, const std::vector<std::uint8_t>& mark, double min_step, bool round_mm) {
      std::vector<double> next;
      for (std::size_t i = 0; i + 1 < x.size(); ++i) {
        next.push_back(x[i]);
        if (mark[i] && x[i + 1] - x[i] >= 2 * min_step - 1e-12) {
          const double m = 0.5 * (x[i] + x[i + 1]);
          next.push_back(round_mm ? rounded_mm(m) : m);
        }
      }
      next.push_back(x.back());
      return next;
    };
    std::vector<double> next_t = halve(tY_mm, split_t, opt.min_step_mm, true);
    std::vector<double> next_q = halve(Q_kN, split_q, opt.min_Q_step_kN, false);
    if (next_t.size() == tY_mm.size() && next_q.size() == Q_kN.size()) break;
    tY_mm = next_t;
    Q_kN = next_q;
    if (!opt.quiet)
      err << "mhcontact table: refinement " << round + 1 << ": " << tY_mm.size() << " t_Y nodes, " << Q_kN.size()
          << " Q nodes\n";
  }
  data.cell_coarse = cell_fail;

  // A t_Y node where some load has no answer (the method's equilibrium not found: at flange onset
  // the answer jumps there) is dropped from the grid, so that the interpolant runs through with
  // continuous forces instead of answering nothing around it; the cells that span a dropped node
  // are coarse (docs/tables.md "Nodes without an answer").
  std::vector<double> dropped;
  {
    const std::size_t nQ = Q_kN.size();
    std::vector<double> keep;
    for (std::size_t i = 0; i < tY_mm.size(); ++i) {
      bool bad = false;
      for (std::size_t j = 0; j < nQ; ++j) bad = bad || is_failure(solved.at({tY_mm[i], Q_kN[j]}).status);
      (bad ? dropped : keep).push_back(tY_mm[i]);
    }
    if (!dropped.empty() && keep.size() >= 2) {
      std::vector<const NodeSolve*> nodes;
      std::vector<double> tY, Q;
      for (double t : keep) {
        tY.push_back(t * units::mm);
        for (double q : Q_kN) nodes.push_back(&solved.at({t, q}));
      }
      for (double q : Q_kN) Q.push_back(q * 1e3);
      data = build_table(tY, Q, nodes);
      std::vector<std::uint8_t> fail((keep.size() - 1) * (nQ - 1), 0);
      for (std::size_t i = 0; i + 1 < keep.size(); ++i) {
        const auto at = std::find(tY_mm.begin(), tY_mm.end(), keep[i]) - tY_mm.begin();
        const bool same = static_cast<std::size_t>(at) + 1 < tY_mm.size() && tY_mm[static_cast<std::size_t>(at) + 1] == keep[i + 1];
        for (std::size_t j = 0; j + 1 < nQ; ++j)
          fail[i * (nQ - 1) + j] = same ? cell_fail[static_cast<std::size_t>(at) * (nQ - 1) + j] : 1;
      }
      cell_fail = fail;
      data.cell_coarse = fail;
      tY_mm = keep;
    } else {
      dropped.clear();
    }
  }
  // Without the dropped nodes the table is another interpolant (new cells span them, and the
  // PCHIP slopes of their neighbours change): its error is checked again at the centres of its
  // own cells, so that the header's error and `checks` are those of the table written.
  if (opt.check && !dropped.empty()) {
    const std::vector<std::pair<double, double>> centres = cell_centres();
    if (!solve_missing(centres)) return made;
    check_cells(centres);
    data.cell_coarse = cell_fail;
  }

  // The header.
  nlohmann::json h;
  h["schema"] = kContactTableSchema;
  h["program"] = program_json();
  h["what"] = "contact table: per node (t_Y, Q) and contact track, the grid method's answer; "
              "interpolate with bicubic Hermite, PCHIP node slopes, zero cross slope (docs/tables.md)";
  h["method"] = to_string(cf.method);
  h["model"] = to_string(cf.model);
  h["inputs"] = inputs_json(cf);
  h["profiles"] = profiles_json(pg);
  h["tY_mm_nodes"] = tY_mm;
  h["Q_kN_nodes"] = Q_kN;
  h["tY_mm_range"] = {tY_mm.front(), tY_mm.back()};
  h["Q_kN_range"] = {Q_kN.front(), Q_kN.back()};
  h["tracks"] = data.n_tracks;
  h["refine"] = opt.refine;
  h["dropped_tY_mm"] = dropped;
  nlohmann::json coarse = nlohmann::json::array();
  for (std::size_t i = 0; i + 1 < tY_mm.size(); ++i)
    for (std::size_t j = 0; j + 1 < Q_kN.size(); ++j)
      if (cell_fail[i * (Q_kN.size() - 1) + j]) coarse.push_back({i, j});
  h["coarse_cells"] = coarse;
  nlohmann::json units_j = {{"tY_mm", "mm"}, {"Q_kN", "kN"}};
  for (const TableColumn& c : kTableColumns) {
    const std::string n = c.name;
    const auto u = n.rfind('_');
    units_j[n] = n[0] == 'C' ? "1" : n.substr(u + 1);
  }
  h["units"] = units_j;
  if (opt.check) h["error"] = error_summary(checks, opt);
  data.header = h;
  made.data = std::move(data);
  made.checks = std::move(checks);
  return made;
}

void write_contact_table(const ContactTableData& t, std::ostream& out) {
  out << "# " << t.header.dump() << "\n";
  out << "tY_mm,Q_kN,status,contact,present";
  for (const TableColumn& c : kTableColumns) out << ',' << c.name;
  out << '\n';
  const std::size_t nk = static_cast<std::size_t>(t.n_tracks);
  const auto tYn = t.header.at("tY_mm_nodes").get<std::vector<double>>();
  const auto Qn = t.header.at("Q_kN_nodes").get<std::vector<double>>();
  std::string line;
  for (std::size_t i = 0; i < t.nT(); ++i)
    for (std::size_t j = 0; j < t.nQ(); ++j)
      for (std::size_t k = 0; k < nk; ++k) {
        line = format_number(tYn[i]) + ',' + format_number(Qn[j]) + ',' + to_string(t.node_status[i * t.nQ() + j]) +
               ',' + std::to_string(k + 1) + ',' + (t.present[(i * t.nQ() + j) * nk + k] ? '1' : '0');
        const double* v = &t.v[t.at(i, j, static_cast<int>(k))];
        for (int q = 0; q < kTableQuantities; ++q) {
          const double x = v[q] / kTableColumns[q].to_si;
          line += ',';
          line += format_number(std::isfinite(x) ? x : 0.0);
        }
        out << line << '\n';
      }
}

int table_job(const CaseFile& cf, const TableMakeOptions& opt, const std::string& out_path, std::ostream& out,
              std::ostream& err, const std::vector<std::string>& shard_files, const std::string& next_path) {
  if (!next_path.empty() && shard_files.empty())
    throw InputError("--next", next_path, "the points of a next pass come from a merge", "give --merge PART... too");
  const PairGeometry pg = build_pair_geometry(cf);
  if (!opt.quiet) warn_profiles(pg, err);
  TableSolves pre;
  unsigned passes = 0;
  if (!shard_files.empty()) pre = read_table_shards(cf, pg, opt, shard_files, &passes);
  const TableMade m = make_contact_table(cf, pg, opt, err, shard_files.empty() ? nullptr : &pre, !next_path.empty());
  if (!m.pending.empty()) {
    write_table_points(cf, pg, opt, passes, m.pending, next_path);
    if (!opt.quiet)
      err << "mhcontact table: the refinement needs " << m.pending.size() << " more points (pass " << passes << "), written to "
          << next_path << ": solve them with `mhcontact table CASE.json --shard K/N --points " << next_path
          << " -o PART`, then merge again with every part; no table written\n";
    return kExitMorePoints;
  }
  if (out_path == "-") {
    write_contact_table(m.data, out);
  } else {
    OutputFile f(out_path);
    write_contact_table(m.data, f.stream());
    f.commit();
  }
  std::size_t failed = m.data.header["dropped_tY_mm"].size();
  for (CaseStatus s : m.data.node_status) failed += is_failure(s);
  const std::size_t coarse = m.data.header["coarse_cells"].size();
  if (!opt.quiet) {
    err << "mhcontact table: " << m.data.nT() << " x " << m.data.nQ() << " nodes, " << m.data.n_tracks
        << " contact tracks, " << m.solves << " solves";
    if (m.data.header.contains("error")) {
      const auto& e = m.data.header["error"];
      err << "; interpolation error at " << e["N"]["checked"].get<std::size_t>() << " cell centres: N max "
          << fmt3(100 * e["N"]["max"].get<double>()) << " % of Q, pmax max "
          << fmt3(100 * e["pmax"]["max"].get<double>()) << " %, area max "
          << fmt3(100 * e["area"]["max"].get<double>()) << " %, position max "
          << fmt3(e["position"]["max"].get<double>()) << " mm";
    }
    err << "; " << coarse << " coarse cells, " << failed << " t_Y nodes without an answer (dropped)\n";
  }
  return coarse || failed ? kExitCasesFailed : kExitOk;
}

}  // namespace mh
