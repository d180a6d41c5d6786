// Profile readers and writers (profiles.md "File formats seen in the field"), the canonical frame
// of profile.hpp and the plausibility checks. Work is done in millimetres (the unit of every
// profile file) and converted to metres only when the Profile is returned.
#include "mhcontact/profile_io.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "mhcontact/checksum.hpp"
#include "mhcontact/errors.hpp"
#include "mhcontact/numfmt.hpp"
#include "mhcontact/output_file.hpp"

namespace mh {

ProfileFormat parse_profile_format(const std::string& s) {
  if (s == "auto") return ProfileFormat::Auto;
  if (s == "simpack") return ProfileFormat::Simpack;
  if (s == "miniprof") return ProfileFormat::MiniProf;
  if (s == "table") return ProfileFormat::Table;
  if (s == "vampire") return ProfileFormat::Vampire;
  throw std::invalid_argument("unknown profile format '" + s +
                              "' (expected auto, simpack, miniprof, table or vampire)");
}

const char* to_string(ProfileFormat f) {
  switch (f) {
    case ProfileFormat::Auto: return "auto";
    case ProfileFormat::Simpack: return "simpack";
    case ProfileFormat::MiniProf: return "miniprof";
    case ProfileFormat::Table: return "table";
    case ProfileFormat::Vampire: return "vampire";
  }
  return "?";
}

namespace {

using L = ProfileCheckLimits;

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string extension(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  return lower(path.substr(dot + 1));
}

std::string trim(const std::string& s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

std::string mm(double v) { return format_number(std::round(v * 1e6) / 1e6) + " mm"; }  // to 1 nm

/// Split on whitespace and commas.
std::vector<std::string> tokens(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (std::isspace(static_cast<unsigned char>(c)) || c == ',') {
      if (!cur.empty()) out.push_back(cur), cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

bool looks_numeric(const std::string& t) {
  if (t.empty()) return false;
  const char c = t[0];
  return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.';
}

/// A number that must be the whole token and finite.
double parse_number(const std::string& tok, const std::string& where) {
  const char* b = tok.c_str();
  char* e = nullptr;
  const double v = std::strtod(b, &e);
  if (e == b) throw InputError(where, "'" + tok + "'", "not a number", "each row must hold numbers only");
  if (*e != '\0')
    throw InputError(where, "'" + tok + "'", "number with trailing junk '" + std::string(e) + "'",
                     "remove the extra characters; use '.' as the decimal separator");
  if (!std::isfinite(v))
    throw InputError(where, "'" + tok + "'", "NaN or infinite coordinate", "every point needs finite y and z");
  return v;
}

/// Points as read, in file order, mm, with their file line (for messages).
struct RawProfile {
  std::vector<double> y, z;
  std::vector<std::size_t> line;
  ProfileKind kind = ProfileKind::Unknown;
  std::string format;
  std::vector<std::string> warnings;
  void add(double yy, double zz, std::size_t ln) { y.push_back(yy); z.push_back(zz); line.push_back(ln); }
  std::size_t size() const { return y.size(); }
};

std::vector<std::string> read_lines(const std::string& path, std::string& bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the profile file", "check the path and permissions");
  std::ostringstream ss;
  ss << in.rdbuf();
  bytes = ss.str();
  std::vector<std::string> lines;
  std::string cur;
  for (char c : bytes) {
    if (c == '\n') {
      if (!cur.empty() && cur.back() == '\r') cur.pop_back();
      lines.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) {
    if (cur.back() == '\r') cur.pop_back();
    lines.push_back(cur);
  }
  return lines;
}

ProfileKind kind_from_extension(const std::string& ext) {
  if (ext == "prr" || ext == "ban" || ext == "rail" || ext == "rai") return ProfileKind::Rail;
  if (ext == "prw" || ext == "whl" || ext == "wheel" || ext == "whe") return ProfileKind::Wheel;
  return ProfileKind::Unknown;
}

// ---------------------------------------------------------------------------------------------
// SIMPACK .prr/.prw
// Transformations in the order of existing readers (profiles.md): shift, rotate, clip to
// bounds, mirror y, mirror z, reverse order, scale to mm. Afterwards y points to the field side
// and z DOWN (Manchester S1002: flange tip at y = −55 mm with z = +28 mm), so canonical = (y, −z).
RawProfile read_simpack(const std::string& path, const std::vector<std::string>& lines) {
  RawProfile r;
  r.format = "simpack";
  enum { None, Header, Spline, Points, Done } state = None;
  double shift_y = 0, shift_z = 0, rotate = 0, by0 = 1, by1 = 0, bz0 = 1, bz1 = 0;
  double len_f = 1000, ang_f = 1;
  bool mirror_y = false, mirror_z = false, inversion = false, seen_begin = false;
  int type = -1;
  std::size_t begin_line = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string where = at_line(path, i + 1);
    std::string l = lines[i];
    const auto bang = l.find('!');
    if (bang != std::string::npos) l.erase(bang);
    l = trim(l);
    if (l.empty() || l[0] == '%') continue;  // '%' lines: commented points (circ_r300.prr)
    if (state == Points) {
      if (l == "point.end") { state = Spline; continue; }
      const auto t = tokens(l);
      if (t.size() < 2 || t.size() > 3)
        throw InputError(where, "'" + l + "'", "a point row must be 'y z [weight]'",
                         "check for a missing point.end or a broken row");
      r.add(parse_number(t[0], where), parse_number(t[1], where), i + 1);
      if (t.size() == 3) parse_number(t[2], where);
      continue;
    }
    if (l == "header.begin") { state = Header; continue; }
    if (l == "header.end" || l == "spline.end") { state = None; continue; }
    if (l == "spline.begin") { state = Spline; continue; }
    if (l == "point.begin") { state = Points; seen_begin = true; begin_line = i + 1; continue; }
    const auto eq = l.find('=');
    if (eq == std::string::npos) continue;  // unknown structural line: ignored
    const std::string key = trim(l.substr(0, eq));
    const std::string val = trim(l.substr(eq + 1));
    auto num = [&]() {
      const auto t = tokens(val);
      if (t.empty()) throw InputError(where, "'" + val + "'", "key " + key + " needs a number");
      return parse_number(t[0], where);
    };
    if (state == Header) {
      if (key == "type") type = static_cast<int>(num());
    } else if (state == Spline) {
      if (key == "shift.y") shift_y = num();
      else if (key == "shift.z") shift_z = num();
      else if (key == "rotate") rotate = num();
      else if (key == "bound.y.min") by0 = num();
      else if (key == "bound.y.max") by1 = num();
      else if (key == "bound.z.min") bz0 = num();
      else if (key == "bound.z.max") bz1 = num();
      else if (key == "mirror.y") mirror_y = num() != 0;
      else if (key == "mirror.z") mirror_z = num() != 0;
      else if (key == "inversion") inversion = num() != 0;
      else if (key == "units.len.f") len_f = num();
      else if (key == "units.ang.f") ang_f = num();
    }
  }
  if (!seen_begin)
    throw InputError(path, "", "no point.begin section: not a SIMPACK profile",
                     "check the file, or force another format with --format");
  if (state == Points)
    throw InputError(at_line(path, begin_line), "point.begin", "missing point.end (file truncated?)",
                     "complete the file; the point list must end with point.end");
  if (type == 0) r.kind = ProfileKind::Rail;
  else if (type == 1) r.kind = ProfileKind::Wheel;
  else if (type != -1)
    throw InputError(path, "type = " + std::to_string(type), "header type must be 0 (rail) or 1 (wheel)");
  if (!(len_f > 0)) throw InputError(path, format_number(len_f), "units.len.f must be positive", "1000 for mm");
  if (!(ang_f > 0)) throw InputError(path, format_number(ang_f), "units.ang.f must be positive", "1 for rad");

  // 1 shift, 2 rotate (about x, counter-clockwise in the file's (y, z) plane), 3 bounds.
  const double a = rotate / ang_f, c = std::cos(a), s = std::sin(a);
  RawProfile t = r;
  t.y.clear(); t.z.clear(); t.line.clear();
  std::size_t clipped = 0;
  for (std::size_t k = 0; k < r.size(); ++k) {
    const double y0 = r.y[k] + shift_y, z0 = r.z[k] + shift_z;
    const double y = c * y0 - s * z0, z = s * y0 + c * z0;
    if ((by0 <= by1 && (y < by0 || y > by1)) || (bz0 <= bz1 && (z < bz0 || z > bz1))) { ++clipped; continue; }
    t.add(y, z, r.line[k]);
  }
  if (clipped) t.warnings.push_back("SIMPACK bounds removed " + std::to_string(clipped) + " points");
  // 4 mirror y, 5 mirror z, 6 reverse order, 7 scale to mm; then canonical (y, −z).
  const double to_mm = 1000.0 / len_f;
  for (std::size_t k = 0; k < t.size(); ++k) {
    double y = t.y[k], z = t.z[k];
    if (mirror_y) y = -y;
    if (mirror_z) z = -z;
    t.y[k] = y * to_mm;
    t.z[k] = -z * to_mm;
  }
  if (inversion) {
    std::reverse(t.y.begin(), t.y.end());
    std::reverse(t.z.begin(), t.z.end());
    std::reverse(t.line.begin(), t.line.end());
  }
  return t;
}

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

// ---------------------------------------------------------------------------------------------
// VAMPIRE .whe/.rai: line 1 WHEELPROFILE/RAILPROFILE, line 2 title, line 3 datum, line 4
// flange-back distance or gauge, then rows "yl zl yr zr"; z up. Each side is taken in its own
// frame with y positive towards its field side (assumption, see README); no real file was
// available to confirm the lateral sign.
RawProfile read_vampire(const std::string& path, const std::vector<std::string>& lines, const std::string& side) {
  RawProfile r;
  r.format = "vampire";
  if (side != "right" && side != "left")
    throw InputError(path, side, "vampire side must be 'right' or 'left'");
  if (lines.size() < 5) throw InputError(path, "", "VAMPIRE file shorter than its 4 header lines");
  const std::string key = trim(lines[0]);
  if (key.rfind("WHEELPROFILE", 0) == 0) r.kind = ProfileKind::Wheel;
  else if (key.rfind("RAILPROFILE", 0) == 0) r.kind = ProfileKind::Rail;
  else throw InputError(at_line(path, 1), "'" + key + "'", "line 1 must be WHEELPROFILE or RAILPROFILE");
  const auto t4 = tokens(lines[3]);
  if (t4.empty()) throw InputError(at_line(path, 4), "", "line 4 must hold the flange-back distance or gauge");
  parse_number(t4[0], at_line(path, 4));
  for (std::size_t i = 4; i < lines.size(); ++i) {
    const std::string where = at_line(path, i + 1);
    const std::string l = trim(lines[i]);
    if (l.empty()) continue;
    const auto t = tokens(l);
    if (t.size() != 4) throw InputError(where, "'" + l + "'", "a VAMPIRE row must be 'yl zl yr zr'");
    double v[4];
    for (int k = 0; k < 4; ++k) v[k] = parse_number(t[k], where);
    if (side == "right") r.add(v[2], v[3], i + 1);
    else r.add(v[0], v[1], i + 1);
  }
  return r;
}

ProfileFormat sniff(const std::vector<std::string>& lines) {
  for (const auto& raw : lines) {
    const std::string l = trim(raw);
    if (l.empty()) continue;
    if (l.rfind("MINIPROF", 0) == 0) return ProfileFormat::MiniProf;
    if (l.rfind("WHEELPROFILE", 0) == 0 || l.rfind("RAILPROFILE", 0) == 0) return ProfileFormat::Vampire;
    break;
  }
  for (const auto& raw : lines) {
    if (raw.find("point.begin") != std::string::npos || raw.find("header.begin") != std::string::npos)
      return ProfileFormat::Simpack;
    if (raw.find("ColumnDef=") != std::string::npos || raw.find("XYPoints=") != std::string::npos)
      return ProfileFormat::MiniProf;
  }
  return ProfileFormat::Table;
}

// ---------------------------------------------------------------------------------------------
// Shape tests, all in the canonical frame (mm), points sorted by file order with y increasing
// on the whole.
struct Shape {
  std::size_t i_min = 0, i_max = 0;  // lowest and highest point
  double y0 = 0, y1 = 0, width = 0;  // y range
  double z_first = 0, z_last = 0;    // z at the two ends (file order)
  double z_at_ymin = 0, z_at_ymax = 0;
};

Shape shape_of(const RawProfile& r) {
  Shape s;
  const auto n = r.size();
  s.i_min = static_cast<std::size_t>(std::min_element(r.z.begin(), r.z.end()) - r.z.begin());
  s.i_max = static_cast<std::size_t>(std::max_element(r.z.begin(), r.z.end()) - r.z.begin());
  const auto iy0 = static_cast<std::size_t>(std::min_element(r.y.begin(), r.y.end()) - r.y.begin());
  const auto iy1 = static_cast<std::size_t>(std::max_element(r.y.begin(), r.y.end()) - r.y.begin());
  s.y0 = r.y[iy0]; s.y1 = r.y[iy1]; s.width = s.y1 - s.y0;
  s.z_at_ymin = r.z[iy0]; s.z_at_ymax = r.z[iy1];
  s.z_first = r.z[0]; s.z_last = r.z[n - 1];
  return s;
}

double frac(const Shape& s, double y) { return s.width > 0 ? (y - s.y0) / s.width : 0.5; }

/// A flange on the gauge side (negative y): the lowest point in the inner 35 % of the width and
/// at least kFlangeHeight_mm below the field-side end.
/// The tip must be a true minimum: the nearer end (the flange back) at least 2 mm higher, so a
/// plain cone (flat_ang200.prw) is not taken for a flange.
bool flange_on_gauge_side(const RawProfile& r, const Shape& s) {
  const double zt = r.z[s.i_min];
  return frac(s, r.y[s.i_min]) < 0.35 && zt <= s.z_at_ymax - L::kFlangeHeight_mm && zt <= s.z_at_ymin - 2.0;
}
bool flange_on_field_side(const RawProfile& r, const Shape& s) {
  const double zt = r.z[s.i_min];
  return frac(s, r.y[s.i_min]) > 0.65 && zt <= s.z_at_ymin - L::kFlangeHeight_mm && zt <= s.z_at_ymax - 2.0;
}
/// A rail head: the highest point inside (5 %…95 % of the width) and both ends at least 5 mm lower.
bool rail_like(const RawProfile& r, const Shape& s) {
  const double f = frac(s, r.y[s.i_max]);
  return f > 0.05 && f < 0.95 && r.z[s.i_max] - s.z_first >= 5.0 && r.z[s.i_max] - s.z_last >= 5.0;
}
/// An upside-down rail head: the lowest point inside (10 %…90 %), both ends ≥ 5 mm higher and a
/// wide bottom (points within 1 mm of the lowest span ≥ 15 mm: a crown of radius ≥ ~30 mm; a
/// conformal groove such as groove_r1002.prr, R = 10 mm, is narrower and passes).
bool upside_down_rail(const RawProfile& r, const Shape& s) {
  const double f = frac(s, r.y[s.i_min]);
  const double zmin = r.z[s.i_min];
  if (!(f > 0.1 && f < 0.9 && s.z_first - zmin >= 5.0 && s.z_last - zmin >= 5.0)) return false;
  double a = 1e300, b = -1e300;
  for (std::size_t k = 0; k < r.size(); ++k)
    if (r.z[k] <= zmin + 1.0) a = std::min(a, r.y[k]), b = std::max(b, r.y[k]);
  return b - a >= 15.0;
}

void reverse_raw(RawProfile& r) {
  std::reverse(r.y.begin(), r.y.end());
  std::reverse(r.z.begin(), r.z.end());
  std::reverse(r.line.begin(), r.line.end());
}

void keep_range(RawProfile& r, std::size_t a, std::size_t b) {  // keep [a, b]
  r.y = std::vector<double>(r.y.begin() + a, r.y.begin() + b + 1);
  r.z = std::vector<double>(r.z.begin() + a, r.z.begin() + b + 1);
  r.line = std::vector<std::size_t>(r.line.begin() + a, r.line.begin() + b + 1);
}

void clean_and_check(RawProfile& r, const std::string& path, const ProfileReadOptions& opt) {
  const std::string kname[] = {"unknown", "wheel", "rail"};
  if (r.size() < L::kMinPoints)
    throw InputError(path, std::to_string(r.size()) + " points",
                     "a profile needs at least " + std::to_string(L::kMinPoints) + " points",
                     "check the file (commented-out points? wrong format?)");
  // Exact duplicates of the previous point.
  std::size_t dups = 0;
  {
    RawProfile c = r;
    c.y.clear(); c.z.clear(); c.line.clear();
    for (std::size_t k = 0; k < r.size(); ++k) {
      if (k > 0 && r.y[k] == c.y.back() && r.z[k] == c.z.back()) { ++dups; continue; }
      c.add(r.y[k], r.z[k], r.line[k]);
    }
    r = c;
  }
  if (dups) r.warnings.push_back("removed " + std::to_string(dups) + " duplicated points");
  if (r.size() == 1)
    throw InputError(path, "y = " + mm(r.y[0]) + ", z = " + mm(r.z[0]), "all points are equal",
                     "the file holds no profile");
  if (r.size() < L::kMinPoints)
    throw InputError(path, std::to_string(r.size()) + " distinct points",
                     "a profile needs at least " + std::to_string(L::kMinPoints) + " points");
  if (r.y.back() < r.y.front()) reverse_raw(r);
  Shape s = shape_of(r);
  if (s.width < L::kMinWidth_mm || s.width > L::kMaxWidth_mm) {
    std::string hint = "check the length unit; use scale";
    if (s.width < L::kMinWidth_mm && s.width * 1000 >= L::kMinWidth_mm) hint = "looks like metres; use scale 1000";
    else if (s.width > L::kMaxWidth_mm && s.width / 1000 <= L::kMaxWidth_mm) hint = "looks like micrometres; use scale 0.001";
    throw InputError(path, "total width " + format_number(s.width) + " mm",
                     "the width of a profile must lie within 5-500 mm", hint);
  }
  // Kind: header/extension, the user's --kind, the shape.
  if (opt.kind != ProfileKind::Unknown && r.kind != ProfileKind::Unknown && opt.kind != r.kind)
    throw InputError(path, std::string("kind ") + to_string(opt.kind),
                     std::string("the file says it is a ") + to_string(r.kind),
                     "drop --kind or use the right file");
  if (r.kind == ProfileKind::Unknown) r.kind = opt.kind;
  if (r.kind == ProfileKind::Unknown) {
    if (flange_on_gauge_side(r, s) || flange_on_field_side(r, s)) r.kind = ProfileKind::Wheel;
    else if (rail_like(r, s)) r.kind = ProfileKind::Rail;
    if (r.kind != ProfileKind::Unknown)
      r.warnings.push_back(std::string("kind '") + to_string(r.kind) + "' guessed from the shape (use --kind to state it)");
  }
  if (opt.check) {
    if (r.kind == ProfileKind::Wheel) {
      if (flange_on_field_side(r, s))
        throw InputError(path, "flange tip at y = " + mm(r.y[s.i_min]),
                         "wheel flange on the field side (positive y); the canonical frame has it at negative y",
                         "use mirror_y (--mirror-y)");
      if (rail_like(r, s) && !flange_on_gauge_side(r, s))
        throw InputError(path, "highest point at y = " + mm(r.y[s.i_max]),
                         "read as a wheel but shaped like a rail head (or a wheel upside down)",
                         "use --kind rail, or mirror_z (--mirror-z) if it is an upside-down wheel");
    } else if (r.kind == ProfileKind::Rail) {
      if (upside_down_rail(r, s))
        throw InputError(path, "lowest point at y = " + mm(r.y[s.i_min]) + " in the middle",
                         "rail upside down: the head top must be the highest point",
                         "use mirror_z (--mirror-z)");
      if (flange_on_gauge_side(r, s) || flange_on_field_side(r, s)) {
        const double f = frac(s, r.y[s.i_min]);
        const bool interior = f > 0.02 && f < 0.98;
        if (interior)
          throw InputError(path, "lowest point at y = " + mm(r.y[s.i_min]),
                           "read as a rail but shaped like a wheel (a flange near one end)",
                           "use --kind wheel or the wheel file");
      }
    }
  }
  // Region that can touch; inside it y must increase strictly; outside, trailing parts that are
  // not monotone in y are clipped off with a warning.
  std::size_t i0 = 0, i1 = r.size() - 1;
  std::string what0 = "start", what1 = "end";
  if (r.kind == ProfileKind::Rail) {
    const double ztop = r.z[s.i_max];
    i0 = i1 = s.i_max;
    while (i0 > 0 && r.z[i0 - 1] > ztop - L::kRailContactDepth_mm) --i0;
    while (i1 + 1 < r.size() && r.z[i1 + 1] > ztop - L::kRailContactDepth_mm) ++i1;
    what0 = "gauge side (flank below the head)";
    what1 = "field side (flank below the head)";
  } else if (r.kind == ProfileKind::Wheel) {
    i0 = s.i_min;
    i1 = static_cast<std::size_t>(std::max_element(r.y.begin() + static_cast<long>(i0), r.y.end()) - r.y.begin());
    what0 = "flange back";
    what1 = "field-side end (rim face)";
  }
  // Measurement jitter: inside the region, a point that does not advance in y, and lies at most
  // kJitter_mm behind the last kept point, is dropped (with a warning); a larger backward step
  // is a loop or zig-zag and an error below.
  {
    std::vector<std::size_t> keep;
    keep.reserve(r.size());
    std::size_t dropped = 0;
    double worst = 0;
    for (std::size_t k = 0; k < r.size(); ++k) {
      if (k > i0 && k <= i1 && !keep.empty() && keep.back() >= i0) {
        const double back = r.y[keep.back()] - r.y[k];
        if (back >= 0 && back <= L::kJitter_mm) {
          ++dropped;
          worst = std::max(worst, back);
          continue;
        }
      }
      keep.push_back(k);
    }
    if (dropped) {
      std::size_t n0 = 0, n1 = 0;
      for (std::size_t j = 0; j < keep.size(); ++j) {
        if (keep[j] == i0) n0 = j;
        if (keep[j] <= i1) n1 = j;
      }
      RawProfile c;
      c.kind = r.kind;
      c.format = r.format;
      c.warnings = r.warnings;
      for (std::size_t k : keep) c.add(r.y[k], r.z[k], r.line[k]);
      r = std::move(c);
      i0 = n0;
      i1 = n1;
      r.warnings.push_back("dropped " + std::to_string(dropped) + " points that stepped back in y by at most " +
                           mm(worst) + " (measurement jitter, at most " + mm(L::kJitter_mm) + ") where contact can happen");
    }
  }
  for (std::size_t k = i0 + 1; k <= i1; ++k)
    if (!(r.y[k] > r.y[k - 1]))
      throw InputError(at_line(path, r.line[k]), "y = " + mm(r.y[k]) + " after y = " + mm(r.y[k - 1]),
                       std::string("y steps backward (a loop or zig-zag) inside the region that can touch the ") +
                           (r.kind == ProfileKind::Wheel ? "rail" : r.kind == ProfileKind::Rail ? "wheel" : "other body"),
                       "fix the points there (remove the loop); y must increase strictly");
  std::size_t a = i0, b = i1;
  while (a > 0 && r.y[a - 1] < r.y[a]) --a;
  while (b + 1 < r.size() && r.y[b + 1] > r.y[b]) ++b;
  if (a > 0) r.warnings.push_back("clipped " + std::to_string(a) + " points not monotone in y at the " + what0);
  if (b + 1 < r.size())
    r.warnings.push_back("clipped " + std::to_string(r.size() - 1 - b) + " points not monotone in y at the " + what1);
  keep_range(r, a, b);
  if (r.size() < L::kMinPoints)
    throw InputError(path, std::to_string(r.size()) + " points left", "too few points after clipping");
  // Taping-line rule for wheels whose file origin is not the taping line (MiniProf: measured
  // from the flange back): if the flange tip is not at negative y, put y = 0 at 70 mm
  // (EN 13715 taping line) from the flange back = the innermost point, lowest y.
  if (r.kind == ProfileKind::Wheel) {
    s = shape_of(r);
    if (flange_on_gauge_side(r, s) && r.y[s.i_min] >= 0) {
      const double shift = s.y0 + L::kTapingLineFromFlangeBack_mm;
      for (auto& y : r.y) y -= shift;
      r.warnings.push_back("y = 0 moved to the taping line, " + mm(L::kTapingLineFromFlangeBack_mm) +
                           " from the flange back at file y = " + mm(s.y0));
    }
  }
}

}  // namespace

ProfileFormat format_from_extension(const std::string& path) {
  const std::string e = extension(path);
  if (e == "prr" || e == "prw") return ProfileFormat::Simpack;
  if (e == "ban" || e == "whl") return ProfileFormat::MiniProf;
  if (e == "txt" || e == "csv" || e == "dat" || e == "wheel" || e == "rail") return ProfileFormat::Table;
  if (e == "whe" || e == "rai") return ProfileFormat::Vampire;
  return ProfileFormat::Auto;
}

Profile read_profile(const std::string& path, const ProfileReadOptions& opt) {
  std::string bytes;
  const auto lines = read_lines(path, bytes);
  const std::string ext = extension(path);
  ProfileFormat f = opt.format;
  if (f == ProfileFormat::Auto) f = format_from_extension(path);
  if (f == ProfileFormat::Auto) f = sniff(lines);
  if (!(opt.scale > 0) || !std::isfinite(opt.scale))
    throw InputError(path, format_number(opt.scale), "scale must be a positive number");
  RawProfile r;
  switch (f) {
    case ProfileFormat::Simpack: r = read_simpack(path, lines); break;
    case ProfileFormat::MiniProf: {
      bool wheel = ext == "whl";
      if (ext != "whl" && ext != "ban") wheel = opt.kind == ProfileKind::Wheel;
      r = read_miniprof(path, lines, wheel);
      break;
    }
    case ProfileFormat::Vampire: r = read_vampire(path, lines, opt.vampire_side); break;
    default: r = read_table(path, lines, ext == "wheel" || ext == "rail"); break;
  }
  // Header type against the extension (a wheel file named .prr, a rail named .whl, ...).
  const ProfileKind ext_kind = kind_from_extension(ext);
  if (r.kind != ProfileKind::Unknown && ext_kind != ProfileKind::Unknown && r.kind != ext_kind)
    throw InputError(path, std::string("header says ") + to_string(r.kind),
                     std::string("but the extension .") + ext + " means a " + to_string(ext_kind),
                     "rename the file or correct the header type (0 rail, 1 wheel)");
  if (r.kind == ProfileKind::Unknown) r.kind = ext_kind;
  // The user's options, after the format's own transformations.
  for (std::size_t k = 0; k < r.size(); ++k) {
    if (opt.mirror_y) r.y[k] = -r.y[k];
    if (opt.mirror_z) r.z[k] = -r.z[k];
    r.y[k] *= opt.scale;
    r.z[k] *= opt.scale;
  }
  clean_and_check(r, path, opt);
  Profile p;
  p.kind = r.kind;
  p.source = path;
  p.format = r.format;
  p.checksum = sha256_hex(bytes);
  p.warnings = r.warnings;
  p.y.resize(r.size());
  p.z.resize(r.size());
  for (std::size_t k = 0; k < r.size(); ++k) p.y[k] = r.y[k] / 1000 + 0.0, p.z[k] = r.z[k] / 1000 + 0.0;  // +0.0: no -0; "/ 1000" so that "* 1000" gives the file digits back
  return p;
}

void write_profile(const Profile& p, const std::string& path) {
  const std::string e = extension(path);
  if (e != "csv" && e != "prr" && e != "prw")
    throw InputError(path, "." + e, "unknown output profile format", "use .csv, .prr or .prw");
  std::string s;
  if (e == "csv") {
    s = "y_mm,z_mm\n";
    for (std::size_t k = 0; k < p.size(); ++k) {
      append_number(s, p.y[k] * 1e3);
      s += ',';
      append_number(s, p.z[k] * 1e3);
      s += '\n';
    }
  } else {
    s = "! SIMPACK profile written by mhcontact from " + (p.source.empty() ? std::string("(generated)") : p.source) +
        " (" + (p.format.empty() ? std::string("?") : p.format) + ")\n";
    s += "! canonical points: y towards the field side, z DOWN (SIMPACK), mm; no transformations\n";
    s += "header.begin\n  version = 1\n  type    = ";
    s += e == "prr" ? "0" : "1";
    s += "\nheader.end\nspline.begin\n  units.len.f = 1000.\n  units.ang.f = 1.\n  point.begin\n";
    for (std::size_t k = 0; k < p.size(); ++k) {
      s += "    ";
      append_number(s, p.y[k] * 1e3);
      s += ' ';
      append_number(s, -p.z[k] * 1e3);
      s += '\n';
    }
    s += "  point.end\nspline.end\n";
  }
  OutputFile out(path);
  out.stream() << s;
  out.commit();
}

}  // namespace mh
