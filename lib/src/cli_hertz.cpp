// Placeholder until `hertz` lands (helper work in progress).
#include <CLI/CLI.hpp>
#include "mhcontact/cli.hpp"
namespace mh {
void add_hertz_command(CLI::App&, CliContext&) {}
}  // namespace mh
