#pragma once
// Batch manifests: one sweep, material, model and method over many wheel–rail profile pairs (a fleet of
// measured wheels × rail sections). Geometry is built once per pair; a pair whose profiles
// cannot be read or placed is reported in its rows and the batch goes on.
//
//   {
//     "pairs": [{"name": "A", "wheel": PROFILE, "rail": PROFILE,          // explicit pairs, each
//                "friction": {...}, "rcf": {...}, ...}, ...],             //   with its own physics keys, or
//     "wheels": [PROFILE or "glob/*.whl", ...], "rails": [...],          // every wheel × every rail
//     "inclination": "as-is" | "none" | "1:40" | "1:20",                 // required, for all rails
//     "nominal_radius_mm": 460, "track": {...}, "geometry": {...}, "material": {...},
//     "model": "elastic", "method": "multi-hertzian" | "strips" | "half-space" | "auto",
//     "half_space": {...}, "strips": {...},                              // the method's options
//     "friction": {...}, "kinematics" | "creepages": {...}, "fastsim": {...}, "rcf": {...},  // for every pair
//     "sweep": {...} | "cases": [...], "solver": {...}, "comment": "..."
//   }
// PROFILE is what a case file accepts under wheel.profile / rail.profile; a string with * ? or [
// is a glob, relative to the manifest, expanded in sorted order (no match is an error). A pair's
// friction, kinematics, creepages, fastsim or rcf replaces the manifest's key of that name for
// that pair (the case-file rules, errors at /pairs/K/...); the keys that decide the tables'
// columns (friction, rcf, rcf.subsurface) are given for every pair or for none.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "input/case_file.hpp"

namespace mh {

struct ManifestPair {
  std::string name;              ///< given, or "WHEEL on RAIL" from the file names
  nlohmann::json wheel, rail;    ///< profile specifications (case-file form)
  /// The pair's own friction, kinematics, creepages, fastsim, rcf (case-file form; an empty
  /// object: none): each replaces the manifest's key of the same name for this pair.
  nlohmann::json keys = nlohmann::json::object();
};

struct Manifest {
  std::string path;
  std::vector<ManifestPair> pairs;
  nlohmann::json common;         ///< the shared case-file fields
};

/// True if the JSON is a manifest (has "pairs" or "wheels"/"rails") rather than a case file.
bool is_manifest(const nlohmann::json& j);

/// Parse and validate a manifest; the shared fields are validated once through the case-file
/// rules (errors name the manifest and the JSON path). Throws InputError.
Manifest parse_manifest(const nlohmann::json& j, const std::string& path);

/// The case file of pair k (profiles are not read here). Throws InputError for a malformed pair.
CaseFile pair_case(const Manifest& m, std::size_t k);

}  // namespace mh
