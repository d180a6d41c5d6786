// Placeholder until `geometry` and `run` land.
#include <CLI/CLI.hpp>
#include "mhcontact/cli.hpp"
namespace mh {
void add_geometry_command(CLI::App&, CliContext&) {}
void add_run_command(CLI::App&, CliContext&) {}
}  // namespace mh
