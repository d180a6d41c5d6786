// A contact table against direct solves (contact_table_check.hpp; docs/tables.md "How it is made").
#include "jobs/contact_table_check.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/units.hpp"

namespace mh {

TableCheckError table_check_error(const TableAnswer& T, const NodeSolve& D, const TablePoint& p) {
  TableCheckError e;
  e.tY = p.tY_mm * units::mm;
  e.Q = p.Q_kN * 1e3;
  e.roll = p.roll_mrad * 1e-3;
  const double Q = e.Q;
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

namespace {

// Per quantity over `checks` (those compared): the count, how many beyond the tolerance, the
// median, 95th percentile and largest error.
void quantity_stats(nlohmann::json& j, const std::vector<TableCheckError>& checks, const TableTolerances& tol) {
  auto stats = [&](double TableCheckError::*f, double limit, double scale, const char* unit) {
    std::vector<double> v;
    for (const auto& e : checks)
      if (e.compared) v.push_back(e.*f * scale);
    std::sort(v.begin(), v.end());
    std::size_t beyond = 0;
    for (double x : v) beyond += x > limit;
    nlohmann::json q = {{"unit", unit}, {"tolerance", limit}, {"checked", v.size()}, {"beyond", beyond}};
    q["max"] = v.empty() ? 0.0 : v.back();
    q["p95"] = v.empty() ? 0.0 : v[std::min(v.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(v.size())))];
    q["median"] = v.empty() ? 0.0 : v[v.size() / 2];
    return q;
  };
  j["N"] = stats(&TableCheckError::e_N, tol.N, 1, "fraction of Q");
  j["pmax"] = stats(&TableCheckError::e_pmax, tol.pmax, 1, "fraction");
  j["area"] = stats(&TableCheckError::e_area, tol.area, 1, "fraction");
  j["position"] = stats(&TableCheckError::e_position, tol.position_mm, 1e3, "mm");
  j["Fy"] = stats(&TableCheckError::e_Fy, tol.N, 1, "fraction of Q");
}

}  // namespace

nlohmann::json table_error_summary(const std::vector<TableCheckError>& checks, const TableTolerances& tol, int check_points) {
  nlohmann::json j;
  j["where"] = check_points == 3
                   ? "the centre of every cell and the points a quarter and three quarters along its main diagonal, "
                     "against a direct solve by the table's method"
                   : "the centre of every cell, against a direct solve by the table's method";
  quantity_stats(j, checks, tol);
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

double table_tolerance_ratio(const TableCheckError& e, const TableTolerances& tol) {
  return std::max({e.e_N / tol.N, e.e_pmax / tol.pmax, e.e_area / tol.area});
}

nlohmann::json table_validation_summary(const std::vector<TableCheckError>& v, const TableTolerances& tol) {
  nlohmann::json j;
  j["where"] = "points drawn uniformly over the table's ranges, never used to refine it or to mark its cells, where "
               "both the table and a direct solve by its method answer ok";
  j["points"] = v.size();
  j["seed"] = kTableValidationSeed;
  std::vector<TableCheckError> both;
  std::size_t direct_ok = 0, table_ok = 0, table_only = 0, direct_only = 0;
  nlohmann::json ok_not_direct = nlohmann::json::array();  // the first five: where the table claims more
  for (const auto& e : v) {
    const bool d = e.direct == CaseStatus::Ok, t = e.table == CaseStatus::Ok;
    direct_ok += d;
    table_ok += t;
    table_only += t && !d;
    direct_only += d && !t;
    if (d && t && e.compared) both.push_back(e);
    if (t && !d && ok_not_direct.size() < 5)
      ok_not_direct.push_back({{"tY_mm", e.tY * 1e3}, {"Q_kN", e.Q * 1e-3}, {"roll_mrad", e.roll * 1e3},
                               {"direct", to_string(e.direct)}});
  }
  j["status"] = {{"direct_ok", direct_ok}, {"table_ok", table_ok}, {"both_ok", both.size()},
                 {"table_ok_direct_not", table_only}, {"direct_ok_table_not", direct_only}};
  quantity_stats(j, both, tol);
  std::sort(both.begin(), both.end(), [&](const TableCheckError& a, const TableCheckError& b) {
    return table_tolerance_ratio(a, tol) > table_tolerance_ratio(b, tol);
  });
  std::size_t beyond = 0;
  for (const auto& e : both) beyond += table_tolerance_ratio(e, tol) > 1;
  j["beyond"] = beyond;
  nlohmann::json worst = nlohmann::json::array();
  for (std::size_t k = 0; k < std::min<std::size_t>(5, both.size()); ++k) {
    const TableCheckError& e = both[k];
    worst.push_back({{"tY_mm", e.tY * 1e3}, {"Q_kN", e.Q * 1e-3}, {"roll_mrad", e.roll * 1e3}, {"N", e.e_N},
                     {"pmax", e.e_pmax}, {"area", e.e_area}});
  }
  j["worst"] = worst;
  j["table_ok_direct_not_points"] = ok_not_direct;
  return j;
}

std::vector<TablePoint> table_validation_points(const std::vector<double>& tY_mm, const std::vector<double>& Q_kN,
                                                const std::vector<double>& roll_mrad, int n) {
  // splitmix64 (Steele, Lea and Flood, OOPSLA 2014): the same points on every platform and
  // standard library, a uniform double in [0, 1) from its top 53 bits.
  std::uint64_t state = kTableValidationSeed;
  auto uniform = [&state] {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
  };
  auto at = [](const std::vector<double>& x, double u) { return x.front() + u * (x.back() - x.front()); };
  std::vector<TablePoint> p;
  for (int k = 0; k < n; ++k) {
    const double t = uniform(), q = uniform(), r = uniform();
    p.push_back({table_point_rounded(at(tY_mm, t)), table_point_rounded(at(Q_kN, q)),
                 roll_mrad.size() > 1 ? table_point_rounded(at(roll_mrad, r)) : roll_mrad[0]});
  }
  return p;
}

}  // namespace mh
