// Contact tables: the reader and the lookup (contact_table.hpp; docs/tables.md).
#include "input/contact_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"

namespace mh {

const std::array<TableColumn, kTableQuantities> kTableColumns{{
    {"N_kN", 1e3, true, true},
    {"y_rail_mm", 1e-3, false, false},
    {"z_rail_mm", 1e-3, false, false},
    {"y_wheel_mm", 1e-3, false, false},
    {"gamma_deg", M_PI / 180, false, false},
    {"r_roll_mm", 1e-3, false, false},
    {"pmax_MPa", 1e6, true, true},
    {"area_mm2", 1e-6, true, true},
    {"a_mm", 1e-3, true, true},
    {"b_mm", 1e-3, true, true},
    {"a_el_mm", 1e-3, true, true},
    {"b_el_mm", 1e-3, true, true},
    {"C11", 1, false, false},
    {"C22", 1, false, false},
    {"C23", 1, false, false},
}};

int status_severity(CaseStatus s) {
  switch (s) {
    case CaseStatus::Ok: return 0;
    case CaseStatus::OutsideValidity: return 1;
    case CaseStatus::Derailed: return 2;
    default: return 3;
  }
}

namespace {

bool parse_status(const std::string& s, CaseStatus& out) {
  for (CaseStatus c : {CaseStatus::Ok, CaseStatus::OutsideValidity, CaseStatus::NoContact, CaseStatus::OutOfRange,
                       CaseStatus::NotConverged, CaseStatus::Derailed})
    if (s == to_string(c)) return out = c, true;
  return false;
}

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> f;
  std::size_t a = 0;
  for (;;) {
    const std::size_t b = line.find(',', a);
    f.push_back(line.substr(a, b == std::string::npos ? std::string::npos : b - a));
    if (b == std::string::npos) break;
    a = b + 1;
  }
  return f;
}

double parse_number(const std::string& s, const std::string& where, const std::string& column) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v))
    throw InputError(where, s, "column " + column + " must be a finite number",
                     "a table is written by `mhcontact table`; regenerate it rather than editing it");
  return v;
}

// PCHIP node slopes of the values f[0..n) (stride `stride` in `f`) at abscissae x (docs/tables.md).
void pchip_slopes(const double* x, std::size_t n, const double* f, std::size_t stride, double* d) {
  if (n < 2) {
    if (n == 1) d[0] = 0;
    return;
  }
  auto F = [&](std::size_t i) { return f[i * stride]; };
  auto D = [&](std::size_t i) -> double& { return d[i * stride]; };
  if (n == 2) {
    D(0) = D(1) = (F(1) - F(0)) / (x[1] - x[0]);
    return;
  }
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
    const double s0 = (F(i) - F(i - 1)) / h0, s1 = (F(i + 1) - F(i)) / h1;
    if (s0 * s1 <= 0) {
      D(i) = 0;
    } else {
      const double w1 = 2 * h1 + h0, w2 = h1 + 2 * h0;
      D(i) = (w1 + w2) / (w1 / s0 + w2 / s1);
    }
  }
  // Ends: the three-point one-sided formula, kept shape-preserving (as Moler's pchip).
  auto end_slope = [](double h0, double h1, double s0, double s1) {
    double e = ((2 * h0 + h1) * s0 - h0 * s1) / (h0 + h1);
    if (e * s0 <= 0) e = 0;
    else if (s0 * s1 <= 0 && std::fabs(e) > std::fabs(3 * s0)) e = 3 * s0;
    return e;
  };
  D(0) = end_slope(x[1] - x[0], x[2] - x[1], (F(1) - F(0)) / (x[1] - x[0]), (F(2) - F(1)) / (x[2] - x[1]));
  const std::size_t m = n - 1;
  D(m) = end_slope(x[m] - x[m - 1], x[m - 1] - x[m - 2], (F(m) - F(m - 1)) / (x[m] - x[m - 1]),
                   (F(m - 1) - F(m - 2)) / (x[m - 1] - x[m - 2]));
}

}  // namespace

ContactTableData read_contact_table(const std::string& path, const char* schema) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the table file", "check the path");
  std::size_t ln = 0;
  ContactTableData t = read_contact_table(in, path, ln, schema);
  if (in.peek() != std::char_traits<char>::eof())
    throw InputError(at_line(path, ln + 1), "", "a second header line: this file holds more than one table",
                     "a wheelset table (two sections) is read by read_wheelset_table / mhc_wheelset_table_read");
  return t;
}

ContactTableData read_contact_table(std::istream& in, const std::string& path, std::size_t& ln, const char* schema) {
  ContactTableData t;
  std::string line;
  const std::size_t hl = ln + 1;  // the header's line
  if (!std::getline(in, line) || line.size() < 2 || line[0] != '#')
    throw InputError(at_line(path, hl), "", "a contact table starts with its JSON header line `# {...}`",
                     "write it with `mhcontact table CASE.json -o FILE`");
  ++ln;
  try {
    t.header = nlohmann::json::parse(line.substr(1));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(at_line(path, hl), "", std::string("the JSON header does not parse: ") + e.what());
  }
  if (!t.header.is_object() || t.header.value("schema", std::string()) != schema)
    throw InputError(at_line(path, hl), t.header.is_object() ? t.header.value("schema", std::string("(none)")) : "",
                     std::string("the header's schema must be ") + schema,
                     t.header.is_object() && t.header.value("schema", std::string()) == kWheelsetTableSchema
                         ? "a wheelset table (two pairs' tables): give one pair's table, as `mhcontact table` wrote it"
                         : "a table of another version: regenerate it with this mhcontact");
  try {
    for (double v : t.header.at("tY_mm_nodes").get<std::vector<double>>()) t.tY.push_back(v * 1e-3);
    for (double v : t.header.at("Q_kN_nodes").get<std::vector<double>>()) t.Q.push_back(v * 1e3);
    t.roll.clear();
    for (double v : t.header.at("roll_mrad_nodes").get<std::vector<double>>()) t.roll.push_back(v * 1e-3);
    t.n_tracks = t.header.at("tracks").get<int>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError(at_line(path, hl), "",
                     std::string("header: tY_mm_nodes, Q_kN_nodes, roll_mrad_nodes and tracks are required: ") + e.what());
  }
  const std::size_t nT = t.nT(), nQ = t.nQ(), nR = t.nR();
  if (nT < 2 || nQ < 2 || nR < 1 || t.n_tracks < 1 || t.n_tracks > 1000)
    throw InputError(at_line(path, hl), "", "header: at least 2 t_Y nodes, 2 Q nodes, 1 roll node and 1 to 1000 tracks");
  for (std::size_t i = 1; i < nT; ++i)
    if (!(t.tY[i] > t.tY[i - 1])) throw InputError(at_line(path, hl), "", "header: tY_mm_nodes must increase");
  for (std::size_t j = 1; j < nQ; ++j)
    if (!(t.Q[j] > t.Q[j - 1])) throw InputError(at_line(path, hl), "", "header: Q_kN_nodes must increase");
  for (std::size_t m = 1; m < nR; ++m)
    if (!(t.roll[m] > t.roll[m - 1] + kTableRollTolerance))
      throw InputError(at_line(path, hl), "", "header: roll_mrad_nodes must increase");
  const std::size_t nk = static_cast<std::size_t>(t.n_tracks), nn = nR * nT * nQ;
  t.node_status.assign(nn, CaseStatus::Ok);
  t.present.assign(nn * nk, 0);
  t.v.assign(nn * nk * kTableQuantities, 0.0);
  t.cell_coarse.assign(t.nRc() * (nT - 1) * (nQ - 1), 0);
  if (t.header.contains("coarse_cells"))
    for (const auto& c : t.header["coarse_cells"]) {
      if (!c.is_array() || c.size() != 3)
        throw InputError(at_line(path, hl), c.dump(), "header: a coarse cell is [i, j, m] (t_Y, Q and roll cell)");
      const auto i = c.at(0).get<std::size_t>(), j = c.at(1).get<std::size_t>(), m = c.at(2).get<std::size_t>();
      if (i + 1 >= nT || j + 1 >= nQ || m >= t.nRc())
        throw InputError(at_line(path, hl), c.dump(), "header: coarse_cells index outside the grid");
      t.cell_coarse[t.cell(m, i, j)] = 1;
    }
  // The column line.
  std::string expect = "tY_mm,Q_kN,roll_mrad,status,contact,present";
  for (const TableColumn& c : kTableColumns) expect += std::string(",") + c.name;
  if (!std::getline(in, line)) throw InputError(at_line(path, hl + 1), "", "the column line is missing");
  ++ln;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  if (line != expect) throw InputError(at_line(path, hl + 1), line, "the columns must be " + expect);
  std::size_t rows = 0;
  // Rows up to the end of the file or the next section's header line.
  while (in.peek() != '#' && std::getline(in, line)) {
    ++ln;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::string where = at_line(path, ln);
    const auto f = split_csv(line);
    if (f.size() != kTableNodeColumns + kTableQuantities)
      throw InputError(where, std::to_string(f.size()) + " fields", "a row has " +
                       std::to_string(kTableNodeColumns + kTableQuantities) + " fields");
    // Rows in order: roll outer, t_Y, Q, then the track.
    const std::size_t k = rows % nk, j = (rows / nk) % nQ, i = (rows / (nk * nQ)) % nT, m = rows / (nk * nQ * nT);
    if (m >= nR) throw InputError(where, "", "more rows than the header's nodes × tracks");
    const double ty = parse_number(f[0], where, "tY_mm") * 1e-3, q = parse_number(f[1], where, "Q_kN") * 1e3;
    const double r = parse_number(f[2], where, "roll_mrad") * 1e-3;
    if (std::fabs(ty - t.tY[i]) > 1e-9 || std::fabs(q - t.Q[j]) > 1e-6 * t.Q[j] || std::fabs(r - t.roll[m]) > 1e-9 ||
        parse_number(f[4], where, "contact") != static_cast<double>(k + 1))
      throw InputError(where, f[0] + "," + f[1] + "," + f[2] + "," + f[4], "rows must run roll outer, t_Y, Q, then contact 1.." +
                       std::to_string(nk) + ", on the header's nodes");
    CaseStatus st;
    if (!parse_status(f[3], st)) throw InputError(where, f[3], "status must be one of the cases.csv words");
    const std::size_t n = t.node(m, i, j);
    t.node_status[n] = st;
    const double pr = parse_number(f[5], where, "present");
    if (pr != 0 && pr != 1) throw InputError(where, f[5], "present must be 0 or 1");
    t.present[n * nk + k] = pr != 0;
    const std::size_t at = t.at(m, i, j, static_cast<int>(k));
    for (int qn = 0; qn < kTableQuantities; ++qn)
      t.v[at + qn] = parse_number(f[kTableNodeColumns + qn], where, kTableColumns[qn].name) * kTableColumns[qn].to_si;
    ++rows;
  }
  if (rows != nn * nk)
    throw InputError(at_line(path, ln), std::to_string(rows) + " rows", "a table has one row per node and contact: " +
                     std::to_string(nn * nk), "the file is truncated: regenerate it");
  return t;
}

ContactTableLookup::ContactTableLookup(ContactTableData data) : d_(std::move(data)) {
  const std::size_t nT = d_.nT(), nQ = d_.nQ(), nR = d_.nR(), nk = static_cast<std::size_t>(d_.n_tracks);
  dx_.assign(d_.v.size(), 0.0);
  dy_.assign(d_.v.size(), 0.0);
  dz_.assign(d_.v.size(), 0.0);
  const std::size_t sk = kTableQuantities;
  for (std::size_t m = 0; m < nR; ++m)
    for (std::size_t j = 0; j < nQ; ++j)
      for (std::size_t k = 0; k < nk; ++k)
        for (std::size_t q = 0; q < sk; ++q) {
          const std::size_t a = d_.at(m, 0, j, static_cast<int>(k)) + q;
          pchip_slopes(d_.tY.data(), nT, &d_.v[a], nQ * nk * sk, &dx_[a]);
        }
  for (std::size_t m = 0; m < nR; ++m)
    for (std::size_t i = 0; i < nT; ++i)
      for (std::size_t k = 0; k < nk; ++k)
        for (std::size_t q = 0; q < sk; ++q) {
          const std::size_t a = d_.at(m, i, 0, static_cast<int>(k)) + q;
          pchip_slopes(d_.Q.data(), nQ, &d_.v[a], nk * sk, &dy_[a]);
        }
  if (nR > 1)
    for (std::size_t i = 0; i < nT; ++i)
      for (std::size_t j = 0; j < nQ; ++j)
        for (std::size_t k = 0; k < nk; ++k)
          for (std::size_t q = 0; q < sk; ++q) {
            const std::size_t a = d_.at(0, i, j, static_cast<int>(k)) + q;
            pchip_slopes(d_.roll.data(), nR, &d_.v[a], nT * nQ * nk * sk, &dz_[a]);
          }
  // The tracks that can be non-zero in each cell: present at a corner (a track absent at all
  // corners has N = 0 and zero slopes there).
  const std::size_t mc = nR > 1 ? 2 : 1;
  cell_first_.push_back(0);
  for (std::size_t m = 0; m < d_.nRc(); ++m)
    for (std::size_t i = 0; i + 1 < nT; ++i)
      for (std::size_t j = 0; j + 1 < nQ; ++j) {
        for (std::size_t k = 0; k < nk; ++k) {
          bool any = false;
          for (std::size_t c = 0; c < mc; ++c)
            for (std::size_t a = 0; a < 2; ++a)
              for (std::size_t b = 0; b < 2; ++b) any = any || d_.present[d_.node(m + c, i + a, j + b) * nk + k];
          if (any) cell_tracks_.push_back(static_cast<int>(k));
        }
        cell_first_.push_back(static_cast<int>(cell_tracks_.size()));
      }
}

void ContactTableLookup::lookup(double tY, double Q, double roll, TableAnswer& out) const {
  out.n_contacts = 0;
  out.Fz = out.Fy = out.dFy_dtY = out.dFy_dQ = out.dFy_droll = 0;
  out.coarse = out.off_roll = false;
  const bool axis = d_.nR() > 1;
  if (!(tY >= d_.tY.front() && tY <= d_.tY.back() && Q >= d_.Q.front() && Q <= d_.Q.back()) || !std::isfinite(roll) ||
      (axis && !(roll >= d_.roll.front() && roll <= d_.roll.back()))) {
    out.status = CaseStatus::OutOfRange;
    return;
  }
  Basis B;
  basis(tY, Q, roll, B);
  // Status: the worst of the cell's corners; a coarse cell, or a roll away from the one layer's,
  // is at best outside_validity.
  CaseStatus st = CaseStatus::Ok;
  for (int c = 0; c < B.nc; ++c)
    for (std::size_t a = 0; a < 2; ++a)
      for (std::size_t b = 0; b < 2; ++b) {
        const CaseStatus s = d_.node_status[d_.node(B.m + static_cast<std::size_t>(c), B.i + a, B.j + b)];
        if (status_severity(s) > status_severity(st)) st = s;
      }
  const std::size_t cell = d_.cell(B.m, B.i, B.j);
  out.coarse = d_.cell_coarse[cell] != 0;
  out.off_roll = !axis && !(std::fabs(roll - d_.roll[0]) <= kTableRollTolerance);
  if ((out.coarse || out.off_roll) && st == CaseStatus::Ok) st = CaseStatus::OutsideValidity;
  out.status = st;
  if (status_severity(st) >= 3) return;
  TableTrackValues t;
  for (int c = cell_first_[cell]; c < cell_first_[cell + 1]; ++c) {
    const int k = cell_tracks_[static_cast<std::size_t>(c)];
    hermite(B, k, t);
    if (!(t.v[kTabN] > 0)) continue;
    for (int q = 0; q < kTableQuantities; ++q)
      if (kTableColumns[q].non_negative && t.v[q] < 0) t.v[q] = t.d_dtY[q] = t.d_dQ[q] = t.d_droll[q] = 0;
    add_table_contact(out, k, t);
  }
}

void add_table_contact(TableAnswer& out, int k, const TableTrackValues& t) {
  const auto& v = t.v;
  const double cg = std::cos(v[kTabGamma]), sg = std::sin(v[kTabGamma]);
  out.Fz += v[kTabN] * cg;
  out.Fy += v[kTabN] * sg;
  out.dFy_dtY += t.d_dtY[kTabN] * sg + v[kTabN] * cg * t.d_dtY[kTabGamma];
  out.dFy_dQ += t.d_dQ[kTabN] * sg + v[kTabN] * cg * t.d_dQ[kTabGamma];
  out.dFy_droll += t.d_droll[kTabN] * sg + v[kTabN] * cg * t.d_droll[kTabGamma];
  if (out.n_contacts < kTableMaxContacts) {
    TableContact& c = out.c[static_cast<std::size_t>(out.n_contacts)];
    c.track = k + 1;
    c.v = v;
    c.d_dtY = t.d_dtY;
    c.d_dQ = t.d_dQ;
    c.d_droll = t.d_droll;
  }
  ++out.n_contacts;
}

namespace {

/// The cubic Hermite basis on an interval of length h at u ∈ [0, 1]: the values' weights P0, the
/// slopes' weights P1, and their derivatives along the axis.
void hermite_1d(double u, double h, double P0[2], double P1[2], double dP0[2], double dP1[2]) {
  const double u2 = u * u, u3 = u2 * u;
  P0[0] = 2 * u3 - 3 * u2 + 1, P0[1] = -2 * u3 + 3 * u2;
  P1[0] = h * (u3 - 2 * u2 + u), P1[1] = h * (u3 - u2);
  dP0[0] = (6 * u2 - 6 * u) / h, dP0[1] = (-6 * u2 + 6 * u) / h;
  dP1[0] = 3 * u2 - 4 * u + 1, dP1[1] = 3 * u2 - 2 * u;
}

}  // namespace

void ContactTableLookup::basis(double tY, double Q, double roll, Basis& B) const {
  B.i = table_interval(d_.tY, tY);
  B.j = table_interval(d_.Q, Q);
  const double hx = d_.tY[B.i + 1] - d_.tY[B.i], hy = d_.Q[B.j + 1] - d_.Q[B.j];
  hermite_1d((tY - d_.tY[B.i]) / hx, hx, B.H0, B.H1, B.dH0, B.dH1);
  hermite_1d((Q - d_.Q[B.j]) / hy, hy, B.G0, B.G1, B.dG0, B.dG1);
  if (d_.nR() > 1) {
    B.m = table_interval(d_.roll, roll);
    B.nc = 2;
    const double hz = d_.roll[B.m + 1] - d_.roll[B.m];
    hermite_1d((roll - d_.roll[B.m]) / hz, hz, B.R0, B.R1, B.dR0, B.dR1);
  } else {
    B.m = 0;
    B.nc = 1;
    B.R0[0] = 1, B.R0[1] = 0;
    B.R1[0] = B.R1[1] = B.dR0[0] = B.dR0[1] = B.dR1[0] = B.dR1[1] = 0;
  }
}

inline void ContactTableLookup::hermite(const Basis& B, int k, TableTrackValues& t) const {
  t.v.fill(0);
  t.d_dtY.fill(0);
  t.d_dQ.fill(0);
  t.d_droll.fill(0);
  if (B.nc == 1) {
    // Without a roll axis: the bicubic surface of layer 0 (its roll terms are all 0).
    for (std::size_t a = 0; a < 2; ++a)
      for (std::size_t b = 0; b < 2; ++b) {
        const std::size_t at = d_.at(0, B.i + a, B.j + b, k);
        const double* f = &d_.v[at];
        const double* fx = &dx_[at];
        const double* fy = &dy_[at];
        const double c0 = B.H0[a] * B.G0[b], c1 = B.H1[a] * B.G0[b], c2 = B.H0[a] * B.G1[b];
        const double x0 = B.dH0[a] * B.G0[b], x1 = B.dH1[a] * B.G0[b], x2 = B.dH0[a] * B.G1[b];
        const double y0 = B.H0[a] * B.dG0[b], y1 = B.H1[a] * B.dG0[b], y2 = B.H0[a] * B.dG1[b];
        for (int q = 0; q < kTableQuantities; ++q) {
          t.v[q] += c0 * f[q] + c1 * fx[q] + c2 * fy[q];
          t.d_dtY[q] += x0 * f[q] + x1 * fx[q] + x2 * fy[q];
          t.d_dQ[q] += y0 * f[q] + y1 * fx[q] + y2 * fy[q];
        }
      }
    return;
  }
  for (int c = 0; c < B.nc; ++c)
    for (std::size_t a = 0; a < 2; ++a)
      for (std::size_t b = 0; b < 2; ++b) {
        const std::size_t at = d_.at(B.m + static_cast<std::size_t>(c), B.i + a, B.j + b, k);
        const double* f = &d_.v[at];
        const double* fx = &dx_[at];
        const double* fy = &dy_[at];
        const double* fz = &dz_[at];
        // Zero cross slopes: f, and one axis's slope weighted by that axis's slope basis.
        const double H = B.H0[a], G = B.G0[b], R = B.R0[c];
        const double c0 = H * G * R, c1 = B.H1[a] * G * R, c2 = H * B.G1[b] * R, c3 = H * G * B.R1[c];
        const double x0 = B.dH0[a] * G * R, x1 = B.dH1[a] * G * R, x2 = B.dH0[a] * B.G1[b] * R, x3 = B.dH0[a] * G * B.R1[c];
        const double y0 = H * B.dG0[b] * R, y1 = B.H1[a] * B.dG0[b] * R, y2 = H * B.dG1[b] * R, y3 = H * B.dG0[b] * B.R1[c];
        const double z0 = H * G * B.dR0[c], z1 = B.H1[a] * G * B.dR0[c], z2 = H * B.G1[b] * B.dR0[c], z3 = H * G * B.dR1[c];
        for (int q = 0; q < kTableQuantities; ++q) {
          t.v[q] += c0 * f[q] + c1 * fx[q] + c2 * fy[q] + c3 * fz[q];
          t.d_dtY[q] += x0 * f[q] + x1 * fx[q] + x2 * fy[q] + x3 * fz[q];
          t.d_dQ[q] += y0 * f[q] + y1 * fx[q] + y2 * fy[q] + y3 * fz[q];
          t.d_droll[q] += z0 * f[q] + z1 * fx[q] + z2 * fy[q] + z3 * fz[q];
        }
      }
}

void ContactTableLookup::track_values(double tY, double Q, double roll, int k, std::array<double, kTableQuantities>& v) const {
  Basis B;
  basis(tY, Q, roll, B);
  TableTrackValues t;
  hermite(B, k, t);
  v = t.v;
  for (int q = 0; q < kTableQuantities; ++q)
    if (kTableColumns[q].non_negative && v[q] < 0) v[q] = 0;
}

}  // namespace mh
