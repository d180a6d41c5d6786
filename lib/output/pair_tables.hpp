#pragma once
// What a run writes about its profile pair (geometry.json, caf.csv, profiles.csv and the
// "inputs" and "potential_ellipses" records of results.json).
#include <string>

#include <nlohmann/json.hpp>

#include "geometry/contact_geometry.hpp"
#include "profile/rail_cant.hpp"
#include "input/case_file.hpp"

namespace mh {

/// What was read of a profile, and how its curvature fit classified it (`curve` may be null).
nlohmann::json profile_json(const Profile& p, const ProfileCurve* curve);
/// {"class": "exact"|"measured", "forced", "median_residual_um", "print_step_mm", ...}
nlohmann::json noise_json(const NoiseDecision& d);
/// {"found", "angle_deg", "ratio", "std_error_deg", "residual_mm", "levels", "confident"[, "why"]}
nlohmann::json cant_json(const RailCant& c);
nlohmann::json ellipses_json(const ContactGeometry& G);
/// The case file's resolved inputs plus what was read of each profile.
/// The resolved inputs as a valid case file (defaults filled in, the sweep or case list, profile
/// paths relative to `base_dir`, or absolute when it is empty): `mhcontact run` on it reproduces
/// the run. The profiles as read (checksums, warnings) are in profiles_json().
nlohmann::json inputs_json(const CaseFile& cf, const std::string& base_dir = {});
/// {"wheel": profile_json(...), "rail": profile_json(...)}
nlohmann::json profiles_json(const PairGeometry& pg);
/// The profiles as used (rail with its inclination), canonical frame, mm: for plots.
void write_profiles_csv(const PairGeometry& pg, const std::string& path);
/// caf.csv: the contact angle function and the main strip per t_Y of the grid.
void write_caf_csv(const ContactGeometry& G, const std::string& path);

}  // namespace mh
