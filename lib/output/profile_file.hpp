#pragma once
// Writing a profile file (`profile convert`, `profile generate`).
#include <string>

#include "profile/profile.hpp"

namespace mh {

/// Write a profile; the format follows the extension: ".csv" canonical table (header "y_mm,z_mm",
/// y to the field side, z up, mm), ".prr"/".prw" SIMPACK (type from the extension, z down as
/// SIMPACK expects, no transformations). Atomic (OutputFile). Throws InputError on an unknown
/// extension or an unwritable path.
void write_profile(const Profile& p, const std::string& path);

}  // namespace mh
