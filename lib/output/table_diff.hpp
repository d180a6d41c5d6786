#pragma once
// Regression comparison of two result tables (a user's reference against a new output):
// rows matched by key columns, numeric cells compared with a tolerance, text cells exactly.
// `mhcontact diff` is a thin wrapper around diff_tables(); a regression test runner can call it
// directly.
//
// Rules (docs/cli.md, "diff"; docs/status.md):
//  - Key: DiffOptions::key if given, else those of `pair`, `case`, `ellipse` present in both
//    headers (in that order); if none is, rows are matched by position (the 1-based row number
//    is the key). Key cells are compared as exact text (numeric keys such as `tY_mm` too).
//    A key that occurs twice in one table is an InputError naming the file and line.
//  - Columns: matched by name (order may differ). Columns only in REF ("missing") or only in
//    OUT ("extra") are reported and make the tables differ.
//  - Solver-noise columns (noise_rules(); DiffOptions::noise_rules, default on): `residual` and
//    `iterations` measure how a solver converged, not the answer, and are compared by a rule that
//    fits them instead of atol/rtol: a residual passes when both cells are converged (|value| ≤
//    1e-6), an iteration count when OUT takes at most twice REF's plus 3. A column tolerance
//    replaces the rule for its column; `--exact-noise` (noise_rules = false) compares them like
//    any column.
//  - Ignored columns (DiffOptions::ignore_columns) are neither compared nor reported missing or
//    extra.
//  - A cell pair is numeric if both cells parse completely as numbers (`nan`, `inf`, `-inf`
//    included, case-insensitive; an optional leading '+'); otherwise both are compared as text
//    (text_cells_match): the text around the numbers inside the cells must be equal byte for
//    byte, integers inside (ellipse=4, strips=3) must be equal, and decimal numbers inside
//    (gap_error=0.525, q_MPa=1523.4) pass with the numeric tolerance of their column. So a
//    warning is compared by its names, its numbers with the tolerance.
//  - A numeric pair passes if |out - ref| <= atol + rtol*|ref|, or, for a column given a
//    column tolerance, |out - ref| <= tol. NaN equals NaN; NaN against a number differs;
//    an infinity equals only the same infinity.
#include <cstddef>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "output/csv_table.hpp"

namespace mh {

struct DiffOptions {
  /// Relative tolerance (dimensionless). Default 1e-9: the tables are written shortest-round-
  /// trip, so the same build reproduces them exactly; 1e-9 absorbs compiler/libm differences
  /// in the last few bits of iterated results while catching any physical change.
  double rtol = 1e-9;
  /// Absolute tolerance, in the unit of each column (mm, kN, MPa, ...). Default 0: a value of
  /// exactly 0 in REF must be exactly 0 in OUT unless atol or a column tolerance says otherwise.
  double atol = 0.0;
  /// Per-column absolute tolerance (in the column's unit), replacing atol and rtol for that
  /// column. Each name must be a column of REF or OUT and not a key column; each value >= 0.
  std::map<std::string, double> column_tol;
  /// Key columns; empty = default (see above). Each must exist in both tables.
  std::vector<std::string> key;
  /// Columns left out of the comparison (e.g. `residual`, whose 1e-16 is noise); each must be a
  /// column of REF or OUT, not a key column and not given a column tolerance.
  std::vector<std::string> ignore_columns;
  /// Compare the solver-noise columns (noise_rules()) by their rules (default true).
  bool noise_rules = true;
  /// How many missing/extra row keys the text report lists (counts are always complete).
  std::size_t max_listed = 5;

  /// True if the option values are usable; otherwise `why` names the field, value and rule.
  bool IsValid(std::string* why) const;
};

/// A rule for a column that measures a solver's convergence rather than the answer.
struct NoiseRule {
  const char* column;
  const char* rule;  ///< as the report prints it
  bool (*pass)(double ref, double out);
};
/// The solver-noise columns of mhcontact's tables and their rules (docs/cli.md, "diff").
const std::vector<NoiseRule>& noise_rules();

/// One cell (or a representative of several) for the report.
struct DiffCell {
  std::string key;   ///< the row's key, e.g. "case=c3" or "pair=p1, case=c3" or "row=7"
  std::string ref;   ///< cell text in REF
  std::string out;   ///< cell text in OUT
};

/// Deviations found in one column (only columns where some cell is not identical are listed).
struct ColumnDiff {
  std::string column;
  double tolerance_abs = -1;     ///< the column tolerance if one applies, else -1 (atol/rtol)
  const NoiseRule* noise = nullptr;  ///< the solver-noise rule applied to it, if any
  std::size_t cells_compared = 0;
  std::size_t cells_out = 0;     ///< cells out of tolerance (numeric or text)
  std::size_t numeric_out = 0;   ///< numeric pairs out of tolerance (NaN/inf mismatches included)
  std::size_t nonfinite_out = 0; ///< of these: NaN against a number, or an infinity against
                                 ///< anything but the same infinity (no finite difference)
  std::size_t text_out = 0;      ///< pairs compared as text that differ
  // Worst deviation among numeric pairs with a finite difference; 0 and empty key if none.
  double worst_abs = 0;          ///< max |out - ref|, in the column's unit
  DiffCell worst_abs_at;
  double worst_rel = 0;          ///< max |out - ref| / |ref| (inf if ref = 0 and out != 0)
  DiffCell worst_rel_at;
  DiffCell first_text;           ///< first (REF row order) text mismatch, if text_out > 0
  DiffCell first_nonfinite;      ///< first NaN/inf mismatch, if nonfinite_out > 0
};

struct TableDiffResult {
  std::string ref_source, out_source;
  std::vector<std::string> key_columns;  ///< empty if matched by row number
  bool by_row_number = false;
  std::size_t rows_ref = 0, rows_out = 0;
  std::size_t rows_compared = 0;         ///< rows whose key is in both tables
  std::vector<std::string> missing_rows; ///< keys in REF but not in OUT (REF order, all of them)
  std::vector<std::string> extra_rows;   ///< keys in OUT but not in REF (OUT order, all of them)
  std::vector<std::string> missing_columns;  ///< in REF, not in OUT (REF order)
  std::vector<std::string> extra_columns;    ///< in OUT, not in REF (OUT order)
  std::vector<ColumnDiff> columns;       ///< columns with any non-identical cell (REF order)
  std::size_t cells_compared = 0;
  std::size_t cells_out = 0;             ///< total cells out of tolerance

  /// True if within tolerance: no cell out of tolerance, no missing/extra rows or columns.
  bool ok() const {
    return cells_out == 0 && missing_rows.empty() && extra_rows.empty() &&
           missing_columns.empty() && extra_columns.empty();
  }
};

/// Compare `out` against `ref`. Throws InputError for invalid options (naming the option),
/// unknown key or tolerance columns, and duplicate keys (naming "file:line").
TableDiffResult diff_tables(const CsvTable& ref, const CsvTable& out, const DiffOptions& opt);

/// Parse a cell as a number: the whole text must be a number (`nan`, `inf` included).
bool parse_cell_number(const std::string& text, double& value);

/// Text cells compared by their words and numbers: true when both split into the same text and
/// number pieces, the text pieces equal, the integer pieces equal, and every pair of decimal
/// pieces (a '.' or an exponent in either) within `within(ref, out)`. A number piece starts at a
/// digit, or at '-' or '.' before a digit, that does not follow a letter, digit, '_' or '.'
/// (so "p0_MPa" and "R13" stay words); it is the longest number read from there.
template <class Within>
bool text_cells_match(const std::string& ref, const std::string& out, Within within);

namespace detail {
/// One piece of a text cell: a word (text) or a number; `integer`: digits with an optional sign.
struct TextPiece {
  bool number = false, integer = false;
  double value = 0;
  std::string text;
};
std::vector<TextPiece> split_text_cell(const std::string& cell);
}  // namespace detail

template <class Within>
bool text_cells_match(const std::string& ref, const std::string& out, Within within) {
  const std::vector<detail::TextPiece> a = detail::split_text_cell(ref), b = detail::split_text_cell(out);
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].number != b[i].number) return false;
    if (!a[i].number || (a[i].integer && b[i].integer)) {
      if (a[i].text != b[i].text) return false;
    } else if (!within(a[i].value, b[i].value)) {
      return false;
    }
  }
  return true;
}

/// The last line of the report: "diff: OK" or
/// "diff: N cells out of tolerance, M missing rows, K extra rows" (followed by
/// ", J missing columns, L extra columns" when the column sets differ).
std::string diff_summary_line(const TableDiffResult& r);

/// Human-readable report (summary, per-column worst deviations, the final line).
void write_diff_report(std::ostream& os, const TableDiffResult& r, const DiffOptions& opt);

/// Machine-readable report (schema "mhcontact.diff", version 1).
nlohmann::json diff_report_json(const TableDiffResult& r, const DiffOptions& opt);

}  // namespace mh
