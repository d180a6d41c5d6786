#pragma once
// One entry for every method: the runner solves a case through solve_method(), whatever the case
// file's "method" is (docs/method.md §4 multi-Hertzian, §8 half-space, §9 strips).
#include "contact/case_result.hpp"
#include "contact/half_space.hpp"
#include "contact/multi_hertz.hpp"
#include "contact/strip_method.hpp"

namespace mh {

/// The options of every method, as the case file sets them.
struct MethodOptions {
  Method method = Method::MultiHertzian;
  SolverOptions multi_hertzian;   ///< case file "solver"
  HalfSpaceOptions half_space;    ///< case file "half_space"
  StripMethodOptions strips;      ///< case file "strips"
};

/// Solve one case by opt.method. Never throws for a numerical reason (the status says it).
CaseResult solve_method(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt);

}  // namespace mh
