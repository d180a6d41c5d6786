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
/// "00".."99".
inline constexpr char kDigitPairs[201] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";
/// v < 10^8 as exactly 8 digits (leading zeros) at p.
inline void write8(char* p, std::uint32_t v) {
  const std::uint32_t a = v / 10000, b = v % 10000;
  std::memcpy(p, kDigitPairs + 2 * (a / 100), 2);
  std::memcpy(p + 2, kDigitPairs + 2 * (a % 100), 2);
  std::memcpy(p + 4, kDigitPairs + 2 * (b / 100), 2);
  std::memcpy(p + 6, kDigitPairs + 2 * (b % 100), 2);
}
// %g layout of the significant digits dig[0..nd) (no trailing zeros) with decimal exponent X.
// dig[0..16) must be readable (digits copied 16 bytes at a time, a constant size the compiler
// turns into two moves, the pointer then advanced by the digits written); `o` has room for 40.
inline char* layout_general(char* o, bool neg, const char* dig, int nd, int X, int d) {
  if (neg) *o++ = '-';
  if (X < d && X >= -4) {  // fixed notation
    if (X < 0) {  // "0." and −X − 1 zeros (at most 3), then the digits
      std::memcpy(o, "0.000", 5);
      o += 1 - X;
      std::memcpy(o, dig, 16);
      return o + nd;
    }
    // X < d: the integer part's X + 1 characters are digits of dig (the trailing zeros dropped
    // from nd are '0' there).
    std::memcpy(o, dig, 16);
    o += X + 1;
    if (nd > X + 1) {
      *o++ = '.';
      std::memcpy(o, dig + X + 1, 16);
      o += nd - X - 1;
    }
    return o;
  }
  *o++ = dig[0];  // scientific, exponent with at least two digits
  if (nd > 1) {
    *o++ = '.';
    std::memcpy(o, dig + 1, 16);
    o += nd - 1;
  }
  *o++ = 'e';
  *o++ = X < 0 ? '-' : '+';
  const int ax = X < 0 ? -X : X;
  if (ax >= 100) *o++ = static_cast<char>('0' + ax / 100);
  *o++ = static_cast<char>('0' + ax / 10 % 10);
  *o++ = static_cast<char>('0' + ax % 10);
  return o;
}

/// The d (1..15) significant digits of normal v, rounded half-even as std::to_chars(general, d)
/// rounds them: with v = m·2^e, q = |v|·10^(d−1−X) rounded, computed exactly in 128-bit integers
/// (a shift when the scale is a power of 10 ≥ 1, else one division). The digits are written
/// right-aligned in buf[0..16) (buf: 32 chars, zero; 16 readable bytes from the first digit for
/// the layouts); returns the first digit, nd the digits without trailing zeros and X the decimal
/// exponent of the first; nullptr where the 128 bits do not hold it (then std::to_chars).
inline const char* round_digits(double v, int d, char (&buf16)[32], int& nd, int& X) {
  __extension__ typedef unsigned __int128 u128;  // GCC and Clang
  static constexpr std::uint64_t p10[20] = {1ull, 10ull, 100ull, 1000ull, 10000ull, 100000ull, 1000000ull,
      10000000ull, 100000000ull, 1000000000ull, 10000000000ull, 100000000000ull, 1000000000000ull,
      10000000000000ull, 100000000000000ull, 1000000000000000ull, 10000000000000000ull,
      100000000000000000ull, 1000000000000000000ull, 10000000000000000000ull};
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  const std::uint64_t m = (bits & ((1ull << 52) - 1)) | (1ull << 52);
  const int e = static_cast<int>((bits >> 52) & 0x7ff) - 1075;  // |v| = m·2^e exactly (v normal)
  // floor(log10 2^(e+52)) = floor((e+52)·log10 2), maybe 1 below log10|v|.
  const int e2m1 = e + 52;
  X = e2m1 >= 0 ? (e2m1 * 78913) >> 18 : -((-e2m1 * 78913 + (1 << 18) - 1) >> 18);
  // q = |v|·10^k rounded half-even, k = d − 1 − X; num/den = |v|·10^k exactly with
  // num = m·10^max(k,0)·2^max(e,0), den = 10^max(−k,0)·2^max(−e,0).
  const int k = d - 1 - X;
  const int k10 = k > 0 ? k : 0, d10 = k < 0 ? -k : 0;
  const int s2 = e < 0 ? -e : 0, n2 = e > 0 ? e : 0;
  if (k10 > 19 || d10 > 19 || n2 > 10) return nullptr;
  u128 num = static_cast<u128>(m) * p10[k10];  // < 2^53·2^64
  if (n2) {
    if (num >> (126 - n2)) return nullptr;
    num <<= n2;
  }
  // The floor qf and where the remainder lies against half a unit: cmp < 0 below, 0 exactly
  // half, > 0 above; sticky: the remainder is not zero.
  u128 qf;
  int cmp;
  bool sticky;
  if (d10 == 0) {  // den = 2^s2: a shift
    if (s2 >= 127) return nullptr;
    if (s2 == 0) { qf = num; cmp = -1; sticky = false; }
    else {
      qf = num >> s2;
      const u128 r = num - (qf << s2), half = static_cast<u128>(1) << (s2 - 1);
      cmp = r > half ? 1 : r == half ? 0 : -1;
      sticky = r != 0;
    }
  } else {
    if (s2 > 60) return nullptr;
    const u128 den = static_cast<u128>(p10[d10]) << s2;  // < 2^64·2^60
    qf = num / den;
    const u128 r2 = (num - qf * den) << 1;
    cmp = r2 > den ? 1 : r2 == den ? 0 : -1;
    sticky = r2 != 0;
  }
  std::uint64_t q;
  if (qf >= p10[d]) {
    // X was one too low (its estimate is floor(log10 2^(e+52)) ≤ log10|v|): one digit more than
    // wanted; drop it, rounding half-even on the dropped digit and the remainder below it.
    ++X;
    // qf < 10^(d+1) ≤ 10^16: 64-bit division by a constant (a multiplication), not 128-bit.
    const std::uint64_t qf64 = static_cast<std::uint64_t>(qf);
    const std::uint64_t q1 = qf64 / 10, last = qf64 % 10;
    q = q1 + ((last > 5 || (last == 5 && (sticky || (q1 & 1)))) ? 1 : 0);
  } else {
    if (qf < p10[d - 1]) return nullptr;  // never: X is never too high
    q = static_cast<std::uint64_t>(qf) + ((cmp > 0 || (cmp == 0 && (qf & 1))) ? 1 : 0);
  }
  if (q == p10[d]) {  // the rounding carried (9.99 -> 10.0): 10^(d−1) at exponent X+1, as %g
    q = p10[d - 1];
    ++X;
  }
  // The d digits of q (< 10^15) right-aligned in 16, written two at a time: q = hi·10^8 + lo
  // (hi < 100 for d ≤ 10, the tables' default); 16 more readable bytes for layout_general.
  const std::uint32_t hi = static_cast<std::uint32_t>(q / 100000000u), lo = static_cast<std::uint32_t>(q % 100000000u);
  if (d <= 10) std::memcpy(buf16 + 6, kDigitPairs + 2 * hi, 2);
  else write8(buf16, hi);
  write8(buf16 + 8, lo);
  const char* dig = buf16 + 16 - d;
  nd = d;
  while (nd > 1 && dig[nd - 1] == '0') --nd;  // trailing zeros dropped (%g and the shortest form)
  return dig;
}

/// nlohmann::json's layout of a number (detail::format_buffer of its dump(): fixed notation for
/// decimal point positions −4 < n ≤ 15, "x.0" for an integer, else d.ddd, 'e', sign and at least
/// two exponent digits) for the significant digits dig[0..nd) with decimal exponent X (n = X + 1).
inline char* layout_json(char* o, bool neg, const char* dig, int nd, int X) {
  if (neg) *o++ = '-';
  const int n = X + 1;
  if (nd <= n && n <= 15) {  // digits, zeros, ".0"
    std::memcpy(o, dig, static_cast<std::size_t>(nd));
    std::memset(o + nd, '0', static_cast<std::size_t>(n - nd));
    o += n;
    *o++ = '.';
    *o++ = '0';
    return o;
  }
  if (0 < n && n <= 15) {  // dig.its
    std::memcpy(o, dig, static_cast<std::size_t>(n));
    o[n] = '.';
    std::memcpy(o + n + 1, dig + n, static_cast<std::size_t>(nd - n));
    return o + nd + 1;
  }
  if (-4 < n && n <= 0) {  // 0.[000]digits
    *o++ = '0';
    *o++ = '.';
    std::memset(o, '0', static_cast<std::size_t>(-n));
    o += -n;
    std::memcpy(o, dig, static_cast<std::size_t>(nd));
    return o + nd;
  }
  *o++ = dig[0];  // d[.igits]e±XX
  if (nd > 1) {
    *o++ = '.';
    std::memcpy(o, dig + 1, static_cast<std::size_t>(nd - 1));
    o += nd - 1;
  }
  *o++ = 'e';
  int e = n - 1;
  *o++ = e < 0 ? '-' : '+';
  if (e < 0) e = -e;
  if (e >= 100) *o++ = static_cast<char>('0' + e / 100);
  *o++ = static_cast<char>('0' + e / 10 % 10);
  *o++ = static_cast<char>('0' + e % 10);
  return o;
}
}  // namespace detail

/// `v` with `d` (1..17) significant digits, byte for byte as std::to_chars(general, d), i.e.
/// printf("%.*g"), into `out` (64 chars at least); returns the end. The exact fast path
/// (detail::round_digits) for d ≤ 15 and normal v, std::to_chars otherwise.
/// tests/unit/output/test_cells.cpp compares both on millions of values.
inline char* general_digits(char* out, double v, int d) {
  if (d <= 15 && std::isnormal(v)) {
    char buf16[32] = {};
    int nd = 0, X = 0;
    if (const char* dig = detail::round_digits(v, d, buf16, nd, X)) return detail::layout_general(out, v < 0, dig, nd, X, d);
  }
  return std::to_chars(out, out + 64, v, std::chars_format::general, d).ptr;
}

/// `v` rounded to `d` (1..15) significant digits in JSON, as nlohmann's dump() lays a number out,
/// with those digits (trailing zeros dropped): the shortest text of the rounded value, since no
/// other decimal of at most 15 digits reads back to the same normal double. The digits by
/// detail::round_digits, or where its 128 bits do not hold them (below about 1e-10, from 2^63)
/// by std::to_chars' scientific form, the same rounding. Into `out` (64 chars); the end, or
/// nullptr for d > 15 and v zero, subnormal or not finite (the caller then dumps the rounded
/// double). nlohmann's own shortest form (Grisu2) writes the same text but for about 1 number in
/// 100 to 1,000, where it writes 16–17 digits of the same double (10.561527420000001 for
/// 10.56152742): results.json, docs/outputs.md.
inline char* json_digits(char* out, double v, int d) {
  if (d < 1 || d > 15 || !std::isnormal(v)) return nullptr;
  char buf16[32] = {};
  int nd = 0, X = 0;
  const char* dig = detail::round_digits(v, d, buf16, nd, X);
  if (!dig) {  // d.ddd…e±XX: its digits and exponent
    char sci[48];
    const char* end = std::to_chars(sci, sci + sizeof sci, std::fabs(v), std::chars_format::scientific, d - 1).ptr;
    const char* p = sci;
    int k = 0;
    buf16[k++] = *p++;
    if (*p == '.')
      for (++p; p < end && *p != 'e'; ++p) buf16[k++] = *p;
    if (p == end || *p != 'e') return nullptr;
    ++p;
    if (*p == '+') ++p;
    if (std::from_chars(p, end, X).ec != std::errc()) return nullptr;
    nd = k;
    while (nd > 1 && buf16[nd - 1] == '0') --nd;
    dig = buf16;
  }
  return detail::layout_json(out, v < 0, dig, nd, X);
}

// Numbers: `digits()` significant digits (%g style: no trailing zeros, exponent when needed);
// radii of straight profiles are "inf" in CSV, null in JSON.
inline void num(std::string& s, double v) {
  const int d = digits();
  if (d <= 0) { append_number(s, v); return; }
  char buf[64];
  // (pointer, length): the iterator-range append goes through basic_string::_M_replace.
  s.append(buf, static_cast<std::size_t>(general_digits(buf, v, d) - buf));
}
/// ',' then num(s, v), one append (a table's separators are most of its calls into the string).
inline void cnum(std::string& s, double v) {
  const int d = digits();
  if (d <= 0) { s += ','; append_number(s, v); return; }
  char buf[65];
  buf[0] = ',';
  s.append(buf, static_cast<std::size_t>(general_digits(buf + 1, v, d) - buf));
}
/// num() for values that repeat over consecutive rows (a sweep's t_Y and Q, an ellipse's geometry,
/// the same for every load at one t_Y): a small per-thread cache of the formatted text, keyed by
/// the bits of v and the digits, so the bytes are exactly num()'s.
inline void num_repeated(std::string& s, double v) {
  struct Entry { std::uint64_t bits; int d1; unsigned len; char text[40]; };  // d1 = digits + 1, 0: empty
  static thread_local Entry cache[1024];
  const int d = digits();
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  Entry& e = cache[(bits * 0x9E3779B97F4A7C15ull) >> 54];
  if (e.d1 == d + 1 && e.bits == bits) { s.append(e.text, e.len); return; }
  const std::size_t at = s.size();
  num(s, v);
  const std::size_t len = s.size() - at;
  if (len <= sizeof e.text) {
    e.bits = bits;
    e.d1 = d + 1;
    e.len = static_cast<unsigned>(len);
    std::memcpy(e.text, s.data() + at, len);
  }
}
/// `v` rounded to `digits()` significant digits (for JSON, where the library prints the double).
inline double rounded(double v) {
  const int d = digits();
  if (d <= 0 || !std::isfinite(v)) return v;
  char buf[64];
  const char* e = general_digits(buf, v, d);  // the text of to_chars(general, d), faster
  double x = v;
  std::from_chars(buf, e, x);
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
  // One pass over the characters (find_first_of calls memchr on the set once per character: on
  // the warnings and message cells of a sweep's row, 1,400 instructions of a case's 32,000).
  bool plain = true;
  for (const char c : t)
    if (c == ',' || c == '"' || c == '\n') {
      plain = false;
      break;
    }
  if (plain) { s += t; return; }
  s += '"';
  std::size_t from = 0;
  for (std::size_t q; (q = t.find('"', from)) != std::string::npos; from = q + 1) {
    s.append(t, from, q + 1 - from);  // up to and including the quote, then the quote again
    s += '"';
  }
  s.append(t, from, std::string::npos);
  s += '"';
}

inline std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (const auto& x : v) { if (!s.empty()) s += sep; s += x; }
  return s;
}


}  // namespace mh::cells
