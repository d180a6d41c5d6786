#pragma once
// The checks the library applies to its callers' numbers, with the command's rules and words
// (docs/c-api.md "Errors"): the plausible ranges of lib/core/plausible.hpp (one table, stated in
// docs/case-file.md "Plausible ranges") on the SI fields of mhc_pair_options and on the load of a
// solve, and the explicit positioning of a pair. Each returns "" when the value passes, else the
// message: the field, the value (in SI and in the table's unit), the rule and the fix.
#include <cstddef>
#include <string>

#include <mhcontact.h>

namespace mh::capi {

/// The fields of *o that mhc_pair_create reads (those up to struct_size) against the plausible
/// ranges: E, nu (wheel; rail unless NaN), p_lim (unless INFINITY), yield stresses (unless NaN),
/// the nominal radius; and positioning with lateral_offset_m. The first failure's message.
std::string check_pair_options(const mhc_pair_options& o, std::size_t struct_size);

/// The load of a solve, Q_N [N]: finite, not negative, at most the plausible range's top
/// (2000 kN). Q = 0 and a load below the range's bottom are solved: a wheel lifting off in a
/// vehicle-dynamics loop passes through them (Q = 0 is no_contact, zero force).
std::string check_load(double Q_N);

/// struct_size of the mhc_pair_options of a header before explicit positioning.
constexpr std::size_t kOptionsSizeBeforePositioning = offsetof(mhc_pair_options, positioning);
/// ... and of a header before the yield stress.
constexpr std::size_t kOptionsSizeBeforeYield = offsetof(mhc_pair_options, yield_wheel_Pa);

}  // namespace mh::capi
