#pragma once
// One JSON record written straight into a string, byte for byte as nlohmann::ordered_json's
// compact dump() of the same values would write it (results.json's per-case records): the keys in
// the order written, doubles by nlohmann's own shortest form (detail::to_chars: "0.0", "1e-05";
// the tables' rounded values by their digits in that layout, table_number),
// integers in decimal, text escaped as dump() escapes it (nlohmann itself for any string that is
// not printable ASCII). A typed writer, so the record is valid JSON by construction; building
// the ordered_json tree and dumping it cost about ten times as much per case (docs/performance.md).
// Internal to lib/output. tests/unit/output/test_json_record.cpp compares it with dump().
#include <cmath>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "output/cells.hpp"

namespace mh {

class JsonRecord {
 public:
  explicit JsonRecord(std::string& out) : s_(out) {}

  void begin_object() { value_start(); s_ += '{'; first_ = true; }
  void end_object() { s_ += '}'; first_ = false; }
  void begin_array() { value_start(); s_ += '['; first_ = true; }
  void end_array() { s_ += ']'; first_ = false; }
  /// The next member's key (inside an object); its value follows. Keys are the code's own names
  /// (identifiers: nothing to escape), written with their separators in one append.
  void key(const char* k) {
    char buf[80];
    std::size_t n = 0;
    if (!first_) buf[n++] = ',';
    first_ = false;
    const std::size_t len = std::char_traits<char>::length(k);
    if (len + 4 > sizeof buf) {  // never for the tables' names; kept correct all the same
      s_.append(buf, n);
      string_body(k);
      s_ += ':';
    } else {
      buf[n++] = '"';
      std::char_traits<char>::copy(buf + n, k, len);
      n += len;
      buf[n++] = '"';
      buf[n++] = ':';
      s_.append(buf, n);
    }
    after_key_ = true;
  }

  /// A double as dump() writes a number_float (null when not finite).
  void number(double v) {
    value_start();
    if (!std::isfinite(v)) { s_ += "null"; return; }
    append_double(v);
  }
  /// A value of the tables, null when not finite: rounded to the tables' digits, its text those
  /// digits in dump()'s layout (cells::json_digits: the rounded value's shortest form, which
  /// dump() writes too but for about 1 number in 1,000); the rounded double dumped where that
  /// fast path does not apply (not normal, --digits max or above 15).
  void table_number(double v) {
    value_start();
    if (!std::isfinite(v)) { s_ += "null"; return; }
    const int d = cells::digits();
    char buf[64];
    if (d > 0)
      if (const char* e = cells::json_digits(buf, v, d)) {
        s_.append(buf, static_cast<std::size_t>(e - buf));
        return;
      }
    append_double(cells::rounded(v));
  }
  /// An integer (the case numbers and counts too: below 2^63, the same digits as dump() of an
  /// unsigned).
  void integer(long long i) { value_start(); append_number(s_, i); }
  void boolean(bool b) { value_start(); s_ += b ? "true" : "false"; }
  void null() { value_start(); s_ += "null"; }
  void string(std::string_view t) { value_start(); string_body(t); }

 private:
  std::string& s_;
  bool first_ = true;      // no member or element yet in the open object or array
  bool after_key_ = false;  // the value of a key comes next (no comma)

  void append_double(double v) {
    char buf[64];
    s_.append(buf, static_cast<std::size_t>(::nlohmann::detail::to_chars(buf, buf + sizeof buf, v) - buf));
  }
  void value_start() {
    if (after_key_) { after_key_ = false; return; }
    if (!first_) s_ += ',';
    first_ = false;
  }
  void string_body(std::string_view t) {
    bool plain = true;
    for (const char c : t) {
      const unsigned char u = static_cast<unsigned char>(c);
      if (u < 0x20 || u >= 0x7f) {  // control or non-ASCII: nlohmann's own escaping and checks
        s_ += nlohmann::json(std::string(t)).dump();
        return;
      }
      if (c == '"' || c == '\\') plain = false;
    }
    s_ += '"';
    if (plain) {
      s_.append(t.data(), t.size());
    } else {
      for (const char c : t) {
        if (c == '"' || c == '\\') s_ += '\\';
        s_ += c;
      }
    }
    s_ += '"';
  }
};

}  // namespace mh
