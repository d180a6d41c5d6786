#pragma once
// Writing a profile file (`profile convert`, `profile generate`).
#include <string>

#include "profile/profile.hpp"

namespace mh {

/// Write a profile; the format follows the extension (profile/write.hpp: csv, txt, dat, prr/prw,
/// ban/whl, rail/wheel, rai/whe), the kind is kept (a wheel is refused for a rail extension and the
/// reverse, naming the right one). Atomic (OutputFile). Throws InputError on an unknown
/// extension, a kind that the extension cannot hold, or an unwritable path.
void write_profile(const Profile& p, const std::string& path);

}  // namespace mh
