#pragma once
// Number formatting for tables: the shortest decimal representation that reads back to the
// same double (std::to_chars), so output round-trips exactly and is byte-identical between
// runs and thread counts. NaN is written "nan"; infinities "inf"/"-inf".
#include <algorithm>
#include <charconv>
#include <cstdarg>
#include <cstdio>
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

/// out = the printf-style text of fmt (at most 511 characters; "%g" prints a double as an
/// ostream's default does), in out's own storage: a message made on a solver's failure path
/// allocates nothing once out has held one as long.
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
inline void assign_format(std::string& out, const char* fmt, ...) {
  char buf[512];
  va_list ap;
  va_start(ap, fmt);
  const int n = std::vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  out.assign(buf, n < 0 ? 0 : std::min<std::size_t>(static_cast<std::size_t>(n), sizeof buf - 1));
}

}  // namespace mh
