#pragma once
// The cases a case file asks for (docs/case-file.md): either a cartesian
// sweep of t_Y and Q whose axes are lists or ranges {"from", "to", "step"} (generated exactly in
// the decimals given, counted before anything is materialised and refused beyond kMaxCases), or
// an explicit list of cases, every entry in its plausible range. SweepAxis, kMaxCases and the
// case enumeration (CaseFile::case_count, case_at) are declared in input/case_file.hpp.
//
// Internal to the case-file reader: namespace detail.
#include <nlohmann/json.hpp>

#include "input/case_file.hpp"
#include "input/json_fields.hpp"

namespace mh {
namespace detail {

/// "sweep" or "cases" of the case-file object `j` into cf.sweep_tY_mm, cf.sweep_Q_kN or cf.cases
/// (and cf.has_cases); both given, or a malformed one, throws InputError.
void parse_sweep_or_cases(const Ctx& c, const nlohmann::json& j, CaseFile& cf);

}  // namespace detail
}  // namespace mh
