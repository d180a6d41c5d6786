// The export of a contact table on a regular grid (contact_table_export.hpp; docs/tables.md
// "Export for MBS codes").
#include "jobs/contact_table_export.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <vector>

#include "core/checksum.hpp"
#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "jobs/contact_table_make.hpp"
#include "jobs/run.hpp"
#include "output/output_file.hpp"

namespace mh {
namespace {

/// The regular grid from..to by step [mm or kN]; throws when the step does not divide the range.
std::vector<double> regular(double from, double to, double step, const std::string& source, const char* option,
                            const char* unit) {
  const double n = std::round((to - from) / step);
  if (!(step > 0) || n < 1 || std::fabs(n * step - (to - from)) > 1e-9 * std::max(1.0, std::fabs(to - from)) ||
      n > 100000) {
    std::ostringstream range;
    range << from << " ... " << to << ' ' << unit;
    throw InputError(std::string(option), format_number(step),
                     "the step must divide the table's range " + range.str() + " (" + source + ") into 1 to 100000 steps",
                     "choose a step that divides " + range.str());
  }
  std::vector<double> x;
  for (long k = 0; k <= static_cast<long>(n); ++k) x.push_back(std::round((from + static_cast<double>(k) * step) * 1e9) / 1e9);
  return x;
}

/// The difference of two answers at one point, by track (docs/tables.md "Export for MBS codes").
struct PointDiff {
  double N = 0, pmax = 0, area = 0, position = 0, Fy = 0;  ///< /Q, relative, relative, [m], /Q
};

PointDiff diff(const TableAnswer& e, const TableAnswer& t, double Q) {
  PointDiff d;
  auto find = [](const TableAnswer& a, int track) -> const TableContact* {
    for (int k = 0; k < std::min(a.n_contacts, kTableMaxContacts); ++k)
      if (a.c[static_cast<std::size_t>(k)].track == track) return &a.c[static_cast<std::size_t>(k)];
    return nullptr;
  };
  double pe = 0, pt = 0, ae = 0, at = 0;
  for (const TableAnswer* a : {&e, &t})
    for (int k = 0; k < std::min(a->n_contacts, kTableMaxContacts); ++k) {
      const TableContact& c = a->c[static_cast<std::size_t>(k)];
      const TableContact* o = find(a == &e ? t : e, c.track);
      const double N = c.v[kTabN], No = o ? o->v[kTabN] : 0.0;
      d.N = std::max(d.N, std::fabs(N - No) / Q);
      if (a == &e) {
        pe = std::max(pe, c.v[kTabPmax]);
        ae += c.v[kTabArea];
      } else {
        pt = std::max(pt, c.v[kTabPmax]);
        at += c.v[kTabArea];
        if (o && N >= 0.05 * Q) d.position = std::max(d.position, std::fabs(o->v[kTabYRail] - c.v[kTabYRail]));
      }
    }
  d.pmax = pt > 0 ? std::fabs(pe - pt) / pt : 0;
  d.area = at > 0 ? std::fabs(ae - at) / at : 0;
  d.Fy = std::fabs(e.Fy - t.Fy) / Q;
  return d;
}

nlohmann::json stats(const std::vector<PointDiff>& v, const char* where) {
  nlohmann::json j;
  j["where"] = where;
  j["checked"] = v.size();
  auto one = [&](double PointDiff::*f, double scale, const char* unit) {
    std::vector<double> x;
    for (const PointDiff& p : v) x.push_back(p.*f * scale);
    std::sort(x.begin(), x.end());
    nlohmann::json s = {{"unit", unit}};
    s["max"] = x.empty() ? 0.0 : x.back();
    s["p95"] = x.empty() ? 0.0 : x[std::min(x.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(x.size())))];
    s["median"] = x.empty() ? 0.0 : x[x.size() / 2];
    return s;
  };
  j["N"] = one(&PointDiff::N, 1, "fraction of Q");
  j["pmax"] = one(&PointDiff::pmax, 1, "fraction");
  j["area"] = one(&PointDiff::area, 1, "fraction");
  j["position"] = one(&PointDiff::position, 1e3, "mm");
  j["Fy"] = one(&PointDiff::Fy, 1, "fraction of Q");
  return j;
}

std::string pct(double v) {
  std::ostringstream o;
  o << std::setprecision(3) << 100 * v;
  return o.str();
}

}  // namespace

ContactTableData export_contact_table(const ContactTableData& table, const std::string& source,
                                      const std::string& sha256, const TableExportOptions& opt) {
  double tY_step = opt.tY_step_mm;
  if (!(tY_step > 0)) {
    double h = 0.25;
    for (std::size_t i = 0; i + 1 < table.nT(); ++i) h = std::min(h, (table.tY[i + 1] - table.tY[i]) * 1e3);
    const double range = (table.tY.back() - table.tY.front()) * 1e3;
    tY_step = range / std::ceil(range / h - 1e-9);
  }
  const std::vector<double> tY_mm = regular(table.tY.front() * 1e3, table.tY.back() * 1e3, tY_step, source,
                                            "--tY-step-mm", "mm");
  const std::vector<double> Q_kN = regular(table.Q.front() * 1e-3, table.Q.back() * 1e-3, opt.Q_step_kN, source,
                                           "--Q-step-kN", "kN");
  const ContactTableLookup look(table);
  ContactTableData ex;
  for (double t : tY_mm) ex.tY.push_back(t * 1e-3);
  for (double q : Q_kN) ex.Q.push_back(q * 1e3);
  ex.roll = table.roll;  // the table's own roll nodes: read linearly between them
  // The grid's ends are the table's ends exactly (the rounding of the mm values aside).
  ex.tY.front() = table.tY.front(), ex.tY.back() = table.tY.back();
  ex.Q.front() = table.Q.front(), ex.Q.back() = table.Q.back();
  ex.n_tracks = table.n_tracks;
  const std::size_t nT = ex.nT(), nQ = ex.nQ(), nR = ex.nR(), nk = static_cast<std::size_t>(ex.n_tracks);
  ex.node_status.assign(nR * nT * nQ, CaseStatus::Ok);
  ex.cell_coarse.assign(ex.nRc() * (nT - 1) * (nQ - 1), 0);
  ex.present.assign(nR * nT * nQ * nk, 0);
  ex.v.assign(nR * nT * nQ * nk * kTableQuantities, 0.0);
  TableAnswer a;
  std::array<double, kTableQuantities> v;
  for (std::size_t m = 0; m < nR; ++m)
    for (std::size_t i = 0; i < nT; ++i)
      for (std::size_t j = 0; j < nQ; ++j) {
        look.lookup(ex.tY[i], ex.Q[j], ex.roll[m], a);
        const std::size_t n = ex.node(m, i, j);
        ex.node_status[n] = a.status;
        const bool answered = status_severity(a.status) < 3;
        for (std::size_t k = 0; k < nk; ++k) {
          // Every track at every point: where its N is 0 (or the point has no answer), the force,
          // pressure and sizes are 0 and the positions, angle, radius and Kalker coefficients the
          // interpolant's, continuous where the contact fades out.
          look.track_values(ex.tY[i], ex.Q[j], ex.roll[m], static_cast<int>(k), v);
          const bool present = answered && v[kTabN] > 0;
          ex.present[n * nk + k] = present;
          double* out = &ex.v[ex.at(m, i, j, static_cast<int>(k))];
          for (int q = 0; q < kTableQuantities; ++q) out[q] = present || !kTableColumns[q].fades ? v[q] : 0.0;
        }
      }

  // The error of reading the export linearly, where the table's answer is ok: at the table's
  // nodes (the method's own answers) and at the centres of the export's cells (against the
  // table's interpolant, where a linear reading errs most).
  std::vector<PointDiff> at_nodes, at_centres;
  TableAnswer e;
  for (double r : table.roll)
    for (double t : table.tY)
      for (double q : table.Q) {
        look.lookup(t, q, r, a);
        if (a.status != CaseStatus::Ok) continue;
        export_linear(ex, t, q, r, e);
        at_nodes.push_back(diff(e, a, q));
      }
  for (std::size_t m = 0; m < ex.nRc(); ++m)
    for (std::size_t i = 0; i + 1 < nT; ++i)
      for (std::size_t j = 0; j + 1 < nQ; ++j) {
        const double t = 0.5 * (ex.tY[i] + ex.tY[i + 1]), q = 0.5 * (ex.Q[j] + ex.Q[j + 1]);
        const double r = nR > 1 ? 0.5 * (ex.roll[m] + ex.roll[m + 1]) : ex.roll[0];
        look.lookup(t, q, r, a);
        if (a.status != CaseStatus::Ok) continue;
        export_linear(ex, t, q, r, e);
        at_centres.push_back(diff(e, a, q));
      }

  nlohmann::json h;
  h["schema"] = kContactTableExportSchema;
  h["program"] = program_json();
  h["what"] = "a contact table resampled on a regular t_Y x Q grid (at the table's roll nodes) for table-driven "
              "contact elements: per point and contact track the table's interpolant; read it linearly per track "
              "(docs/tables.md)";
  const nlohmann::json& th = table.header;
  nlohmann::json src = {{"file", source}, {"sha256", sha256}, {"schema", th.value("schema", std::string())}};
  for (const char* key : {"method", "model", "profiles", "inputs", "tY_mm_nodes", "Q_kN_nodes", "roll_mrad_nodes",
                          "dropped_tY_mm", "coarse_cells", "error", "validation"})
    if (th.contains(key)) src[key] = th[key];
  h["source"] = src;
  h["interpolation"] = "per track, every column bilinear in (tY_mm, Q_kN) on the grid cell (trilinear in (tY_mm, Q_kN, "
                       "roll_mrad) with more than one roll node); a contact where the interpolated N_kN > 0; the status "
                       "the worst of the cell's corners (ok < outside_validity < derailed < the statuses without an "
                       "answer); with one roll node, at best outside_validity at another roll";
  h["grid"] = {{"tY_mm", {{"from", tY_mm.front()}, {"to", tY_mm.back()}, {"step", tY_step}, {"points", nT}}},
               {"Q_kN", {{"from", Q_kN.front()}, {"to", Q_kN.back()}, {"step", opt.Q_step_kN}, {"points", nQ}}}};
  h["tY_mm_nodes"] = tY_mm;
  h["Q_kN_nodes"] = Q_kN;
  std::vector<double> roll_mrad;
  for (double r : ex.roll) roll_mrad.push_back(std::round(r * 1e3 * 1e9) / 1e9);
  h["roll_mrad_nodes"] = th.contains("roll_mrad_nodes") ? th["roll_mrad_nodes"] : nlohmann::json(roll_mrad);
  h["tracks"] = ex.n_tracks;
  h["units"] = th.contains("units") ? th["units"] : nlohmann::json::object();
  nlohmann::json err;
  err["at_table_nodes"] = stats(at_nodes, "the table's nodes where its answer is ok: the export read bilinearly "
                                          "against the method's answers there");
  err["at_export_cell_centres"] = stats(at_centres, "the centres of the export's cells where the table's answer is ok: "
                                                    "the export read bilinearly against the table's interpolant");
  // What a bilinear reading of the export is expected to hold against the method itself where
  // the table's answer is ok: the table's tolerance (held at its cell centres) plus the largest
  // resampling error measured above.
  if (th.contains("error")) {
    nlohmann::json b;
    for (const char* q : {"N", "pmax", "area"}) {
      const double tol = th["error"][q].value("tolerance", 0.0);
      const double rs = std::max(err["at_table_nodes"][q]["max"].get<double>(),
                                 err["at_export_cell_centres"][q]["max"].get<double>());
      b[q] = {{"unit", err["at_table_nodes"][q]["unit"]}, {"table_tolerance", tol}, {"resample_max", rs}, {"bound", tol + rs}};
    }
    b["where"] = "points whose export status is ok, against a direct solve by the table's method";
    err["against_method"] = b;
  }
  h["error"] = err;
  ex.header = h;
  return ex;
}

void export_linear(const ContactTableData& ex, double tY, double Q, double roll, TableAnswer& out) {
  out.n_contacts = 0;
  out.Fz = out.Fy = out.dFy_dtY = out.dFy_dQ = out.dFy_droll = 0;
  out.coarse = out.off_roll = false;
  const std::size_t nR = ex.nR(), nk = static_cast<std::size_t>(ex.n_tracks);
  const bool axis = nR > 1;
  if (!(tY >= ex.tY.front() && tY <= ex.tY.back() && Q >= ex.Q.front() && Q <= ex.Q.back()) || !std::isfinite(roll) ||
      (axis && !(roll >= ex.roll.front() && roll <= ex.roll.back()))) {
    out.status = CaseStatus::OutOfRange;
    return;
  }
  const std::size_t i = table_interval(ex.tY, tY), j = table_interval(ex.Q, Q), m = axis ? table_interval(ex.roll, roll) : 0;
  const std::size_t nc = axis ? 2 : 1;
  CaseStatus st = CaseStatus::Ok;
  for (std::size_t c = 0; c < nc; ++c)
    for (std::size_t a = 0; a < 2; ++a)
      for (std::size_t b = 0; b < 2; ++b) {
        const CaseStatus s = ex.node_status[ex.node(m + c, i + a, j + b)];
        if (status_severity(s) > status_severity(st)) st = s;
      }
  out.off_roll = !axis && !(std::fabs(roll - ex.roll[0]) <= kTableRollTolerance);
  if (out.off_roll && st == CaseStatus::Ok) st = CaseStatus::OutsideValidity;
  out.status = st;
  if (status_severity(st) >= 3) return;
  const double hx = ex.tY[i + 1] - ex.tY[i], hy = ex.Q[j + 1] - ex.Q[j];
  const double u = (tY - ex.tY[i]) / hx, w = (Q - ex.Q[j]) / hy;
  const double hz = axis ? ex.roll[m + 1] - ex.roll[m] : 1.0, s = axis ? (roll - ex.roll[m]) / hz : 0.0;
  // Weights of the corners (a, b, c) and their derivatives along each axis.
  const double U[2] = {1 - u, u}, W[2] = {1 - w, w}, S[2] = {1 - s, s};
  const double dU[2] = {-1 / hx, 1 / hx}, dW[2] = {-1 / hy, 1 / hy}, dS[2] = {-1 / hz, 1 / hz};
  TableTrackValues t;
  for (std::size_t k = 0; k < nk; ++k) {
    t.v.fill(0), t.d_dtY.fill(0), t.d_dQ.fill(0), t.d_droll.fill(0);
    for (std::size_t c = 0; c < nc; ++c)
      for (std::size_t a = 0; a < 2; ++a)
        for (std::size_t b = 0; b < 2; ++b) {
          const double* f = &ex.v[ex.at(m + c, i + a, j + b, static_cast<int>(k))];
          const double Sc = axis ? S[c] : 1.0, dSc = axis ? dS[c] : 0.0;
          const double c0 = U[a] * W[b] * Sc, cx = dU[a] * W[b] * Sc, cy = U[a] * dW[b] * Sc, cz = U[a] * W[b] * dSc;
          for (int q = 0; q < kTableQuantities; ++q) {
            t.v[q] += c0 * f[q];
            t.d_dtY[q] += cx * f[q];
            t.d_dQ[q] += cy * f[q];
            t.d_droll[q] += cz * f[q];
          }
        }
    if (!(t.v[kTabN] > 0)) continue;
    add_table_contact(out, static_cast<int>(k), t);
  }
}

int table_export_job(const std::string& table_path, const TableExportOptions& opt, const std::string& out_path,
                     std::ostream& out, std::ostream& err, bool quiet) {
  const ContactTableData table = read_contact_table(table_path);
  const std::string sha = sha256_file(table_path);
  const ContactTableData ex = export_contact_table(table, table_path, sha, opt);
  if (out_path == "-") {
    write_contact_table(ex, out);
  } else {
    OutputFile f(out_path);
    write_contact_table(ex, f.stream());
    f.commit();
  }
  if (!quiet) {
    const auto& e = ex.header["error"];
    auto line = [&](const nlohmann::json& s) {
      err << s["checked"].get<std::size_t>() << ": N max " << pct(s["N"]["max"].get<double>()) << " % of Q, pmax max "
          << pct(s["pmax"]["max"].get<double>()) << " %, area max " << pct(s["area"]["max"].get<double>()) << " %";
    };
    err << "mhcontact table-export: " << ex.nT() << " x " << ex.nQ();
    if (ex.nR() > 1) err << " x " << ex.nR();
    err << " points, " << ex.n_tracks << " contact tracks; linear error at the table's ok nodes, ";
    line(e["at_table_nodes"]);
    err << "; at the export's ok cell centres, ";
    line(e["at_export_cell_centres"]);
    err << '\n';
  }
  return kExitOk;
}

}  // namespace mh
