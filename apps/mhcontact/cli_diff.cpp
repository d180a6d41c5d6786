// `mhcontact diff REF.csv OUT.csv`: regression comparison of result tables (a thin wrapper
// around diff_tables(), see table_diff.hpp for the rules).
#include <CLI/CLI.hpp>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

#include "cli.hpp"
#include "output/csv_table.hpp"
#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "output/table_diff.hpp"

namespace mh {

namespace {

/// A tolerance given on the command line: a finite number >= 0, the whole text.
double parse_tolerance(const std::string& option, const std::string& text) {
  double v;
  if (!parse_cell_number(text, v))
    throw InputError(option, "\"" + text + "\"", "not a number", "e.g. 1e-6");
  if (!(std::isfinite(v) && v >= 0))
    throw InputError(option, text, "tolerance must be finite and >= 0");
  return v;
}

struct DiffArgs {
  std::string ref, out;
  std::string rtol, atol;
  std::vector<std::string> column_tol;
  std::vector<std::string> key;
  std::vector<std::string> ignore_columns;
  bool exact_noise = false;
  bool json = false;
  bool quiet = false;
};

}  // namespace

void add_diff_command(CLI::App& app, CliContext& ctx) {
  auto args = std::make_shared<DiffArgs>();
  const DiffOptions defaults;
  CLI::App* cmd = app.add_subcommand(
      "diff",
      "Compare a result table (cases.csv, ellipses.csv, geometry.csv, caf.csv, pressure.csv, ...) against a "
      "reference: rows matched by key, numbers within tolerance, text by its words with the numbers "
      "inside within tolerance (warnings). Exit 0 within "
      "tolerance, 1 if they differ, 2 if an input is unreadable or malformed.");
  cmd->add_option("REF", args->ref, "Reference CSV table")->required()->type_name("FILE");
  cmd->add_option("OUT", args->out, "CSV table to check against REF")->required()->type_name("FILE");
  cmd->add_option("--rtol", args->rtol,
                  "Relative tolerance: a number passes if |out - ref| <= atol + rtol*|ref| "
                  "(default " + format_number(defaults.rtol) + ")")
      ->type_name("R");
  cmd->add_option("--atol", args->atol,
                  "Absolute tolerance in each column's own unit (default " +
                      format_number(defaults.atol) + ")")
      ->type_name("A");
  cmd->add_option("--column-tol", args->column_tol,
                  "COL=TOL: absolute tolerance for column COL in its unit, replacing atol/rtol "
                  "(repeatable), e.g. --column-tol Fz_kN=1e-6")
      ->type_name("COL=TOL")
      ->allow_extra_args(false);
  cmd->add_option("--key", args->key,
                  "Key column (repeatable or comma separated); default: those of pair, case, "
                  "ellipse present in both tables (with tY_mm before ellipse when there is no case), "
                  "else the row number")
      ->delimiter(',')
      ->type_name("COL")
      ->allow_extra_args(false);
  cmd->add_option("--ignore-columns", args->ignore_columns,
                  "Columns left out of the comparison (repeatable or comma separated), e.g. "
                  "--ignore-columns residual,iterations")
      ->delimiter(',')
      ->type_name("COL")
      ->allow_extra_args(false);
  cmd->add_flag("--exact-noise", args->exact_noise,
                "Compare the solver-noise columns (residual, iterations) with the tolerances of "
                "every column instead of their rules (residual: both <= 1e-6; iterations: "
                "out <= 2 ref + 3)");
  cmd->add_flag("--json", args->json, "Print a machine-readable JSON report instead of text");
  cmd->add_flag("--quiet", args->quiet, "Print only the final line (diff: OK / diff: N cells ...)");

  cmd->callback([args, &ctx]() {
    DiffOptions opt;
    if (!args->rtol.empty()) opt.rtol = parse_tolerance("--rtol", args->rtol);
    if (!args->atol.empty()) opt.atol = parse_tolerance("--atol", args->atol);
    for (const std::string& spec : args->column_tol) {
      const auto eq = spec.find('=');
      if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size())
        throw InputError("--column-tol", "\"" + spec + "\"", "expected COL=TOL",
                         "e.g. --column-tol Fz_kN=1e-6");
      const std::string col = spec.substr(0, eq);
      if (opt.column_tol.count(col))
        throw InputError("--column-tol", col, "column given twice");
      opt.column_tol[col] = parse_tolerance("--column-tol " + col, spec.substr(eq + 1));
    }
    opt.key = args->key;
    opt.ignore_columns = args->ignore_columns;
    opt.noise_rules = !args->exact_noise;
    std::string why;
    if (!opt.IsValid(&why)) throw InputError("diff options", "", why);

    const CsvTable ref = read_csv_file(args->ref);
    const CsvTable out = read_csv_file(args->out);
    const TableDiffResult r = diff_tables(ref, out, opt);

    if (args->json)
      ctx.out << diff_report_json(r, opt).dump(2) << "\n";
    else if (args->quiet)
      ctx.out << diff_summary_line(r) << "\n";
    else
      write_diff_report(ctx.out, r, opt);
    ctx.exit_code = r.ok() ? kExitOk : kExitCasesFailed;
  });
}

}  // namespace mh
