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
#include "jobs/contact_table_check.hpp"
#include "jobs/contact_table_shards.hpp"
#include "jobs/contact_table_solves.hpp"
#include "jobs/contact_table_tracks.hpp"
#include "jobs/run.hpp"
#include "output/output_file.hpp"
#include "output/pair_tables.hpp"

namespace mh {
namespace {

TableTolerances tolerances(const TableMakeOptions& opt) {
  return {opt.tol_N, opt.tol_pmax, opt.tol_area, opt.tol_position_mm};
}

std::string fmt3(double v) {
  std::ostringstream o;
  o << std::setprecision(3) << v;
  return o.str();
}

}  // namespace

void table_initial_nodes(const CaseFile& cf, std::vector<double>& tY_mm, std::vector<double>& Q_kN,
                         std::vector<double>& roll_mrad) {
  const std::string where = cf.path + ": /sweep";
  if (!cf.cases.empty() || cf.sweep_tY_mm.size() < 2 || cf.sweep_Q_kN.size() < 2)
    throw InputError(where, "", "a table needs a sweep with at least two t_Y and two Q values (its nodes)",
                     "e.g. \"sweep\": {\"tY_mm\": {\"from\": -8, \"to\": 10, \"step\": 0.5}, \"Q_kN\": [20, 40, 60, 80, 100, 120, 140]}");
  if (cf.method == Method::MultiHertzian)
    throw InputError(cf.path + ": /method", "multi-hertzian", "a table is made by a grid method: strips, half-space or auto",
                     "the multi-Hertzian method is as fast as a table lookup: call it directly");
  tY_mm.clear();
  Q_kN.clear();
  roll_mrad.clear();
  for (std::uint64_t i = 0; i < cf.sweep_tY_mm.size(); ++i) tY_mm.push_back(cf.sweep_tY_mm.at(i));
  for (std::uint64_t i = 0; i < cf.sweep_Q_kN.size(); ++i) Q_kN.push_back(cf.sweep_Q_kN.at(i));
  for (std::uint64_t i = 0; i < cf.sweep_roll_mrad.size(); ++i) roll_mrad.push_back(cf.sweep_roll_mrad.at(i));
  if (roll_mrad.empty()) roll_mrad.push_back(0.0);
  for (auto* x : {&tY_mm, &Q_kN, &roll_mrad}) {
    std::sort(x->begin(), x->end());
    x->erase(std::unique(x->begin(), x->end()), x->end());
  }
  if (tY_mm.size() < 2 || Q_kN.size() < 2 || !(Q_kN.front() > 0))
    throw InputError(where, "", "a table needs two distinct t_Y values and two distinct loads Q > 0");
  for (std::size_t m = 1; m < roll_mrad.size(); ++m)
    if (!(roll_mrad[m] - roll_mrad[m - 1] >= 1e3 * kTableRollTolerance))
      throw InputError(where + "/roll_mrad", format_number(roll_mrad[m]), "roll nodes at least 0.001 mrad apart");
}

namespace {

/// The grid of a table being made, in the units of its file.
struct TableGrid {
  std::vector<double> tY, Q, roll;  ///< [mm], [kN], [mrad]
  std::size_t nRc() const { return roll.size() > 1 ? roll.size() - 1 : 1; }
  std::size_t cell_count() const { return nRc() * (tY.size() - 1) * (Q.size() - 1); }
  /// The roll at the lower and upper side of roll cell m (the one roll twice without a roll axis).
  double r_lo(std::size_t m) const { return roll[m]; }
  double r_hi(std::size_t m) const { return roll.size() > 1 ? roll[m + 1] : roll[0]; }
  /// The nodes in ContactTableData::node order (roll outer, t_Y, Q).
  std::vector<TablePoint> nodes() const {
    std::vector<TablePoint> p;
    for (double r : roll)
      for (double t : tY)
        for (double q : Q) p.push_back({t, q, r});
    return p;
  }
  /// The check points of the cells in ContactTableData::cell order, `per` a cell: its centre
  /// (per = 1), then the points a quarter and three quarters along its main diagonal (per = 3).
  std::vector<TablePoint> centres(int per = 1) const {
    std::vector<TablePoint> c;
    auto at = [](double a, double b, double f) { return a + f * (b - a); };
    for (std::size_t m = 0; m < nRc(); ++m)
      for (std::size_t i = 0; i + 1 < tY.size(); ++i)
        for (std::size_t j = 0; j + 1 < Q.size(); ++j)
          for (double f : {0.5, 0.25, 0.75}) {
            if (f != 0.5 && per < 3) break;
            c.push_back({table_point_rounded(at(tY[i], tY[i + 1], f)), at(Q[j], Q[j + 1], f),
                         roll.size() > 1 ? table_point_rounded(at(r_lo(m), r_hi(m), f)) : roll[0]});
          }
    return c;
  }
};

}  // namespace

std::vector<TablePoint> table_first_points(const CaseFile& cf, const TableMakeOptions& opt) {
  TableGrid g;
  table_initial_nodes(cf, g.tY, g.Q, g.roll);
  std::vector<TablePoint> pts = g.nodes();
  if (opt.check) {
    const auto c = g.centres(opt.check_points);
    pts.insert(pts.end(), c.begin(), c.end());
    const auto v = table_validation_points(g.tY, g.Q, g.roll, opt.validate);
    pts.insert(pts.end(), v.begin(), v.end());
  }
  return pts;
}

TableMade make_contact_table(const CaseFile& cf, const PairGeometry& pg, const TableMakeOptions& opt, std::ostream& err,
                             const TableSolves* presolved, bool defer) {
  TableGrid g;
  table_initial_nodes(cf, g.tY, g.Q, g.roll);
  const bool roll_axis = g.roll.size() > 1;
  // Solved with the first round's points (one pass of shards), compared once the table is made.
  const std::vector<TablePoint> validation =
      opt.check ? table_validation_points(g.tY, g.Q, g.roll, opt.validate) : std::vector<TablePoint>{};

  const unsigned nt = std::max(1u, opt.threads ? opt.threads : std::thread::hardware_concurrency());
  Pool pool(nt);
  TableMade made;
  TableSolves solved;
  if (presolved) solved = *presolved;
  // Solve the points not solved yet; false when deferred (they are then made.pending).
  auto solve_missing = [&](const std::vector<TablePoint>& pts) {
    std::vector<TablePoint> todo;
    for (const auto& p : pts)
      if (!solved.count(p)) todo.push_back(p);
    std::sort(todo.begin(), todo.end());
    todo.erase(std::unique(todo.begin(), todo.end()), todo.end());
    if (defer && !todo.empty()) {
      made.pending = std::move(todo);
      return false;
    }
    const auto res = solve_points(cf, pg, todo, pool);
    for (std::size_t k = 0; k < todo.size(); ++k) solved[todo[k]] = res[k];
    made.solves += todo.size();
    return true;
  };
  auto si = [](const std::vector<double>& x, double f) {
    std::vector<double> y;
    for (double v : x) y.push_back(v * f);
    return y;
  };
  auto build = [&] {
    std::vector<const NodeSolve*> nodes;
    for (const auto& p : g.nodes()) nodes.push_back(&solved.at(p));
    return build_table(si(g.tY, units::mm), si(g.Q, 1e3), si(g.roll, 1e-3), nodes);
  };

  ContactTableData data;
  std::vector<TableCheckError> checks;
  std::vector<std::uint8_t> cell_fail;
  // The table `data` against the direct solves at its cells' check points (solved already,
  // opt.check_points a cell): `checks`, and the cells beyond a tolerance at any of them marked in
  // `cell_fail`.
  const std::size_t per = opt.check_points == 3 ? 3 : 1;
  auto check_cells = [&](const std::vector<TablePoint>& centres) {
    const ContactTableLookup look(data);
    TableAnswer ans;
    checks.clear();
    for (std::size_t c = 0; c < centres.size(); ++c) {
      const TablePoint& p = centres[c];
      look.lookup(p.tY_mm * units::mm, p.Q_kN * 1e3, p.roll_mrad * 1e-3, ans);
      checks.push_back(table_check_error(ans, solved.at(p), p));
      const TableCheckError& e = checks.back();
      cell_fail[c / per] |= e.compared && (e.e_N > opt.tol_N || e.e_pmax > opt.tol_pmax || e.e_area > opt.tol_area);
    }
  };
  for (int round = 0;; ++round) {
    const std::vector<TablePoint> pts = g.nodes();
    std::vector<TablePoint> centres;
    if (opt.check) centres = g.centres(opt.check_points);
    // The nodes and the centres of their cells in one batch (one pass of shards).
    std::vector<TablePoint> batch = pts;
    batch.insert(batch.end(), centres.begin(), centres.end());
    if (round == 0) batch.insert(batch.end(), validation.begin(), validation.end());
    if (!solve_missing(batch)) return made;
    data = build();
    checks.clear();
    cell_fail.assign(g.cell_count(), 0);
    if (!opt.check) break;
    check_cells(centres);
    if (round >= opt.refine) break;
    const ContactTableLookup look(data);
    TableAnswer ans;
    // Which way to halve a failing cell (docs/tables.md "Check and refinement"): its edges'
    // midpoints measure the interpolation along one axis alone, (t_Y midpoint, Q node) along t_Y
    // and (t_Y node, Q midpoint) along Q (and with a roll axis (t_Y node, Q node, roll midpoint)
    // along the roll), two edges per axis at opposite corners. The roll is halved when its edges
    // miss their tolerances most; else Q when the edges along t_Y hold their tolerances and those
    // along Q come nearer to missing theirs; else t_Y. Where both miss (flange onset, a contact
    // appearing) t_Y, along which contacts jump: a halved Q interval adds a row of nodes across
    // the whole t_Y range.
    const std::size_t nTc = g.tY.size() - 1, nQc = g.Q.size() - 1;
    const std::size_t per_cell = roll_axis ? 6 : 4;
    std::vector<TablePoint> edges;
    for (std::size_t c = 0; c < cell_fail.size(); ++c)
      if (cell_fail[c]) {
        const std::size_t m = c / (nTc * nQc), i = (c / nQc) % nTc, j = c % nQc;
        const double tm = table_point_rounded(0.5 * (g.tY[i] + g.tY[i + 1])), qm = 0.5 * (g.Q[j] + g.Q[j + 1]);
        const double r0 = g.r_lo(m), r1 = g.r_hi(m);
        edges.insert(edges.end(), {{tm, g.Q[j], r0}, {tm, g.Q[j + 1], r1}, {g.tY[i], qm, r0}, {g.tY[i + 1], qm, r1}});
        if (roll_axis) {
          const double rm = table_point_rounded(0.5 * (r0 + r1));
          edges.insert(edges.end(), {{g.tY[i], g.Q[j], rm}, {g.tY[i + 1], g.Q[j + 1], rm}});
        }
      }
    if (!solve_missing(edges)) return made;
    // An edge midpoint's error in units of its tolerances (> 1: missed; 0 where not compared).
    auto score = [&](const TablePoint& p) {
      look.lookup(p.tY_mm * units::mm, p.Q_kN * 1e3, p.roll_mrad * 1e-3, ans);
      const TableCheckError e = table_check_error(ans, solved.at(p), p);
      return e.compared ? table_tolerance_ratio(e, tolerances(opt)) : 0.0;
    };
    std::vector<std::uint8_t> split_t(nTc, 0), split_q(nQc, 0), split_r(g.roll.size() - 1, 0);
    for (std::size_t c = 0, k = 0; c < cell_fail.size(); ++c)
      if (cell_fail[c]) {
        const double sT = std::max(score(edges[k]), score(edges[k + 1]));
        const double sQ = std::max(score(edges[k + 2]), score(edges[k + 3]));
        const double sR = roll_axis ? std::max(score(edges[k + 4]), score(edges[k + 5])) : 0.0;
        k += per_cell;
        const std::size_t m = c / (nTc * nQc), j = c % nQc;
        const bool r_can = roll_axis && g.roll[m + 1] - g.roll[m] >= 2 * opt.min_roll_step_mrad - 1e-12;
        if (r_can && sR > 1 && sR >= std::max(sT, sQ)) {
          split_r[m] = 1;
          continue;
        }
        const bool q_can = g.Q[j + 1] - g.Q[j] >= 2 * opt.min_Q_step_kN - 1e-12;  // else t_Y is all that is left
        const bool q = q_can && sT <= 1 && sQ > sT;
        split_q[j] |= q;
        split_t[(c / nQc) % nTc] |= !q;
      }
    // A node without an answer leaves its cells without one: halving its t_Y intervals narrows
    // that band.
    const std::vector<TablePoint> nodes = g.nodes();
    const std::size_t nT = g.tY.size(), nQ = g.Q.size();
    for (std::size_t m = 0; m < g.roll.size(); ++m)
      for (std::size_t i = 0; i + 1 < nT; ++i)
        for (std::size_t j = 0; j < nQ; ++j)
          split_t[i] |= is_failure(solved.at(nodes[(m * nT + i) * nQ + j]).status) ||
                        is_failure(solved.at(nodes[(m * nT + i + 1) * nQ + j]).status);
    // Halve the marked intervals (not below min_step_mm, min_Q_step_kN, min_roll_step_mrad).
    auto halve = [](const std::vector<double>& x, const std::vector<std::uint8_t>& mark, double min_step, bool round_mm) {
      std::vector<double> next;
      for (std::size_t i = 0; i + 1 < x.size(); ++i) {
        next.push_back(x[i]);
        if (mark[i] && x[i + 1] - x[i] >= 2 * min_step - 1e-12) {
          const double mid = 0.5 * (x[i] + x[i + 1]);
          next.push_back(round_mm ? table_point_rounded(mid) : mid);
        }
      }
      next.push_back(x.back());
      return next;
    };
    std::vector<double> next_t = halve(g.tY, split_t, opt.min_step_mm, true);
    std::vector<double> next_q = halve(g.Q, split_q, opt.min_Q_step_kN, false);
    std::vector<double> next_r = roll_axis ? halve(g.roll, split_r, opt.min_roll_step_mrad, true) : g.roll;
    if (next_t.size() == g.tY.size() && next_q.size() == g.Q.size() && next_r.size() == g.roll.size()) break;
    g.tY = next_t;
    g.Q = next_q;
    g.roll = next_r;
    if (!opt.quiet) {
      err << "mhcontact table: refinement " << round + 1 << ": " << g.tY.size() << " t_Y nodes, " << g.Q.size() << " Q nodes";
      if (roll_axis) err << ", " << g.roll.size() << " roll nodes";
      err << "\n";
    }
  }
  data.cell_coarse = cell_fail;

  // A t_Y node where some load (at some roll) has no answer (the method's equilibrium not found:
  // at flange onset the answer jumps there) is dropped from the grid, so that the interpolant
  // runs through with continuous forces instead of answering nothing around it; the cells that
  // span a dropped node are coarse (docs/tables.md "Nodes without an answer").
  std::vector<double> dropped;
  {
    std::vector<double> keep;
    for (double t : g.tY) {
      bool bad = false;
      for (double r : g.roll)
        for (double q : g.Q) bad = bad || is_failure(solved.at({t, q, r}).status);
      (bad ? dropped : keep).push_back(t);
    }
    if (!dropped.empty() && keep.size() >= 2) {
      const std::size_t nQc = g.Q.size() - 1, nTc_old = g.tY.size() - 1, nTc = keep.size() - 1;
      std::vector<std::uint8_t> fail(g.nRc() * nTc * nQc, 0);
      for (std::size_t i = 0; i < nTc; ++i) {
        const auto at = static_cast<std::size_t>(std::find(g.tY.begin(), g.tY.end(), keep[i]) - g.tY.begin());
        const bool same = at + 1 < g.tY.size() && g.tY[at + 1] == keep[i + 1];
        for (std::size_t m = 0; m < g.nRc(); ++m)
          for (std::size_t j = 0; j < nQc; ++j)
            fail[(m * nTc + i) * nQc + j] = same ? cell_fail[(m * nTc_old + at) * nQc + j] : 1;
      }
      g.tY = keep;
      data = build();
      cell_fail = fail;
      data.cell_coarse = fail;
    } else {
      dropped.clear();
    }
  }
  // Without the dropped nodes the table is another interpolant (new cells span them, and the
  // PCHIP slopes of their neighbours change): its error is checked again at the centres of its
  // own cells, so that the header's error and `checks` are those of the table written.
  if (opt.check && !dropped.empty()) {
    const std::vector<TablePoint> centres = g.centres(opt.check_points);
    if (!solve_missing(centres)) return made;
    check_cells(centres);
    data.cell_coarse = cell_fail;
  }

  // The validation points against the table written (its coarse cells marked: a lookup there is
  // at best outside_validity, as a caller's is).
  std::vector<TableCheckError> validated;
  {
    const ContactTableLookup look(data);
    TableAnswer ans;
    for (const TablePoint& p : validation) {
      look.lookup(p.tY_mm * units::mm, p.Q_kN * 1e3, p.roll_mrad * 1e-3, ans);
      validated.push_back(table_check_error(ans, solved.at(p), p));
    }
  }

  // The checks were made before their cells were marked: a coarse cell's table answer is at best
  // outside_validity (the lookup of the table written), as the status counts of `error` say.
  for (std::size_t c = 0; c < checks.size() && c / per < cell_fail.size(); ++c)
    if (cell_fail[c / per] && checks[c].table == CaseStatus::Ok) checks[c].table = CaseStatus::OutsideValidity;

  // The header.
  nlohmann::json h;
  h["schema"] = kContactTableSchema;
  h["program"] = program_json();
  h["what"] = "contact table: per node (t_Y, Q, roll) and contact track, the grid method's answer; "
              "interpolate with bicubic Hermite (tricubic with more than one roll node), PCHIP node slopes, "
              "zero cross slopes (docs/tables.md)";
  h["method"] = to_string(cf.method);
  h["model"] = to_string(cf.model);
  h["inputs"] = inputs_json(cf);
  h["profiles"] = profiles_json(pg);
  // Where the pair sits in a wheelset (the wheelset call's placement, wheelset_contact.cpp
  // place()): the taping line a from the wheelset centre, the axle centre z0 + R0 above the
  // wheel profile's origin, the rail origin c from the track centre. A wheelset table
  // (wheelset_table.hpp) places each wheel by them: t_Y = σ y + a (cos δ − 1) + (z0 + R0) sin δ.
  {
    const double a = cf.track.flange_back_distance / 2 - cf.track.flange_back_position;
    h["wheelset_placement"] = {{"a_mm", a * 1e3},
                               {"axle_height_mm", (pg.geo.wheel_z0 + pg.geo.nominal_radius) * 1e3},
                               {"rail_offset_mm", (a - pg.geo.y_offset) * 1e3}};
  }
  h["tY_mm_nodes"] = g.tY;
  h["Q_kN_nodes"] = g.Q;
  h["roll_mrad_nodes"] = g.roll;
  h["tY_mm_range"] = {g.tY.front(), g.tY.back()};
  h["Q_kN_range"] = {g.Q.front(), g.Q.back()};
  h["roll_mrad_range"] = {g.roll.front(), g.roll.back()};
  h["tracks"] = data.n_tracks;
  h["refine"] = opt.refine;
  h["check_points"] = opt.check ? opt.check_points : 0;
  h["dropped_tY_mm"] = dropped;
  nlohmann::json coarse = nlohmann::json::array();
  for (std::size_t m = 0; m < g.nRc(); ++m)
    for (std::size_t i = 0; i + 1 < g.tY.size(); ++i)
      for (std::size_t j = 0; j + 1 < g.Q.size(); ++j)
        if (cell_fail[data.cell(m, i, j)]) coarse.push_back({i, j, m});
  h["coarse_cells"] = coarse;
  nlohmann::json units_j = {{"tY_mm", "mm"}, {"Q_kN", "kN"}, {"roll_mrad", "mrad"}};
  for (const TableColumn& c : kTableColumns) {
    const std::string n = c.name;
    const auto u = n.rfind('_');
    units_j[n] = n[0] == 'C' ? "1" : n.substr(u + 1);
  }
  h["units"] = units_j;
  if (opt.check) h["error"] = table_error_summary(checks, tolerances(opt), opt.check_points);
  if (!validation.empty()) h["validation"] = table_validation_summary(validated, tolerances(opt));
  data.header = h;
  made.data = std::move(data);
  made.checks = std::move(checks);
  made.validation = std::move(validated);
  return made;
}

void write_contact_table(const ContactTableData& t, std::ostream& out) {
  out << "# " << t.header.dump() << "\n";
  out << "tY_mm,Q_kN,roll_mrad,status,contact,present";
  for (const TableColumn& c : kTableColumns) out << ',' << c.name;
  out << '\n';
  const std::size_t nk = static_cast<std::size_t>(t.n_tracks);
  const auto tYn = t.header.at("tY_mm_nodes").get<std::vector<double>>();
  const auto Qn = t.header.at("Q_kN_nodes").get<std::vector<double>>();
  const auto Rn = t.header.at("roll_mrad_nodes").get<std::vector<double>>();
  std::string line;
  for (std::size_t m = 0; m < t.nR(); ++m)
    for (std::size_t i = 0; i < t.nT(); ++i)
      for (std::size_t j = 0; j < t.nQ(); ++j)
        for (std::size_t k = 0; k < nk; ++k) {
          const std::size_t n = t.node(m, i, j);
          line = format_number(tYn[i]) + ',' + format_number(Qn[j]) + ',' + format_number(Rn[m]) + ',' +
                 to_string(t.node_status[n]) + ',' + std::to_string(k + 1) + ',' + (t.present[n * nk + k] ? '1' : '0');
          const double* v = &t.v[t.at(m, i, j, static_cast<int>(k))];
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
    err << "mhcontact table: " << m.data.nT() << " x " << m.data.nQ();
    if (m.data.nR() > 1) err << " x " << m.data.nR();
    err << " nodes, " << m.data.n_tracks
        << " contact tracks, " << m.solves << " solves";
    if (m.data.header.contains("error")) {
      const auto& e = m.data.header["error"];
      err << "; interpolation error at " << e["N"]["checked"].get<std::size_t>()
          << (opt.check_points == 3 ? " check points: N max " : " cell centres: N max ")
          << fmt3(100 * e["N"]["max"].get<double>()) << " % of Q, pmax max "
          << fmt3(100 * e["pmax"]["max"].get<double>()) << " %, area max "
          << fmt3(100 * e["area"]["max"].get<double>()) << " %, position max "
          << fmt3(e["position"]["max"].get<double>()) << " mm";
    }
    err << "; " << coarse << " coarse cells, " << failed << " t_Y nodes without an answer (dropped)\n";
    if (m.data.header.contains("validation")) {
      const auto& v = m.data.header["validation"];
      const auto& st = v["status"];
      err << "mhcontact table: validation at " << v["points"].get<std::size_t>() << " random points: ok table "
          << st["table_ok"].get<std::size_t>() << ", direct " << st["direct_ok"].get<std::size_t>() << ", both "
          << st["both_ok"].get<std::size_t>() << ", table and not direct " << st["table_ok_direct_not"].get<std::size_t>()
          << "; where both ok: N max " << fmt3(100 * v["N"]["max"].get<double>()) << " % of Q, pmax max "
          << fmt3(100 * v["pmax"]["max"].get<double>()) << " %, area max " << fmt3(100 * v["area"]["max"].get<double>())
          << " %; " << v["beyond"].get<std::size_t>() << " ok answers beyond a tolerance\n";
    }
  }
  // A validation point where the table answers ok beyond a tolerance, or ok where the method does
  // not, is a cell known to miss, as a coarse one: exit 1 (its cell is not marked: the points
  // measure the table, they do not make it).
  bool missed = false;
  if (m.data.header.contains("validation")) {
    const auto& v = m.data.header["validation"];
    missed = v["beyond"].get<std::size_t>() > 0 || v["status"]["table_ok_direct_not"].get<std::size_t>() > 0;
  }
  return coarse || failed || missed ? kExitCasesFailed : kExitOk;
}

}  // namespace mh
