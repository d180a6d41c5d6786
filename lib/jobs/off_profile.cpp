#include "jobs/off_profile.hpp"

#include <algorithm>
#include <string>

namespace mh {

bool all_contacts_off_profile(const CaseResult& r) {
  if (!r.loaded.empty())
    return std::all_of(r.loaded.begin(), r.loaded.end(), [](const LoadedEllipse& e) { return e.g.off_profile; });
  if (!r.patches.empty())
    return std::all_of(r.patches.begin(), r.patches.end(), [&r](const PatchResult& p) {
      const std::string w = "off_profile:patch=" + std::to_string(p.patch);
      return std::find(r.warnings.begin(), r.warnings.end(), w) != r.warnings.end();
    });
  return false;
}

}  // namespace mh
