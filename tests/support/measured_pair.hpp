#pragma once
// The measured pairs of tests/data/profiles/ as a one-case case file: a MiniProf or other
// measured wheel (nominal radius 460 mm) on a measured rail, E 210 GPa, ν 0.28.
#include <string>

#include <nlohmann/json.hpp>

#include "input/case_file.hpp"

namespace mh::testing {

/// A case file of `wheel` on `rail` (file names in tests/data/profiles/) with the rail at
/// `inclination` and one case (t_Y [mm], Q [kN]); `geometry` is merged into the file's
/// "geometry" object (e.g. {"smoothing_mm": 0} for the unsmoothed measured gap).
inline CaseFile measured_pair_case(const std::string& wheel, const std::string& rail, double tY_mm, double Q_kN,
                                   const nlohmann::json& geometry = nlohmann::json::object(),
                                   const std::string& inclination = "1:40") {
  const std::string data = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/profiles/";
  nlohmann::json j = {{"wheel", {{"profile", data + wheel}, {"nominal_radius_mm", 460}}},
                      {"rail", {{"profile", data + rail}, {"inclination", inclination}}},
                      {"material", {{"E_GPa", 210}, {"nu", 0.28}}},
                      {"sweep", {{"tY_mm", {tY_mm}}, {"Q_kN", {Q_kN}}}}};
  if (!geometry.empty()) j["geometry"] = geometry;
  return parse_case_json(j, data + "measured_pair.json", true);
}

}  // namespace mh::testing
