#pragma once
// Number formatting for tables: the shortest decimal representation that reads back to the
// same double (std::to_chars), so output round-trips exactly and is byte-identical between
// runs and thread counts. NaN is written "nan"; infinities "inf"/"-inf".
#include <charconv>
#include <string>

namespace mh {

/// Append the shortest round-trip representation of v to s.
inline void append_number(std::string& s, double v) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  s.append(buf, r.ptr);
}
inline void append_number(std::string& s, long long v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  s.append(buf, r.ptr);
}
inline std::string format_number(double v) {
  std::string s;
  append_number(s, v);
  return s;
}

}  // namespace mh
