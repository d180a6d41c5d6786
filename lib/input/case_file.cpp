#include "input/case_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "core/plausible.hpp"
#include "profile/standard_profiles.hpp"
#include "core/units.hpp"

namespace mh {

using nlohmann::json;

const char* to_string(Model m) { return m == Model::Plastic ? "plastic" : "elastic"; }

namespace {

// Validation context: file name + JSON path.
struct Ctx {
  std::string file;
  [[noreturn]] void fail(const std::string& path, const json* v, const std::string& rule,
                         const std::string& hint = {}) const {
    throw InputError(file + ": " + (path.empty() ? "/" : path), v ? v->dump() : std::string(), rule, hint);
  }
  void only_keys(const json& obj, const std::string& path, const std::set<std::string>& allowed) const {
    if (!obj.is_object()) fail(path, &obj, "must be an object");
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      if (!allowed.count(it.key())) {
        std::string list;
        for (const auto& k : allowed) list += (list.empty() ? "" : ", ") + k;
        fail(path + "/" + it.key(), nullptr, "unknown key", "allowed here: " + list);
      }
    }
  }
  double number(const json& obj, const std::string& path, const std::string& key) const {
    const json& v = obj.at(key);
    if (!v.is_number()) fail(path + "/" + key, &v, "must be a number");
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(path + "/" + key, &v, "must be finite");
    return d;
  }
  double positive(const json& obj, const std::string& path, const std::string& key) const {
    const double d = number(obj, path, key);
    if (!(d > 0)) fail(path + "/" + key, &obj.at(key), "must be > 0");
    return d;
  }
  /// A number inside its plausible range (core/plausible.hpp), refused with the unit hint.
  double plausible(const json& obj, const std::string& path, const std::string& key, const plausible::Range& r) const {
    const double d = number(obj, path, key);
    check(d, path + "/" + key, obj.at(key), r);
    return d;
  }
  void check(double d, const std::string& path, const json& v, const plausible::Range& r) const {
    if (!plausible::inside(r, d)) fail(path, &v, plausible::rule(r), plausible::hint(r, d));
  }
  /// An integer in [lo, hi], range-checked as an integer before any conversion (4294967297 must
  /// not wrap to 1, 1e3 or 2.5 are not integers).
  long long integer(const json& obj, const std::string& path, const std::string& key, long long lo, long long hi,
                    std::string rule = {}) const {
    const json& v = obj.at(key);
    if (rule.empty()) rule = "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (!v.is_number_integer()) fail(path + "/" + key, &v, rule);
    bool in_range;
    if (v.is_number_unsigned()) {
      const std::uint64_t u = v.get<std::uint64_t>();  // compared as unsigned first: no wrap
      in_range = hi >= 0 && u <= static_cast<std::uint64_t>(hi) && static_cast<long long>(u) >= lo;
    } else {
      const std::int64_t i = v.get<std::int64_t>();
      in_range = i >= lo && i <= hi;
    }
    if (!in_range) fail(path + "/" + key, &v, rule);
    return v.is_number_unsigned() ? static_cast<long long>(v.get<std::uint64_t>()) : static_cast<long long>(v.get<std::int64_t>());
  }
  bool boolean(const json& obj, const std::string& path, const std::string& key) const {
    const json& v = obj.at(key);
    if (!v.is_boolean()) fail(path + "/" + key, &v, "must be true or false");
    return v.get<bool>();
  }
  std::string string(const json& obj, const std::string& path, const std::string& key) const {
    const json& v = obj.at(key);
    if (!v.is_string()) fail(path + "/" + key, &v, "must be a string");
    return v.get<std::string>();
  }
};

std::string resolve_path(const std::string& case_path, const std::string& p) {
  std::filesystem::path q(p);
  if (q.is_absolute()) return p;
  return (std::filesystem::path(case_path).parent_path() / q).lexically_normal().string();
}

ProfileSource parse_profile_source(const Ctx& c, const json& v, const std::string& path, const std::string& case_path) {
  ProfileSource s;
  s.json_path = path;
  s.case_file = case_path;
  if (v.is_string()) {
    s.file = resolve_path(case_path, v.get<std::string>());
    return s;
  }
  if (!v.is_object()) c.fail(path, &v, "a profile is a file name, {\"file\": ...} or {\"standard\": ...}");
  if (v.contains("standard")) {
    c.only_keys(v, path, {"standard", "step_mm"});
    s.standard = c.string(v, path, "standard");
    if (v.contains("step_mm")) s.step = c.positive(v, path, "step_mm") * units::mm;
    return s;
  }
  c.only_keys(v, path, {"file", "format", "mirror_y", "mirror_z", "scale", "kind", "vampire_side", "check", "cleanup"});
  if (!v.contains("file")) c.fail(path, &v, "a profile object needs \"file\" (or \"standard\")");
  s.file = resolve_path(case_path, c.string(v, path, "file"));
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
  if (v.contains("kind")) c.fail(path + "/kind", &v.at("kind"), "the kind follows from the section (wheel or rail)");
  return s;
}

// Decimal places of the shortest representation of v ("0.3" -> 1, "1e-05" -> 5, "2.5e-07" -> 8,
// "1e+20" -> 0).
int decimals(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  const std::string t(buf, r.ptr);
  const auto e = t.find('e');
  const std::string mant = t.substr(0, e);
  const int exp10 = e == std::string::npos ? 0 : std::stoi(t.substr(e + 1));
  const auto dot = mant.find('.');
  const int frac = dot == std::string::npos ? 0 : static_cast<int>(mant.size() - dot - 1);
  return std::max(0, frac - exp10);
}

// A range {from, to, step} counted and, where the inputs are short decimals, scaled to integers:
// F = from·10^d, S = step·10^d, T = to·10^d with d the most decimals of the three. Values are
// F + i·S for i = 0 … n−1 with n = floor((T − F) / S) + 1: `to` is included when it lies on the
// grid (exactly, in the decimals given), otherwise the last value is the largest grid value below
// `to`. Long decimals (d > 15) or huge integers fall back to from + i·step with a 1e-9 tolerance.
struct RangeCount {
  double count = 0;
  long long F = 0, S = 0;
  double scale = 0;
};
RangeCount range_count(double from, double to, double step) {
  RangeCount rc;
  const int d = std::max({decimals(from), decimals(to), decimals(step)});
  if (d <= 15) {
    const double sc = std::pow(10.0, d);
    const double f = std::round(from * sc), t = std::round(to * sc), st = std::round(step * sc);
    const double lim = 9007199254740992.0;  // 2^53: integers exact in a double
    if (std::fabs(f) < lim && std::fabs(t) < lim && st >= 1 && st < lim && f / sc == from && t / sc == to && st / sc == step) {
      rc.F = static_cast<long long>(f);
      rc.S = static_cast<long long>(st);
      rc.scale = sc;
      rc.count = static_cast<double>((static_cast<long long>(t) - rc.F) / rc.S) + 1;
      return rc;
    }
  }
  rc.count = std::floor((to - from) / step + 1e-9) + 1;
  return rc;
}

// Number of values an axis will have (0 when malformed: parse_axis then reports the error).
double axis_count(const json& v) {
  if (v.is_array()) return static_cast<double>(v.size());
  if (v.is_number()) return 1;
  if (v.is_object() && v.contains("from") && v.contains("to") && v.contains("step") && v["from"].is_number() &&
      v["to"].is_number() && v["step"].is_number()) {
    const double from = v["from"].get<double>(), to = v["to"].get<double>(), step = v["step"].get<double>();
    if (std::isfinite(from) && std::isfinite(to) && step > 0 && to >= from && std::isfinite((to - from) / step))
      return range_count(from, to, step).count;
  }
  return 0;
}

// A sweep axis: a list of numbers or {"from", "to", "step"} (a range is not materialised).
// Every value lies in the plausible range `r` (core/plausible.hpp): each list entry is checked,
// a range by its first and last value.
SweepAxis parse_axis(const Ctx& c, const json& v, const std::string& path, const plausible::Range& r) {
  SweepAxis out;
  if (v.is_array()) {
    if (v.empty()) c.fail(path, &v, "an empty list gives no cases");
    for (std::size_t i = 0; i < v.size(); ++i) {
      const std::string p = path + "/" + std::to_string(i);
      if (!v[i].is_number() || !std::isfinite(v[i].get<double>())) c.fail(p, &v[i], "must be a finite number");
      const double d = v[i].get<double>();
      c.check(d, p, v[i], r);
      out.list.push_back(d);
    }
    out.n = out.list.size();
    return out;
  }
  if (v.is_number()) {
    const double d = v.get<double>();
    if (!std::isfinite(d)) c.fail(path, &v, "must be a finite number");
    c.check(d, path, v, r);
    out.list = {d};
    out.n = 1;
    return out;
  }
  if (!v.is_object()) c.fail(path, &v, "a sweep axis is a list of numbers or {\"from\", \"to\", \"step\"}");
  c.only_keys(v, path, {"from", "to", "step"});
  for (const char* k : {"from", "to", "step"})
    if (!v.contains(k)) c.fail(path, &v, std::string("a range needs \"") + k + "\"");
  const double from = c.number(v, path, "from"), to = c.number(v, path, "to");
  const double step = c.number(v, path, "step");
  if (!(step > 0)) c.fail(path + "/step", &v.at("step"), "must be > 0");
  if (to < from) c.fail(path + "/to", &v.at("to"), "must be >= from (" + format_number(from) + ")");
  const RangeCount rc = range_count(from, to, step);
  if (!(rc.count <= static_cast<double>(kMaxCases)))
    c.fail(path, &v, "gives " + format_number(rc.count) + " values, more than the limit of " + std::to_string(kMaxCases) + " cases");
  out.from = from;
  out.step = step;  // values from + i·step, by multiplication (or scaled integers): no accumulated drift
  out.n = static_cast<std::uint64_t>(rc.count);
  out.F = rc.F;
  out.S = rc.S;
  out.scale = rc.scale;
  c.check(out.at(0), path + "/from", v.at("from"), r);
  c.check(out.at(out.n - 1), path + "/to", v.at("to"), r);
  return out;
}

}  // namespace

double SweepAxis::min() const {
  return list.empty() ? from : *std::min_element(list.begin(), list.end());
}
double SweepAxis::max() const {
  return list.empty() ? at(n - 1) : *std::max_element(list.begin(), list.end());
}

std::uint64_t CaseFile::case_count() const {
  if (!cases.empty()) return cases.size();
  return static_cast<std::uint64_t>(sweep_tY_mm.size()) * sweep_Q_kN.size();
}

CasePoint CaseFile::case_at(std::uint64_t i) const {
  if (!cases.empty()) return cases[i];
  const std::uint64_t nq = sweep_Q_kN.size();
  const double t = sweep_tY_mm.at(i / nq), q = sweep_Q_kN.at(i % nq);
  return {t * units::mm, q * units::kN, t, q};
}

nlohmann::json read_json_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the case file");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    std::size_t line = 1, col = 1;
    for (std::size_t i = 0; i < e.byte && i < text.size(); ++i) {
      if (text[i] == '\n') { ++line; col = 1; } else ++col;
    }
    std::string msg = e.what();
    const auto p = msg.find("syntax error");
    throw InputError(path + ":" + std::to_string(line) + ":" + std::to_string(col), "",
                     "JSON syntax error: " + (p != std::string::npos ? msg.substr(p) : msg));
  } catch (const json::exception& e) {
    // Fuzz finding: a number too large for a double ("5E555") is not a parse_error.
    std::string msg = e.what();
    const auto p = msg.find("] ");
    throw InputError(path, "", "invalid JSON: " + (p != std::string::npos ? msg.substr(p + 2) : msg));
  }
}

CaseFile load_case_file(const std::string& path, bool need_cases) {
  return parse_case_json(read_json_file(path), path, need_cases);
}

CaseFile parse_case_json(const nlohmann::json& j, const std::string& path, bool need_cases) {
  Ctx c{path};
  CaseFile cf;
  cf.path = path;
  c.only_keys(j, "", {"wheel", "rail", "track", "geometry", "material", "model", "method", "half_space", "strips", "sweep", "cases", "solver", "comment"});

  // wheel
  if (!j.contains("wheel")) c.fail("/wheel", nullptr, "required");
  const json& w = j.at("wheel");
  c.only_keys(w, "/wheel", {"profile", "nominal_radius_mm"});
  if (!w.contains("profile")) c.fail("/wheel/profile", nullptr, "required");
  cf.wheel = parse_profile_source(c, w.at("profile"), "/wheel/profile", path);
  if (w.contains("nominal_radius_mm")) {
    const double r = c.plausible(w, "/wheel", "nominal_radius_mm", plausible::kRadius_mm);
    cf.track.nominal_radius = r * units::mm;
  }
  // rail
  if (!j.contains("rail")) c.fail("/rail", nullptr, "required");
  const json& rl = j.at("rail");
  c.only_keys(rl, "/rail", {"profile", "inclination"});
  if (!rl.contains("profile")) c.fail("/rail/profile", nullptr, "required");
  cf.rail = parse_profile_source(c, rl.at("profile"), "/rail/profile", path);
  if (!rl.contains("inclination"))
    c.fail("/rail/inclination", nullptr, "required: \"as-is\" (the profile is already laid as used), \"none\", \"1:N\" (\"1:40\", \"1:30\", \"1:20\" ...) or an angle such as \"2.5deg\"",
           "say whether the tool must cant the rail, so it is never applied twice");
  try {
    cf.inclination = parse_inclination(c.string(rl, "/rail", "inclination"));
  } catch (const std::invalid_argument& e) {
    c.fail("/rail/inclination", &rl.at("inclination"), e.what());
  }
  // track
  if (j.contains("track")) {
    const json& t = j.at("track");
    c.only_keys(t, "/track", {"gauge_mm", "gauge_height_mm", "flange_back_distance_mm", "flange_back_position_mm",
                              "positioning", "lateral_offset_mm", "roller_radius_mm"});
    if (t.contains("positioning")) {
      const std::string pos = c.string(t, "/track", "positioning");
      if (pos == "explicit") cf.track.positioning = TrackSetup::Positioning::Explicit;
      else if (pos != "gauge")
        c.fail("/track/positioning", &t.at("positioning"), "must be \"gauge\" (default) or \"explicit\"");
    }
    if (cf.track.positioning == TrackSetup::Positioning::Explicit) {
      if (!t.contains("lateral_offset_mm"))
        c.fail("/track/lateral_offset_mm", nullptr,
               "required with positioning \"explicit\": the rail y [mm] of the wheel profile's origin (taping line) "
               "at t_Y = 0",
               "e.g. 0 when both profiles have their origin on the same vertical line");
      cf.track.lateral_offset = c.number(t, "/track", "lateral_offset_mm") * units::mm;
      if (std::abs(cf.track.lateral_offset) > 0.2)
        c.fail("/track/lateral_offset_mm", &t.at("lateral_offset_mm"), "must lie within -200 … 200 mm");
    } else if (t.contains("lateral_offset_mm")) {
      c.fail("/track/lateral_offset_mm", &t.at("lateral_offset_mm"), "only used with positioning \"explicit\"",
             "add \"positioning\": \"explicit\" or remove it");
    }
    if (t.contains("roller_radius_mm")) {
      const double rr = c.positive(t, "/track", "roller_radius_mm");
      if (rr < 50 || rr > 5000) c.fail("/track/roller_radius_mm", &t.at("roller_radius_mm"), "must be between 50 and 5000 mm");
      cf.track.roller_radius = rr * units::mm;
    }
    if (t.contains("gauge_mm")) cf.track.gauge = c.positive(t, "/track", "gauge_mm") * units::mm;
    if (t.contains("gauge_height_mm")) cf.track.gauge_height = c.positive(t, "/track", "gauge_height_mm") * units::mm;
    if (t.contains("flange_back_distance_mm")) cf.track.flange_back_distance = c.positive(t, "/track", "flange_back_distance_mm") * units::mm;
    if (t.contains("flange_back_position_mm")) cf.track.flange_back_position = c.number(t, "/track", "flange_back_position_mm") * units::mm;
    if (cf.track.gauge_height > 0.05) c.fail("/track/gauge_height_mm", &t.at("gauge_height_mm"), "must be at most 50 mm");
    if (cf.track.flange_back_distance >= cf.track.gauge)
      c.fail("/track/flange_back_distance_mm", t.contains("flange_back_distance_mm") ? &t.at("flange_back_distance_mm") : nullptr,
             "must be smaller than the gauge (" + format_number(cf.track.gauge * units::per_mm) + " mm)");
  }
  // geometry
  bool range_given = false;
  if (j.contains("geometry")) {
    const json& g = j.at("geometry");
    c.only_keys(g, "/geometry", {"tY_min_mm", "tY_max_mm", "tY_step_mm", "strip_width_mm", "jump_threshold_deg",
                                 "jump_distance_mm", "min_ellipse_width_mm", "fit_window_mm", "measured_fit_window_mm", "noise"});
    if (g.contains("tY_min_mm") != g.contains("tY_max_mm"))
      c.fail("/geometry", &g, "give both tY_min_mm and tY_max_mm, or neither (then the range covers the sweep)");
    if (g.contains("tY_min_mm")) {
      range_given = true;
      cf.geometry.tY_min = c.number(g, "/geometry", "tY_min_mm") * units::mm;
      cf.geometry.tY_max = c.number(g, "/geometry", "tY_max_mm") * units::mm;
      if (cf.geometry.tY_max < cf.geometry.tY_min) c.fail("/geometry/tY_max_mm", &g.at("tY_max_mm"), "must be >= tY_min_mm");
      if (cf.geometry.tY_max - cf.geometry.tY_min > 0.2) c.fail("/geometry", &g, "the t_Y range must be at most 200 mm wide");
    }
    if (g.contains("tY_step_mm")) {
      const double s = c.positive(g, "/geometry", "tY_step_mm");
      if (s < 1e-4 || s > 1) c.fail("/geometry/tY_step_mm", &g.at("tY_step_mm"), "must be between 0.0001 and 1 mm");
      cf.geometry.tY_step = s * units::mm;
    }
    if (g.contains("strip_width_mm")) {
      const double s = c.positive(g, "/geometry", "strip_width_mm");
      if (s < 0.001 || s > 5) c.fail("/geometry/strip_width_mm", &g.at("strip_width_mm"), "must be between 0.001 and 5 mm");
      cf.geometry.strip_width = s * units::mm;
    }
    if (g.contains("jump_threshold_deg")) cf.geometry.jump_threshold = c.positive(g, "/geometry", "jump_threshold_deg") * units::deg;
    if (g.contains("jump_distance_mm")) cf.geometry.jump_distance = c.number(g, "/geometry", "jump_distance_mm") * units::mm;
    if (g.contains("min_ellipse_width_mm")) cf.geometry.min_ellipse_width = c.number(g, "/geometry", "min_ellipse_width_mm") * units::mm;
    if (g.contains("fit_window_mm")) cf.geometry.curve.window_half_width = c.positive(g, "/geometry", "fit_window_mm") * units::mm;
    if (g.contains("measured_fit_window_mm")) cf.geometry.curve.measured_window_half_width = c.positive(g, "/geometry", "measured_fit_window_mm") * units::mm;
    // Measured or exact (profiles.md "Measured or exact"): one value for both profiles or
    // {"wheel": ..., "rail": ...} (a missing one stays "auto").
    if (g.contains("noise")) {
      const json& nz = g.at("noise");
      auto noise = [&](const json& v, const std::string& path) {
        if (!v.is_string()) c.fail(path, &v, "must be \"auto\", \"exact\" or \"measured\"");
        try {
          return parse_profile_noise(v.get<std::string>());
        } catch (const std::invalid_argument&) {
          c.fail(path, &v, "must be \"auto\", \"exact\" or \"measured\"");
        }
        return ProfileNoise::Auto;
      };
      if (nz.is_object()) {
        c.only_keys(nz, "/geometry/noise", {"wheel", "rail"});
        if (nz.contains("wheel")) cf.geometry.wheel_noise = noise(nz.at("wheel"), "/geometry/noise/wheel");
        if (nz.contains("rail")) cf.geometry.rail_noise = noise(nz.at("rail"), "/geometry/noise/rail");
      } else {
        cf.geometry.wheel_noise = cf.geometry.rail_noise = noise(nz, "/geometry/noise");
      }
    }
  }
  // model and material
  if (j.contains("model")) {
    const std::string m = c.string(j, "", "model");
    if (m == "elastic") cf.model = Model::Elastic;
    else if (m == "plastic") cf.model = Model::Plastic;
    else c.fail("/model", &j.at("model"), "must be \"elastic\" or \"plastic\"");
  }
  if (j.contains("method")) {
    const std::string m = c.string(j, "", "method");
    try {
      cf.method = parse_method(m);
    } catch (const std::invalid_argument&) {
      c.fail("/method", &j.at("method"), "must be \"multi-hertzian\", \"half-space\", \"strips\" or \"auto\"");
    }
  }
  if (j.contains("material")) {
    const json& m = j.at("material");
    c.only_keys(m, "/material", {"E_GPa", "nu", "p_lim_MPa", "wheel", "rail"});
    // Either one E and nu for both bodies, or "wheel": {...} and "rail": {...} (each defaulting
    // to the common values).
    auto elastic = [&](const json& o, const std::string& path, double* E_out, double* nu_out) {
      if (o.contains("E_GPa")) {
        const double E = c.plausible(o, path, "E_GPa", plausible::kE_GPa);
        *E_out = E * units::GPa;
      }
      if (o.contains("nu")) {
        const double nu = c.plausible(o, path, "nu", plausible::kNu);
        *nu_out = nu;
      }
    };
    elastic(m, "/material", &cf.material.E, &cf.material.nu);
    if (m.contains("wheel") || m.contains("rail")) {
      if (m.contains("E_GPa") || m.contains("nu"))
        c.fail("/material", &m, "give E_GPa and nu either for both bodies or per body (\"wheel\", \"rail\"), not both");
      double Er = cf.material.E, nur = cf.material.nu;
      for (const char* body : {"wheel", "rail"}) {
        if (!m.contains(body)) continue;
        const json& b = m.at(body);
        const std::string path = std::string("/material/") + body;
        if (!b.is_object()) c.fail(path, &b, "must be an object {\"E_GPa\": ..., \"nu\": ...}");
        c.only_keys(b, path, {"E_GPa", "nu"});
        if (std::string(body) == "wheel") elastic(b, path, &cf.material.E, &cf.material.nu);
        else elastic(b, path, &Er, &nur);
      }
      cf.material.E_rail = Er;
      cf.material.nu_rail = nur;
    }
    if (m.contains("p_lim_MPa")) {
      if (cf.model != Model::Plastic)
        c.fail("/material/p_lim_MPa", &m.at("p_lim_MPa"), "is used by the plastic model only",
               "set \"model\": \"plastic\" or remove p_lim_MPa");
      const double p = c.plausible(m, "/material", "p_lim_MPa", plausible::kPlim_MPa);
      cf.material.p_lim = p * units::MPa;
    }
  }
  if (cf.model == Model::Plastic && !std::isfinite(cf.material.p_lim))
    c.fail("/material/p_lim_MPa", nullptr, "required for the plastic model");
  // solver
  if (j.contains("solver")) {
    const json& s = j.at("solver");
    c.only_keys(s, "/solver", {"rtol", "max_iterations", "exact_coefficients"});
    if (s.contains("rtol")) cf.solver.rtol = c.positive(s, "/solver", "rtol");
    if (s.contains("max_iterations"))
      cf.solver.max_iterations = static_cast<int>(c.integer(s, "/solver", "max_iterations", 1, 10000));
    if (s.contains("exact_coefficients")) cf.solver.exact_coefficients = c.boolean(s, "/solver", "exact_coefficients");
    std::string why;
    if (!cf.solver.valid(&why)) c.fail("/solver", &s, why);
  }
  // half-space method options (docs/method.md §8)
  if (j.contains("half_space")) {
    const json& h = j.at("half_space");
    c.only_keys(h, "/half_space", {"dx_mm", "ds_mm", "d_comb_mm", "force_rtol", "tol", "max_iterations"});
    HalfSpaceOptions& o = cf.half_space;
    if (h.contains("dx_mm")) o.dx = c.positive(h, "/half_space", "dx_mm") * units::mm;
    if (h.contains("ds_mm")) o.ds = c.positive(h, "/half_space", "ds_mm") * units::mm;
    if (h.contains("d_comb_mm")) o.d_comb = c.number(h, "/half_space", "d_comb_mm") * units::mm;
    if (h.contains("force_rtol")) o.force_rtol = c.positive(h, "/half_space", "force_rtol");
    if (h.contains("tol")) o.cg.tol = c.positive(h, "/half_space", "tol");
    if (h.contains("max_iterations"))
      o.cg.max_iterations = static_cast<int>(c.integer(h, "/half_space", "max_iterations", 1, 100000));
    std::string why;
    if (!o.valid(&why)) c.fail("/half_space", &h, why);
  }
  // strip method options (docs/method.md §9)
  if (j.contains("strips")) {
    const json& h = j.at("strips");
    c.only_keys(h, "/strips", {"ds_mm", "d_comb_mm", "force_rtol", "gauss_points", "outlier_factor"});
    StripMethodOptions& o = cf.strips;
    if (h.contains("ds_mm")) o.ds = c.positive(h, "/strips", "ds_mm") * units::mm;
    if (h.contains("d_comb_mm")) o.d_comb = c.number(h, "/strips", "d_comb_mm") * units::mm;
    if (h.contains("force_rtol")) o.force_rtol = c.positive(h, "/strips", "force_rtol");
    if (h.contains("outlier_factor")) o.strips.outlier_factor = c.positive(h, "/strips", "outlier_factor");
    if (h.contains("gauss_points")) {
      const long long g = c.integer(h, "/strips", "gauss_points", 2, 256, "must be an even integer in [2, 256]");
      if (g % 2 != 0) c.fail("/strips/gauss_points", &h.at("gauss_points"), "must be an even integer in [2, 256]");
      o.strips.gauss_points = static_cast<int>(g);
    }
    std::string why;
    if (!o.valid(&why)) c.fail("/strips", &h, why);
  }
  // cases
  if (j.contains("sweep") && j.contains("cases")) c.fail("/cases", nullptr, "give either \"sweep\" or \"cases\", not both");
  if (j.contains("sweep")) {
    const json& s = j.at("sweep");
    c.only_keys(s, "/sweep", {"tY_mm", "Q_kN"});
    if (!s.contains("tY_mm")) c.fail("/sweep/tY_mm", nullptr, "required");
    if (!s.contains("Q_kN")) c.fail("/sweep/Q_kN", nullptr, "required");
    // Count before materialising anything: a sweep of 10^12 cases is refused up front.
    const double n = axis_count(s.at("tY_mm")) * axis_count(s.at("Q_kN"));
    if (n > static_cast<double>(kMaxCases))
      c.fail("/sweep", nullptr, "gives " + format_number(n) + " cases, more than the limit of " + std::to_string(kMaxCases),
             "split the study (shards) or coarsen the steps");
    cf.sweep_tY_mm = parse_axis(c, s.at("tY_mm"), "/sweep/tY_mm", plausible::kTY_mm);
    cf.sweep_Q_kN = parse_axis(c, s.at("Q_kN"), "/sweep/Q_kN", plausible::kQ_kN);
    cf.has_cases = true;
  } else if (j.contains("cases")) {
    const json& a = j.at("cases");
    if (!a.is_array() || a.empty()) c.fail("/cases", &a, "must be a non-empty list of {\"tY_mm\", \"Q_kN\"}");
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::string p = "/cases/" + std::to_string(i);
      c.only_keys(a[i], p, {"tY_mm", "Q_kN"});
      if (!a[i].contains("tY_mm") || !a[i].contains("Q_kN")) c.fail(p, &a[i], "needs tY_mm and Q_kN");
      // Every entry is checked (not a sample), whatever the length of the list.
      const double t = c.plausible(a[i], p, "tY_mm", plausible::kTY_mm), q = c.plausible(a[i], p, "Q_kN", plausible::kQ_kN);
      cf.cases.push_back({t * units::mm, q * units::kN, t, q});
    }
    cf.has_cases = true;
  }
  if (need_cases && !cf.has_cases) c.fail("/sweep", nullptr, "required: a \"sweep\" or a \"cases\" list");
  // The geometry range covers the default range and the sweep unless given.
  if (!range_given && cf.has_cases) {
    // Every case of a list, not a sample: a value at any index widens the range (it costs nothing
    // next to the solve). A sweep's axis gives its ends directly.
    for (const CasePoint& p : cf.cases) {
      cf.geometry.tY_min = std::min(cf.geometry.tY_min, p.tY);
      cf.geometry.tY_max = std::max(cf.geometry.tY_max, p.tY);
    }
    if (cf.sweep_tY_mm.size() > 0) {
      cf.geometry.tY_min = std::min(cf.geometry.tY_min, cf.sweep_tY_mm.min() * units::mm);
      cf.geometry.tY_max = std::max(cf.geometry.tY_max, cf.sweep_tY_mm.max() * units::mm);
    }
    // Snap outwards onto the grid step so the sweep's ends are inside.
    cf.geometry.tY_min = std::floor(cf.geometry.tY_min / cf.geometry.tY_step + 1e-6) * cf.geometry.tY_step;
    cf.geometry.tY_max = std::ceil(cf.geometry.tY_max / cf.geometry.tY_step - 1e-6) * cf.geometry.tY_step;
    if (cf.geometry.tY_max - cf.geometry.tY_min > 0.2)
      c.fail("/sweep/tY_mm", nullptr, "the t_Y values span more than 200 mm");
  }
  std::string why;
  if (!cf.geometry.valid(&why)) c.fail("/geometry", nullptr, why);
  return cf;
}

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

nlohmann::json CaseFile::resolved_json() const {
  auto src = [](const ProfileSource& s) {
    json o;
    if (!s.standard.empty()) { o["standard"] = s.standard; o["step_mm"] = s.step * units::per_mm; }
    else {
      o["file"] = s.file;
      o["format"] = to_string(s.read.format);
      o["mirror_y"] = s.read.mirror_y;
      o["mirror_z"] = s.read.mirror_z;
      o["scale"] = s.read.scale;
    }
    return o;
  };
  json j;
  j["case_file"] = path;
  j["wheel"] = {{"profile", src(wheel)}, {"nominal_radius_mm", track.nominal_radius * units::per_mm}};
  j["rail"] = {{"profile", src(rail)}, {"inclination", to_string(inclination)}};
  j["track"] = {{"gauge_mm", track.gauge * units::per_mm}, {"gauge_height_mm", track.gauge_height * units::per_mm},
                {"flange_back_distance_mm", track.flange_back_distance * units::per_mm},
                {"flange_back_position_mm", track.flange_back_position * units::per_mm}};
  // Only when used: the resolved inputs of gauge-positioned straight-rail cases stay as they were.
  if (track.positioning == TrackSetup::Positioning::Explicit) {
    j["track"]["positioning"] = "explicit";
    j["track"]["lateral_offset_mm"] = track.lateral_offset * units::per_mm;
  }
  if (track.roller_radius > 0) j["track"]["roller_radius_mm"] = track.roller_radius * units::per_mm;
  j["geometry"] = {{"tY_min_mm", geometry.tY_min * units::per_mm}, {"tY_max_mm", geometry.tY_max * units::per_mm},
                   {"tY_step_mm", geometry.tY_step * units::per_mm}, {"strip_width_mm", geometry.strip_width * units::per_mm},
                   {"jump_threshold_deg", geometry.jump_threshold / units::deg},
                   {"jump_distance_mm", geometry.jump_distance * units::per_mm},
                   {"min_ellipse_width_mm", geometry.min_ellipse_width * units::per_mm},
                   {"fit_window_mm", geometry.curve.window_half_width * units::per_mm},
                   {"measured_fit_window_mm", geometry.curve.measured_window_half_width * units::per_mm},
                   {"noise", {{"wheel", to_string(geometry.wheel_noise)}, {"rail", to_string(geometry.rail_noise)}}}};
  json mat = {{"E_GPa", material.E / units::GPa}, {"nu", material.nu}};
  if (!std::isnan(material.E_rail))
    mat = {{"wheel", {{"E_GPa", material.E / units::GPa}, {"nu", material.nu}}},
           {"rail", {{"E_GPa", material.E_rail / units::GPa}, {"nu", material.nu_rail}}}};
  if (model == Model::Plastic) mat["p_lim_MPa"] = material.p_lim / units::MPa;
  j["material"] = mat;
  j["model"] = to_string(model);
  j["method"] = to_string(method);
  if (method == Method::HalfSpace)
    j["half_space"] = {{"dx_mm", half_space.dx * units::per_mm}, {"ds_mm", half_space.ds * units::per_mm},
                       {"d_comb_mm", half_space.d_comb * units::per_mm}, {"force_rtol", half_space.force_rtol},
                       {"tol", half_space.cg.tol}, {"max_iterations", half_space.cg.max_iterations}};
  if (method == Method::Strips || method == Method::Auto)
    j["strips"] = {{"ds_mm", strips.ds * units::per_mm}, {"d_comb_mm", strips.d_comb * units::per_mm},
                   {"force_rtol", strips.force_rtol}, {"gauss_points", strips.strips.gauss_points},
                   {"outlier_factor", strips.strips.outlier_factor}};
  j["solver"] = {{"rtol", solver.rtol}, {"max_iterations", solver.max_iterations},
                 {"exact_coefficients", solver.exact_coefficients}};
  j["case_order"] = cases.empty() ? "sweep: tY_mm outer, Q_kN inner" : "as listed";
  j["case_count"] = case_count();
  return j;
}

}  // namespace mh
