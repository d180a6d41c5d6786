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

/// The MiniProf styles, told apart by their content (not by the first line alone). Drawing
/// elements count only when numbered elements MPD<k>= are there: a Key=Value header of points
/// (ColumnDef=, XYPoints=) may carry stray MPDC=/MPDN= keys from a CAD export.
enum class Style { KeyValue, Old, Elements, Multi };

bool is_element_key(const std::string& l) {  // "MPD<digits>=..."
  if (l.rfind("MPD", 0) != 0) return false;
  const auto eq = l.find('=');
  if (eq == std::string::npos || eq == 3) return false;
  const std::string num = trim(l.substr(3, eq - 3));
  return !num.empty() && std::all_of(num.begin(), num.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

/// "[Profile<N>Info]" or "[Profile<N>Points]": N (> 0) and whether it is the points section; 0 otherwise.
long profile_section(const std::string& l, bool* points) {
  static const std::string a = "[Profile";
  if (l.size() < a.size() + 3 || l.compare(0, a.size(), a) != 0 || l.back() != ']') return 0;
  std::size_t k = a.size();
  std::string num;
  while (k < l.size() && std::isdigit(static_cast<unsigned char>(l[k]))) num += l[k++];
  const std::string rest = l.substr(k, l.size() - 1 - k);
  if (num.empty() || num.size() > 6 || (rest != "Info" && rest != "Points")) return 0;
  if (points) *points = rest == "Points";
  return std::stol(num);
}

Style style_of(const std::vector<std::string>& lines) {
  bool kv = false, elements = false;
  for (const auto& raw : lines) {
    const std::string l = unquote(raw);
    if (profile_section(l, nullptr) > 0) return Style::Multi;
  }
  for (const auto& raw : lines) {
    const std::string l = unquote(raw);
    if (l.empty()) break;
    if (l.rfind("MINIPROF", 0) == 0 || l.rfind("#MINI", 0) == 0 || is_dotted_field(l) || is_legend(l)) return Style::Old;
    if (l.rfind("ColumnDef=", 0) == 0 || l.rfind("XYPoints=", 0) == 0) kv = true;
  }
  if (kv) return Style::KeyValue;
  for (const auto& raw : lines)
    if (is_element_key(unquote(raw))) elements = true;
  return elements ? Style::Elements : Style::KeyValue;
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
  throw InputError(at_line(path, lines.size()), "", "MiniProf header without the empty line that ends it, or no data",
                   "the header must end with an empty line followed by the data rows");
}

/// Drawing elements (MPDC=<count>, MPD<k>=L y1 z1 y2 z2 or MPD<k>=A y1 z1 y2 z2 yc zc) of one
/// profile, as parsed from its lines.
struct El { char type; double v[6]; std::size_t line; };
struct ElementSet {
  std::vector<std::pair<long, El>> els;
  long count = -1;             ///< MPDC, -1: not given (or left empty)
  std::size_t count_line = 0;  ///< its line
};

/// Parse a line "MPDC=..." or "MPD<k>=..." into `set`; other lines are ignored.
void parse_element_line(const std::string& path, std::size_t i, const std::string& l, ElementSet& set) {
  const std::string where = at_line(path, i + 1);
  const auto eq = l.find('=');
  if (eq == std::string::npos || l.rfind("MPD", 0) != 0) return;
  const std::string key = trim(l.substr(0, eq)), val = trim(l.substr(eq + 1));
  if (key == "MPDC") {
    if (val.empty()) return;  // left empty by a CAD export: no count to check against
    set.count = parse_integer(val, where, "MPDC (the number of drawing elements)", 0, 1000000);
    set.count_line = i + 1;
    return;
  }
  if (!is_element_key(l)) return;  // other MPD... keys (MPDN=, ...)
  const std::string num = key.substr(3);
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
    throw InputError(where, "'" + key + "'", "drawing element number too large (at most 9 digits)",
                     "number the elements MPD1=, MPD2=, ... in drawing order");
  set.els.emplace_back(std::stol(num), e);
}

/// The elements of `set` sampled into points in file coordinates (`what`: " of [Profile2Info]" or "").
void sample_elements(const std::string& path, ElementSet& set, RawProfile& r, const std::string& what) {
  auto& els = set.els;
  std::stable_sort(els.begin(), els.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  if (els.empty())
    throw InputError(set.count_line ? at_line(path, set.count_line) : path,
                     set.count >= 0 ? "MPDC=" + std::to_string(set.count) : "",
                     "MiniProf drawing elements announced" + what + " but no element MPD<k>= found",
                     "add the elements (MPD1=L y1 z1 y2 z2, MPD2=A y1 z1 y2 z2 yc zc, ...), or for a file of points "
                     "a Key=Value header with ColumnDef=X,Y and the rows after an empty line");
  if (set.count >= 0 && static_cast<long>(els.size()) < set.count)
    throw InputError(at_line(path, set.count_line), "MPDC=" + std::to_string(set.count),
                     "only " + std::to_string(els.size()) + " elements MPD<k>= found" + what + " (file truncated?)",
                     "complete the file or correct MPDC");
  if (set.count >= 0 && static_cast<long>(els.size()) > set.count)
    r.warnings.push_back("MPDC=" + std::to_string(set.count) + " but " + std::to_string(els.size()) +
                         " elements found" + what + " (all used)");
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
    r.warnings.push_back(std::to_string(gaps) + " drawing element(s)" + what + " do not join the previous one (largest gap " +
                         mm(worst_gap) + " at line " + std::to_string(worst_line) + "); joined by a straight piece");
  r.warnings.push_back("sampled " + std::to_string(els.size()) + " drawing elements" + what + " into " +
                       std::to_string(r.size()) + " points (spacing at most " + mm(step) + ", arcs exactly)");
}

/// A file of drawing elements without sections: all its elements.
void read_elements(const std::string& path, const std::vector<std::string>& lines, RawProfile& r) {
  ElementSet set;
  for (std::size_t i = 0; i < lines.size(); ++i) parse_element_line(path, i, unquote(lines[i]), set);
  sample_elements(path, set, r, "");
}

/// Into the canonical frame (MiniProf axes, profiles.md): wheels y = X, z = −Y; rails y = −X and
/// Y a depth (z = −Y) or a height (z = Y) as `yaxis` says (+1 depth, −1 height, 0 from the values).
void orient(RawProfile& r, int yaxis) {
  if (r.kind == ProfileKind::Wheel) {
    for (auto& z : r.z) z = -z;
    return;
  }
  r.kind = ProfileKind::Rail;
  const double ymax = *std::max_element(r.z.begin(), r.z.end());
  const double ymin = *std::min_element(r.z.begin(), r.z.end());
  const bool depth = yaxis != 0 ? yaxis > 0 : ymax > -ymin;
  for (std::size_t k = 0; k < r.size(); ++k) {
    r.y[k] = -r.y[k];
    if (depth) r.z[k] = -r.z[k];
  }
}

/// The header keys that hold wheel measures (Key=Value wheel files store Sd=, Sh=, qR=).
bool is_measure_key(const std::string& key) {
  const std::string k = lower(key);
  return k == "sd" || k == "sh" || k == "qr";
}

/// Multi-profile files (.mpt): sections [Profile<N>Info] (Name=, ColumnDef=, XYPoints=, MPDC=,
/// MPD<k>= drawing elements) and [Profile<N>Points] (X Y rows). Each profile is its points when
/// it has them, else its sampled elements. `section` (1-based N) chooses one; without it the
/// only profile that can be `hint` (a wheel or a rail; either when Unknown) is read, else the
/// file is refused with the list of profiles.
RawProfile read_multi(const std::string& path, const std::vector<std::string>& lines, ProfileKind hint, int section) {
  struct Part {
    long n = 0;
    std::string name;
    std::size_t info_line = 0;
    ElementSet el;
    RawProfile pts;
    long xypoints = -1;
    std::size_t xy_line = 0;
    RawProfile raw;  // what is read: the points, else the sampled elements
    std::string sampled_error;
  };
  std::vector<Part> parts;
  auto part = [&](long n, std::size_t line) -> Part& {
    for (auto& p : parts)
      if (p.n == n) return p;
    parts.push_back(Part{});
    parts.back().n = n;
    parts.back().info_line = line;
    return parts.back();
  };
  long cur = 0;
  bool in_points = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string l = unquote(lines[i]);
    if (l.empty()) continue;
    bool pts = false;
    if (const long n = profile_section(l, &pts)) {
      cur = n;
      in_points = pts;
      Part& p = part(n, i + 1);
      if (!pts) p.info_line = i + 1;
      continue;
    }
    if (l.front() == '[') { cur = 0; continue; }  // another section: not a profile
    if (cur == 0) continue;                        // file header
    Part& p = part(cur, i + 1);
    const std::string where = at_line(path, i + 1);
    if (in_points) {
      const auto t = tokens(l);
      if (t.size() < 2)
        throw InputError(where, "'" + l + "'", "a row of [Profile" + std::to_string(cur) + "Points] needs X and Y",
                         "check the row: X Y [more columns], whitespace or comma separated");
      p.pts.add(t[0], t[1], where, i + 1);
      continue;
    }
    const auto eq = l.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = trim(l.substr(0, eq)), val = trim(l.substr(eq + 1));
    if (key == "Name") p.name = val;
    else if (key == "XYPoints" && !val.empty()) {
      p.xypoints = parse_integer(val, where, "XYPoints (the number of points)", 0, 100000000);
      p.xy_line = i + 1;
    } else parse_element_line(path, i, l, p.el);
  }
  std::stable_sort(parts.begin(), parts.end(), [](const Part& a, const Part& b) { return a.n < b.n; });
  for (Part& p : parts) {
    const std::string what = " of [Profile" + std::to_string(p.n) + "Info]";
    if (p.xypoints >= 0 && static_cast<long>(p.pts.size()) < p.xypoints)
      throw InputError(at_line(path, p.xy_line), "XYPoints=" + std::to_string(p.xypoints),
                       "only " + std::to_string(p.pts.size()) + " rows in [Profile" + std::to_string(p.n) +
                           "Points] (file truncated?)",
                       "complete the file or correct XYPoints");
    if (p.pts.size() > 0) {
      p.raw = p.pts;
      if (!p.el.els.empty())
        p.raw.warnings.push_back("profile " + std::to_string(p.n) + ": its [Profile" + std::to_string(p.n) +
                                 "Points] rows read, its " + std::to_string(p.el.els.size()) + " drawing elements not used");
    } else if (!p.el.els.empty()) {
      sample_elements(path, p.el, p.raw, what);
    }
  }
  auto width = [](const RawProfile& r) {
    if (r.size() == 0) return 0.0;
    return *std::max_element(r.y.begin(), r.y.end()) - *std::min_element(r.y.begin(), r.y.end());
  };
  auto list = [&]() {
    std::string s;
    for (const Part& p : parts) {
      if (!s.empty()) s += "; ";
      s += std::to_string(p.n) + " '" + p.name + "' " +
           (p.raw.size() ? format_number(std::round(width(p.raw) * 100) / 100) + " mm wide, " + std::to_string(p.raw.size()) +
                               (p.pts.size() ? " points" : " points sampled from drawing elements")
                         : std::string("no points"));
    }
    return s;
  };
  const std::string fix = "choose one: {\"file\": ..., \"section\": K} in the case file, --section K for profile info and convert";
  if (parts.empty())
    throw InputError(path, "", "multi-profile MiniProf file without [Profile<N>Info] sections", fix);
  const Part* chosen = nullptr;
  std::string why;
  if (section > 0) {
    for (const Part& p : parts)
      if (p.n == section) chosen = &p;
    if (!chosen)
      throw InputError(path, "section " + std::to_string(section),
                       "the file holds no profile " + std::to_string(section) + " ([Profile" + std::to_string(section) +
                           "Info]); it holds " + std::to_string(parts.size()) + ": " + list(),
                       fix);
    why = "section " + std::to_string(section) + " as asked";
  } else if (parts.size() == 1) {
    chosen = &parts[0];
    why = "the only one";
  } else {
    std::vector<const Part*> can;
    for (const Part& p : parts) {
      if (p.raw.size() < ProfileCheckLimits::kMinPoints) continue;
      bool ok = false;
      for (ProfileKind k : {ProfileKind::Wheel, ProfileKind::Rail}) {
        if (hint != ProfileKind::Unknown && k != hint) continue;
        RawProfile t = p.raw;
        t.kind = k;
        orient(t, 0);
        ok = ok || shape_could_be(t, k);
      }
      if (ok) can.push_back(&p);
    }
    const std::string kinds = hint == ProfileKind::Unknown ? "a wheel or a rail" : std::string("a ") + to_string(hint);
    if (can.size() != 1)
      throw InputError(path, std::to_string(parts.size()) + " profiles",
                       "a multi-profile MiniProf file: " + std::to_string(can.size()) + " of its profiles can be " + kinds +
                           ", say which one to read (profiles: " + list() + ")",
                       fix);
    chosen = can[0];
    why = "the only one of " + std::to_string(parts.size()) + " that can be " + kinds;
  }
  if (chosen->raw.size() == 0) {
    if (chosen->el.count > 0) {  // elements announced but none there: that error, at MPDC's line
      ElementSet el = chosen->el;
      RawProfile t;
      sample_elements(path, el, t, " of [Profile" + std::to_string(chosen->n) + "Info]");
    }
    throw InputError(at_line(path, chosen->info_line), "profile " + std::to_string(chosen->n),
                     "[Profile" + std::to_string(chosen->n) + "Info] has neither [Profile" + std::to_string(chosen->n) +
                         "Points] rows nor drawing elements",
                     "add its [Profile" + std::to_string(chosen->n) + "Points] rows or its elements MPD1=..., or " + fix);
  }
  RawProfile r = chosen->raw;
  r.kind = hint;
  if (hint == ProfileKind::Unknown) {  // the kind its shape allows (a rail when both or neither)
    RawProfile t = r;
    t.kind = ProfileKind::Wheel;
    orient(t, 0);
    RawProfile u = r;
    u.kind = ProfileKind::Rail;
    orient(u, 0);
    if (shape_could_be(t, ProfileKind::Wheel) && !shape_could_be(u, ProfileKind::Rail)) r.kind = ProfileKind::Wheel;
  }
  r.warnings.insert(r.warnings.begin(), "multi-profile file: read profile " + std::to_string(chosen->n) + " '" + chosen->name +
                                            "' (" + why + "; profiles: " + list() + ")");
  return r;
}

}  // namespace

RawProfile read_miniprof(const std::string& path, const std::vector<std::string>& lines, ProfileKind hint, int section) {
  RawProfile r;
  r.format = "miniprof";
  r.kind = hint;
  std::size_t i = 0;
  std::size_t ncols = 0;
  long xypoints = -1;
  std::size_t xy_line = 0;
  int yaxis = 0;  // rails: +1 Y is a depth, −1 a height, 0 from the values
  const Style style = style_of(lines);
  if (section > 0 && style != Style::Multi)
    throw InputError(path, "section " + std::to_string(section),
                     "the file holds one profile (no [Profile<N>Info] sections): a section applies only to "
                     "multi-profile MiniProf files",
                     "drop \"section\" (--section)");
  if (style == Style::Multi) {
    RawProfile m = read_multi(path, lines, hint, section);
    m.format = r.format;
    r = std::move(m);
  } else if (style == Style::Elements) {
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
          throw InputError(at_line(path, i + 1), "'" + val + "'", "YAxis must be depth (Y down) or height (Y up)",
                           "write YAxis=depth or YAxis=height, or drop the line");
      }
      if (key == "XYPoints" && !val.empty()) {
        xypoints = parse_integer(val, at_line(path, i + 1), "XYPoints (the number of points)", 0, 100000000);
        xy_line = i + 1;
      }
      // Wheel measures stored in the header (Sd=, Sh=, qR=): reported as the file's measures.
      if (is_measure_key(key) && !val.empty()) {
        parse_number(val, at_line(path, i + 1));
        r.measures.emplace_back(key, val);
      }
    }
    if (i == lines.size())
      throw InputError(at_line(path, lines.size()), "", "MiniProf header without the empty line that ends it, or no data",
                       "the header must end with an empty line followed by the data rows");
    if (ncols == 0)
      throw InputError(at_line(path, i + 1), "", "MiniProf Key=Value header without ColumnDef",
                       "add e.g. ColumnDef=X,Y (or, for the old style, a first line MINIPROF and the "
                       "(Sd/Sh/qR) measures line)");
    ++i;
  }
  bool junk_warned = false;
  if (style == Style::KeyValue || style == Style::Old)
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
    throw InputError(at_line(path, xy_line), "XYPoints=" + std::to_string(xypoints),
                     "only " + std::to_string(r.size()) + " data rows (file truncated?)",
                     "complete the file or correct XYPoints");
  if (xypoints >= 0 && static_cast<long>(r.size()) > xypoints)
    r.warnings.push_back("XYPoints=" + std::to_string(xypoints) + " but " + std::to_string(r.size()) +
                         " data rows read (all used)");
  if (r.size() == 0)  // fuzz finding: the orientation below needs at least one point
    throw InputError(at_line(path, lines.size()), "", "MiniProf file without data rows after its header",
                     "add the rows X Y after the empty line that ends the header");
  orient(r, yaxis);
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
