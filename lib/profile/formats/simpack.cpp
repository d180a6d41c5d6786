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
      r.add(t[0], t[1], where, i + 1);
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
      if (t.empty()) throw InputError(where, "'" + val + "'", "key " + key + " needs a number", "write " + key + " = <number>, or drop the line");
      return parse_number(t[0], where);
    };
    if (state == Header) {
      if (key == "type") {
        const double v = num();
        if (v != 0 && v != 1)
          throw InputError(where, "type = " + tokens(val)[0], "header type must be 0 (rail) or 1 (wheel)", "write type = 0 or type = 1");
        type = static_cast<int>(v);
      }
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
    throw InputError(path, "type = " + std::to_string(type), "header type must be 0 (rail) or 1 (wheel)", "write type = 0 or type = 1 between header.begin and header.end");
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
  t.print_step = r.print_step * to_mm;
  for (double& q : t.line_step) q *= to_mm;
  if (inversion) {
    std::reverse(t.y.begin(), t.y.end());
    std::reverse(t.z.begin(), t.z.end());
    std::reverse(t.line.begin(), t.line.end());
  }
  return t;
}

std::string write_simpack(const Profile& p, bool wheel) {
  std::string s = "! SIMPACK profile " + provenance(p) + "\n";
  s += "! canonical points: y towards the field side, z DOWN (SIMPACK), mm; no transformations\n";
  s += "header.begin\n  version = 1\n  type    = ";
  s += wheel ? "1" : "0";
  s += "\nheader.end\nspline.begin\n  units.len.f = 1000.\n  units.ang.f = 1.\n  point.begin\n";
  for (std::size_t k = 0; k < p.size(); ++k) {
    s += "    ";
    append_number(s, p.y[k] * 1e3);
    s += ' ';
    append_number(s, -p.z[k] * 1e3);
    s += '\n';
  }
  s += "  point.end\nspline.end\n";
  return s;
}

}  // namespace mh::formats
