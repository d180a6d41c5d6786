#pragma once
// Typed readers of case-file fields (input/case_file.hpp): a number, a positive number, a number
// in its plausible range (core/plausible.hpp), a range-checked integer, a boolean, a string, and
// the allowed keys of an object. Each checks the JSON type and the rule and throws InputError
// naming the file, the JSON path (e.g. /material/E_GPa), the value and the rule, with a hint
// where one helps; unknown keys are errors. Field reference: docs/case-file.md.
//
// Internal to the case-file reader: namespace detail.
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "core/plausible.hpp"

namespace mh {
namespace detail {

// Validation context: file name + JSON path. `origins`: where top-level keys of the object read
// came from, when it was assembled from several places (a manifest pair's keys: "friction" ->
// "/pairs/3"); a path under such a key is named with that prefix.
struct Ctx {
  std::string file;
  std::map<std::string, std::string> origins;
  [[noreturn]] void fail(const std::string& path, const nlohmann::json* v, const std::string& rule,
                         const std::string& hint = {}) const {
    std::string at = path.empty() ? "/" : path;
    if (!origins.empty() && at.size() > 1) {
      const auto o = origins.find(at.substr(1, at.find('/', 1) - 1));
      if (o != origins.end()) at = o->second + at;
    }
    throw InputError(file + ": " + at, v ? v->dump() : std::string(), rule, hint);
  }
  void only_keys(const nlohmann::json& obj, const std::string& path, const std::set<std::string>& allowed) const {
    if (!obj.is_object()) fail(path, &obj, "must be an object");
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      if (!allowed.count(it.key())) {
        std::string list;
        for (const auto& k : allowed) list += (list.empty() ? "" : ", ") + k;
        fail(path + "/" + it.key(), nullptr, "unknown key", "allowed here: " + list);
      }
    }
  }
  double number(const nlohmann::json& obj, const std::string& path, const std::string& key) const {
    const nlohmann::json& v = obj.at(key);
    if (!v.is_number()) fail(path + "/" + key, &v, "must be a number");
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(path + "/" + key, &v, "must be finite");
    return d;
  }
  double positive(const nlohmann::json& obj, const std::string& path, const std::string& key) const {
    const double d = number(obj, path, key);
    if (!(d > 0)) fail(path + "/" + key, &obj.at(key), "must be > 0");
    return d;
  }
  /// A number inside its plausible range (core/plausible.hpp), refused with the unit hint.
  double plausible(const nlohmann::json& obj, const std::string& path, const std::string& key, const plausible::Range& r) const {
    const double d = number(obj, path, key);
    check(d, path + "/" + key, obj.at(key), r);
    return d;
  }
  void check(double d, const std::string& path, const nlohmann::json& v, const plausible::Range& r) const {
    if (!plausible::inside(r, d)) fail(path, &v, plausible::rule(r), plausible::hint(r, d));
  }
  /// An integer in [lo, hi], range-checked as an integer before any conversion (4294967297 must
  /// not wrap to 1, 1e3 or 2.5 are not integers).
  long long integer(const nlohmann::json& obj, const std::string& path, const std::string& key, long long lo, long long hi,
                    std::string rule = {}) const {
    const nlohmann::json& v = obj.at(key);
    if (rule.empty()) rule = "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (!v.is_number_integer()) fail(path + "/" + key, &v, rule);
    bool in_range;
    if (v.is_number_unsigned()) {
      const std::uint64_t u = v.get<std::uint64_t>();  // compared as unsigned first: no wrap
      in_range = hi >= 0 && u <= static_cast<std::uint64_t>(hi) && static_cast<long long>(u) >= lo;
    } else {
      const std::int64_t i = v.get<std::int64_t>();
      in_range = i >= lo && i <= hi;
    }
    if (!in_range) fail(path + "/" + key, &v, rule);
    return v.is_number_unsigned() ? static_cast<long long>(v.get<std::uint64_t>()) : static_cast<long long>(v.get<std::int64_t>());
  }
  bool boolean(const nlohmann::json& obj, const std::string& path, const std::string& key) const {
    const nlohmann::json& v = obj.at(key);
    if (!v.is_boolean()) fail(path + "/" + key, &v, "must be true or false");
    return v.get<bool>();
  }
  std::string string(const nlohmann::json& obj, const std::string& path, const std::string& key) const {
    const nlohmann::json& v = obj.at(key);
    if (!v.is_string()) fail(path + "/" + key, &v, "must be a string");
    return v.get<std::string>();
  }
};

}  // namespace detail
}  // namespace mh
