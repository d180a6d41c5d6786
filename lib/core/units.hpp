#pragma once
// Unit conversions at the edges. The library works in SI (m, N, Pa, rad) throughout;
// files, JSON keys and CSV columns use mm, kN, MPa, GPa and degrees (method.md §1).
#include <cmath>

namespace mh::units {

constexpr double pi = 3.14159265358979323846;

constexpr double mm = 1e-3;   ///< metres per millimetre
constexpr double kN = 1e3;    ///< newtons per kilonewton
constexpr double MPa = 1e6;   ///< pascals per megapascal
constexpr double GPa = 1e9;   ///< pascals per gigapascal
constexpr double deg = pi / 180.0;  ///< radians per degree

// Output conversions as multiplications (x * per_mm, not x / mm: the two differ in the last bit
// and the tables are compared byte for byte).
constexpr double per_mm = 1e3;        ///< millimetres per metre
constexpr double per_mm2 = 1e6;       ///< square millimetres per square metre

}  // namespace mh::units
