// The library's input checks (capi/checks.hpp) and the pair's warnings (mhc_pair_n_warnings,
// mhc_pair_warning): the command's rules and words through the C interface.
#include "capi/checks.hpp"

#include <cmath>
#include <string>

#include "capi/handles.hpp"
#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "core/plausible.hpp"

namespace mh::capi {

namespace {

/// v [SI] against r after the conversion v * to_unit; "" or the message naming the field, the
/// value in both units, the rule and the fix. The fix is the field's SI unit with an example, not
/// the table's hint: that one guesses at the case file's units ("is it in TPa?" for an E of
/// 210e3 Pa typed in MPa), the fields here are SI.
std::string implausible(const char* field, double v, const char* si_unit, double to_unit, const plausible::Range& r,
                        const char* si_example) {
  const double u = v * to_unit;
  if (plausible::inside(r, u)) return "";
  std::string value = format_number(v) + " " + si_unit;
  if (std::string(r.unit) != "-" && std::isfinite(v)) value += " (" + format_number(u) + " " + r.unit + ")";
  const std::string hint = std::string(si_unit) != "-" ? std::string(field) + " is in " + si_unit + ": " + si_example
                                                       : std::string(si_example);
  return InputError::format(std::string("options.") + field, value, plausible::rule(r), hint);
}

}  // namespace

std::string check_pair_options(const mhc_pair_options& o, std::size_t struct_size) {
  const bool has_yield = struct_size >= kOptionsSizeBeforePositioning;
  const bool has_positioning = struct_size >= sizeof(mhc_pair_options);
  std::string m;
  auto first = [&](std::string s) {
    if (m.empty()) m = std::move(s);
  };
  first(implausible("E_wheel_Pa", o.E_wheel_Pa, "Pa", 1e-9, plausible::kE_GPa, "steel is 210e9"));
  if (!std::isnan(o.E_rail_Pa))
    first(implausible("E_rail_Pa", o.E_rail_Pa, "Pa", 1e-9, plausible::kE_GPa, "steel is 210e9 (NaN: the wheel's)"));
  first(implausible("nu_wheel", o.nu_wheel, "-", 1, plausible::kNu, "steel is about 0.28-0.3"));
  if (!std::isnan(o.nu_rail)) first(implausible("nu_rail", o.nu_rail, "-", 1, plausible::kNu, "NaN: the wheel's"));
  if (!(std::isinf(o.p_lim_Pa) && o.p_lim_Pa > 0))
    first(implausible("p_lim_Pa", o.p_lim_Pa, "Pa", 1e-6, plausible::kPlim_MPa, "1500 MPa is 1500e6 (INFINITY: elastic)"));
  if (has_yield) {
    if (!std::isnan(o.yield_wheel_Pa))
      first(implausible("yield_wheel_Pa", o.yield_wheel_Pa, "Pa", 1e-6, plausible::kYield_MPa, "350 MPa is 350e6 (NaN: not given)"));
    if (!std::isnan(o.yield_rail_Pa))
      first(implausible("yield_rail_Pa", o.yield_rail_Pa, "Pa", 1e-6, plausible::kYield_MPa, "350 MPa is 350e6 (NaN: the wheel's)"));
  }
  first(implausible("nominal_radius_m", o.nominal_radius_m, "m", 1e3, plausible::kRadius_mm, "460 mm is 0.46"));
  if (has_positioning && m.empty()) {
    // As the case file's track.positioning and track.lateral_offset_mm (docs/case-file.md).
    if (o.positioning != MHC_POSITIONING_GAUGE && o.positioning != MHC_POSITIONING_EXPLICIT)
      m = InputError::format("options.positioning", std::to_string(o.positioning),
                             "must be MHC_POSITIONING_GAUGE (0, default) or MHC_POSITIONING_EXPLICIT (1)", "");
    else if (!(std::fabs(o.lateral_offset_m) <= 0.2))
      m = InputError::format("options.lateral_offset_m", format_number(o.lateral_offset_m) + " m",
                             "must lie within -0.2 … 0.2 m", "it is in m: -3.4 mm is -3.4e-3");
    else if (o.positioning == MHC_POSITIONING_GAUGE && o.lateral_offset_m != 0)
      m = InputError::format("options.lateral_offset_m", format_number(o.lateral_offset_m) + " m",
                             "only used with positioning MHC_POSITIONING_EXPLICIT",
                             "set positioning = MHC_POSITIONING_EXPLICIT, or leave it 0");
  }
  return m;
}

std::string check_load(double Q_N) {
  if (std::isfinite(Q_N) && Q_N >= 0 && Q_N * 1e-3 <= plausible::kQ_kN.hi) return "";
  const std::string fix = "Q_N is in N: 50 kN is 50e3";
  if (!std::isfinite(Q_N)) return InputError::format("Q_N", format_number(Q_N) + " N", "must be finite", fix);
  const std::string value = format_number(Q_N) + " N (" + format_number(Q_N * 1e-3) + " kN)";
  if (Q_N < 0)
    return InputError::format("Q_N", value, "a wheel load must not be negative (0: the wheel lifted, no_contact)", fix);
  return InputError::format("Q_N", value,
                            "must be at most " + format_number(plausible::kQ_kN.hi) +
                                " kN (the top of the plausible range of Q, docs/case-file.md \"Plausible ranges\")",
                            fix);
}

}  // namespace mh::capi

extern "C" {

int32_t mhc_pair_n_warnings(const mhc_pair* pair) { return pair ? static_cast<int32_t>(pair->warnings.size()) : 0; }

const char* mhc_pair_warning(const mhc_pair* pair, int32_t i) {
  if (!pair || i < 0 || static_cast<std::size_t>(i) >= pair->warnings.size()) return nullptr;
  return pair->warnings[static_cast<std::size_t>(i)].c_str();
}

}  // extern "C"
