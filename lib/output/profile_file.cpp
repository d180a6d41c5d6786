#include "output/profile_file.hpp"

#include <cctype>
#include <string>

#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "output/output_file.hpp"

namespace mh {

namespace {
std::string extension(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string e = path.substr(dot + 1);
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}
}  // namespace

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
