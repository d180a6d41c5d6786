// all_contacts_off_profile (jobs/off_profile.hpp): a table of constructed results, as the
// multi-Hertzian solver (LoadedEllipse::g.off_profile) and the grid methods (the warning
// "off_profile:patch=<k>", contact/solve.cpp) mark them.
#include <catch2/catch.hpp>

#include "jobs/off_profile.hpp"

using namespace mh;

namespace {
CaseResult ellipses(std::initializer_list<bool> off) {
  CaseResult r;
  int k = 0;
  for (bool o : off) {
    LoadedEllipse e;
    e.ellipse = ++k;
    e.g.off_profile = o;
    r.loaded.push_back(e);
  }
  return r;
}
CaseResult patches(int n, std::initializer_list<int> off) {
  CaseResult r;
  r.method = Method::HalfSpace;
  for (int k = 1; k <= n; ++k) {
    PatchResult p;
    p.patch = k;
    r.patches.push_back(p);
  }
  r.warnings.push_back("non_hertzian_excluded:ellipse=1");
  for (int k : off) r.warnings.push_back("off_profile:patch=" + std::to_string(k));
  return r;
}
}  // namespace

TEST_CASE("all_contacts_off_profile: every contact, not some", "[off_profile]") {
  struct Row { const char* what; CaseResult r; bool expect; };
  const Row rows[] = {
      {"no contact", CaseResult{}, false},
      {"one ellipse on the profile", ellipses({false}), false},
      {"one ellipse off", ellipses({true}), true},
      {"two ellipses, one off", ellipses({true, false}), false},
      {"two ellipses, both off", ellipses({true, true}), true},
      {"one patch off", patches(1, {1}), true},
      {"two patches, the second off", patches(2, {2}), false},
      {"two patches, both off", patches(2, {2, 1}), true},
      {"a patch, a warning for another patch", patches(1, {2}), false},
  };
  for (const Row& row : rows) {
    CAPTURE(row.what);
    CHECK(all_contacts_off_profile(row.r) == row.expect);
  }
}
