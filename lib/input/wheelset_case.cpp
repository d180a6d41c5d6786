// The wheelset case file; see wheelset_case.hpp.
#include "input/wheelset_case.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <glob.h>

#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "core/units.hpp"
#include "input/json_fields.hpp"
#include "input/profile_source.hpp"

namespace mh {

using nlohmann::json;
using detail::Ctx;

namespace {

/// A list of numbers or {"from", "to", "step"} [mm], values in [lo, hi]; ranges are generated in
/// integers of the step's decimals so that 0.01 steps print as 0.01, 0.02, ...
std::vector<double> parse_values(const Ctx& c, const json& v, const std::string& path, double lo, double hi,
                                 std::size_t max_n) {
  std::vector<double> out;
  if (v.is_array()) {
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (!v[i].is_number() || !std::isfinite(v[i].get<double>())) c.fail(path + "/" + std::to_string(i), &v[i], "must be a finite number");
      out.push_back(v[i].get<double>());
    }
  } else if (v.is_object()) {
    c.only_keys(v, path, {"from", "to", "step"});
    for (const char* k : {"from", "to", "step"})
      if (!v.contains(k)) c.fail(path, &v, std::string("a range needs \"") + k + "\"");
    const double from = c.number(v, path, "from"), to = c.number(v, path, "to"), step = c.number(v, path, "step");
    if (!(step > 0)) c.fail(path + "/step", &v.at("step"), "must be > 0");
    if (to < from) c.fail(path + "/to", &v.at("to"), "must be >= from (" + format_number(from) + ")");
    const double n = std::floor((to - from) / step + 1e-9) + 1;
    if (!(n <= static_cast<double>(max_n))) c.fail(path, &v, "gives " + format_number(n) + " values, more than " + std::to_string(max_n));
    int d = 0;
    while (d < 9 && std::fabs(std::round(step * std::pow(10, d)) - step * std::pow(10, d)) > 1e-9) ++d;
    while (d < 9 && std::fabs(std::round(from * std::pow(10, d)) - from * std::pow(10, d)) > 1e-9) ++d;
    const double sc = std::pow(10, d);
    const long long F = std::llround(from * sc), S = std::llround(step * sc);
    for (long long i = 0; i < static_cast<long long>(n); ++i) out.push_back(static_cast<double>(F + S * i) / sc);
  } else {
    c.fail(path, &v, "a list of numbers or {\"from\", \"to\", \"step\"}");
  }
  if (out.empty()) c.fail(path, &v, "gives no values");
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (out[i] < lo || out[i] > hi)
      c.fail(path, &v, "value " + format_number(out[i]) + " outside " + format_number(lo) + " … " + format_number(hi) + " mm");
    if (i > 0 && !(out[i] > out[i - 1])) c.fail(path, &v, "values must increase");
  }
  return out;
}

/// A length given as one number or {"left": ..., "right": ...} [mm], each in [lo, hi].
void parse_pair(const Ctx& c, const json& obj, const std::string& path, const std::string& key, double lo, double hi,
                double& left, double& right) {
  const json& v = obj.at(key);
  const std::string p = path + "/" + key;
  auto check = [&](double d, const std::string& q, const json& x) {
    if (d < lo || d > hi) c.fail(q, &x, "must lie in " + format_number(lo) + " … " + format_number(hi) + " mm");
    return d * units::mm;
  };
  if (v.is_object()) {
    c.only_keys(v, p, {"left", "right"});
    if (!v.contains("left") || !v.contains("right")) c.fail(p, &v, "needs \"left\" and \"right\"");
    left = check(c.number(v, p, "left"), p + "/left", v.at("left"));
    right = check(c.number(v, p, "right"), p + "/right", v.at("right"));
  } else {
    left = right = check(c.number(obj, path, key), p, v);
  }
}

std::vector<json> expand_globs(const Ctx& c, const json& list, const std::string& path) {
  if (!list.is_array() || list.empty()) c.fail("/wheels", &list, "must be a non-empty list of profiles (file names, globs or objects)");
  std::vector<json> out;
  const std::filesystem::path base = std::filesystem::path(path).parent_path();
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& e = list[i];
    if (!(e.is_string() && e.get<std::string>().find_first_of("*?[") != std::string::npos)) {
      out.push_back(e);
      continue;
    }
    const std::string pattern = e.get<std::string>();
    const bool abs = std::filesystem::path(pattern).is_absolute();
    glob_t g{};
    std::vector<std::string> files;
    if (::glob((abs ? pattern : (base / pattern).string()).c_str(), 0, nullptr, &g) == 0)
      for (std::size_t k = 0; k < g.gl_pathc; ++k) files.emplace_back(g.gl_pathv[k]);
    ::globfree(&g);
    if (files.empty()) c.fail("/wheels/" + std::to_string(i), &e, "the pattern matches no file");
    std::sort(files.begin(), files.end());
    for (auto& f : files)
      out.emplace_back(abs ? f : std::filesystem::path(f).lexically_relative(base.empty() ? "." : base).string());
  }
  return out;
}

}  // namespace

WheelsetCase load_wheelset_case(const std::string& path) { return parse_wheelset_json(read_json_file(path), path); }

WheelsetCase parse_wheelset_json(const json& j, const std::string& path) {
  const Ctx c{path, {}};
  WheelsetCase w;
  w.path = path;
  // A contact case file (mhcontact run) given here: say where its placement goes, not only that
  // its keys are unknown.
  if (j.is_object())
    for (const char* k : {"track", "material", "sweep", "method", "model", "friction", "kinematics", "geometry"})
      if (j.contains(k))
        c.fail(std::string("/") + k, nullptr, "a key of a contact case file (mhcontact run), not of a wheelset case file",
               "a wheelset case places the rails by rail.gauge_mm, rail.gauge_height_mm or rail.placement \"absolute\", "
               "and the wheels by wheelset.flange_back_distance_mm, wheelset.flange_back_position_mm, "
               "wheelset.nominal_radius_mm; it needs no material or sweep: docs/wheelset.md \"Case file\"");
  c.only_keys(j, "", {"comment", "wheel", "wheels", "rail", "wheelset", "y_mm", "amplitudes_mm"});
  if (j.contains("wheel") == j.contains("wheels"))
    c.fail("", nullptr, "give either \"wheel\" (one wheelset) or \"wheels\" (a fleet)");
  if (j.contains("wheel")) {
    const json& v = j.at("wheel");
    if (v.is_object() && v.contains("nominal_radius_mm"))
      c.fail("/wheel/nominal_radius_mm", &v.at("nominal_radius_mm"), "the wheels' radius is a key of \"wheelset\" here",
             "write it as wheelset.nominal_radius_mm, one number or {\"left\": …, \"right\": …}: docs/wheelset.md \"Case file\"");
    c.only_keys(v, "/wheel", {"profile", "left", "right"});
    if (v.contains("profile")) {
      if (v.contains("left") || v.contains("right")) c.fail("/wheel", &v, "give \"profile\" (mirrored) or \"left\" and \"right\"");
      w.wheel_left = w.wheel_right = detail::parse_profile_source(c, v.at("profile"), "/wheel/profile", path);
    } else {
      if (!v.contains("left") || !v.contains("right")) c.fail("/wheel", &v, "needs \"profile\", or \"left\" and \"right\"");
      w.wheel_left = detail::parse_profile_source(c, v.at("left"), "/wheel/left", path);
      w.wheel_right = detail::parse_profile_source(c, v.at("right"), "/wheel/right", path);
      w.one_wheel = false;
    }
  } else {
    w.is_fleet = true;
    const std::vector<json> list = expand_globs(c, j.at("wheels"), path);
    for (std::size_t i = 0; i < list.size(); ++i)
      w.fleet.push_back(detail::parse_profile_source(c, list[i], "/wheels/" + std::to_string(i), path));
  }
  if (!j.contains("rail")) c.fail("/rail", nullptr, "missing", "the rail profile(s), inclination and placement");
  const json& r = j.at("rail");
  c.only_keys(r, "/rail", {"profile", "left", "right", "inclination", "placement", "gauge_mm", "gauge_height_mm", "origin_mm"});
  if (r.contains("profile")) {
    w.rail_left = w.rail_right = detail::parse_profile_source(c, r.at("profile"), "/rail/profile", path);
  } else {
    if (!r.contains("left") || !r.contains("right")) c.fail("/rail", &r, "needs \"profile\", or \"left\" and \"right\"");
    w.rail_left = detail::parse_profile_source(c, r.at("left"), "/rail/left", path);
    w.rail_right = detail::parse_profile_source(c, r.at("right"), "/rail/right", path);
    w.one_rail = false;
  }
  if (!r.contains("inclination"))
    c.fail("/rail/inclination", nullptr, "missing: the rail's cant must be stated",
           "\"as-is\" for a profile already canted (EN 15302 rail A: 1:20), \"1:40\" or \"1:20\" to cant an upright one");
  try {
    w.inclination = parse_inclination(c.string(r, "/rail", "inclination"));
  } catch (const std::invalid_argument& e) {
    c.fail("/rail/inclination", &r.at("inclination"), e.what());
  }
  WheelsetPlacement& P = w.placement;
  const std::string placement = r.contains("placement") ? c.string(r, "/rail", "placement") : "gauge";
  if (placement == "gauge") {
    if (r.contains("origin_mm")) c.fail("/rail/origin_mm", &r.at("origin_mm"), "only with placement \"absolute\"");
    if (r.contains("gauge_mm")) {
      const double g = c.number(r, "/rail", "gauge_mm");
      if (g < 500 || g > 2000) c.fail("/rail/gauge_mm", &r.at("gauge_mm"), "must lie in 500 … 2000 mm", "is it in metres? give mm");
      P.gauge = g * units::mm;
    }
    if (r.contains("gauge_height_mm")) {
      const double g = c.number(r, "/rail", "gauge_height_mm");
      if (g < 0 || g > 30) c.fail("/rail/gauge_height_mm", &r.at("gauge_height_mm"), "must lie in 0 … 30 mm");
      P.gauge_height = g * units::mm;
    }
  } else if (placement == "absolute") {
    P.rails = WheelsetPlacement::Rails::Absolute;
    if (!r.contains("origin_mm")) c.fail("/rail/origin_mm", nullptr, "missing: absolute placement needs |Y| of the rail origins", "e.g. 750");
    if (r.contains("gauge_mm")) c.fail("/rail/gauge_mm", &r.at("gauge_mm"), "only with placement \"gauge\"");
    parse_pair(c, r, "/rail", "origin_mm", 250, 1000, P.rail_origin_left, P.rail_origin_right);
  } else {
    c.fail("/rail/placement", &r.at("placement"), "must be \"gauge\" or \"absolute\"");
  }
  if (j.contains("wheelset")) {
    const json& s = j.at("wheelset");
    c.only_keys(s, "/wheelset", {"flange_back_distance_mm", "flange_back_position_mm", "nominal_radius_mm", "roll"});
    if (s.contains("flange_back_distance_mm")) {
      const double d = c.number(s, "/wheelset", "flange_back_distance_mm");
      if (d < 500 || d > 2000) c.fail("/wheelset/flange_back_distance_mm", &s.at("flange_back_distance_mm"), "must lie in 500 … 2000 mm");
      P.flange_back_distance = d * units::mm;
    }
    if (s.contains("flange_back_position_mm")) {
      const double d = c.number(s, "/wheelset", "flange_back_position_mm");
      if (d < -150 || d > 0) c.fail("/wheelset/flange_back_position_mm", &s.at("flange_back_position_mm"), "must lie in -150 … 0 mm");
      P.flange_back_position = d * units::mm;
    }
    if (s.contains("nominal_radius_mm"))
      parse_pair(c, s, "/wheelset", "nominal_radius_mm", 100, 1000, P.nominal_radius_left, P.nominal_radius_right);
    if (s.contains("roll")) {
      try {
        w.options.roll = parse_wheelset_roll(c.string(s, "/wheelset", "roll"));
      } catch (const std::invalid_argument& e) {
        c.fail("/wheelset/roll", &s.at("roll"), e.what(), "\"none\": the EN 15302 reference convention");
      }
    }
  }
  w.y_mm = j.contains("y_mm") ? parse_values(c, j.at("y_mm"), "/y_mm", -40, 40, 1000000)
                              : parse_values(c, json{{"from", -8}, {"to", 8}, {"step", 0.01}}, "/y_mm", -40, 40, 1000000);
  if (w.y_mm.size() < 3) c.fail("/y_mm", &j.at("y_mm"), "needs at least 3 values (Δr is integrated over y)");
  w.amplitudes_mm = j.contains("amplitudes_mm")
                        ? parse_values(c, j.at("amplitudes_mm"), "/amplitudes_mm", 1e-3, 20, 10000)
                        : parse_values(c, json{{"from", 1}, {"to", 7.4}, {"step", 0.2}}, "/amplitudes_mm", 1e-3, 20, 10000);
  for (double v : w.y_mm) w.y.push_back(v * units::mm);
  for (double v : w.amplitudes_mm) w.amplitudes.push_back(v * units::mm);
  return w;
}

nlohmann::json WheelsetCase::resolved_json() const {
  nlohmann::ordered_json j;
  j["case_file"] = path;
  j["inclination"] = to_string(inclination);
  j["placement"] = placement.rails == WheelsetPlacement::Rails::Gauge ? "gauge" : "absolute";
  if (placement.rails == WheelsetPlacement::Rails::Gauge) {
    j["gauge_mm"] = placement.gauge * units::per_mm;
    j["gauge_height_mm"] = placement.gauge_height * units::per_mm;
  }
  j["flange_back_distance_mm"] = placement.flange_back_distance * units::per_mm;
  j["flange_back_position_mm"] = placement.flange_back_position * units::per_mm;
  j["nominal_radius_mm"] = {{"left", placement.nominal_radius_left * units::per_mm},
                            {"right", placement.nominal_radius_right * units::per_mm}};
  j["roll"] = to_string(options.roll);
  return j;
}

}  // namespace mh
