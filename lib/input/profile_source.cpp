// Profile sources of the case file; see profile_source.hpp.
#include "input/profile_source.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/errors.hpp"
#include "profile/standard_profiles.hpp"
#include "core/units.hpp"

namespace mh {

using nlohmann::json;

namespace {

std::string resolve_path(const std::string& case_path, const std::string& p) {
  std::filesystem::path q(p);
  if (q.is_absolute()) return p;
  return (std::filesystem::path(case_path).parent_path() / q).lexically_normal().string();
}

}  // namespace

namespace detail {

ProfileSource parse_profile_source(const Ctx& c, const json& v, const std::string& path, const std::string& case_path) {
  ProfileSource s;
  s.json_path = path;
  s.case_file = case_path;
  if (v.is_string()) {
    s.given = v.get<std::string>();
    s.file = resolve_path(case_path, s.given);
    return s;
  }
  if (!v.is_object()) c.fail(path, &v, "a profile is a file name, {\"file\": ...} or {\"standard\": ...}");
  if (v.contains("standard")) {
    c.only_keys(v, path, {"standard", "step_mm"});
    s.standard = c.string(v, path, "standard");
    if (v.contains("step_mm")) s.step = c.positive(v, path, "step_mm") * units::mm;
    return s;
  }
  c.only_keys(v, path, {"file", "format", "mirror_y", "mirror_z", "scale", "kind", "vampire_side", "check", "cleanup", "section"});
  if (!v.contains("file")) c.fail(path, &v, "a profile object needs \"file\" (or \"standard\")");
  s.given = c.string(v, path, "file");
  s.file = resolve_path(case_path, s.given);
  if (v.contains("format")) {
    try {
      s.read.format = parse_profile_format(c.string(v, path, "format"));
    } catch (const std::invalid_argument& e) {
      c.fail(path + "/format", &v.at("format"), e.what());
    }
  }
  if (v.contains("mirror_y")) s.read.mirror_y = c.boolean(v, path, "mirror_y");
  if (v.contains("mirror_z")) s.read.mirror_z = c.boolean(v, path, "mirror_z");
  if (v.contains("scale")) s.read.scale = c.positive(v, path, "scale");
  if (v.contains("check")) s.read.check = c.boolean(v, path, "check");
  if (v.contains("cleanup")) {
    try {
      s.read.cleanup = parse_profile_cleanup(c.string(v, path, "cleanup"));
    } catch (const std::invalid_argument& e) {
      c.fail(path + "/cleanup", &v.at("cleanup"), e.what());
    }
  }
  if (v.contains("vampire_side")) {
    s.read.vampire_side = c.string(v, path, "vampire_side");
    if (s.read.vampire_side != "left" && s.read.vampire_side != "right")
      c.fail(path + "/vampire_side", &v.at("vampire_side"), "must be \"left\" or \"right\"");
  }
  // Multi-profile MiniProf files (.mpt): which profile, K of [Profile<K>Info] (docs/profiles.md).
  if (v.contains("section")) {
    const json& k = v.at("section");
    if (!k.is_number_unsigned() || k.get<std::uint64_t>() < 1 || k.get<std::uint64_t>() > 1000000)
      c.fail(path + "/section", &k, "section must be a whole number K >= 1: the profile [Profile<K>Info] of a multi-profile MiniProf file");
    s.read.section = static_cast<int>(k.get<std::uint64_t>());
  }
  if (v.contains("kind")) c.fail(path + "/kind", &v.at("kind"), "the kind follows from the section (wheel or rail)");
  return s;
}

}  // namespace detail

Profile load_profile(const ProfileSource& src, ProfileKind kind, Inclination incl) {
  Profile p;
  if (!src.standard.empty()) {
    ProfileKind k;
    try {
      k = standard_profile_kind(src.standard);
    } catch (const InputError& e) {
      throw InputError(src.case_file + ": " + src.json_path + "/standard", "\"" + src.standard + "\"", e.rule(), e.hint());
    }
    if (k != kind)
      throw InputError(src.case_file + ": " + src.json_path + "/standard", "\"" + src.standard + "\"",
                       std::string("is a ") + to_string(k) + " profile, but a " + to_string(kind) + " is needed here");
    // The generator applies the inclination itself (it knows where a 1:20 flank turns vertical).
    return make_standard_profile(src.standard, kind == ProfileKind::Rail ? incl : Inclination::None, src.step);
  }
  // A standard's name given as a file name ("60E1", or "60e1" as typed): no such file, and the
  // fix is the object with the name spelt as the generator knows it.
  std::error_code ec;
  const auto same_letters = [](const std::string& a, const std::string& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
             return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
  };
  if (!src.case_file.empty() && !std::filesystem::exists(src.file, ec))
    for (const std::string& name : standard_profile_names())
      if (same_letters(name, src.given))
        throw InputError(src.case_file + ": " + src.json_path, "\"" + src.given + "\"",
                         "no such profile file (" + src.file + "); \"" + name + "\" is the name of a standard profile",
                         "write {\"standard\": \"" + name + "\"} to generate it from its definition: docs/case-file.md");
  ProfileReadOptions o = src.read;
  o.kind = kind;
  try {
    p = read_profile(src.file, o);
  } catch (const InputError& e) {
    // Say which entry of the case file named the profile, then the profile's own location.
    if (src.case_file.empty()) throw;
    throw InputError(src.case_file + ": " + src.json_path + ": " + e.where(), e.value(), e.rule(), e.hint());
  }
  if (kind == ProfileKind::Rail) rotate_towards_track_centre(p, inclination_angle(incl));
  return p;
}

}  // namespace mh
