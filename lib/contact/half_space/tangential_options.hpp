#pragma once
// Options of the exact half-space steady-rolling tangential solver (tangential_rolling.hpp), light
// enough for any reader. Documented defaults.
#include <string>

namespace mh {

struct HalfSpaceTangentialOptions {
  /// [-] convergence: the largest change of a traction component in one sweep, relative to the
  /// largest traction bound μ·max p. Default 1e-6.
  double tol = 1e-6;
  /// sweeps (one FFT evaluation of the displacements and one Gauss–Seidel pass over the rows
  /// each) before giving up with NotConverged. Default 500.
  int max_sweeps = 500;

  /// Ceres-style check: true when valid; otherwise false and *why names the field, the value and
  /// the rule (0 < tol < 1, max_sweeps ≥ 1).
  bool valid(std::string* why = nullptr) const {
    if (!(tol > 0) || !(tol < 1)) {
      if (why) *why = "tol = " + std::to_string(tol) + ": must be in (0, 1)";
      return false;
    }
    if (max_sweeps < 1) {
      if (why) *why = "max_sweeps = " + std::to_string(max_sweeps) + ": must be ≥ 1";
      return false;
    }
    return true;
  }
};

}  // namespace mh
