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
// Plain tables (.txt/.csv/.dat) and GENSYS (.wheel/.rail): two columns y z, '#' comments, blank
// lines, one optional header line of words. Separators: whitespace (tabs too), ',' or ';'. A
// row with ';' is European Excel: ';' separates, ',' is the decimal mark ("12,5;-3,25"). Canonical
// as read, except GENSYS (y towards the track centre, z down): both mirrored.
namespace {
/// The fields of a row; decimal commas become points where ';' or tabs separate.
std::vector<std::string> table_fields(const std::string& l) {
  char sep = 0;
  if (l.find(';') != std::string::npos) sep = ';';
  else if (l.find('\t') != std::string::npos && l.find(',') != std::string::npos) {
    // "12,5<TAB>-3,25": tabs separate, commas are decimal marks (each field holds at most one).
    std::size_t fields = 1, commas_per_field_max = 0, cur = 0;
    for (char c : l) {
      if (c == '\t') ++fields, cur = 0;
      else if (c == ',') commas_per_field_max = std::max(commas_per_field_max, ++cur);
    }
    if (fields >= 2 && commas_per_field_max == 1) sep = '\t';
  }
  if (!sep) return tokens(l);
  std::vector<std::string> out;
  std::string f;
  auto flush = [&]() {
    std::string t = trim(f);
    for (char& c : t)
      if (c == ',') c = '.';
    if (!t.empty()) out.push_back(t);
    f.clear();
  };
  for (char c : l) {
    if (c == sep) flush();
    else f += c;
  }
  flush();
  return out;
}
}  // namespace

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
    const auto t = table_fields(l);
    if (t.empty()) continue;  // e.g. ";;" of an empty spreadsheet row
    if (r.size() == 0 && !header_seen &&
        std::all_of(t.begin(), t.end(), [](const std::string& s) { return std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '"'; })) {
      header_seen = true;  // e.g. "y_mm,z_mm"
      continue;
    }
    if (t.size() == 4 && l.find(';') == std::string::npos && l.find('\t') == std::string::npos &&
        std::count(l.begin(), l.end(), ',') >= 2)
      throw InputError(where, "'" + l + "'",
                       "four numbers where a table row holds two: decimal commas with ',' also as the separator "
                       "cannot be told apart",
                       "export with ';' as the separator (European Excel CSV) or with '.' as the decimal mark");
    if (t.size() != 2)
      throw InputError(where, "'" + l + "'", "a table row must hold exactly two numbers y z",
                       "remove extra columns; use '#' for comments");
    r.add(t[0], t[1], where, i + 1);
  }
  if (gensys)
    for (std::size_t k = 0; k < r.size(); ++k) r.y[k] = -r.y[k], r.z[k] = -r.z[k];
  return r;
}

std::string write_table(const Profile& p, char sep, bool gensys) {
  std::string s;
  if (gensys) s = "# GENSYS-style profile " + provenance(p) + "; y towards the track centre, z down, mm\n";
  else s = std::string("y_mm") + sep + "z_mm\n";
  const double f = gensys ? -1e3 : 1e3;
  for (std::size_t k = 0; k < p.size(); ++k) {
    append_number(s, p.y[k] * f);  // no "+ 0.0": the bytes of the csv format kept
    s += sep;
    append_number(s, p.z[k] * f);
    s += '\n';
  }
  return s;
}

}  // namespace mh::formats
