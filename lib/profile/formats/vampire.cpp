#include "profile/formats/formats.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/numfmt.hpp"

namespace mh::formats {

// ---------------------------------------------------------------------------------------------
// VAMPIRE .whe/.rai: line 1 WHEELPROFILE/RAILPROFILE, line 2 title, line 3 datum, line 4
// flange-back distance or gauge, then rows "yl zl yr zr"; z up. Each side is taken in its own
// frame with y positive towards its field side (assumption, see docs/profiles.md §4); no real file was
// available to confirm the lateral sign.
RawProfile read_vampire(const std::string& path, const std::vector<std::string>& lines, const std::string& side) {
  RawProfile r;
  r.format = "vampire";
  if (side != "right" && side != "left")
    throw InputError(path, side, "vampire side must be 'right' or 'left'", "vampire_side \"right\" or \"left\" (--vampire-side)");
  if (lines.size() < 5) throw InputError(at_line(path, lines.size()), "", "VAMPIRE file shorter than its 4 header lines",
                                          "lines 1-4: WHEELPROFILE or RAILPROFILE, a title, the datum, the flange-back distance or gauge; then the rows");
  const std::string key = trim(lines[0]);
  if (key.rfind("WHEELPROFILE", 0) == 0) r.kind = ProfileKind::Wheel;
  else if (key.rfind("RAILPROFILE", 0) == 0) r.kind = ProfileKind::Rail;
  else throw InputError(at_line(path, 1), "'" + key + "'", "line 1 must be WHEELPROFILE or RAILPROFILE",
                   "start the file with WHEELPROFILE or RAILPROFILE, or choose the format with --format");
  const auto t4 = tokens(lines[3]);
  if (t4.empty()) throw InputError(at_line(path, 4), "", "line 4 must hold the flange-back distance or gauge",
                                           "write the number in mm on line 4, e.g. 1360");
  parse_number(t4[0], at_line(path, 4));
  for (std::size_t i = 4; i < lines.size(); ++i) {
    const std::string where = at_line(path, i + 1);
    const std::string l = trim(lines[i]);
    if (l.empty()) continue;
    const auto t = tokens(l);
    if (t.size() != 4) throw InputError(where, "'" + l + "'", "a VAMPIRE row must be 'yl zl yr zr'",
                                            "four numbers a row: the left and the right side");
    double v[4];
    for (int k = 0; k < 4; ++k) v[k] = parse_number(t[k], where);
    (void)v;
    if (side == "right") r.add(t[2], t[3], where, i + 1);
    else r.add(t[0], t[1], where, i + 1);
  }
  return r;
}

std::string write_vampire(const Profile& p, bool wheel) {
  std::string s = wheel ? "WHEELPROFILE\n" : "RAILPROFILE\n";
  s += provenance(p) + " (both sides the same profile)\nEUROPEAN\n";
  s += wheel ? "1360.0\n" : "1435.0\n";
  for (std::size_t k = 0; k < p.size(); ++k) {
    std::string row;
    append_number(row, p.y[k] * 1e3 + 0.0);
    row += ' ';
    append_number(row, p.z[k] * 1e3 + 0.0);
    s += row + ' ' + row + '\n';
  }
  return s;
}

}  // namespace mh::formats
