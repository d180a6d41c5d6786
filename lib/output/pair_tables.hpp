#pragma once
// What a run writes about its profile pair (geometry.json, caf.csv, profiles.csv and the
// "inputs" and "potential_ellipses" records of results.json).
#include <string>

#include <nlohmann/json.hpp>

#include "geometry/contact_geometry.hpp"
#include "input/case_file.hpp"

namespace mh {

nlohmann::json profile_json(const Profile& p, double window);
nlohmann::json ellipses_json(const ContactGeometry& G);
/// The case file's resolved inputs plus what was read of each profile.
nlohmann::json inputs_json(const CaseFile& cf, const PairGeometry& pg);
/// The profiles as used (rail with its inclination), canonical frame, mm: for plots.
void write_profiles_csv(const PairGeometry& pg, const std::string& path);
/// caf.csv: the contact angle function and the main strip per t_Y of the grid.
void write_caf_csv(const ContactGeometry& G, const std::string& path);

}  // namespace mh
