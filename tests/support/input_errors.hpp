#pragma once
// What the input tests share: the message of the InputError a reader throws ("" when it reads),
// and a one-case copy of the shipped Manchester case file to vary key by key.
#include <string>

#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "input/case_file.hpp"
#include "profile/read.hpp"

namespace mh::testing {

/// [path] cases/manchester.json of the source tree: the base of the case-file tests.
inline std::string manchester_case_path() { return std::string(MHCONTACT_SOURCE_DIR) + "/cases/manchester.json"; }

/// cases/manchester.json reduced to one case (t_Y = 0 mm, Q = 100 kN): every other key as shipped.
inline nlohmann::json manchester_case_json() {
  nlohmann::json j = read_json_file(manchester_case_path());
  j.erase("cases");
  j["sweep"] = {{"tY_mm", {0}}, {"Q_kN", {100}}};
  return j;
}

/// The message of the InputError thrown by parsing `j` as if read from cases/manchester.json
/// ("" if it parses).
inline std::string case_error(const nlohmann::json& j) {
  try {
    parse_case_json(j, manchester_case_path(), true);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// The message of the InputError thrown by reading the profile file `path` ("" if it reads).
inline std::string profile_error(const std::string& path, const ProfileReadOptions& opt = {}) {
  try {
    read_profile(path, opt);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// Whether one of `warnings` contains `part`.
template <class Warnings>
bool has_warning(const Warnings& warnings, const std::string& part) {
  for (const auto& w : warnings)
    if (w.find(part) != std::string::npos) return true;
  return false;
}

}  // namespace mh::testing
