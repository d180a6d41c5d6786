#pragma once
// The command-line layer as a library function: apps/mhcontact/main.cpp only forwards argv and the
// standard streams, tests call run_cli() directly with an argument list.
#include <iosfwd>
#include <string>
#include <vector>

#include "profile/read.hpp"

namespace CLI { class App; }

namespace mh {

struct CliContext {
  std::ostream& out;
  std::ostream& err;
  int exit_code = 0;   ///< set by the subcommand that ran (see errors.hpp ExitCode)
};

/// Run `mhcontact` with `args` (without the program name). Returns the process exit code.
int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// Add the reading options shared by every profile command to `app`:
/// --format auto|simpack|miniprof|table|vampire, --kind wheel|rail, --mirror-y, --mirror-z,
/// --scale S, --vampire-side left|right, --no-check.
void add_profile_read_options(CLI::App& app, ProfileReadOptions& opt);

// Subcommand registration, one function per command family (each in its own cli_*.cpp).
void add_profile_io_commands(CLI::App& profile, CliContext& ctx);    // profile convert, info
void add_profile_generate_command(CLI::App& profile, CliContext& ctx);  // profile generate
void add_hertz_command(CLI::App& app, CliContext& ctx);              // hertz
void add_diff_command(CLI::App& app, CliContext& ctx);               // diff
void add_geometry_command(CLI::App& app, CliContext& ctx);           // geometry
void add_run_command(CLI::App& app, CliContext& ctx);                // run
void add_merge_command(CLI::App& app, CliContext& ctx);              // merge
void add_wheelset_command(CLI::App& app, CliContext& ctx);           // wheelset
void add_table_command(CLI::App& app, CliContext& ctx);               // table
void add_table_export_command(CLI::App& app, CliContext& ctx);        // table-export
void add_table_wheelset_command(CLI::App& app, CliContext& ctx);      // table-wheelset

}  // namespace mh
