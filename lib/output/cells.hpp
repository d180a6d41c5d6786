#pragma once
// Cells of the output tables: numbers (a fixed number of significant digits, default 10, or the
// shortest round-trip), radii (inf for straight profiles), t_Y grid values, RFC 4180 text.
// Shared by every table writer.
#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "core/numfmt.hpp"
#include "core/units.hpp"

namespace mh::cells {

/// Significant digits of the numbers in the tables: 1..17, or 0 for the shortest representation
/// that reads back to the same double (`--digits max`). Default 10: no physical use needs more,
/// and the tables are half the size. Set once before the writers run (not while they do).
constexpr int kDefaultDigits = 10;
inline int& digits() {
  static int d = kDefaultDigits;
  return d;
}
/// RAII: set the digits for the lifetime of a job.
struct DigitsScope {
  int saved;
  explicit DigitsScope(int d) : saved(digits()) { digits() = d; }
  ~DigitsScope() { digits() = saved; }
};

// Numbers: `digits()` significant digits (%g style: no trailing zeros, exponent when needed);
// radii of straight profiles are "inf" in CSV, null in JSON.
inline void num(std::string& s, double v) {
  const int d = digits();
  if (d <= 0) { append_number(s, v); return; }
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, d);
  s.append(buf, r.ptr);
}
/// `v` rounded to `digits()` significant digits (for JSON, where the library prints the double).
inline double rounded(double v) {
  const int d = digits();
  if (d <= 0 || !std::isfinite(v)) return v;
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, d);
  double x = v;
  std::from_chars(buf, r.ptr, x);
  return x;
}
inline void jnum(std::string& s, double v) {
  if (std::isfinite(v)) num(s, v); else s += "null";
}
/// Radius in mm of curvature k (1/m). A curvature below 1e-6 1/m (a radius beyond 10^9 mm) is
/// the numerical noise of a straight profile: its radius is inf.
inline double radius_mm(double k) { return std::abs(k) < 1e-6 ? INFINITY : units::per_mm / k; }
// Grid t_Y values in mm, rounded to 1e-9 mm so that 6.6e-3 m prints 6.6 and not 6.6000000000000005.
inline double grid_mm(double m) { return std::round(m * 1e12) / 1e9; }

// RFC 4180 quoting for text cells.
inline void csv_text(std::string& s, const std::string& t) {
  if (t.find_first_of(",\"\n") == std::string::npos) { s += t; return; }
  s += '"';
  for (char c : t) { if (c == '"') s += '"'; s += c; }
  s += '"';
}

inline std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (const auto& x : v) { if (!s.empty()) s += sep; s += x; }
  return s;
}


}  // namespace mh::cells
