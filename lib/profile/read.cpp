// Reading a profile file: the format from the extension or the content, the format's reader,
// the user's transformations, the shape checks, then the canonical Profile in metres.
#include "profile/read.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/checksum.hpp"
#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "profile/formats/formats.hpp"

namespace mh {

using namespace formats;

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

ProfileCleanup parse_profile_cleanup(const std::string& s) {
  if (s == "envelope" || s == "on") return ProfileCleanup::Envelope;
  if (s == "strict") return ProfileCleanup::Strict;
  if (s == "off") return ProfileCleanup::Off;
  throw std::invalid_argument("unknown clean-up '" + s + "' (expected envelope, strict or off)");
}

const char* to_string(ProfileCleanup c) {
  switch (c) {
    case ProfileCleanup::Envelope: return "envelope";
    case ProfileCleanup::Strict: return "strict";
    case ProfileCleanup::Off: return "off";
  }
  return "?";
}

ProfileFormat format_from_extension(const std::string& path) {
  const std::string e = extension(path);
  if (e == "prr" || e == "prw") return ProfileFormat::Simpack;
  if (e == "ban" || e == "whl" || e == "mpt") return ProfileFormat::MiniProf;
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
  if (opt.section < 0)
    throw InputError(path, std::to_string(opt.section), "a section is a profile number K >= 1 ([Profile<K>Info])");
  if (opt.section > 0 && f != ProfileFormat::MiniProf)
    throw InputError(path, "section " + std::to_string(opt.section),
                     std::string("a section applies only to multi-profile MiniProf files, not to a ") + to_string(f) + " file",
                     "drop \"section\" (--section)");
  RawProfile r;
  switch (f) {
    case ProfileFormat::Simpack: r = read_simpack(path, lines); break;
    case ProfileFormat::MiniProf: {
      ProfileKind hint = ext == "whl" ? ProfileKind::Wheel : ext == "ban" ? ProfileKind::Rail : opt.kind;
      r = read_miniprof(path, lines, hint, opt.section);
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
  p.cleanup = r.cleanup;
  p.taping_line = r.taping_line;
  p.file_measures = r.measures;
  p.print_step = r.print_step * opt.scale / 1000;
  if (!r.line_step.empty()) {
    p.point_step.resize(r.size());
    for (std::size_t k = 0; k < r.size(); ++k) p.point_step[k] = r.step_of_line(r.line[k]) * opt.scale / 1000;
  }
  p.y.resize(r.size());
  p.z.resize(r.size());
  for (std::size_t k = 0; k < r.size(); ++k) p.y[k] = r.y[k] / 1000 + 0.0, p.z[k] = r.z[k] / 1000 + 0.0;  // +0.0: no -0; "/ 1000" so that "* 1000" gives the file digits back
  for (std::size_t k = 0; k < r.face_y.size(); ++k)
    p.face_y.push_back(r.face_y[k] / 1000 + 0.0), p.face_z.push_back(r.face_z[k] / 1000 + 0.0);
  return p;
}

}  // namespace mh
