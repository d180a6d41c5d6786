// Placeholder until the profile I/O commands land (helper work in progress).
#include <CLI/CLI.hpp>
#include "mhcontact/cli.hpp"
namespace mh {
void add_profile_io_commands(CLI::App&, CliContext&) {}
}  // namespace mh
