// Placeholder until `profile generate` lands (helper work in progress).
#include <CLI/CLI.hpp>
#include "mhcontact/cli.hpp"
namespace mh {
void add_profile_generate_command(CLI::App&, CliContext&) {}
}  // namespace mh
