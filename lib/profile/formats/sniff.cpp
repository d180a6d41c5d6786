#include "profile/formats/formats.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/numfmt.hpp"

namespace mh::formats {

ProfileFormat sniff(const std::vector<std::string>& lines) {
  for (const auto& raw : lines) {
    const std::string l = trim(raw);
    if (l.empty()) continue;
    if (l.rfind("MINIPROF", 0) == 0 || l.rfind("#MINI", 0) == 0) return ProfileFormat::MiniProf;
    if (l.rfind("WHEELPROFILE", 0) == 0 || l.rfind("RAILPROFILE", 0) == 0) return ProfileFormat::Vampire;
    break;
  }
  for (const auto& raw : lines) {
    if (raw.find("point.begin") != std::string::npos || raw.find("header.begin") != std::string::npos)
      return ProfileFormat::Simpack;
    if (raw.find("ColumnDef=") != std::string::npos || raw.find("XYPoints=") != std::string::npos ||
        raw.rfind("MPDC=", 0) == 0 || raw.rfind("MPD1=", 0) == 0 || raw.find("(Sd/Sh/qR)") != std::string::npos)
      return ProfileFormat::MiniProf;
  }
  return ProfileFormat::Table;
}

}  // namespace mh::formats
