#pragma once
// Plausible ranges of the physical inputs: one table, applied alike by the
// case file, the manifest (through the case-file rules) and every subcommand. A value outside
// its range is refused with a hint at the likely unit mistake (newtons typed as kN, MPa typed as
// GPa, ...). The table is stated in docs/case-file.md "Plausible ranges" and docs/method.md §1.
//
//   quantity                    unit   low      high      hint below / above
//   Q (wheel load)              kN     0.01     2000      "is it in MN?" / "did you give newtons?"
//   E (Young's modulus)         GPa    50       400       "is it in TPa?" / "is it in MPa?"
//   nu (Poisson's ratio)        -      0.1      0.45      - / "steel is about 0.28-0.3"
//   p_lim (limit pressure)      MPa    100      20000     "is it in GPa?" / "is it in kPa?"
//   t_Y (lateral displacement)  mm     -60      60        - / "is it in micrometres?"
//   nominal / rolling radius    mm     100      2000      "is it in metres?" / "is it a diameter?"
//   profile radius |R|          mm     1        1e6       "is it in metres?" / "omit it for a straight profile"
//   curvature sums A, B         1/mm   1e-7     1         - / "is it in 1/m?"
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "core/numfmt.hpp"

namespace mh::plausible {

struct Range {
  const char* name;       ///< as in messages, e.g. "Q"
  const char* unit;       ///< "kN", "GPa", "-", ...
  double lo, hi;          ///< inclusive bounds
  const char* hint_low;   ///< likely mistake when below (may be empty)
  const char* hint_high;  ///< likely mistake when above (may be empty)
};

inline constexpr Range kQ_kN{"Q", "kN", 0.01, 2000, "is it in MN?", "did you give newtons? Q is in kN"};
inline constexpr Range kE_GPa{"E", "GPa", 50, 400, "is it in TPa?", "is it in MPa? E is in GPa, steel is 210"};
inline constexpr Range kNu{"nu", "-", 0.1, 0.45, "", "steel is about 0.28-0.3"};
inline constexpr Range kYield_MPa{"yield", "MPa", 50, 5000, "is it in GPa? the yield stress is in MPa", "is it in kPa or Pa? the yield stress is in MPa"};
inline constexpr Range kPlim_MPa{"p_lim", "MPa", 100, 20000, "is it in GPa? p_lim is in MPa", "is it in kPa? p_lim is in MPa"};
inline constexpr Range kTY_mm{"t_Y", "mm", -60, 60, "", "is it in micrometres? t_Y is in mm"};
/// The wheel's roll against the rail: the rolled gap's domain (method.md §3.8), |δ| ≤ 50 mrad.
inline constexpr Range kRoll_mrad{"roll", "mrad", -50, 50, "is it in microradians? the roll is in mrad",
                                  "is it in microradians? the roll is in mrad"};
inline constexpr Range kRadius_mm{"radius", "mm", 100, 2000, "is it in metres? radii are in mm", "is it a diameter? give the radius"};
inline constexpr Range kProfileRadius_mm{"|profile radius|", "mm", 1, 1e6, "is it in metres? radii are in mm", "omit it for a straight profile"};
inline constexpr Range kCurvature_per_mm{"curvature sum", "1/mm", 1e-7, 1, "", "is it in 1/m? A and B are in 1/mm"};

/// True when v is finite and inside [lo, hi].
inline bool inside(const Range& r, double v) { return std::isfinite(v) && v >= r.lo && v <= r.hi; }

/// The rule text for a refused value, e.g. "must be between 0.01 and 2000 kN (plausible range of Q)".
inline std::string rule(const Range& r) {
  std::string s = "must be between " + format_number(r.lo) + " and " + format_number(r.hi);
  if (std::string(r.unit) != "-") s += std::string(" ") + r.unit;
  return s + " (plausible range of " + r.name + ", docs/case-file.md \"Plausible ranges\")";
}

/// The hint for a refused value: which unit mistake it looks like.
/// No unit hint for zero or a negative value of a positive quantity: that is no unit mistake.
inline std::string hint(const Range& r, double v) {
  if (v <= 0 && r.lo > 0) return "";
  return v < r.lo ? r.hint_low : (v > r.hi ? r.hint_high : "");
}

/// Throw InputError(where, value, rule, hint) unless v is inside the range.
inline void require(const Range& r, double v, const std::string& where, const std::string& value_text) {
  if (!inside(r, v)) throw InputError(where, value_text, rule(r), hint(r, v));
}

}  // namespace mh::plausible
