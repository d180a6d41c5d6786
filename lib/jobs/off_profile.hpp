#pragma once
// Whether a case's contact stands entirely on extrapolated geometry (issue #22 §1: "a case whose
// contact is off_profile on every patch is not ok"). The status that follows from it is set by
// the code that owns the statuses; this only detects.
#include "contact/case_result.hpp"

namespace mh {

/// True when the case has at least one contact and every one of them is off the end of a profile
/// (method.md §3.7): every loaded ellipse of a multi-Hertzian solution has its candidate's
/// off_profile flag, every patch of a grid method carries the warning "off_profile:patch=<k>".
/// False for a case without contact (its own status says so).
bool all_contacts_off_profile(const CaseResult& r);

}  // namespace mh
