#pragma once
// Cells of the output tables: numbers (a fixed number of significant digits, default 10, or the
// shortest round-trip), radii (inf for straight profiles), t_Y grid values, RFC 4180 text.
// Shared by every table writer.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
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

namespace detail {
// %g layout of the significant digits dig[0..nd) (no trailing zeros) with decimal exponent X.
inline char* layout_general(char* o, bool neg, const char* dig, int nd, int X, int d) {
  if (neg) *o++ = '-';
  if (X < d && X >= -4) {  // fixed notation
    if (X < 0) {
      *o++ = '0'; *o++ = '.';
      for (int k = 0; k < -X - 1; ++k) *o++ = '0';
      for (int k = 0; k < nd; ++k) *o++ = dig[k];
    } else {
      for (int k = 0; k <= X; ++k) *o++ = k < nd ? dig[k] : '0';
      if (nd > X + 1) {
        *o++ = '.';
        for (int k = X + 1; k < nd; ++k) *o++ = dig[k];
      }
    }
    return o;
  }
  *o++ = dig[0];  // scientific, exponent with at least two digits
  if (nd > 1) {
    *o++ = '.';
    for (int k = 1; k < nd; ++k) *o++ = dig[k];
  }
  *o++ = 'e';
  *o++ = X < 0 ? '-' : '+';
  const int ax = X < 0 ? -X : X;
  if (ax >= 100) *o++ = static_cast<char>('0' + ax / 100);
  *o++ = static_cast<char>('0' + ax / 10 % 10);
  *o++ = static_cast<char>('0' + ax % 10);
  return o;
}
}  // namespace detail

/// `v` with `d` (1..17) significant digits, byte for byte as std::to_chars(general, d), i.e.
/// printf("%.*g"), into `out` (64 chars at least); returns the end. Fast exact path for d ≤ 15
/// and normal v: with v = m·2^e, the digits are q = v·10^(d−1−X) rounded half-even, computed
/// exactly in 128-bit integers (a shift when the scale is a power of 10 ≥ 1, else one division);
/// what does not fit 128 bits goes to std::to_chars. tests/unit/output/test_cells.cpp compares
/// both on millions of values.
inline char* general_digits(char* out, double v, int d) {
  if (d > 15 || !std::isnormal(v)) return std::to_chars(out, out + 64, v, std::chars_format::general, d).ptr;
  __extension__ typedef unsigned __int128 u128;  // GCC and Clang
  static constexpr std::uint64_t p10[20] = {1ull, 10ull, 100ull, 1000ull, 10000ull, 100000ull, 1000000ull,
      10000000ull, 100000000ull, 1000000000ull, 10000000000ull, 100000000000ull, 1000000000000ull,
      10000000000000ull, 100000000000000ull, 1000000000000000ull, 10000000000000000ull,
      100000000000000000ull, 1000000000000000000ull, 10000000000000000000ull};
  const bool neg = v < 0;
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  const std::uint64_t m = (bits & ((1ull << 52) - 1)) | (1ull << 52);
  const int e = static_cast<int>((bits >> 52) & 0x7ff) - 1075;  // |v| = m·2^e exactly (v normal)
  // floor(log10 2^(e+52)) = floor((e+52)·log10 2), maybe 1 below log10|v|.
  const int e2m1 = e + 52;
  int X = e2m1 >= 0 ? (e2m1 * 78913) >> 18 : -((-e2m1 * 78913 + (1 << 18) - 1) >> 18);
  std::uint64_t q = 0;
  for (int attempt = 0;; ++attempt) {
    if (attempt == 3) return std::to_chars(out, out + 64, v, std::chars_format::general, d).ptr;
    const int k = d - 1 - X;  // q = round(|v|·10^k)
    // |v|·10^k = num/den, num = m·10^max(k,0)·2^max(e,0), den = 10^max(−k,0)·2^max(−e,0).
    const int k10 = k > 0 ? k : 0, d10 = k < 0 ? -k : 0;
    const int s2 = e < 0 ? -e : 0, n2 = e > 0 ? e : 0;
    if (k10 > 19 || d10 > 19 || n2 > 10) return std::to_chars(out, out + 64, v, std::chars_format::general, d).ptr;
    u128 num = static_cast<u128>(m) * p10[k10];  // < 2^53·2^64
    if (n2) {
      if (num >> (126 - n2)) return std::to_chars(out, out + 64, v, std::chars_format::general, d).ptr;
      num <<= n2;
    }
    u128 qq, r, half;
    bool exact_half;
    if (d10 == 0) {  // den = 2^s2: a shift
      if (s2 >= 127) return std::to_chars(out, out + 64, v, std::chars_format::general, d).ptr;
      if (s2 == 0) { qq = num; r = 0; half = 1; exact_half = false; }
      else {
        qq = num >> s2;
        r = num - (qq << s2);
        half = static_cast<u128>(1) << (s2 - 1);
        exact_half = r == half;
      }
      const bool up = r > half || (exact_half && (qq & 1));
      if (s2 != 0 && up) ++qq;
    } else {
      if (s2 > 60) return std::to_chars(out, out + 64, v, std::chars_format::general, d).ptr;
      const u128 den = static_cast<u128>(p10[d10]) << s2;  // < 2^64·2^60
      qq = num / den;
      r = num - qq * den;
      const u128 r2 = r << 1;
      if (r2 > den || (r2 == den && (qq & 1))) ++qq;
    }
    // Digit count: X too low gives ≥ 10^d before rounding, X too high < 10^(d−1).
    if (qq < p10[d - 1]) { --X; continue; }
    if (qq > p10[d]) { ++X; continue; }
    if (qq == p10[d]) {
      // Either X was one too low (the floor is already 10^d) or the rounding carried (9.99 -> 10.0):
      // both print 10^(d−1) at exponent X+1, as %g does.
      qq = p10[d - 1];
      ++X;
    }
    q = static_cast<std::uint64_t>(qq);
    break;
  }
  char dig[20];
  for (int i = d - 1; i >= 0; --i) { dig[i] = static_cast<char>('0' + q % 10); q /= 10; }
  int nd = d;
  while (nd > 1 && dig[nd - 1] == '0') --nd;  // %g drops trailing zeros
  return detail::layout_general(out, neg, dig, nd, X, d);
}

// Numbers: `digits()` significant digits (%g style: no trailing zeros, exponent when needed);
// radii of straight profiles are "inf" in CSV, null in JSON.
inline void num(std::string& s, double v) {
  const int d = digits();
  if (d <= 0) { append_number(s, v); return; }
  char buf[64];
  s.append(buf, general_digits(buf, v, d));
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
