#include "input/manifest.hpp"

#include <glob.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "core/errors.hpp"
#include "input/case_tangential_rcf.hpp"

namespace mh {

using nlohmann::json;

bool is_manifest(const json& j) {
  return j.is_object() && (j.contains("pairs") || j.contains("wheels") || j.contains("rails"));
}

namespace {

const std::vector<std::string> kCommonKeys = {"track", "geometry", "material", "model", "method", "half_space", "strips",
                                               "sweep", "cases", "solver", "friction", "kinematics", "creepages", "fastsim", "rcf"};

// The case of pair k: the manifest's shared keys, the pair's own keys over them (each replacing
// the manifest's key of that name), its profiles. `origins`: the pair's keys' JSON path prefix.
json assemble(const Manifest& m, std::size_t k, std::map<std::string, std::string>* origins) {
  const ManifestPair& p = m.pairs.at(k);
  json c = m.common;
  c.erase("inclination");
  c.erase("nominal_radius_mm");
  for (auto it = p.keys.begin(); it != p.keys.end(); ++it) {
    c[it.key()] = it.value();
    if (origins) (*origins)[it.key()] = "/pairs/" + std::to_string(k);
  }
  c["wheel"] = {{"profile", p.wheel}};
  if (m.common.contains("nominal_radius_mm")) c["wheel"]["nominal_radius_mm"] = m.common["nominal_radius_mm"];
  c["rail"] = {{"profile", p.rail}, {"inclination", m.common["inclination"]}};
  return c;
}

std::string label(const json& spec) {
  if (spec.is_string()) return std::filesystem::path(spec.get<std::string>()).filename().string();
  if (spec.is_object() && spec.contains("standard") && spec["standard"].is_string()) return spec["standard"].get<std::string>();
  if (spec.is_object() && spec.contains("file") && spec["file"].is_string())
    return std::filesystem::path(spec["file"].get<std::string>()).filename().string();
  return spec.dump();
}

// Expand globs in a list of profile specifications.
std::vector<json> expand(const json& list, const std::string& where, const std::string& path) {
  if (!list.is_array() || list.empty())
    throw InputError(path + ": " + where, list.dump(), "must be a non-empty list of profiles (file names, globs or objects)");
  std::vector<json> out;
  const std::filesystem::path base = std::filesystem::path(path).parent_path();
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& e = list[i];
    if (e.is_string() && e.get<std::string>().find_first_of("*?[") != std::string::npos) {
      const std::string pattern = e.get<std::string>();
      const std::string full = std::filesystem::path(pattern).is_absolute() ? pattern : (base / pattern).string();
      glob_t g{};
      const int rc = ::glob(full.c_str(), 0, nullptr, &g);
      std::vector<std::string> files;
      if (rc == 0)
        for (std::size_t k = 0; k < g.gl_pathc; ++k) files.emplace_back(g.gl_pathv[k]);
      ::globfree(&g);
      if (files.empty()) throw InputError(path + ": " + where + "/" + std::to_string(i), e.dump(), "the pattern matches no file");
      std::sort(files.begin(), files.end());
      // Keep matches relative to the manifest, as the pattern was: outputs then do not depend on
      // where the repository or study lives.
      for (auto& f : files)
        out.emplace_back(std::filesystem::path(pattern).is_absolute() ? f : std::filesystem::path(f).lexically_relative(base.empty() ? "." : base).string());
    } else {
      out.push_back(e);
    }
  }
  return out;
}

}  // namespace

Manifest parse_manifest(const json& j, const std::string& path) {
  Manifest m;
  m.path = path;
  auto fail = [&](const std::string& where, const json* v, const std::string& rule, const std::string& hint = {}) {
    throw InputError(path + ": " + where, v ? v->dump() : std::string(), rule, hint);
  };
  if (!j.is_object()) fail("/", &j, "must be an object");
  static const std::vector<std::string> allowed = {"pairs", "wheels", "rails", "inclination", "nominal_radius_mm", "track",
                                                   "geometry", "material", "model", "method", "half_space", "strips",
                                                   "sweep", "cases", "solver", "comment", "friction", "kinematics",
                                                   "creepages", "fastsim", "rcf"};
  for (auto it = j.begin(); it != j.end(); ++it)
    if (std::find(allowed.begin(), allowed.end(), it.key()) == allowed.end())
      fail("/" + it.key(), nullptr, "unknown key in a manifest",
           "allowed: pairs, wheels, rails, inclination, nominal_radius_mm, track, geometry, material, model, method, "
           "half_space, strips, sweep, cases, solver, friction, kinematics, creepages, fastsim, rcf, comment");
  if (!j.contains("inclination"))
    fail("/inclination", nullptr, "required: \"as-is\", \"none\", \"1:40\" or \"1:20\", for every rail of the batch");
  if (j.contains("pairs") && (j.contains("wheels") || j.contains("rails")))
    fail("/pairs", nullptr, "give either \"pairs\" or \"wheels\" and \"rails\", not both");
  if (j.contains("pairs")) {
    const json& a = j["pairs"];
    if (!a.is_array() || a.empty()) fail("/pairs", &a, "must be a non-empty list of {\"name\", \"wheel\", \"rail\"}");
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::string w = "/pairs/" + std::to_string(i);
      if (!a[i].is_object()) fail(w, &a[i], "must be an object {\"name\", \"wheel\", \"rail\"}");
      const auto& own = detail::tangential_rcf_keys();
      ManifestPair p;
      p.keys = json::object();
      for (auto it = a[i].begin(); it != a[i].end(); ++it) {
        if (std::find(own.begin(), own.end(), it.key()) != own.end()) p.keys[it.key()] = it.value();
        else if (it.key() != "name" && it.key() != "wheel" && it.key() != "rail")
          fail(w + "/" + it.key(), nullptr, "unknown key (name, wheel, rail; friction, kinematics, creepages, fastsim, rcf)");
      }
      if (!a[i].contains("wheel") || !a[i].contains("rail")) fail(w, &a[i], "needs \"wheel\" and \"rail\"");
      p.wheel = a[i]["wheel"];
      p.rail = a[i]["rail"];
      if (a[i].contains("name")) {
        if (!a[i]["name"].is_string()) fail(w + "/name", &a[i]["name"], "must be a string");
        p.name = a[i]["name"].get<std::string>();
      } else {
        p.name = label(p.wheel) + " on " + label(p.rail);
      }
      m.pairs.push_back(p);
    }
  } else {
    if (!j.contains("wheels") || !j.contains("rails")) fail("/wheels", nullptr, "a manifest needs \"pairs\", or both \"wheels\" and \"rails\"");
    const auto wheels = expand(j["wheels"], "/wheels", path), rails = expand(j["rails"], "/rails", path);
    for (const auto& w : wheels)
      for (const auto& r : rails) m.pairs.push_back({label(w) + " on " + label(r), w, r});
  }
  m.common = json::object();
  for (const auto& k : kCommonKeys)
    if (j.contains(k)) m.common[k] = j[k];
  m.common["inclination"] = j["inclination"];
  if (j.contains("nominal_radius_mm")) m.common["nominal_radius_mm"] = j["nominal_radius_mm"];
  // Validate the shared fields once, with a placeholder pair (profiles are not read here).
  json probe = m.common;
  probe.erase("inclination");
  probe.erase("nominal_radius_mm");
  probe["wheel"] = {{"profile", {{"standard", "S1002"}}}};
  if (m.common.contains("nominal_radius_mm")) probe["wheel"]["nominal_radius_mm"] = m.common["nominal_radius_mm"];
  probe["rail"] = {{"profile", {{"standard", "60E1"}}}, {"inclination", m.common["inclination"]}};
  const CaseFile shared = parse_case_json(probe, path, true);
  // A pair's own keys through the same rules, its errors at the pair's JSON path. Every pair of a
  // batch writes the same tables: the keys that decide their columns (friction given, rcf, its
  // subsurface stresses) are given for every pair or for none.
  CaseFile first;
  for (std::size_t k = 0; k < m.pairs.size(); ++k) {
    if (k > 0 && m.pairs[k].keys.empty() && m.pairs[0].keys.empty()) continue;  // the shared case's columns
    std::map<std::string, std::string> origins;
    json c = assemble(m, k, &origins);
    c["wheel"]["profile"] = probe["wheel"]["profile"];
    c["rail"]["profile"] = probe["rail"]["profile"];
    const CaseFile cf = m.pairs[k].keys.empty() ? shared : parse_case_json(c, path, true, origins);
    cf.refuse_table_axes();
    if (k == 0) {
      first = cf;
      continue;
    }
    auto differ = [&](bool a, bool b, const char* key, const char* what) {
      if (a == b) return;
      const std::string at = m.pairs[k].keys.contains(key) ? "/pairs/" + std::to_string(k) + "/" + key : "/pairs/" + std::to_string(k);
      fail(at, nullptr,
           std::string("every pair of a batch writes the same columns: ") + what + " for every pair or for none (pair 0 " +
               (a ? "gives it" : "does not") + ")",
           "give it in the manifest's shared keys and change its values per pair");
    };
    differ(first.tangential.enabled(), cf.tangential.enabled(), "friction", "give friction");
    differ(first.rcf.enabled(), cf.rcf.enabled(), "rcf", "give rcf");
    differ(first.rcf.subsurface, cf.rcf.subsurface, "rcf", "give rcf.subsurface");
  }
  return m;
}

CaseFile pair_case(const Manifest& m, std::size_t k) {
  const ManifestPair& p = m.pairs.at(k);
  std::map<std::string, std::string> origins;
  const json c = assemble(m, k, &origins);
  try {
    return parse_case_json(c, m.path, true, origins);
  } catch (const InputError& e) {
    throw InputError(m.path + ": pair " + std::to_string(k) + " (" + p.name + ")", e.value(), e.rule() + " [" + e.where() + "]", e.hint());
  }
}

}  // namespace mh
