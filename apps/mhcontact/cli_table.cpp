// `mhcontact table CASE.json -o FILE` (docs/tables.md): a contact table made by the case file's
// grid method over its t_Y × Q sweep, checked against direct solves at the cell centres; and
// `mhcontact table-export TABLE.csv -o FILE`: the table on a regular grid for MBS codes.
#include <CLI/CLI.hpp>

#include <memory>

#include "cli.hpp"
#include "input/case_file.hpp"
#include "jobs/contact_table_export.hpp"
#include "jobs/contact_table_make.hpp"
#include "jobs/contact_table_shards.hpp"
#include "jobs/wheelset_table_make.hpp"

namespace mh {

void add_table_command(CLI::App& app, CliContext& ctx) {
  struct Opts {
    std::string case_file, out, shard, points, next;
    std::vector<std::string> merge;
    TableMakeOptions make;
    bool no_check = false;
  };
  auto o = std::make_shared<Opts>();
  CLI::App* cmd = app.add_subcommand(
      "table", "Contact table for time-stepping callers: the case's grid method (strips, half-space, auto) at every "
               "node of its t_Y x Q (x roll) sweep, contacts matched across nodes, the interpolation error measured at "
               "the cell centres and t_Y, Q or the roll refined where it misses (writes FILE, CSV with a JSON header). "
               "Exit 0 if every cell meets its tolerance, every node has an answer and no validation point finds an ok "
               "answer beyond tolerance (or ok where the method is not), 1 if not.");
  cmd->add_option("case", o->case_file, "Case file (JSON) with a method other than multi-hertzian and a sweep: its nodes")
      ->required();
  cmd->add_option("-o,--output", o->out, "Table file to write (- for standard output)")->required();
  cmd->add_option("--threads", o->make.threads, "Worker threads (0 = all cores; the table is identical whatever the count)")
      ->check(CLI::Range(0u, 1024u))->capture_default_str();
  cmd->add_option("--refine", o->make.refine, "Rounds of halving the t_Y, Q and roll intervals whose cells miss a tolerance")
      ->check(CLI::Range(0, 8))->capture_default_str();
  cmd->add_option("--min-step-mm", o->make.min_step_mm, "Smallest t_Y interval refinement makes [mm]")
      ->check(CLI::Range(0.001, 10.0))->capture_default_str();
  cmd->add_option("--min-Q-step-kN", o->make.min_Q_step_kN, "Smallest Q interval refinement makes [kN]")
      ->check(CLI::Range(0.1, 1000.0))->capture_default_str();
  cmd->add_option("--min-roll-step-mrad", o->make.min_roll_step_mrad, "Smallest roll interval refinement makes [mrad]")
      ->check(CLI::Range(0.001, 50.0))->capture_default_str();
  cmd->add_option("--tol-N", o->make.tol_N, "Tolerance of a contact's normal force, fraction of Q")
      ->check(CLI::Range(1e-6, 1.0))->capture_default_str();
  cmd->add_option("--tol-pmax", o->make.tol_pmax, "Tolerance of the peak pressure, fraction")
      ->check(CLI::Range(1e-6, 1.0))->capture_default_str();
  cmd->add_option("--check-points", o->make.check_points,
                  "Check points a cell: 1 its centre, or 3: also a quarter and three quarters along its main diagonal "
                  "(a cell missing a tolerance at any is refined; docs/tables.md \"Checking a table at random points\")")
      ->check(CLI::IsMember({1, 3}))->capture_default_str();
  cmd->add_option("--validate", o->make.validate,
                  "Random points solved directly and compared with the table made, never used to refine it: their "
                  "errors and statuses go into the header's `validation` (docs/tables.md \"How it is made\", step 6); 0: none")
      ->check(CLI::Range(0, 100000))->capture_default_str();
  cmd->add_flag("--no-check", o->no_check, "Make the nodes only: no direct solves at the cell centres or validation "
                                           "points, no refinement");
  cmd->add_flag("-q,--quiet", o->make.quiet, "No summary on standard error");
  auto* shard = cmd->add_option("--shard", o->shard, "Solve only the K-th of N slices of the first round's points "
                                                     "(nodes and cell centres) and write them to the output (JSON)");
  cmd->add_option("--points", o->points, "With --shard: solve the slice of this refinement pass's points (the file "
                                         "written by --merge ... --next) instead of the first round's")
      ->needs(shard);
  auto* merge = cmd->add_option("--merge", o->merge, "Shard files of this case (all N of one split, of every pass): take "
                                                     "their solves, refine here, write the table (byte for byte the "
                                                     "one-process table)")
      ->excludes(shard);
  cmd->add_option("--next", o->next, "With --merge: do not solve what the shards lack; write those points (the next "
                                     "refinement pass) to this file for --shard K/N --points, and exit 5 without a table")
      ->needs(merge);
  cmd->callback([o, &ctx] {
    o->make.check = !o->no_check;
    if (o->no_check) o->make.refine = 0;
    const CaseFile cf = load_case_file(o->case_file, true);
    ctx.exit_code = o->shard.empty() ? table_job(cf, o->make, o->out, ctx.out, ctx.err, o->merge, o->next)
                                     : table_shard_job(cf, o->make, o->shard, o->out, ctx.out, ctx.err, o->points);
  });
}

void add_table_export_command(CLI::App& app, CliContext& ctx) {
  struct Opts { std::string table, out; TableExportOptions ex; bool quiet = false; };
  auto o = std::make_shared<Opts>();
  CLI::App* cmd = app.add_subcommand(
      "table-export", "A contact table resampled on a regular t_Y x Q grid for table-driven contact elements of MBS "
                      "codes: the table's interpolant at every grid point, every contact track, the table's columns "
                      "with units; the error of reading it bilinearly measured and written into its header.");
  cmd->add_option("table", o->table, "Contact table written by `mhcontact table`")->required();
  cmd->add_option("-o,--output", o->out, "Export file to write (- for standard output)")->required();
  cmd->add_option("--tY-step-mm", o->ex.tY_step_mm, "Grid step in t_Y [mm]; must divide the table's t_Y range "
                                                    "(default: the table's smallest t_Y interval, at most 0.25 mm)")
      ->check(CLI::Range(0.001, 100.0));
  cmd->add_option("--Q-step-kN", o->ex.Q_step_kN, "Grid step in Q [kN]; must divide the table's Q range")
      ->check(CLI::Range(0.01, 10000.0))->capture_default_str();
  cmd->add_flag("-q,--quiet", o->quiet, "No summary on standard error");
  cmd->callback([o, &ctx] { ctx.exit_code = table_export_job(o->table, o->ex, o->out, ctx.out, ctx.err, o->quiet); });
}

void add_table_wheelset_command(CLI::App& app, CliContext& ctx) {
  struct Opts { std::string left, right, out; bool quiet = false; };
  auto o = std::make_shared<Opts>();
  CLI::App* cmd = app.add_subcommand(
      "table-wheelset", "A wheelset table: the contact tables of the left and the right wheel's pair (each made by "
                        "`mhcontact table`, with the wheelset's flange-back distance) in one file, read by "
                        "mhc_wheelset_table_read / mhcontact.WheelsetTable, whose lookup places both wheels from the "
                        "wheelset's y and roll (docs/tables.md \"A wheelset table\").");
  cmd->add_option("left", o->left, "The left wheel's pair table")->required();
  cmd->add_option("right", o->right, "The right wheel's pair table (may be the same file)")->required();
  cmd->add_option("-o,--output", o->out, "Wheelset table to write (- for standard output)")->required();
  cmd->add_flag("-q,--quiet", o->quiet, "No summary on standard error");
  cmd->callback([o, &ctx] { ctx.exit_code = wheelset_table_job(o->left, o->right, o->out, ctx.out, ctx.err, o->quiet); });
}

}  // namespace mh
