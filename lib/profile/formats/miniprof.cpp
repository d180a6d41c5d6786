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
#include "core/units.hpp"

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
namespace {

constexpr double kPi = units::pi;

bool is_legend(const std::string& l) {  // "(Sd/Sh/qR)" possibly after the numbers; no '=' (a Key=Value line)
  const auto a = l.find('('), b = l.rfind(')');
  if (a == std::string::npos || b == std::string::npos || b <= a || l.find('=') != std::string::npos) return false;
  const std::string in = l.substr(a + 1, b - a - 1);
  return in.find('/') != std::string::npos && in.find(' ') == std::string::npos;
}
bool is_dotted_field(const std::string& l) {  // "Stock.......: 1234"
  const auto c = l.find(':');
  return c != std::string::npos && c >= 2 && l[c - 1] == '.' && l.find('=') == std::string::npos;
}
std::string unquote(std::string l) {
  l = trim(l);
  while (!l.empty() && l.front() == '"') l.erase(0, 1);
  while (!l.empty() && l.back() == '"') l.pop_back();
  return trim(l);
}

/// The three MiniProf styles, told apart by their content (not by the first line alone).
enum class Style { KeyValue, Old, Elements };

Style style_of(const std::vector<std::string>& lines) {
  bool kv = false;
  for (const auto& raw : lines) {
    const std::string l = unquote(raw);
    if (l.empty()) break;
    if (l.rfind("MINIPROF", 0) == 0 || l.rfind("#MINI", 0) == 0 || is_dotted_field(l) || is_legend(l)) return Style::Old;
    if (l.rfind("MPD", 0) == 0 && l.find('=') != std::string::npos) return Style::Elements;
    if (l.rfind("ColumnDef=", 0) == 0 || l.rfind("XYPoints=", 0) == 0) kv = true;
  }
  if (kv) return Style::KeyValue;
  for (const auto& raw : lines) {
    const std::string l = unquote(raw);
    if (l.rfind("MPD", 0) == 0 && l.find('=') != std::string::npos) return Style::Elements;
  }
  return Style::KeyValue;
}

/// Old style: "#MINIWHEELPROF" / name / "MINIPROF <year ...>" / dotted fields / measures and their
/// legend "(Sd/Sh/qR)" / empty line / rows "X Y [A]".
std::size_t read_old_header(const std::string& path, const std::vector<std::string>& lines, RawProfile& r) {
  std::size_t i = 0;
  std::string prev;
  for (; i < lines.size(); ++i) {
    const std::string l = unquote(lines[i]);
    if (l.empty()) return i + 1;
    if (is_legend(l)) {
      const auto a = l.find('('), b = l.rfind(')');
      std::vector<std::string> names;
      std::string cur;
      for (char ch : l.substr(a + 1, b - a - 1)) {
        if (ch == '/') names.push_back(trim(cur)), cur.clear();
        else cur += ch;
      }
      names.push_back(trim(cur));
      std::vector<std::string> vals = tokens(unquote(l.substr(0, a)));
      if (vals.empty()) vals = tokens(prev);  // the legend on its own line, under the numbers
      if (vals.size() != names.size())
        throw InputError(at_line(path, i + 1), "'" + l + "'",
                         "the MiniProf measures line holds " + std::to_string(vals.size()) + " numbers for " +
                             std::to_string(names.size()) + " names in its legend",
                         "give one number per name, e.g. \"32.5 28.0 10.8\" (Sd/Sh/qR)");
      for (std::size_t k = 0; k < names.size(); ++k) {
        parse_number(vals[k], at_line(path, i + 1));
        r.measures.emplace_back(names[k], vals[k]);
      }
    } else if (is_dotted_field(l)) {
      const auto c = l.find(':');
      std::string key = l.substr(0, c);
      while (!key.empty() && key.back() == '.') key.pop_back();
      const std::string val = trim(l.substr(c + 1));
      if (!val.empty()) r.measures.emplace_back(trim(key), val);
    } else if (l.rfind("#MINIWHEEL", 0) == 0) {
      if (r.kind == ProfileKind::Unknown) r.kind = ProfileKind::Wheel;
    } else if (l.rfind("#MINIRAIL", 0) == 0) {
      if (r.kind == ProfileKind::Unknown) r.kind = ProfileKind::Rail;
    }
    prev = l;
  }
  throw InputError(path, "", "MiniProf header without the empty line that ends it, or no data",
                   "the header must end with an empty line followed by the data rows");
}

/// Drawing elements ("[Profile1Info]" sections, MPDC=<count>, MPD<k>=L y1 z1 y2 z2 or
/// MPD<k>=A y1 z1 y2 z2 yc zc): sampled into points in file coordinates.
void read_elements(const std::string& path, const std::vector<std::string>& lines, RawProfile& r) {
  struct El { char type; double v[6]; std::size_t line; };
  std::vector<std::pair<long, El>> els;
  long count = -1;
  std::size_t count_line = 0;
  std::string section, first_section;
  bool other_section_warned = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string where = at_line(path, i + 1);
    const std::string l = unquote(lines[i]);
    if (l.size() >= 2 && l.front() == '[' && l.back() == ']') { section = l; continue; }
    const auto eq = l.find('=');
    if (eq == std::string::npos || l.rfind("MPD", 0) != 0) continue;
    if (first_section.empty()) first_section = section.empty() ? "(none)" : section;
    if ((section.empty() ? "(none)" : section) != first_section) {
      if (!other_section_warned)
        r.warnings.push_back(where + ": drawing elements of " + section + " ignored (only the first profile, " +
                             first_section + ", is read)");
      other_section_warned = true;
      continue;
    }
    const std::string key = trim(l.substr(0, eq)), val = trim(l.substr(eq + 1));
    if (key == "MPDC") {
      count = parse_integer(val, where, "MPDC (the number of drawing elements)", 0, 1000000);
      count_line = i + 1;
      continue;
    }
    const std::string num = key.substr(3);
    if (num.empty() || !std::all_of(num.begin(), num.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
      continue;  // other MPD... keys
    const auto t = tokens(val);
    El e{};
    e.line = i + 1;
    e.type = t.empty() ? '?' : static_cast<char>(std::toupper(static_cast<unsigned char>(t[0][0])));
    const std::size_t need = e.type == 'L' ? 5 : e.type == 'A' ? 7 : 0;
    if (need == 0 || t.size() != need || t[0].size() != 1)
      throw InputError(where, "'" + l + "'",
                       "a drawing element must be 'L y1 z1 y2 z2' (line) or 'A y1 z1 y2 z2 yc zc' (arc, centre yc zc)",
                       "correct the element");
    for (std::size_t k = 1; k < need; ++k) e.v[k - 1] = parse_number(t[k], where);
    if (num.size() > 9)
      throw InputError(where, "'" + key + "'", "drawing element number too large (at most 9 digits)");
    els.emplace_back(std::stol(num), e);
  }
  std::stable_sort(els.begin(), els.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  if (els.empty()) throw InputError(path, "", "MiniProf drawing-element file without MPD<k>= elements");
  if (count >= 0 && static_cast<long>(els.size()) < count)
    throw InputError(at_line(path, count_line), "MPDC=" + std::to_string(count),
                     "only " + std::to_string(els.size()) + " elements MPD<k>= found (file truncated?)",
                     "complete the file or correct MPDC");
  if (count >= 0 && static_cast<long>(els.size()) > count)
    r.warnings.push_back("MPDC=" + std::to_string(count) + " but " + std::to_string(els.size()) +
                         " elements found (all used)");
  const double step = ProfileCheckLimits::kElementStep_mm;
  std::size_t gaps = 0;
  double worst_gap = 0;
  std::size_t worst_line = 0;
  for (std::size_t n = 0; n < els.size(); ++n) {
    const El& e = els[n].second;
    const double y1 = e.v[0], z1 = e.v[1], y2 = e.v[2], z2 = e.v[3];
    if (n > 0) {
      const double gap = std::hypot(y1 - r.y.back(), z1 - r.z.back());
      if (gap > ProfileCheckLimits::kElementJoin_mm) {
        ++gaps;
        if (gap > worst_gap) worst_gap = gap, worst_line = e.line;
      }
      if (gap > ProfileCheckLimits::kMaxBridge_mm)
        throw InputError(at_line(path, e.line), "gap of " + mm(gap),
                         "drawing element MPD" + std::to_string(els[n].first) + " starts " + mm(gap) +
                             " away from the end of the previous element (more than " +
                             mm(ProfileCheckLimits::kMaxBridge_mm) + ")",
                         "check the order and the end points of the elements");
      if (gap <= 1e-9) { r.y.pop_back(); r.z.pop_back(); r.line.pop_back(); }  // the shared end point once
    }
    // An element longer than the widest plausible profile is a broken file, and would be
    // sampled into more points than memory holds: rejected before sampling.
    auto check_length = [&](double len) {
      if (!(len <= ProfileCheckLimits::kMaxWidth_mm))
        throw InputError(at_line(path, e.line), "length " + mm(len),
                         "a drawing element cannot be longer than the widest profile (" +
                             mm(ProfileCheckLimits::kMaxWidth_mm) + ")",
                         "check the end points (and the units: mm expected)");
    };
    if (e.type == 'L') {
      check_length(std::hypot(y2 - y1, z2 - z1));
      const int m = std::max(1, static_cast<int>(std::ceil(std::hypot(y2 - y1, z2 - z1) / step - 1e-9)));
      for (int k = 0; k <= m; ++k) r.add(y1 + (y2 - y1) * k / m, z1 + (z2 - z1) * k / m, e.line);
    } else {
      const double yc = e.v[4], zc = e.v[5];
      const double R1 = std::hypot(y1 - yc, z1 - zc), R2 = std::hypot(y2 - yc, z2 - zc);
      if (std::abs(R1 - R2) > ProfileCheckLimits::kElementJoin_mm || R1 <= 0)
        throw InputError(at_line(path, e.line), "radii " + mm(R1) + " and " + mm(R2),
                         "the end points of an arc must lie at the same distance from its centre",
                         "correct the end points or the centre");
      const double a1 = std::atan2(z1 - zc, y1 - yc);
      double da = std::atan2(z2 - zc, y2 - yc) - a1;  // the minor arc from the start to the end
      while (da > kPi) da -= 2 * kPi;
      while (da < -kPi) da += 2 * kPi;
      check_length(std::abs(da) * R1);
      const int m = std::max(1, static_cast<int>(std::ceil(std::abs(da) * R1 / step - 1e-9)));
      for (int k = 0; k <= m; ++k) {
        const double a = a1 + da * k / m;
        if (k == m) r.add(y2, z2, e.line);  // the end point exactly as written
        else r.add(yc + R1 * std::cos(a), zc + R1 * std::sin(a), e.line);
      }
    }
  }
  if (gaps)
    r.warnings.push_back(std::to_string(gaps) + " drawing element(s) do not join the previous one (largest gap " +
                         mm(worst_gap) + " at line " + std::to_string(worst_line) + "); joined by a straight piece");
  r.warnings.push_back("sampled " + std::to_string(els.size()) + " drawing elements into " + std::to_string(r.size()) +
                       " points (spacing at most " + mm(step) + ", arcs exactly)");
}

}  // namespace

RawProfile read_miniprof(const std::string& path, const std::vector<std::string>& lines, ProfileKind hint) {
  RawProfile r;
  r.format = "miniprof";
  r.kind = hint;
  std::size_t i = 0;
  std::size_t ncols = 0;
  long xypoints = -1;
  int yaxis = 0;  // rails: +1 Y is a depth, −1 a height, 0 from the values
  const Style style = style_of(lines);
  if (style == Style::Elements) {
    read_elements(path, lines, r);
  } else if (style == Style::Old) {
    i = read_old_header(path, lines, r);
  } else {
    for (; i < lines.size(); ++i) {
      std::string l = trim(lines[i]);
      if (l.empty()) break;  // the header ends with an empty line
      if (!l.empty() && l.front() == '"') l.erase(0, 1);
      if (!l.empty() && l.back() == '"') l.pop_back();
      const auto eq = l.find('=');
      if (eq == std::string::npos) continue;
      const std::string key = trim(l.substr(0, eq)), val = trim(l.substr(eq + 1));
      if (key == "ColumnDef") ncols = tokens(val).size();
      if (key == "YAxis") {  // written by mhcontact (write_miniprof): no guessing of the rail's Y sign
        if (val == "depth") yaxis = 1;
        else if (val == "height") yaxis = -1;
        else
          throw InputError(at_line(path, i + 1), "'" + val + "'", "YAxis must be depth (Y down) or height (Y up)");
      }
      if (key == "XYPoints" && !val.empty()) xypoints = parse_integer(val, at_line(path, i + 1), "XYPoints (the number of points)", 0, 100000000);
    }
    if (i == lines.size())
      throw InputError(path, "", "MiniProf header without the empty line that ends it, or no data",
                       "the header must end with an empty line followed by the data rows");
    if (ncols == 0)
      throw InputError(path, "", "MiniProf Key=Value header without ColumnDef",
                       "add e.g. ColumnDef=X,Y (or, for the old style, a first line MINIPROF and the "
                       "(Sd/Sh/qR) measures line)");
    ++i;
  }
  bool junk_warned = false;
  if (style != Style::Elements)
    for (; i < lines.size(); ++i) {
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
      r.add(t[0], t[1], where, i + 1);
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
  if (r.kind == ProfileKind::Wheel) {
    for (auto& z : r.z) z = -z;
  } else {
    r.kind = ProfileKind::Rail;
    const double ymax = *std::max_element(r.z.begin(), r.z.end());
    const double ymin = *std::min_element(r.z.begin(), r.z.end());
    const bool depth = yaxis != 0 ? yaxis > 0 : ymax > -ymin;
    for (std::size_t k = 0; k < r.size(); ++k) {
      r.y[k] = -r.y[k];
      if (depth) r.z[k] = -r.z[k];
    }
  }
  return r;
}

std::string write_miniprof(const Profile& p, bool wheel) {
  std::string s = "Filename=" + p.source + "\nProgramName=mhcontact\n";
  s += "Comment=" + provenance(p) + "; " +
       (wheel ? "wheel: X = y (taping line at X = 0), Y = -z (increase of radius)"
              : "rail: X = -y (towards the gauge side), Y = -z (depth)") +
       ", mm\n";
  if (!wheel) s += "YAxis=depth\n";  // read back without guessing the sign from the values
  s += "XYPoints=" + std::to_string(p.size()) + "\nColumnDef=X,Y\n\n";
  for (std::size_t k = 0; k < p.size(); ++k) {
    append_number(s, (wheel ? p.y[k] : -p.y[k]) * 1e3 + 0.0);
    s += ',';
    append_number(s, -p.z[k] * 1e3 + 0.0);
    s += '\n';
  }
  return s;
}

}  // namespace mh::formats
