#include "cli.hpp"

#include <CLI/CLI.hpp>
#include <csignal>
#include <iostream>
#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "output/output_file.hpp"

namespace mh {
namespace {

extern "C" void on_fatal_signal(int sig) {
  remove_pending_output_temporaries();
  std::signal(sig, SIG_DFL);
  std::raise(sig);
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
             "2 invalid input; 3 internal error; 1xx command-line syntax (CLI11).");

  CLI::App* profile = app.add_subcommand("profile", "Read, convert, inspect and generate profiles");
  profile->require_subcommand(1);
  add_profile_io_commands(*profile, ctx);
  add_profile_generate_command(*profile, ctx);
  add_geometry_command(app, ctx);
  add_run_command(app, ctx);
  add_merge_command(app, ctx);
  add_hertz_command(app, ctx);
  add_diff_command(app, ctx);

  std::signal(SIGINT, on_fatal_signal);
  std::signal(SIGTERM, on_fatal_signal);

  // CLI11 parses in reverse order of a vector of arguments.
  std::vector<std::string> rev(args.rbegin(), args.rend());
  try {
    app.parse(rev);
  } catch (const CLI::CallForHelp& e) {
    out << app.help();
    return 0;
  } catch (const CLI::CallForAllHelp& e) {
    out << app.help("", CLI::AppFormatMode::All);
    return 0;
  } catch (const CLI::CallForVersion& e) {
    out << e.what() << "\n";
    return 0;
  } catch (const CLI::ParseError& e) {
    // Help requested on a subcommand arrives here too (CLI11 reports it as a ParseError with
    // exit code 0); print through CLI11's own formatter.
    return app.exit(e, out, err);
  } catch (const InputError& e) {
    err << "mhcontact: error: " << e.what() << "\n";
    return kExitInputError;
  } catch (const nlohmann::json::exception& e) {
    err << "mhcontact: error: " << e.what() << "\n";
    return kExitInputError;
  } catch (const std::exception& e) {
    err << "mhcontact: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  return ctx.exit_code;
}

}  // namespace mh
