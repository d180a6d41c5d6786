// `mhcontact hertz`: one Hertzian ellipse (docs/method.md §2), optionally with the plastic law (§5).
// Input in engineering units (1/mm, mm, kN, GPa, MPa), output text or JSON with units in the keys.
#include <CLI/CLI.hpp>

#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>
#include <string>

#include "cli.hpp"
#include "contact/ellipse/ellipse_law.hpp"
#include "contact/options.hpp"
#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "core/plausible.hpp"
#include "core/units.hpp"

namespace mh {
namespace {

/// Options of `mhcontact hertz`, in the units of the command line. NaN = not given.
struct HertzCliOptions {
  double A_per_mm = NAN, B_per_mm = NAN;          ///< [1/mm] curvature sums (eq. 1)
  double R_wyy_mm = NAN, R_wxx_mm = NAN, R_rxx_mm = NAN;  ///< [mm] radii; wxx/rxx omitted = straight
  double N_kN = NAN;                               ///< [kN] normal load
  double E_GPa = NAN;                              ///< [GPa] Young's modulus
  double nu = NAN;                                 ///< [-] Poisson's ratio
  double p_lim_MPa = NAN;                          ///< [MPa] limit pressure; not given = elastic
  double yield_MPa = NAN;                          ///< [MPa] yield stress; p_lim derived from it unless --p-lim
  bool json = false;                               ///< one JSON object instead of text lines
  bool exact = false;                              ///< exact elliptic integrals instead of the table
};

/// JSON schema tag of `hertz --json` (bumped on any incompatible change of keys or meanings).
constexpr const char* kHertzSchema = "mhcontact.hertz/1";

[[noreturn]] void bad(const std::string& option, double value, const std::string& rule,
                      const std::string& hint = {}) {
  throw InputError("hertz " + option, format_number(value), rule, hint);
}

/// Refuse a value outside its plausible range (core/plausible.hpp), as the case file does.
void plausible_or_bad(const std::string& option, double value, const plausible::Range& r) {
  if (!plausible::inside(r, value)) bad(option, value, plausible::rule(r), plausible::hint(r, value));
}

void run_hertz(const HertzCliOptions& o, CliContext& ctx) {
  // ---- Geometry (eq. 1): SI curvature sums [1/m] ----
  const bool by_AB = !std::isnan(o.A_per_mm) || !std::isnan(o.B_per_mm);
  const bool by_R = !std::isnan(o.R_wyy_mm) || !std::isnan(o.R_wxx_mm) || !std::isnan(o.R_rxx_mm);
  if (!by_AB && !by_R)
    throw InputError("hertz", "", "give the curvature sums (--A and --B) or the radii (--R-wyy with --R-wxx and/or --R-rxx)");
  double A = 0, B = 0;
  if (by_AB) {
    if (std::isnan(o.A_per_mm) || std::isnan(o.B_per_mm))
      throw InputError("hertz", "", "--A and --B go together");
    if (!(o.A_per_mm > 0) || !std::isfinite(o.A_per_mm))
      bad("--A", o.A_per_mm, "A must be > 0 1/mm", "A = 1/(2 R_wyy); A = 0 is a line contact");
    if (!(o.B_per_mm > 0) || !std::isfinite(o.B_per_mm))
      bad("--B", o.B_per_mm, "B must be > 0 1/mm",
          "B <= 0: the profiles are conformal or diverge across the contact, no Hertzian ellipse");
    plausible_or_bad("--A", o.A_per_mm, plausible::kCurvature_per_mm);
    plausible_or_bad("--B", o.B_per_mm, plausible::kCurvature_per_mm);
    A = o.A_per_mm / units::mm;
    B = o.B_per_mm / units::mm;
  } else {
    if (std::isnan(o.R_wyy_mm))
      throw InputError("hertz --R-wyy", "", "missing: the wheel radius in the rolling direction is required with the radii");
    if (!(o.R_wyy_mm > 0) || !std::isfinite(o.R_wyy_mm))
      bad("--R-wyy", o.R_wyy_mm, "R_wyy must be > 0 mm and finite");
    plausible_or_bad("--R-wyy", o.R_wyy_mm, plausible::kRadius_mm);
    auto curv = [](double R_mm, const char* opt) {  // 1/R [1/m]; omitted = straight profile
      if (std::isnan(R_mm)) return 0.0;
      if (R_mm == 0 || !std::isfinite(R_mm))
        bad(opt, R_mm, "a profile radius must be non-zero and finite (mm)", "omit it for a straight profile");
      plausible_or_bad(opt, std::fabs(R_mm), plausible::kProfileRadius_mm);
      return 1.0 / (R_mm * units::mm);
    };
    const CurvatureSums s = curvature_sums(o.R_wyy_mm * units::mm, 0.0, curv(o.R_wxx_mm, "--R-wxx"),
                                           curv(o.R_rxx_mm, "--R-rxx"));  // (eq. 1)
    A = s.A;
    B = s.B;
    if (!(B > 0))
      throw InputError("hertz --R-wxx/--R-rxx", "B = " + format_number(B * units::mm) + " 1/mm",
                       "B = (1/R_wxx + 1/R_rxx)/2 must be > 0",
                       "the profiles are conformal or diverge across the contact: no Hertzian ellipse");
  }
  // ---- Load and material ----
  if (std::isnan(o.N_kN) || !(o.N_kN >= 0) || !std::isfinite(o.N_kN))
    bad("--N", o.N_kN, "the normal load must be >= 0 kN and finite");
  if (o.N_kN != 0) plausible_or_bad("--N", o.N_kN, plausible::kQ_kN);  // 0: the unloaded ellipse
  if (!(o.E_GPa > 0) || !std::isfinite(o.E_GPa)) bad("--E", o.E_GPa, "Young's modulus must be > 0 GPa");
  if (!(o.nu > 0 && o.nu < 0.5)) bad("--nu", o.nu, "Poisson's ratio must be in (0, 0.5)");
  plausible_or_bad("--E", o.E_GPa, plausible::kE_GPa);
  plausible_or_bad("--nu", o.nu, plausible::kNu);
  const bool by_yield = !std::isnan(o.yield_MPa);
  if (by_yield && (!(o.yield_MPa > 0) || std::isinf(o.yield_MPa)))
    bad("--yield", o.yield_MPa, "the yield stress must be > 0 MPa and finite", "omit it for an elastic contact");
  if (by_yield) plausible_or_bad("--yield", o.yield_MPa, plausible::kYield_MPa);
  const bool plastic = !std::isnan(o.p_lim_MPa) || by_yield;
  if (!std::isnan(o.p_lim_MPa) && (!(o.p_lim_MPa > 0) || std::isinf(o.p_lim_MPa)))
    bad("--p-lim", o.p_lim_MPa, "the limit pressure must be > 0 MPa and finite", "omit it for an elastic contact");
  if (!std::isnan(o.p_lim_MPa)) plausible_or_bad("--p-lim", o.p_lim_MPa, plausible::kPlim_MPa);
  Material mat;
  mat.E = o.E_GPa * units::GPa;
  mat.nu = o.nu;
  if (by_yield) mat.yield = o.yield_MPa * units::MPa;
  // --p-lim takes precedence over --yield (the law capped at the user's p_lim); --yield alone: the
  // yield law (method.md §5.1), as in the case file.
  mat.p_lim = !std::isnan(o.p_lim_MPa) ? o.p_lim_MPa * units::MPa : INFINITY;
  derive_plastic_law(mat);

  EllipseLaw law;
  try {
    law = make_ellipse_law(A, B, mat, o.exact);
  } catch (const std::invalid_argument& e) {
    throw InputError("hertz", "", e.what());
  }
  const EllipseState s = ellipse_state_for_force(law, o.N_kN * units::kN);

  // ---- Output (units at the edge) ----
  struct Item { const char* key; const char* name; double value; const char* unit; };
  const Item elastic_items[] = {
      {"lambda", "lambda", law.c.lambda, "-"},
      {"m", "m", law.c.m, "-"},
      {"n", "n", law.c.n, "-"},
      {"a_mm", "a", s.a / units::mm, "mm"},
      {"b_mm", "b", s.b / units::mm, "mm"},
      {"p0_MPa", "p0", s.p0 / units::MPa, "MPa"},
      {"pmean_MPa", "p_mean", s.p_mean / units::MPa, "MPa"},
      {"h0_mm", "h0", s.h0 / units::mm, "mm"},
      {"approach_mm", "approach", s.approach / units::mm, "mm"},
  };
  const Item plastic_items[] = {
      {"p_max_MPa", "p_max", s.p_max / units::MPa, "MPa"},
      {"h_y_mm", "h_y", law.h_y / units::mm, "mm"},
      {"N_y_kN", "N_y", law.N_y / units::kN, "kN"},
      {"a_el_mm", "a_el", s.a_el / units::mm, "mm"},
      {"b_el_mm", "b_el", s.b_el / units::mm, "mm"},
      {"area_ratio", "area_ratio", s.area_ratio, "-"},
      {"plateau_a_mm", "plateau_a", s.plateau_a / units::mm, "mm"},
      {"plateau_b_mm", "plateau_b", s.plateau_b / units::mm, "mm"},
  };
  if (o.json) {
    nlohmann::ordered_json j;
    j["schema"] = kHertzSchema;
    j["A_per_mm"] = A * units::mm;
    j["B_per_mm"] = B * units::mm;
    j["N_kN"] = o.N_kN;
    for (const Item& it : elastic_items) j[it.key] = it.value;
    if (by_yield) {
      j["yield_MPa"] = o.yield_MPa;
      if (mat.yield_law) {
        j["p_y_MPa"] = law.p_lim / units::MPa;
        j["beta"] = law.beta;
      } else {
        j["p_lim_MPa"] = mat.p_lim / units::MPa;
      }
    }
    if (plastic) {
      j["plastic"] = s.plastic;
      for (const Item& it : plastic_items) j[it.key] = it.value;
    }
    ctx.out << j.dump(2) << "\n";
  } else {
    auto line = [&](const char* name, double v, const char* unit) {
      ctx.out << name << " = " << format_number(v) << " " << unit << "\n";
    };
    for (const Item& it : elastic_items) line(it.name, it.value, it.unit);
    if (by_yield) {
      line("yield", o.yield_MPa, "MPa");
      if (mat.yield_law) {
        line("p_y", law.p_lim / units::MPa, "MPa");
        line("beta", law.beta, "-");
      } else {
        line("p_lim", mat.p_lim / units::MPa, "MPa");
      }
    }
    if (plastic) {
      ctx.out << "plastic = " << (s.plastic ? "true" : "false") << " -\n";
      for (const Item& it : plastic_items) line(it.name, it.value, it.unit);
    }
  }
  ctx.exit_code = kExitOk;
}

}  // namespace

void add_hertz_command(CLI::App& app, CliContext& ctx) {
  auto opt = std::make_shared<HertzCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "hertz",
      "One Hertzian ellipse (paper eqs. 1-8, docs/method.md section 2): lambda, m, n, semi-axes, peak and "
      "mean pressure, virtual penetration h0 and true approach; with --p-lim the plastic law "
      "(docs/method.md section 5), or with --yield from the yield stress. Give --A and --B, or the radii.");
  cmd->footer(
      "Example (docs/method.md section 5): mhcontact hertz --R-wyy 460 --R-rxx 300 --N 100 --E 210 --nu 0.3 --p-lim 800\n"
      "Radii are positive when the centre of curvature is inside the material (concave: negative); "
      "an omitted --R-wxx or --R-rxx is a straight profile. A = 1/(2 R_wyy), B = (1/R_wxx + 1/R_rxx)/2.\n"
      "Exit codes: 0 ok; 2 invalid value (the message names the option); 1xx command-line syntax.");
  CLI::Option* oA = cmd->add_option("--A", opt->A_per_mm, "[1/mm] curvature sum along x (rolling), A = 1/(2 R_wyy)");
  CLI::Option* oB = cmd->add_option("--B", opt->B_per_mm, "[1/mm] curvature sum along y (lateral), B = (1/R_wxx + 1/R_rxx)/2");
  CLI::Option* oRwyy = cmd->add_option("--R-wyy", opt->R_wyy_mm, "[mm] wheel radius in the rolling direction (> 0)");
  CLI::Option* oRwxx = cmd->add_option("--R-wxx", opt->R_wxx_mm, "[mm] wheel profile radius (omit: straight; concave < 0)");
  CLI::Option* oRrxx = cmd->add_option("--R-rxx", opt->R_rxx_mm, "[mm] rail profile radius (omit: straight)");
  oA->needs(oB);
  oB->needs(oA);
  for (CLI::Option* r : {oRwyy, oRwxx, oRrxx}) {
    oA->excludes(r);
    oB->excludes(r);
  }
  cmd->add_option("--N", opt->N_kN, "[kN] normal load (>= 0)")->required();
  cmd->add_option("--E", opt->E_GPa, "[GPa] Young's modulus of wheel and rail")->required();
  cmd->add_option("--nu", opt->nu, "[-] Poisson's ratio of wheel and rail, in (0, 0.5)")->required();
  cmd->add_option("--p-lim", opt->p_lim_MPa, "[MPa] limit pressure of the plastic law (omit: elastic; takes precedence over --yield)");
  cmd->add_option("--yield", opt->yield_MPa,
                  "[MPa] yield stress of the softer body: the plastic law with p_lim = 2.1 x yield (docs/method.md section 5.1)");
  cmd->add_flag("--json", opt->json, "print one JSON object (keys carry their units) instead of text");
  cmd->add_flag("--exact", opt->exact, "exact elliptic integrals instead of the tabulated fast path");
  cmd->callback([opt, &ctx]() { run_hertz(*opt, ctx); });
}

}  // namespace mh
