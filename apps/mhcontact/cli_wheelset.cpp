// `mhcontact wheelset CASE.json -o DIR` (docs/wheelset.md): rolling-radius difference, contact
// angles and EN 15302 equivalent conicity of a wheelset, or of a fleet of wheels on one rail pair.
#include <CLI/CLI.hpp>

#include <memory>

#include "cli.hpp"
#include "input/wheelset_case.hpp"
#include "jobs/run.hpp"
#include "jobs/wheelset_run.hpp"

namespace mh {

void add_wheelset_command(CLI::App& app, CliContext& ctx) {
  struct Opts { std::string case_file, digits = "10"; WheelsetRunOptions run; };
  auto o = std::make_shared<Opts>();
  CLI::App* cmd = app.add_subcommand(
      "wheelset", "Wheelset geometry: rolling-radius difference, contact angles and EN 15302 equivalent conicity "
                  "(writes DIR/wheelset.csv, DIR/conicity.csv, DIR/summary.json; a fleet writes DIR/fleet.csv). "
                  "Exit 0 if every row and amplitude is ok, 1 if some are not.");
  cmd->add_option("case", o->case_file, "Wheelset case file (JSON; \"wheels\": [...] for a fleet)")->required();
  cmd->add_option("-o,--output", o->run.out_dir, "Output directory (created if missing)")->required();
  cmd->add_option("--threads", o->run.threads, "Worker threads (0 = all cores; output is identical whatever the count)")
      ->check(CLI::Range(0u, 1024u))->capture_default_str();
  cmd->add_option("--digits", o->digits, "Significant digits of the numbers in the tables (1..17), or max for the shortest round-trip")
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", o->run.quiet, "No summary on standard error");
  cmd->callback([o, &ctx] {
    o->run.digits = parse_digits(o->digits);
    const WheelsetCase wc = load_wheelset_case(o->case_file);
    ctx.exit_code = wheelset_job(wc, o->run, ctx.out, ctx.err);
  });
}

}  // namespace mh
