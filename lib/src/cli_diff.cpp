// Placeholder until `diff` lands (helper work in progress).
#include <CLI/CLI.hpp>
#include "mhcontact/cli.hpp"
namespace mh {
void add_diff_command(CLI::App&, CliContext&) {}
}  // namespace mh
