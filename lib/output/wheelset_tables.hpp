#pragma once
// The tables of `mhcontact wheelset` (docs/wheelset.md "Outputs"): DIR/wheelset.csv (one row per
// lateral displacement y), DIR/conicity.csv (one row per amplitude), DIR/fleet.csv (one row per
// wheel of a fleet). Numbers with cells::num (the run's --digits); lengths in mm, angles in
// degrees, as the column names say.
#include <string>
#include <vector>

#include "geometry/conicity.hpp"
#include "geometry/wheelset.hpp"

namespace mh {

/// Schema of DIR/summary.json.
constexpr const char* kWheelsetSchema = "mhcontact.wheelset/1";

/// "ok", "off_profile" (a contact at the end of a profile: not a real contact), "no_contact" (a
/// wheel does not face its rail), "roll_not_converged".
std::string wheelset_row_status(const WheelsetState& s);

/// y_mm,delta_r_mm,r_left_mm,r_right_mm,gamma_left_deg,gamma_right_deg,delta_tan_gamma[,roll_deg],
/// two_point_left,two_point_right, the contact points (y_wheel/z_wheel/y_rail/z_rail per side,
/// each in its own profile's frame), status.
std::string wheelset_csv_header(bool roll);
/// One row; `y_mm` is the displacement as given (printed verbatim).
void wheelset_csv_row(std::string& row, double y_mm, const WheelsetState& s, bool roll);

/// amplitude_mm,tan_gamma_e,y1_mm,y2_mm,window_lo,window_hi,status,message (why an amplitude is
/// outside the conicity's domain: the bound crossed, geometry/conicity_domain.hpp)
std::string conicity_csv_header();
void conicity_csv_row(std::string& row, double amplitude_mm, const ConicityResult& c, const std::string& message = "");

/// wheel,source,status,tan_gamma_e_3mm,tan_gamma_e_<A>mm... (every amplitude but the headline
/// 3 mm, already first),Sd_en15313_mm,Sh_en15313_mm,qR_en15313_mm (from the profile),
/// Sd_file_mm,Sh_file_mm,qR_file_mm (as the file's header states them),measures_check (the
/// EN 15313 measures against EN 15313's limits: ok, outside_en15313, unknown;
/// conicity_domain.hpp),message
std::string fleet_csv_header(const std::vector<double>& amplitudes_mm);
/// True for the headline amplitude, 3 mm [m]: the fleet table's tan_gamma_e_3mm column.
bool fleet_headline_amplitude(double amplitude);

}  // namespace mh
