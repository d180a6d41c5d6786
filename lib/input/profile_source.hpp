#pragma once
// Where a profile comes from, as the case file gives it (docs/case-file.md):
// a file name, {"file": ...} with reading options (paths relative to the case file), or
// {"standard": ...}; and reading or generating it with the rail inclination applied once
// (load_profile, declared in input/case_file.hpp).
//
// Internal to the case-file reader: namespace detail.
#include <string>

#include <nlohmann/json.hpp>

#include "input/case_file.hpp"
#include "input/json_fields.hpp"

namespace mh {
namespace detail {

/// The profile entry `v` at JSON path `path` of the case file `case_path` (which anchors
/// relative file names). Throws InputError.
ProfileSource parse_profile_source(const Ctx& c, const nlohmann::json& v, const std::string& path, const std::string& case_path);

}  // namespace detail
}  // namespace mh
