#pragma once
// The text of cases/manchester-halfspace.json for a test that writes its own case file: the
// profile paths made absolute (the file is written elsewhere), and everything from "sweep" to
// the end replaced by `tail` (the test's friction, kinematics or RCF keys and its sweep, closed).
#include <fstream>
#include <sstream>
#include <string>

namespace mh::test {

inline std::string manchester_halfspace_case(const std::string& tail) {
  const std::string src = MHCONTACT_SOURCE_DIR;
  std::ifstream in(src + "/cases/manchester-halfspace.json");
  std::stringstream text;
  text << in.rdbuf();
  std::string j = text.str();
  for (const char* prof : {"MBench_S1002_v3.prw", "MBench_UIC60_v3.prr"}) {
    const std::string rel = std::string("../profiles/") + prof;
    j.replace(j.find(rel), rel.size(), src + "/profiles/" + prof);
  }
  const std::size_t sweep = j.find("\"sweep\"");
  j.replace(sweep, j.size() - sweep, tail);
  return j;
}

}  // namespace mh::test
