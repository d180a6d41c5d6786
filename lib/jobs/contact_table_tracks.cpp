// Contacts across the nodes of a contact table (contact_table_tracks.hpp; docs/tables.md).
#include "jobs/contact_table_tracks.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <map>
#include <numeric>

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

}  // namespace

// See contact_table_tracks.hpp.
ContactTableData build_table(const std::vector<double>& tY, const std::vector<double>& Q, const std::vector<double>& roll,
                             const std::vector<const NodeSolve*>& nodes) {
  const std::size_t nT = tY.size(), nQ = Q.size(), nR = roll.size(), nn = nR * nT * nQ;
  constexpr double kMargin = 0.5e-3;
  std::vector<std::size_t> first(nn + 1, 0);
  for (std::size_t n = 0; n < nn; ++n) first[n + 1] = first[n] + nodes[n]->contacts.size();
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
  auto node = [&](std::size_t m, std::size_t i, std::size_t j) { return (m * nT + i) * nQ + j; };
  for (std::size_t m = 0; m < nR; ++m)
    for (std::size_t i = 0; i < nT; ++i)
      for (std::size_t j = 0; j < nQ; ++j) {
        if (i + 1 < nT) link(node(m, i, j), node(m, i + 1, j));
        if (j + 1 < nQ) link(node(m, i, j), node(m, i, j + 1));
        if (m + 1 < nR) link(node(m, i, j), node(m + 1, i, j));
      }
  // Components → tracks; a second contact of one node in a component starts its own track.
  std::map<std::size_t, std::size_t> root_track;
  std::vector<std::map<std::size_t, std::size_t>> track_nodes;  // node → contact (global index)
  for (std::size_t n = 0; n < nn; ++n) {
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
  d.roll = roll;
  d.n_tracks = static_cast<int>(std::max<std::size_t>(nk0, 1));
  const std::size_t nk = static_cast<std::size_t>(d.n_tracks);
  d.node_status.resize(nn);
  for (std::size_t n = 0; n < nn; ++n) d.node_status[n] = nodes[n]->status;
  d.present.assign(nn * nk, 0);
  d.v.assign(nn * nk * kTableQuantities, 0.0);
  d.cell_coarse.assign(d.nRc() * (nT - 1) * (nQ - 1), 0);
  for (std::size_t kk = 0; kk < nk0; ++kk) {
    const auto& tn = track_nodes[order[kk]];
    for (std::size_t n = 0; n < nn; ++n) {
      double* v = &d.v[n * nk * kTableQuantities + kk * kTableQuantities];
      auto it = tn.find(n);
      if (it != tn.end()) {
        d.present[n * nk + kk] = 1;
        const auto& c = contact_at(it->second);
        std::copy(c.v.begin(), c.v.end(), v);
        continue;
      }
      // Absent: the nearest node with the contact by (|Δroll|, |ΔQ| rows, the lower row first,
      // |Δt_Y|), the first in node order on a tie.
      const long m = static_cast<long>(n / (nT * nQ)), i = static_cast<long>((n / nQ) % nT), j = static_cast<long>(n % nQ);
      std::size_t src = tn.begin()->first;
      std::array<long, 4> bestk{{-1, 0, 0, 0}};
      for (const auto& [o, g] : tn) {
        const long mo = static_cast<long>(o / (nT * nQ)), io = static_cast<long>((o / nQ) % nT), jo = static_cast<long>(o % nQ);
        const std::array<long, 4> key{{std::labs(mo - m), std::labs(jo - j), jo > j ? 1 : 0, std::labs(io - i)}};
        if (bestk[0] < 0 || key < bestk) bestk = key, src = o;
      }
      const auto& c = contact_at(tn.at(src));
      for (int q = 0; q < kTableQuantities; ++q) v[q] = kTableColumns[q].fades ? 0.0 : c.v[q];
    }
  }
  return d;
}

}  // namespace mh
