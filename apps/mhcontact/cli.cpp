#include "cli.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <csignal>
#include <iostream>
#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "output/output_file.hpp"

namespace mh {
namespace {

extern "C" void on_fatal_signal(int sig) {
  remove_pending_output_temporaries();
  print_interrupt_message();
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

// Levenshtein distance, for "did you mean".
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> d(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) d[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t prev = d[0];
    d[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cur = d[j];
      d[j] = std::min({d[j] + 1, d[j - 1] + 1, prev + (a[i - 1] == b[j - 1] ? 0 : 1)});
      prev = cur;
    }
  }
  return d[b.size()];
}

// The first argument must be a command or one of the top-level options; anything else gets the
// documented error format and a hint, instead of CLI11's "A subcommand is required".
// Returns an empty string when the arguments are fine for CLI11.
std::string check_command(const std::vector<std::string>& args, const CLI::App& app, std::string* hint) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  if (args.empty()) {
    *hint = "commands: " + list + "; see mhcontact --help";
    return "command: a command is required";
  }
  const std::string& a = args[0];
  if (a == "-h" || a == "--help" || a == "--help-all" || a == "--version") return {};
  if (a == "-V" || a == "-v" || a == "version") {
    *hint = "the version is printed by `mhcontact --version`";
    return "command: value " + a + ": unknown command or option";
  }
  for (const auto& n : names) if (a == n) return {};
  std::string best;
  std::size_t best_d = 3;
  for (const auto& n : names) {
    const std::size_t dd = edit_distance(a, n);
    if (dd < best_d) { best_d = dd; best = n; }
  }
  *hint = (best.empty() ? std::string() : "did you mean `" + best + "`? ") + "commands: " + list + "; see mhcontact --help";
  return std::string("command: value ") + a + ": " + (a[0] == '-' ? "unknown option" : "unknown command");
}

}  // namespace

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CliContext ctx{out, err};
  CLI::App app{"mhcontact: multi-Hertzian wheel-rail normal contact, elastic and plastic "
               "(Sebes et al., Wear 314 (2014) 118-124).",
               "mhcontact"};
  app.set_version_flag("--version", std::string("mhcontact ") + MHCONTACT_VERSION + " (commit " + MHCONTACT_GIT_COMMIT + ")");
  app.require_subcommand(1);
  app.footer("Exit codes: 0 ok; 1 some cases failed (run) or tables differ (diff); "
             "2 invalid input; 3 internal error; 4 output could not be written; 1xx command-line syntax (CLI11).");

  CLI::App* profile = app.add_subcommand("profile", "Read, convert, inspect and generate profiles");
  profile->require_subcommand(1);
  add_profile_io_commands(*profile, ctx);
  add_profile_generate_command(*profile, ctx);
  add_geometry_command(app, ctx);
  add_run_command(app, ctx);
  add_merge_command(app, ctx);
  add_wheelset_command(app, ctx);
  add_table_command(app, ctx);
  add_table_export_command(app, ctx);
  add_table_wheelset_command(app, ctx);
  add_hertz_command(app, ctx);
  add_diff_command(app, ctx);

  std::signal(SIGINT, on_fatal_signal);
  std::signal(SIGTERM, on_fatal_signal);

  {
    std::string hint;
    const std::string bad = check_command(args, app, &hint);
    if (!bad.empty()) {
      err << "mhcontact: error: " << bad << " (" << hint << ")\n";
      return kExitInputError;
    }
  }

  // CLI11 parses in reverse order of a vector of arguments.
  std::vector<std::string> rev(args.rbegin(), args.rend());
  int rc = 0;
  try {
    app.parse(rev);
    rc = ctx.exit_code;
  } catch (const CLI::CallForHelp& e) {
    out << app.help();
  } catch (const CLI::CallForAllHelp& e) {
    out << app.help("", CLI::AppFormatMode::All);
  } catch (const CLI::CallForVersion& e) {
    out << e.what() << "\n";
  } catch (const CLI::ParseError& e) {
    // Help requested on a subcommand arrives here too (CLI11 reports it as a ParseError with
    // exit code 0); print through CLI11's own formatter.
    rc = app.exit(e, out, err);
  } catch (const InputError& e) {
    err << "mhcontact: error: " << e.what() << "\n";
    return kExitInputError;
  } catch (const OutputError& e) {
    err << "mhcontact: error: " << e.what() << "\n";
    return kExitOutput;
  } catch (const nlohmann::json::exception& e) {
    err << "mhcontact: error: " << e.what() << "\n";
    return kExitInputError;
  } catch (const std::exception& e) {
    err << "mhcontact: internal error: " << e.what() << " (a bug: please report it with the input)\n";
    return kExitInternal;
  }
  // Every byte written to standard output must have arrived: `> /dev/full` is an error.
  out.flush();
  if (!out) {
    err << "mhcontact: error: standard output: output could not be written (disk full, or the reader closed the pipe?)\n";
    return kExitOutput;
  }
  return rc;
}

}  // namespace mh
