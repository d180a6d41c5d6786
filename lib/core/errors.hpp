#pragma once
// Error channels (style.md habit 6):
//  - assertions for bugs;
//  - InputError for bad input: carries where (file and line, or JSON path), the offending value,
//    the rule it breaks and, where possible, the fix;
//  - a per-case status in solver results (never an exception).
#include <stdexcept>
#include <string>

namespace mh {

/// Documented process exit codes (README "Errors and exit codes").
enum ExitCode : int {
  kExitOk = 0,           ///< everything computed, every case ok
  kExitCasesFailed = 1,  ///< outputs written, but some cases did not end `ok` (or `diff` found deviations)
  kExitInputError = 2,   ///< invalid input: file, JSON, option values; nothing written
  kExitInternal = 3,     ///< an unexpected internal error (a bug): please report
  kExitOutput = 4,       ///< output could not be written (disk full, closed pipe, /dev/full, rename failed)
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
    std::string s = where;
    if (!value.empty()) s += ": value " + value;
    s += ": " + rule;
    if (!hint.empty()) s += " (" + hint + ")";
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
