// The tangential keys of the case file (docs/case-file.md, docs/tangential.md): friction,
// kinematics | creepages, fastsim; read, resolved, and refused with their JSON path.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "input/case_file.hpp"

using namespace mh;
using nlohmann::json;

namespace {
std::string path() { return std::string(MHCONTACT_SOURCE_DIR) + "/cases/manchester.json"; }
void refused(const json& j, const std::string& where) {
  CAPTURE(j.dump());
  try {
    parse_case_json(j, path(), true);
    FAIL("accepted");
  } catch (const InputError& e) {
    CHECK_THAT(e.where(), Catch::Contains(where));
  }
}
}  // namespace

TEST_CASE("tangential keys: read and resolved", "[input][tangential]") {
  json j = read_json_file(path());
  CHECK_FALSE(parse_case_json(j, path(), true).tangential.enabled());
  CHECK_FALSE(parse_case_json(j, path(), true).resolved_json().contains("friction"));
  j["friction"] = {{"coefficient", 0.3}};
  j["kinematics"] = {{"speed_m_s", 30}, {"yaw_mrad_per_mm", 2.4}, {"yaw_rate_rad_s", 0.01}};
  const CaseFile cf = parse_case_json(j, path(), true);
  CHECK(cf.tangential.mu == 0.3);
  CHECK(cf.tangential.kin.V == 30);
  CHECK(cf.tangential.yaw_per_tY == 2.4);  // mrad/mm = rad/m
  CHECK(std::isnan(cf.tangential.kin.pitch_rate));
  CHECK(cf.tangential.l_origin == Approx(0.75));
  CHECK(cf.method_options().tangential.enabled());
  const json rj = cf.resolved_json();
  CHECK(rj["kinematics"]["pitch_rate_rad_s"] == "nominal");
  // The resolved inputs read back to the same options.
  json back = j;
  back["kinematics"] = rj["kinematics"];
  back["fastsim"] = rj["fastsim"];
  const CaseFile cf2 = parse_case_json(back, path(), true);
  CHECK(cf2.tangential.yaw_per_tY == 2.4);
  CHECK(cf2.tangential.fastsim.nx == cf.tangential.fastsim.nx);
  j.erase("kinematics");
  j["creepages"] = {{"xi", 1e-3}, {"eta", -2e-3}, {"phi_per_mm", 0.5e-3}};
  const CaseFile cc = parse_case_json(j, path(), true);
  CHECK(cc.tangential.source == TangentialOptions::Source::Creepages);
  CHECK(cc.tangential.creep.phi == Approx(0.5));  // 1/m
}

TEST_CASE("tangential keys: refused with their JSON path", "[input][tangential]") {
  const json base = read_json_file(path());
  json j = base;
  j["kinematics"] = {{"speed_m_s", 30}};
  refused(j, "/kinematics");  // no friction
  j = base;
  j["friction"] = {{"coefficient", 0.3}};
  refused(j, "/friction");  // neither kinematics nor creepages
  j["kinematics"] = {{"speed_m_s", 30}};
  j["creepages"] = {{"xi", 0}};
  refused(j, "/creepages");  // both
  j.erase("creepages");
  j["friction"]["coefficient"] = 1.5;
  refused(j, "/friction/coefficient");
  j["friction"]["coefficient"] = 0.3;
  j["kinematics"] = {{"speed_m_s", 108}, {"yaw_mrad", 1}, {"yaw_mrad_per_mm", 1}};
  refused(j, "/kinematics/yaw_mrad_per_mm");
  j["kinematics"] = {{"speed_m_s", 300}};
  refused(j, "/kinematics/speed_m_s");
  j["kinematics"] = {{"yaw_mrad", 1}};
  refused(j, "/kinematics/speed_m_s");
  j["kinematics"] = {{"speed_m_s", 30}, {"pitch_rate_rad_s", 30}};
  refused(j, "/kinematics/pitch_rate_rad_s");
  j["kinematics"] = {{"speed_m_s", 30}, {"yaw", 1}};
  refused(j, "/kinematics");
  j.erase("kinematics");
  j["creepages"] = {{"xi", 5}};
  refused(j, "/creepages/xi");
  j["creepages"] = {{"phi_per_mm", 5}};
  refused(j, "/creepages/phi_per_mm");
  j["creepages"] = {{"xi", 0}};
  j["fastsim"] = {{"bound", "square"}};
  refused(j, "/fastsim/bound");
  j["fastsim"] = {{"nx", 100000}};
  refused(j, "/fastsim/nx");
}
