#include "output/table_diff.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <ostream>
#include <unordered_map>
#include <unordered_set>

#include "core/errors.hpp"
#include "core/numfmt.hpp"

namespace mh {

const std::vector<NoiseRule>& noise_rules() {
  // residual: (Σ N cos γ − Q)/Q at the end of a solve; every method stops far below 1e-6 (the
  // shipped tables: at most 1e-8), so two converged solves differ there by noise alone.
  // iterations: a count that moves with the last bits of the start; more than doubling it is a
  // change of convergence worth a look.
  static const std::vector<NoiseRule> rules{
      {"residual", "both |value| <= 1e-6 (converged)",
       [](double a, double b) { return std::fabs(a) <= 1e-6 && std::fabs(b) <= 1e-6; }},
      {"iterations", "out <= 2 ref + 3", [](double a, double b) { return b <= 2 * a + 3; }},
  };
  return rules;
}

namespace {

/// Default key candidates, in key order (pair, then case, then ellipse).
const char* const kDefaultKeys[] = {"pair", "case", "ellipse"};

/// Deviations are printed with 3 significant digits: enough to judge against a tolerance.
std::string dev_str(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

/// A cell as shown in reports: numbers verbatim, anything else in double quotes.
std::string show_cell(const std::string& s) {
  double v;
  if (parse_cell_number(s, v)) return s;
  std::string q = "\"";
  for (char c : s) {
    if (c == '"') q += "\\\"";
    else if (c == '\n') q += "\\n";
    else if (c == '\r') q += "\\r";
    else q += c;
  }
  return q + "\"";
}

std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) s += sep;
    s += v[i];
  }
  return s;
}

std::string header_list(const CsvTable& t) { return "columns: " + join(t.header, ", "); }

struct KeyIndex {
  std::vector<std::string> shown;                 // per row: "case=c1, ellipse=1" or "row=3"
  std::unordered_map<std::string, std::size_t> row_of;  // exact key text -> row index
};

KeyIndex index_keys(const CsvTable& t, const std::vector<std::string>& key_cols, bool default_key) {
  std::vector<int> idx;
  for (const std::string& k : key_cols) idx.push_back(t.column(k));
  KeyIndex ki;
  ki.shown.reserve(t.rows.size());
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    std::string exact, shown;
    if (key_cols.empty()) {
      exact = std::to_string(i + 1);
      shown = "row=" + exact;
    } else {
      for (std::size_t j = 0; j < idx.size(); ++j) {
        const std::string& cell = t.rows[i][static_cast<std::size_t>(idx[j])];
        if (j) {
          exact += '\x1f';  // unit separator: cannot be confused with cell text in practice
          shown += ", ";
        }
        exact += cell;
        shown += key_cols[j] + "=" + (cell.empty() || cell.find_first_of(", \"") != std::string::npos
                                          ? show_cell(cell) : cell);
      }
    }
    auto [it, inserted] = ki.row_of.emplace(exact, i);
    if (!inserted)
      throw InputError(at_line(t.source, t.row_line[i]), shown,
                       "duplicate key: the same key is on line " +
                           std::to_string(t.row_line[it->second]),
                       default_key
                           ? "the default key is those of pair, case, ellipse in both tables (with tY_mm when there is no case); choose "
                             "the key columns with --key, e.g. --key tY_mm for caf.csv, --key "
                             "case,ellipse,x_mm,y_mm for pressure.csv"
                           : "each row must have its own key; choose the key columns with --key");
    ki.shown.push_back(std::move(shown));
  }
  return ki;
}

}  // namespace

bool parse_cell_number(const std::string& text, double& value) {
  const char* b = text.data();
  const char* e = b + text.size();
  if (b != e && *b == '+') ++b;  // from_chars does not take a leading '+'
  if (b == e) return false;
  auto r = std::from_chars(b, e, value);
  return r.ec == std::errc() && r.ptr == e;
}

namespace detail {

std::vector<TextPiece> split_text_cell(const std::string& cell) {
  std::vector<TextPiece> pieces;
  auto word_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.'; };
  auto digit = [](char c) { return c >= '0' && c <= '9'; };
  const std::size_t n = cell.size();
  std::size_t i = 0;
  while (i < n) {
    const bool after_word = i > 0 && word_char(cell[i - 1]);
    const bool starts = !after_word && (digit(cell[i]) || ((cell[i] == '-' || cell[i] == '.') && i + 1 < n &&
                                                           (digit(cell[i + 1]) || (cell[i + 1] == '.' && i + 2 < n && digit(cell[i + 2])))));
    double v = 0;
    const char* end = nullptr;
    if (starts) {
      const auto r = std::from_chars(cell.data() + i, cell.data() + n, v);
      if (r.ec == std::errc() || r.ec == std::errc::result_out_of_range) end = r.ptr;
    }
    if (end && end > cell.data() + i) {
      TextPiece p;
      p.number = true;
      p.value = v;
      p.text.assign(cell.data() + i, end);
      p.integer = p.text.find_first_not_of("-0123456789") == std::string::npos;
      pieces.push_back(std::move(p));
      i = static_cast<std::size_t>(end - cell.data());
      continue;
    }
    if (pieces.empty() || pieces.back().number) pieces.emplace_back();
    pieces.back().text += cell[i++];
  }
  return pieces;
}

}  // namespace detail

bool DiffOptions::IsValid(std::string* why) const {
  auto fail = [&](const std::string& msg) {
    if (why) *why = msg;
    return false;
  };
  if (!(std::isfinite(rtol) && rtol >= 0)) return fail("rtol = " + format_number(rtol) + ": must be finite and >= 0");
  if (!(std::isfinite(atol) && atol >= 0)) return fail("atol = " + format_number(atol) + ": must be finite and >= 0");
  for (const auto& [col, tol] : column_tol) {
    if (col.empty()) return fail("column_tol: empty column name");
    if (!(std::isfinite(tol) && tol >= 0))
      return fail("column_tol[" + col + "] = " + format_number(tol) + ": must be finite and >= 0");
  }
  std::unordered_set<std::string> seen;
  for (const std::string& k : key) {
    if (k.empty()) return fail("key: empty column name");
    if (!seen.insert(k).second) return fail("key: column " + k + " given twice");
  }
  std::unordered_set<std::string> ignored;
  for (const std::string& c : ignore_columns) {
    if (c.empty()) return fail("ignore_columns: empty column name");
    if (!ignored.insert(c).second) return fail("ignore_columns: column " + c + " given twice");
    if (seen.count(c)) return fail("ignore_columns: column " + c + " is a key column");
    if (column_tol.count(c)) return fail("ignore_columns: column " + c + " also has a column tolerance");
  }
  return true;
}

TableDiffResult diff_tables(const CsvTable& ref, const CsvTable& out, const DiffOptions& opt) {
  std::string why;
  if (!opt.IsValid(&why)) throw InputError("diff options", "", why);

  TableDiffResult r;
  r.ref_source = ref.source;
  r.out_source = out.source;
  r.rows_ref = ref.rows.size();
  r.rows_out = out.rows.size();

  // Key columns.
  if (!opt.key.empty()) {
    for (const std::string& k : opt.key) {
      for (const CsvTable* t : {&ref, &out})
        if (!t->has_column(k))
          throw InputError(t->source, k, "key column is not in the header", header_list(*t));
    }
    r.key_columns = opt.key;
  } else {
    for (const char* k : kDefaultKeys)
      if (ref.has_column(k) && out.has_column(k)) r.key_columns.push_back(k);
    // A table with one row per (t_Y, ellipse) and no case column (geometry.csv, caf.csv): t_Y
    // joins the key, before the ellipse (pair, tY_mm, ellipse).
    const auto has = [&](const char* k) { return std::find(r.key_columns.begin(), r.key_columns.end(), k) != r.key_columns.end(); };
    if (has("ellipse") && !has("case") && ref.has_column("tY_mm") && out.has_column("tY_mm"))
      r.key_columns.insert(r.key_columns.end() - 1, "tY_mm");
  }
  r.by_row_number = r.key_columns.empty();
  const std::unordered_set<std::string> is_key(r.key_columns.begin(), r.key_columns.end());
  const std::unordered_set<std::string> ignored(opt.ignore_columns.begin(), opt.ignore_columns.end());
  for (const std::string& col : opt.ignore_columns) {
    if (!ref.has_column(col) && !out.has_column(col))
      throw InputError("--ignore-columns", col, "not a column of " + ref.source + " or " + out.source,
                       header_list(ref));
    if (is_key.count(col))
      throw InputError("--ignore-columns", col, "is a key column; rows are matched by it");
  }

  // Column sets (order may differ).
  std::vector<std::string> common;
  for (const std::string& c : ref.header) {
    if (ignored.count(c)) continue;
    if (!out.has_column(c)) r.missing_columns.push_back(c);
    else if (!is_key.count(c)) common.push_back(c);
  }
  for (const std::string& c : out.header)
    if (!ref.has_column(c) && !ignored.count(c)) r.extra_columns.push_back(c);

  for (const auto& [col, tol] : opt.column_tol) {
    (void)tol;
    if (!ref.has_column(col) && !out.has_column(col))
      throw InputError("--column-tol", col, "not a column of " + ref.source + " or " + out.source,
                       header_list(ref));
    if (is_key.count(col))
      throw InputError("--column-tol", col, "is a key column; key cells are matched as exact text");
  }

  const KeyIndex ref_keys = index_keys(ref, r.key_columns, opt.key.empty());
  const KeyIndex out_keys = index_keys(out, r.key_columns, opt.key.empty());

  // Column positions and per-column accumulators.
  struct Col {
    int iref, iout;
    bool has_tol;
    double tol;
    ColumnDiff d;
  };
  std::vector<Col> cols;
  for (const std::string& c : common) {
    Col col{ref.column(c), out.column(c), false, 0.0, {}};
    col.d.column = c;
    if (auto it = opt.column_tol.find(c); it != opt.column_tol.end()) {
      col.has_tol = true;
      col.tol = it->second;
      col.d.tolerance_abs = it->second;
    } else if (opt.noise_rules) {
      for (const NoiseRule& n : noise_rules())
        if (c == n.column) col.d.noise = &n;
    }
    cols.push_back(std::move(col));
  }

  // Rows present in OUT, in REF order; cells compared per column.
  std::unordered_set<std::size_t> out_matched;
  for (std::size_t i = 0; i < ref.rows.size(); ++i) {
    std::size_t j;
    if (r.by_row_number) {
      if (i >= out.rows.size()) {
        r.missing_rows.push_back(ref_keys.shown[i]);
        continue;
      }
      j = i;
    } else {
      std::string exact;
      for (std::size_t k = 0; k < r.key_columns.size(); ++k) {
        if (k) exact += '\x1f';
        exact += ref.rows[i][static_cast<std::size_t>(ref.column(r.key_columns[k]))];
      }
      auto it = out_keys.row_of.find(exact);
      if (it == out_keys.row_of.end()) {
        r.missing_rows.push_back(ref_keys.shown[i]);
        continue;
      }
      j = it->second;
    }
    out_matched.insert(j);
    ++r.rows_compared;
    const std::string& key = ref_keys.shown[i];

    for (Col& c : cols) {
      const std::string& a_text = ref.rows[i][static_cast<std::size_t>(c.iref)];
      const std::string& b_text = out.rows[j][static_cast<std::size_t>(c.iout)];
      ColumnDiff& d = c.d;
      ++d.cells_compared;
      ++r.cells_compared;
      if (a_text == b_text) continue;  // identical text: equal whatever it means

      auto text_differs = [&]() {
        ++d.cells_out;
        if (d.text_out++ == 0) d.first_text = {key, a_text, b_text};
      };
      auto nonfinite_differs = [&]() {
        ++d.cells_out;
        ++d.numeric_out;
        if (d.nonfinite_out++ == 0) d.first_nonfinite = {key, a_text, b_text};
      };
      const auto within = [&](double x, double y) {
        if (std::isnan(x) || std::isnan(y)) return std::isnan(x) && std::isnan(y);
        if (x == y) return true;
        if (!std::isfinite(x) || !std::isfinite(y)) return false;
        return std::fabs(y - x) <= (c.has_tol ? c.tol : opt.atol + opt.rtol * std::fabs(x));
      };
      double a, b;
      if (!(parse_cell_number(a_text, a) && parse_cell_number(b_text, b))) {
        // Text cells (warnings, message): equal words, the numbers inside within tolerance.
        if (!text_cells_match(a_text, b_text, within)) text_differs();
        continue;
      }
      if (std::isnan(a) || std::isnan(b)) {
        if (!(std::isnan(a) && std::isnan(b))) nonfinite_differs();  // NaN equals only NaN
        continue;
      }
      if (a == b) continue;  // "1" vs "1.0", "-0" vs "0", inf vs inf
      if (!std::isfinite(a) || !std::isfinite(b)) {
        nonfinite_differs();  // an infinity equals only the same infinity
        continue;
      }
      const double dev = std::fabs(b - a);
      const double rel = a != 0 ? dev / std::fabs(a) : HUGE_VAL;
      const double tol = c.has_tol ? c.tol : opt.atol + opt.rtol * std::fabs(a);
      if (d.noise ? !d.noise->pass(a, b) : dev > tol) {
        ++d.cells_out;
        ++d.numeric_out;
      }
      if (dev > d.worst_abs) {
        d.worst_abs = dev;
        d.worst_abs_at = {key, a_text, b_text};
      }
      if (rel > d.worst_rel) {
        d.worst_rel = rel;
        d.worst_rel_at = {key, a_text, b_text};
      }
    }
  }
  for (std::size_t j = 0; j < out.rows.size(); ++j)
    if (!out_matched.count(j)) r.extra_rows.push_back(out_keys.shown[j]);

  for (Col& c : cols) {
    r.cells_out += c.d.cells_out;
    if (c.d.cells_out > 0 || c.d.worst_abs > 0) r.columns.push_back(std::move(c.d));
  }
  return r;
}

std::string diff_summary_line(const TableDiffResult& r) {
  if (r.ok()) return "diff: OK";
  std::string s = "diff: " + std::to_string(r.cells_out) + " cells out of tolerance, " +
                  std::to_string(r.missing_rows.size()) + " missing rows, " +
                  std::to_string(r.extra_rows.size()) + " extra rows";
  if (!r.missing_columns.empty() || !r.extra_columns.empty())
    s += ", " + std::to_string(r.missing_columns.size()) + " missing columns, " +
         std::to_string(r.extra_columns.size()) + " extra columns";
  return s;
}

void write_diff_report(std::ostream& os, const TableDiffResult& r, const DiffOptions& opt) {
  os << "REF: " << r.ref_source << " (" << r.rows_ref << " rows)\n";
  os << "OUT: " << r.out_source << " (" << r.rows_out << " rows)\n";
  if (r.by_row_number)
    os << "key: none of pair, case, ellipse in both tables; rows compared by position "
          "(the row number is the key)\n";
  else
    os << "key: " << join(r.key_columns, ", ") << "\n";
  os << "tolerance: |out - ref| <= atol + rtol*|ref| with atol " << format_number(opt.atol)
     << ", rtol " << format_number(opt.rtol);
  if (!opt.column_tol.empty()) {
    os << "; per column |out - ref| <=";
    bool first = true;
    for (const auto& [col, tol] : opt.column_tol) {
      os << (first ? " " : ", ") << col << " " << format_number(tol);
      first = false;
    }
  }
  os << "\n";
  if (opt.noise_rules) {
    os << "solver-noise columns by their rules (--exact-noise: as any column):";
    bool first = true;
    for (const NoiseRule& n : noise_rules()) {
      if (opt.column_tol.count(n.column)) continue;
      os << (first ? " " : "; ") << n.column << " " << n.rule;
      first = false;
    }
    os << "\n";
  }
  if (!opt.ignore_columns.empty()) os << "ignored columns: " << join(opt.ignore_columns, ", ") << "\n";
  os << "rows compared: " << r.rows_compared << ", missing in OUT: " << r.missing_rows.size()
     << ", extra in OUT: " << r.extra_rows.size() << "\n";

  auto list = [&](const char* what, const std::vector<std::string>& keys) {
    if (keys.empty()) return;
    os << what << " (" << keys.size() << "): ";
    const std::size_t n = std::min(keys.size(), opt.max_listed);
    for (std::size_t i = 0; i < n; ++i) os << (i ? "; " : "") << keys[i];
    if (keys.size() > n) os << "; ... and " << keys.size() - n << " more";
    os << "\n";
  };
  list("rows missing in OUT", r.missing_rows);
  list("rows extra in OUT", r.extra_rows);
  if (!r.missing_columns.empty())
    os << "columns missing in OUT (" << r.missing_columns.size() << "): " << join(r.missing_columns, ", ") << "\n";
  if (!r.extra_columns.empty())
    os << "columns extra in OUT (" << r.extra_columns.size() << "): " << join(r.extra_columns, ", ") << "\n";

  for (const ColumnDiff& d : r.columns) {
    os << "column " << d.column << ": " << d.cells_out << " of " << d.cells_compared
       << " cells out of tolerance";
    if (d.tolerance_abs >= 0) os << " (|out - ref| <= " << format_number(d.tolerance_abs) << ")";
    if (d.noise) os << " (solver noise, rule: " << d.noise->rule << ")";
    os << "\n";
    if (d.worst_abs > 0) {
      os << "  worst abs deviation " << dev_str(d.worst_abs) << " at " << d.worst_abs_at.key
         << ": ref " << d.worst_abs_at.ref << ", out " << d.worst_abs_at.out << "\n";
      os << "  worst rel deviation " << dev_str(d.worst_rel) << " at " << d.worst_rel_at.key
         << ": ref " << d.worst_rel_at.ref << ", out " << d.worst_rel_at.out << "\n";
    }
    if (d.text_out)
      os << "  text differs in " << d.text_out << " cell(s); first at " << d.first_text.key
         << ": ref " << show_cell(d.first_text.ref) << ", out " << show_cell(d.first_text.out) << "\n";
    if (d.nonfinite_out)
      os << "  nan/inf against a different value in " << d.nonfinite_out << " cell(s); first at "
         << d.first_nonfinite.key << ": ref " << show_cell(d.first_nonfinite.ref) << ", out "
         << show_cell(d.first_nonfinite.out) << "\n";
  }
  os << diff_summary_line(r) << "\n";
}

nlohmann::json diff_report_json(const TableDiffResult& r, const DiffOptions& opt) {
  using nlohmann::json;
  auto num = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  auto cell = [](const DiffCell& c) { return json{{"key", c.key}, {"ref", c.ref}, {"out", c.out}}; };
  json j;
  j["schema"] = "mhcontact.diff";
  j["version"] = 1;
  j["ok"] = r.ok();
  j["ref"] = {{"file", r.ref_source}, {"rows", r.rows_ref}};
  j["out"] = {{"file", r.out_source}, {"rows", r.rows_out}};
  j["key"] = r.key_columns;
  j["by_row_number"] = r.by_row_number;
  json ct = json::object();
  for (const auto& [col, tol] : opt.column_tol) ct[col] = tol;
  j["tolerance"] = {{"rtol", opt.rtol}, {"atol", opt.atol}, {"column_tol", ct}};
  j["ignored_columns"] = opt.ignore_columns;
  j["noise_rules"] = opt.noise_rules;
  j["rows_compared"] = r.rows_compared;
  j["cells_compared"] = r.cells_compared;
  j["cells_out_of_tolerance"] = r.cells_out;
  j["missing_rows"] = r.missing_rows;
  j["extra_rows"] = r.extra_rows;
  j["missing_columns"] = r.missing_columns;
  j["extra_columns"] = r.extra_columns;
  json cols = json::array();
  for (const ColumnDiff& d : r.columns) {
    json c{{"column", d.column},
           {"cells_compared", d.cells_compared},
           {"cells_out_of_tolerance", d.cells_out},
           {"numeric_out_of_tolerance", d.numeric_out},
           {"nonfinite_out_of_tolerance", d.nonfinite_out},
           {"text_differ", d.text_out},
           {"column_tol", d.tolerance_abs >= 0 ? json(d.tolerance_abs) : json(nullptr)},
           {"noise_rule", d.noise ? json(d.noise->rule) : json(nullptr)}};
    if (d.worst_abs > 0) {
      c["worst_abs"] = cell(d.worst_abs_at);
      c["worst_abs"]["deviation"] = num(d.worst_abs);
      c["worst_rel"] = cell(d.worst_rel_at);
      c["worst_rel"]["deviation"] = num(d.worst_rel);  // null if ref = 0 (infinite)
    }
    if (d.text_out) c["first_text"] = cell(d.first_text);
    if (d.nonfinite_out) c["first_nonfinite"] = cell(d.first_nonfinite);
    cols.push_back(std::move(c));
  }
  j["columns"] = std::move(cols);
  j["summary"] = diff_summary_line(r);
  return j;
}

}  // namespace mh
