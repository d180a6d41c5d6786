#pragma once
// Cells of the output tables: numbers (shortest round-trip), radii (inf for straight profiles),
// t_Y grid values, RFC 4180 text. Shared by every table writer.
#include <cmath>
#include <string>
#include <vector>

#include "core/numfmt.hpp"
#include "core/units.hpp"

namespace mh::cells {

// Numbers: shortest round-trip; radii of straight profiles are "inf" in CSV, null in JSON.
inline void num(std::string& s, double v) { append_number(s, v); }
inline void jnum(std::string& s, double v) {
  if (std::isfinite(v)) append_number(s, v); else s += "null";
}
inline double radius_mm(double k) { return k == 0 ? INFINITY : units::per_mm / k; }
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
