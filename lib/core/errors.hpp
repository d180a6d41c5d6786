#pragma once
// Error channels:
//  - assertions for bugs;
//  - InputError for bad input: carries where (file and line, or JSON path), the offending value,
//    the rule it breaks and, where possible, the fix;
//  - a per-case status in solver results (never an exception).
#include <stdexcept>
#include <string>

namespace mh {

/// Documented process exit codes (docs/cli.md "Exit codes").
enum ExitCode : int {
  kExitOk = 0,           ///< everything computed, every case ok
  kExitCasesFailed = 1,  ///< outputs written, but some cases did not end `ok` (or `diff` found deviations)
  kExitInputError = 2,   ///< invalid input: file, JSON, option values; nothing written
  kExitInternal = 3,     ///< an unexpected internal error (a bug): please report
  kExitOutput = 4,       ///< output could not be written (disk full, closed pipe, /dev/full, rename failed)
  kExitMorePoints = 5,   ///< `table --merge ... --next FILE`: the refinement needs more points, written to FILE
  // CLI11's own codes (e.g. 105 for a parse error, 106 for a validation error) are passed through.
};

/// Bad input. `where` is "file:line", "file" or "case.json: /json/path".
class InputError : public std::runtime_error {
 public:
  InputError(std::string where, std::string value, std::string rule, std::string hint = {})
      : std::runtime_error(format(where, value, rule, hint)),
        where_(std::move(where)), value_(std::move(value)), rule_(std::move(rule)),
        hint_(std::move(hint)) {}

  const std::string& where() const { return where_; }
  const std::string& value() const { return value_; }
  const std::string& rule() const { return rule_; }
  const std::string& hint() const { return hint_; }

  static std::string format(const std::string& where, const std::string& value,
                            const std::string& rule, const std::string& hint) {
    std::string s = printable(where);
    if (!value.empty()) s += ": value " + printable(value);
    s += ": " + printable(rule);
    if (!hint.empty()) s += " (" + printable(hint) + ")";
    return s;
  }

  /// Control bytes (NUL, ESC, ...) as \xNN: a message quoting a line of a binary file must not be
  /// cut at its first NUL byte (the rule and the fix come after the value). UTF-8 is kept.
  static std::string printable(const std::string& in) {
    static const char* hex = "0123456789abcdef";
    std::string s;
    s.reserve(in.size());
    for (char ch : in) {
      const auto c = static_cast<unsigned char>(ch);
      if (c < 0x20 && c != '\t' && c != '\n') {
        s += "\\x";
        s += hex[c >> 4];
        s += hex[c & 15];
      } else if (c == 0x7f) {
        s += "\\x7f";
      } else {
        s += ch;
      }
    }
    return s;
  }

 private:
  std::string where_, value_, rule_, hint_;
};

/// "file:line" for messages.
inline std::string at_line(const std::string& file, std::size_t line) {
  return file + ":" + std::to_string(line);
}

}  // namespace mh
