#pragma once
// Kalker's linear theory by his series method, solved to convergence (scripts/kalker_series.py,
// tests/data/kalker_series/README.md): creepage coefficients independent of any element grid, of
// the library and of Table E.3. The converged value is the mean of the rows of degree 14 and 16
// (they differ by at most 0.016 %).
#include <cmath>

#include "support/data_csv.hpp"

namespace mh::test {

struct SeriesCoefficients {
  double C11 = 0, C22 = 0, C23 = 0, C33 = 0;
};

/// The converged coefficients at a/b and ν, rows of the table only (a/b 0.2, 0.5, 1, 2, 5;
/// ν 0.25, 0.28); a missing row fails the test.
inline SeriesCoefficients kalker_series(double a_over_b, double nu) {
  SeriesCoefficients s;
  int found = 0;
  for (const DataRow& r : read_data_rows("kalker_series/kalker_series.csv")) {
    if (std::abs(r["a_over_b"] - a_over_b) > 1e-9 || std::abs(r["nu"] - nu) > 1e-9) continue;
    if (r["degree"] != 14 && r["degree"] != 16) continue;
    s.C11 += r["C11"] / 2;
    s.C22 += r["C22"] / 2;
    s.C23 += r["C23"] / 2;
    s.C33 += r["C33"] / 2;
    ++found;
  }
  REQUIRE(found == 2);
  return s;
}

}  // namespace mh::test
