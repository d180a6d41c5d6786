// `mhcontact profile generate NAME [--inclination none|1:40|1:20] [--step MM] -o FILE`
// (docs/profiles.md §2): a standard profile from its definition (standard_profiles.hpp),
// written by write_profile (output/profile_file.hpp).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <memory>
#include <ostream>

#include "cli.hpp"
#include "core/errors.hpp"
#include "output/profile_file.hpp"
#include "profile/read.hpp"
#include "profile/standard_profiles.hpp"
#include "core/units.hpp"

namespace mh {
namespace {

struct GenerateArgs {
  std::string name;
  std::string inclination = "none";
  double step_mm = 0.1;  ///< [mm] largest node spacing along the profile (default 0.1 mm)
  std::string output;
};

std::string lower_extension(const std::string& path) {
  const auto slash = path.find_last_of("/\\");
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string e = path.substr(dot + 1);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

void generate(const GenerateArgs& a, CliContext& ctx) {
  const ProfileKind kind = standard_profile_kind(a.name);  // InputError listing the valid names
  // A SIMPACK file's type follows its extension: refuse a wheel written as .prr or a rail as .prw.
  const std::string e = lower_extension(a.output);
  if ((e == "prr" && kind == ProfileKind::Wheel) || (e == "prw" && kind == ProfileKind::Rail))
    throw InputError(a.output, "." + e, std::string("a ") + to_string(kind) + " cannot be written as a SIMPACK " +
                                            (e == "prr" ? "rail (.prr)" : "wheel (.prw)"),
                     std::string("use .csv or ") + (kind == ProfileKind::Wheel ? ".prw" : ".prr"));
  const Profile p = make_standard_profile(a.name, parse_inclination(a.inclination), a.step_mm * units::mm);
  write_profile(p, a.output);
  for (const auto& w : p.warnings) ctx.err << "warning: " << a.name << ": " << w << "\n";
  ctx.out << "wrote " << a.output << " (" << a.name << " " << to_string(p.kind) << ", inclination "
          << a.inclination << ", " << p.size() + p.face_y.size() << " points"
          << (p.face_y.empty() ? "" : ", " + std::to_string(p.face_y.size()) + " of them on the gauge face") << ")\n";
  ctx.exit_code = kExitOk;
}

}  // namespace

void add_profile_generate_command(CLI::App& profile, CliContext& ctx) {
  auto a = std::make_shared<GenerateArgs>();
  CLI::App* c = profile.add_subcommand(
      "generate", "write a standard profile (S1002 wheel; 60E1, 54E1, 60E2, 49E1 rails; EN 15302 wheel A, rail A) generated from its definition");
  c->add_option("NAME", a->name, "S1002 (wheel, EN 13715), 60E1, 54E1, 60E2 or 49E1 (rails, EN 13674-1), EN15302-wheel-A or EN15302-rail-A")->required();
  c->add_option("--inclination", a->inclination,
                "rails: none (vertical, default), 1:N (1:40, 1:30, 1:20, N >= 5) or an angle (2.5deg), rotated about the crown top towards the "
                "track centre; wheels: none only")
      ->check(CLI::Validator(
          [](std::string& v) {
            try {
              parse_inclination(v);
            } catch (const std::invalid_argument& e) {
              return std::string(e.what());
            }
            return std::string();
          },
          "INCLINATION"));
  c->add_option("--step", a->step_mm, "largest node spacing along the profile [mm] (default 0.1; 0.001 … 5)");
  c->add_option("-o,--output", a->output,
                "output file: .csv (y_mm,z_mm; y to the field side, z up) or .prr/.prw (SIMPACK, z down)")
      ->required();
  c->callback([a, &ctx]() { generate(*a, ctx); });
}

}  // namespace mh
