// Joining two pair tables into a wheelset table (wheelset_table_make.hpp).
#include "jobs/wheelset_table_make.hpp"

#include <cmath>
#include <fstream>
#include <ostream>
#include <sstream>

#include "core/checksum.hpp"
#include "core/errors.hpp"
#include "input/wheelset_table.hpp"
#include "jobs/run.hpp"
#include "output/output_file.hpp"

namespace mh {

namespace {

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the table file", "check the path");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

int wheelset_table_job(const std::string& left_path, const std::string& right_path, const std::string& out_path,
                       std::ostream& out, std::ostream& err, bool quiet) {
  const std::string paths[2] = {left_path, right_path};
  const char* side[2] = {"left", "right"};
  ContactTableData t[2];
  std::string text[2];  // each file's text, copied into the wheelset table and hashed as read
  for (int s = 0; s < 2; ++s) {
    t[s] = read_contact_table(paths[s]);
    table_placement(t[s].header, at_line(paths[s], 1));
    text[s] = file_text(paths[s]);
  }
  // One wheelset: its flange-back distance, and one method and model for both wheels.
  const auto& in0 = t[0].header.at("inputs");
  const auto& in1 = t[1].header.at("inputs");
  for (const char* key : {"method", "model"})
    if (t[0].header.value(key, std::string()) != t[1].header.value(key, std::string()))
      throw InputError(right_path, t[1].header.value(key, std::string()),
                       std::string("the two tables' ") + key + " must agree (left: " + t[0].header.value(key, std::string()) + ")",
                       "make both tables from case files of one method and model");
  const double fbd0 = in0.at("track").value("flange_back_distance_mm", NAN),
               fbd1 = in1.at("track").value("flange_back_distance_mm", NAN);
  if (!(std::fabs(fbd0 - fbd1) <= 1e-9))
    throw InputError(right_path, std::to_string(fbd1) + " mm",
                     "the two tables' track.flange_back_distance_mm must agree (left: " + std::to_string(fbd0) + " mm): one wheelset",
                     "make both tables with the wheelset's flange-back distance");
  nlohmann::json h;
  h["schema"] = kWheelsetTableSchema;
  h["program"] = program_json();
  h["what"] = "wheelset table: the left pair's contact table, then the right pair's (each a mhcontact.table/2 "
              "section: header line, column line, rows); each wheel placed at delta = sigma roll, t_Y = sigma y + "
              "a (cos delta - 1) + axle_height sin delta, sigma +1 left, -1 right (docs/tables.md \"A wheelset table\")";
  h["frame"] = "track: x forward, y towards the left rail, z up; roll positive raising the left wheel; each pair in "
               "its own frame (y towards its field side)";
  for (int s = 0; s < 2; ++s) {
    const auto& d = t[s];
    nlohmann::json j;
    j["source"] = paths[s];
    j["sha256"] = sha256_hex(text[s]);
    j["sigma"] = s == 0 ? 1 : -1;
    j["wheelset_placement"] = d.header.at("wheelset_placement");
    j["profiles"] = d.header.value("profiles", nlohmann::json::object());
    j["tY_mm_range"] = d.header.at("tY_mm_range");
    j["Q_kN_range"] = d.header.at("Q_kN_range");
    j["roll_mrad_range"] = d.header.at("roll_mrad_range");
    h[side[s]] = j;
  }
  h["method"] = t[0].header.value("method", std::string());
  h["model"] = t[0].header.value("model", std::string());
  h["units"] = {{"y", "m"}, {"roll", "rad"}, {"a_mm", "mm"}, {"axle_height_mm", "mm"}, {"rail_offset_mm", "mm"}};
  auto write = [&](std::ostream& o) {
    o << "# " << h.dump() << '\n';
    for (int s = 0; s < 2; ++s) o << text[s] << (text[s].empty() || text[s].back() != '\n' ? "\n" : "");
  };
  if (out_path == "-") {
    write(out);
  } else {
    OutputFile f(out_path);
    write(f.stream());
    f.commit();
  }
  if (!quiet) {
    err << "mhcontact table-wheelset: ";
    for (int s = 0; s < 2; ++s) {
      const auto& d = t[s];
      err << side[s] << " " << d.nT() << " x " << d.nQ();
      if (d.nR() > 1) err << " x " << d.nR();
      err << " nodes, roll " << d.roll.front() * 1e3 << " ... " << d.roll.back() * 1e3 << " mrad"
          << (s == 0 ? "; " : "\n");
    }
    // The y range where both wheels are inside their tables upright.
    const double lo = std::max(t[0].tY.front(), -t[1].tY.back()), hi = std::min(t[0].tY.back(), -t[1].tY.front());
    if (lo < hi)
      err << "mhcontact table-wheelset: both wheels inside their tables for y " << lo * 1e3 << " ... " << hi * 1e3
          << " mm (upright)\n";
    else
      err << "mhcontact table-wheelset: warning: no lateral displacement y has both wheels inside their tables' t_Y ranges\n";
    // Each pair table's own validation at random points (docs/tables.md "How it is made", step 6).
    err << "mhcontact table-wheelset: validation: ";
    for (int s = 0; s < 2; ++s) {
      err << side[s] << " ";
      if (t[s].header.contains("validation")) {
        const auto& v = t[s].header["validation"];
        err << "both ok at " << v["status"]["both_ok"].get<std::size_t>() << " of " << v["points"].get<std::size_t>()
            << " points, " << v["beyond"].get<std::size_t>() << " beyond a tolerance, table ok and direct not "
            << v["status"]["table_ok_direct_not"].get<std::size_t>();
      } else {
        err << "none (made with --validate 0 or --no-check)";
      }
      err << (s == 0 ? "; " : "\n");
    }
  }
  return kExitOk;
}

}  // namespace mh
