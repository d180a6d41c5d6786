#pragma once
// One entry for every method: the runner solves a case through solve_contact(), whatever the case
// file's "method" is (docs/method.md §4 multi-Hertzian, §8 half-space, §9 strips).
#include "contact/options.hpp"
#include "contact/case_result.hpp"
#include "contact/judge/judge.hpp"
#include "contact/half_space/half_space_method.hpp"
#include "contact/multi_hertz/multi_hertz.hpp"
#include "contact/strips/strip_method.hpp"

namespace mh {

/// Solve one case by opt.method. Never throws for a numerical reason (the status says it).
CaseResult solve_contact(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt);

/// The same into `out`. The multi-Hertzian method reuses out's vectors (solve_multi_hertz's
/// second form: no allocation once they have grown, for the C interface's workspace); the other
/// methods assign a fresh result.
void solve_contact(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt,
                   CaseResult& out);

}  // namespace mh
