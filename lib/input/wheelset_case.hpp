#pragma once
// The wheelset case file and the wheelset fleet manifest (docs/wheelset.md "Case file"), JSON.
// Every error names the file, the JSON path, the value and the rule; unknown keys are errors.
//
//   {
//     "wheel": {"profile": PROFILE}  |  {"left": PROFILE, "right": PROFILE},
//     "wheels": [PROFILE or "glob/*.whl", ...],           // a fleet instead of "wheel"
//     "rail": {"profile": PROFILE | "left": PROFILE, "right": PROFILE,
//              "inclination": "as-is" | "none" | "1:40" | ...,     // required
//              "placement": "gauge" (default) | "absolute",
//              "gauge_mm": 1435, "gauge_height_mm": 14,            // gauge placement
//              "origin_mm": 750 | {"left": 750, "right": 750}},    // absolute: |Y| of the rail origins
//     "wheelset": {"flange_back_distance_mm": 1360, "flange_back_position_mm": -70,
//                  "nominal_radius_mm": 460 | {"left": 460, "right": 459},
//                  "roll": "none" (default) | "solved"},
//     "y_mm": {"from": -8, "to": 8, "step": 0.01},                 // default as shown
//     "amplitudes_mm": [1, 2, 3] | {"from": 1, "to": 7.4, "step": 0.2},  // default as shown
//     "comment": "..."
//   }
// PROFILE is what a contact case file accepts (a file name relative to this file, {"file": ...}
// with reading options, or {"standard": ...}). One profile for both sides is mirrored (each
// profile is in its canonical frame, field side positive). A fleet's globs expand in sorted order.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/wheelset.hpp"
#include "input/case_file.hpp"

namespace mh {

struct WheelsetCase {
  std::string path;
  ProfileSource wheel_left, wheel_right;  ///< single pair (same source twice: mirrored)
  bool one_wheel = true;
  std::vector<ProfileSource> fleet;       ///< fleet: one wheel profile per entry (both sides)
  bool is_fleet = false;
  ProfileSource rail_left, rail_right;
  bool one_rail = true;
  Inclination inclination = Inclination::AsIs;
  WheelsetPlacement placement;
  WheelsetOptions options;
  std::vector<double> y;                  ///< [m] the sweep, increasing
  std::vector<double> y_mm;               ///< as given (written back verbatim)
  std::vector<double> amplitudes;         ///< [m]
  std::vector<double> amplitudes_mm;      ///< as given
  nlohmann::json resolved_json() const;
};

/// Parse and validate a wheelset case file or fleet manifest. Throws InputError.
WheelsetCase load_wheelset_case(const std::string& path);
WheelsetCase parse_wheelset_json(const nlohmann::json& j, const std::string& path);

}  // namespace mh
