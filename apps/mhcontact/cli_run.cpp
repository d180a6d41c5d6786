// `mhcontact geometry` and `mhcontact run`.
#include <CLI/CLI.hpp>
#include <unistd.h>

#include "input/case_file.hpp"
#include "cli.hpp"
#include "core/errors.hpp"
#include "input/manifest.hpp"
#include "jobs/batch.hpp"
#include "jobs/resume.hpp"
#include "jobs/run.hpp"
#include "jobs/shards.hpp"

namespace mh {

void add_geometry_command(CLI::App& app, CliContext& ctx) {
  struct Opts { std::string case_file, out_dir, digits = "10"; bool quiet = false; };
  auto o = std::make_shared<Opts>();
  CLI::App* cmd = app.add_subcommand(
      "geometry", "Contact geometry of the case's profile pair: CAF, radii and potential ellipses "
                  "(writes DIR/caf.csv and DIR/geometry.json)");
  cmd->add_option("case", o->case_file, "Case file or batch manifest (JSON); a manifest writes DIR/pairs/<k>/ per pair")->required();
  cmd->add_option("-o,--output", o->out_dir, "Output directory (created if missing)")->required();
  cmd->add_option("--digits", o->digits, "Significant digits of the numbers in the tables (1..17), or max for the shortest round-trip")
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", o->quiet, "No summary on standard error");
  cmd->callback([o, &ctx] {
    const int digits = parse_digits(o->digits);
    const nlohmann::json j = read_json_file(o->case_file);
    if (is_manifest(j)) {
      ctx.exit_code = geometry_batch_job(j, o->case_file, o->out_dir, ctx.err, o->quiet, digits);
      return;
    }
    const CaseFile cf = load_case_file(o->case_file, false);
    ctx.exit_code = geometry_job(cf, o->out_dir, ctx.out, ctx.err, o->quiet, digits);
  });
}

void add_run_command(CLI::App& app, CliContext& ctx) {
  struct Opts { std::string case_file, out_dir, format = "both"; unsigned threads = 0; int pressure_grid = 0; bool quiet = false, force = false, strips = false, fail_on_warning = false, resume = false; std::string shard, shard_by = "pairs", shard_sizes = "equal", fail_on, digits = "10", pressure_cases; };
  auto o = std::make_shared<Opts>();
  CLI::App* cmd = app.add_subcommand(
      "run", "Solve every case of the case file's sweep (or of a batch manifest over many profile pairs) (writes DIR/cases.csv, DIR/ellipses.csv, DIR/geometry.csv, "
             "DIR/results.json). Exit 0 if every case has an answer (status ok or outside_validity), 1 if some have "
             "none (no_contact, out_of_range, not_converged, invalid_pair) or a --fail-on class occurred.");
  cmd->add_option("case", o->case_file, "Case file (JSON)")->required();
  cmd->add_option("-o,--output", o->out_dir, "Output directory (created if missing); '-' writes results.json to standard output")->required();
  cmd->add_option("--format", o->format, "Which outputs: csv, json or both")
      ->check(CLI::IsMember({"csv", "json", "both"}))->capture_default_str();
  cmd->add_option("--threads", o->threads, "Worker threads (0 = all cores; output is identical whatever the count)")
      ->check(CLI::Range(0u, 1024u))->capture_default_str();
  cmd->add_option("--pressure-grid", o->pressure_grid,
                  "Also write DIR/pressure.csv: the pressure of every loaded ellipse on an N x N grid over its patch");
  cmd->add_option("--pressure-cases", o->pressure_cases,
                  "With --pressure-grid: only these cases, e.g. 3,17,40-45 (case numbers; in a batch, per pair)");
  cmd->add_flag("--strips", o->strips, "Strip method: also write DIR/strips.csv, one row per loaded strip");
  cmd->add_option("--digits", o->digits, "Significant digits of the numbers in the tables (1..17), or max for the shortest round-trip")
      ->capture_default_str();
  cmd->add_flag("--fail-on-warning", o->fail_on_warning,
                "Exit 1 when any case has a warning (e.g. non_hertzian_excluded), or the rail cant is warned about, "
                "as when a case fails: for CI");
  CLI::Option* fail_on = cmd->add_option("--fail-on", o->fail_on,
                  "Exit 1 when any case has a warning of these classes, e.g. off_profile,pressure_spike "
                  "(non_hertzian, non_hertzian_excluded, interacting, off_profile, flange_climb, nadal_limit, derailed, smoothing_sensitive, pressure_spike, "
                  "strip_outlier, auto, cant): for CI")
      ->type_name("CLASSES");
  cmd->add_flag("--force", o->force, "Write pressure.csv even when it would be larger than the limit of 10 GB");
  cmd->add_option("--shard", o->shard, "K/N: run only the K-th of N deterministic slices of the case list (join them with `mhcontact merge`)");
  cmd->add_option("--shard-by", o->shard_by,
                  "Batch manifest with --shard: slice the pairs, or the list of every pair's cases (a pair's cases "
                  "spread over shards; docs/batch-and-shards.md)")
      ->check(CLI::IsMember({"pairs", "cases"}))->capture_default_str();
  cmd->add_option("--shard-sizes", o->shard_sizes,
                  "With --shard: equal slices, or tapered (slice K's share proportional to N-K+1, the last the "
                  "smallest) for shards handed out as workers free up; every shard of a run alike (docs/batch-and-shards.md)")
      ->check(CLI::IsMember({"equal", "tapered"}))->capture_default_str();
  cmd->add_flag("--resume", o->resume,
                "Batch manifest: run pair by pair into DIR.parts/ and merge into DIR; after an interruption the same "
                "command skips the pairs already complete (docs/cluster.md)");
  cmd->add_flag("-q,--quiet", o->quiet, "No progress or summary on standard error");
  cmd->callback([o, fail_on, &ctx] {
    RunOptions ro;
    if (!o->shard.empty()) parse_shard(o->shard, &ro.shard_index, &ro.shard_count);
    ro.shard_by_cases = o->shard_by == "cases";
    ro.shard_sizes = parse_shard_sizes(o->shard_sizes);
    const nlohmann::json j = read_json_file(o->case_file);
    ro.out_dir = o->out_dir;
    ro.csv = o->format != "json";
    ro.json = o->format != "csv";
    ro.threads = o->threads;
    ro.fail_on_warning = o->fail_on_warning;
    if (fail_on->count()) ro.fail_on = parse_fail_on(o->fail_on);
    ro.quiet = o->quiet;
    ro.pressure_grid = o->pressure_grid;
    if (!o->pressure_cases.empty()) ro.pressure_cases = parse_case_selection(o->pressure_cases);
    ro.strips = o->strips;
    ro.force = o->force;
    ro.digits = parse_digits(o->digits);
    ro.progress = (&ctx.err == &std::cerr) && ::isatty(2);
    if (is_manifest(j)) {
      const Manifest m = parse_manifest(j, o->case_file);
      ctx.exit_code = o->resume ? resumable_batch_job(m, ro, ctx.out, ctx.err) : batch_job(m, ro, ctx.out, ctx.err);
    } else if (o->resume) {
      throw InputError("--resume", o->case_file, "is for batch manifests (a fleet of pairs)",
                       "split a case file's sweep with --shard K/N and re-run the missing shards");
    } else {
      ctx.exit_code = run_job(parse_case_json(j, o->case_file, true), ro, ctx.out, ctx.err);
    }
  });
}

}  // namespace mh

namespace mh {

void add_merge_command(CLI::App& app, CliContext& ctx) {
  struct Opts { std::vector<std::string> dirs; std::string out_dir; bool quiet = false; };
  auto o = std::make_shared<Opts>();
  CLI::App* cmd = app.add_subcommand(
      "merge", "Join the output directories of all shards of one `run --shard K/N` into the tables a single run "
               "would have written. Exit 0 if every case is ok, 1 if some are not.");
  cmd->add_option("dirs", o->dirs, "Shard output directories (any order)")->required();
  cmd->add_option("-o,--output", o->out_dir, "Output directory")->required();
  cmd->add_flag("-q,--quiet", o->quiet, "No summary on standard error");
  cmd->callback([o, &ctx] { ctx.exit_code = merge_job(o->dirs, o->out_dir, ctx.err, o->quiet); });
}

}  // namespace mh
