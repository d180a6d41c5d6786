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
// Plain tables (.txt/.csv/.dat) and GENSYS (.wheel/.rail): two columns y z, whitespace or comma,
// '#' comments, blank lines, one optional header line of words. Canonical as read, except GENSYS
// (y towards the track centre, z down): both mirrored.
RawProfile read_table(const std::string& path, const std::vector<std::string>& lines, bool gensys) {
  RawProfile r;
  r.format = "table";
  bool header_seen = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string where = at_line(path, i + 1);
    std::string l = lines[i];
    const auto hash = l.find('#');
    if (hash != std::string::npos) l.erase(hash);
    l = trim(l);
    if (l.empty()) continue;
    const auto t = tokens(l);
    if (r.size() == 0 && !header_seen &&
        std::all_of(t.begin(), t.end(), [](const std::string& s) { return std::isalpha(static_cast<unsigned char>(s[0])); })) {
      header_seen = true;  // e.g. "y_mm,z_mm"
      continue;
    }
    if (t.size() != 2)
      throw InputError(where, "'" + l + "'", "a table row must hold exactly two numbers y z",
                       "remove extra columns; use '#' for comments");
    r.add(parse_number(t[0], where), parse_number(t[1], where), i + 1);
  }
  if (gensys)
    for (std::size_t k = 0; k < r.size(); ++k) r.y[k] = -r.y[k], r.z[k] = -r.z[k];
  return r;
}

}  // namespace mh::formats
