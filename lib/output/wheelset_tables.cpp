// Wheelset tables; see wheelset_tables.hpp.
#include "output/wheelset_tables.hpp"

#include <cmath>

#include "core/numfmt.hpp"
#include "core/units.hpp"
#include "output/cells.hpp"

namespace mh {

using cells::num;

std::string wheelset_row_status(const WheelsetState& s) {
  if (!s.found) return "no_contact";
  if (!s.converged) return "roll_not_converged";
  if (s.left.off_profile || s.right.off_profile) return "off_profile";
  return "ok";
}

std::string wheelset_csv_header(bool roll) {
  std::string h = "y_mm,delta_r_mm,r_left_mm,r_right_mm,gamma_left_deg,gamma_right_deg,delta_tan_gamma,";
  if (roll) h += "roll_deg,";
  h += "two_point_left,two_point_right,y_wheel_left_mm,z_wheel_left_mm,y_rail_left_mm,z_rail_left_mm,"
       "y_wheel_right_mm,z_wheel_right_mm,y_rail_right_mm,z_rail_right_mm,status\n";
  return h;
}

void wheelset_csv_row(std::string& row, double y_mm, const WheelsetState& s, bool roll) {
  append_number(row, y_mm);
  const double f = units::per_mm;
  for (double v : {s.delta_r() * f, s.left.r * f, s.right.r * f, s.left.gamma / units::deg, s.right.gamma / units::deg,
                   s.delta_tan_gamma()}) {
    row += ',';
    num(row, v);
  }
  if (roll) {
    row += ',';
    num(row, s.roll / units::deg);
  }
  row += s.left.two_point ? ",1" : ",0";
  row += s.right.two_point ? ",1" : ",0";
  for (const WheelContact* c : {&s.left, &s.right})
    for (double v : {c->y_w * f, c->z_w * f, c->y_r * f, c->z_r * f}) {
      row += ',';
      num(row, v);
    }
  row += ',' + wheelset_row_status(s) + '\n';
}

std::string conicity_csv_header() { return "amplitude_mm,tan_gamma_e,y1_mm,y2_mm,window_lo,window_hi,status,message\n"; }

void conicity_csv_row(std::string& row, double amplitude_mm, const ConicityResult& c, const std::string& message) {
  append_number(row, amplitude_mm);
  const double w = en15302_window(c.tan_gamma_e);
  for (double v : {c.tan_gamma_e, c.y1 * units::per_mm, c.y2 * units::per_mm, c.tan_gamma_e - w, c.tan_gamma_e + w}) {
    row += ',';
    num(row, v);
  }
  row += ',' + c.status + ',';
  cells::csv_text(row, message);
  row += '\n';
}

bool fleet_headline_amplitude(double amplitude) { return std::fabs(amplitude - 3e-3) < 1e-12; }

std::string fleet_csv_header(const std::vector<double>& amplitudes_mm) {
  std::string h = "wheel,source,status,tan_gamma_e_3mm";
  for (double a : amplitudes_mm)
    if (!fleet_headline_amplitude(a * 1e-3)) h += ",tan_gamma_e_" + format_number(a) + "mm";
  return h + ",Sd_en15313_mm,Sh_en15313_mm,qR_en15313_mm,Sd_file_mm,Sh_file_mm,qR_file_mm,measures_check,message\n";
}

}  // namespace mh
