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
// MiniProf .ban/.whl. X lateral, Y vertical. Axis conventions worked out from the shipped files:
//  rails (.ban): X positive towards the GAUGE side (MBench_UIC60_v3.ban is MBench_UIC60_v3.prr
//    with y mirrored; avg_low2.ban's extra point "to extend gauge face" is at positive X), so
//    y = −X. The vertical sign differs between files (Manchester: Y = depth below the top,
//    0…38.5; avg_*.ban: Y up, −25…−0.2): Y is taken as a depth (z = −Y) when max Y > −min Y,
//    else as a height (z = Y).
//  wheels (.whl): X from the flange back towards the field side, Y = increase of rolling radius
//    (flange tip = largest Y): y = X, z = −Y; the taping-line rule then puts y = 0 70 mm from
//    the flange back.
RawProfile read_miniprof(const std::string& path, const std::vector<std::string>& lines, bool wheel) {
  RawProfile r;
  r.format = "miniprof";
  std::size_t i = 0;
  std::size_t ncols = 0;
  long xypoints = -1;
  const bool old_style = !lines.empty() && trim(lines[0]).rfind("MINIPROF", 0) == 0;
  for (; i < lines.size(); ++i) {
    std::string l = trim(lines[i]);
    if (l.empty()) break;  // the header ends with an empty line
    if (old_style) continue;
    if (!l.empty() && l.front() == '"') l.erase(0, 1);
    if (!l.empty() && l.back() == '"') l.pop_back();
    const auto eq = l.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = trim(l.substr(0, eq)), val = trim(l.substr(eq + 1));
    if (key == "ColumnDef") ncols = tokens(val).size();
    if (key == "XYPoints" && !val.empty()) xypoints = static_cast<long>(parse_number(val, at_line(path, i + 1)));
  }
  if (i == lines.size())
    throw InputError(path, "", "MiniProf header without the empty line that ends it, or no data",
                     "the header must end with an empty line followed by the data rows");
  if (!old_style && ncols == 0)
    throw InputError(path, "", "MiniProf Key=Value header without ColumnDef", "add e.g. ColumnDef=X,Y");
  if (old_style) ncols = 0;  // old style: X Y [A]: the first two numbers count
  bool junk_warned = false;
  for (++i; i < lines.size(); ++i) {
    const std::string where = at_line(path, i + 1);
    std::string l = trim(lines[i]);
    while (!l.empty() && l.front() == '"') l.erase(0, 1);
    while (!l.empty() && l.back() == '"') l.pop_back();
    if (l.empty()) continue;
    const auto t = tokens(l);
    const std::size_t need = ncols ? ncols : 2;
    std::size_t nnum = 0;
    for (; nnum < t.size() && nnum < std::max<std::size_t>(need, 2); ++nnum) parse_number(t[nnum], where);
    if (nnum < 2)
      throw InputError(where, "'" + l + "'", "a MiniProf row needs at least X and Y",
                       "check the row (ColumnDef says " + std::to_string(need) + " columns)");
    if (t.size() > nnum && !looks_numeric(t[nnum]) && !junk_warned) {
      r.warnings.push_back(where + ": ignored the text after the columns ('" + t[nnum] + "...')");
      junk_warned = true;
    }
    const double X = parse_number(t[0], where), Y = parse_number(t[1], where);
    r.add(X, Y, i + 1);
  }
  if (xypoints >= 0 && static_cast<long>(r.size()) < xypoints)
    throw InputError(path, "XYPoints=" + std::to_string(xypoints),
                     "only " + std::to_string(r.size()) + " data rows (file truncated?)",
                     "complete the file or correct XYPoints");
  if (xypoints >= 0 && static_cast<long>(r.size()) > xypoints)
    r.warnings.push_back("XYPoints=" + std::to_string(xypoints) + " but " + std::to_string(r.size()) +
                         " data rows read (all used)");
  if (r.size() == 0)  // fuzz finding: the orientation below needs at least one point
    throw InputError(path, "", "MiniProf file without data rows after its header");
  if (wheel) {
    r.kind = ProfileKind::Wheel;
    for (auto& z : r.z) z = -z;
  } else {
    r.kind = ProfileKind::Rail;
    const double ymax = *std::max_element(r.z.begin(), r.z.end());
    const double ymin = *std::min_element(r.z.begin(), r.z.end());
    const bool depth = ymax > -ymin;
    for (std::size_t k = 0; k < r.size(); ++k) {
      r.y[k] = -r.y[k];
      if (depth) r.z[k] = -r.z[k];
    }
  }
  return r;
}

}  // namespace mh::formats
