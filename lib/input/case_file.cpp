// The case file: JSON -> CaseFile, section by section; see case_file.hpp. The typed field
// readers are in json_fields.hpp, the profile entries in profile_source.cpp, the sweep and the
// case list in case_sweep.cpp, friction, kinematics or creepages, FASTSIM and the RCF keys in
// case_tangential_rcf.cpp.
#include "input/case_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "core/plausible.hpp"
#include "core/units.hpp"
#include "input/case_sweep.hpp"
#include "input/case_tangential_rcf.hpp"
#include "input/json_fields.hpp"
#include "input/profile_source.hpp"

namespace mh {

using nlohmann::json;
using detail::Ctx;
using detail::parse_profile_source;

const char* to_string(Model m) { return m == Model::Plastic ? "plastic" : "elastic"; }

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
  return parse_case_json(read_json_file(path), path, need_cases, {});
}

CaseFile parse_case_json(const nlohmann::json& j, const std::string& path, bool need_cases,
                         const std::map<std::string, std::string>& origins) {
  Ctx c{path, origins};
  CaseFile cf;
  cf.path = path;
  c.only_keys(j, "", {"wheel", "rail", "track", "geometry", "material", "model", "method", "half_space", "strips", "rcf", "sweep", "cases", "solver", "comment",
                      "friction", "kinematics", "creepages", "fastsim"});

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
                                 "jump_distance_mm", "min_ellipse_width_mm", "fit_window_mm", "measured_fit_window_mm", "noise",
                                 "smoothing_mm", "smoothing_band"});
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
    // Smoothing of measured profiles for the grid methods' contact gap (profiles.md §7).
    // "auto" (the default): each measured profile's length from its own noise; a number forces it.
    if (g.contains("smoothing_mm")) {
      const json& v = g.at("smoothing_mm");
      if (v.is_string()) {
        if (v.get<std::string>() != "auto")
          c.fail("/geometry/smoothing_mm", &v, "must be \"auto\" (from each profile's noise) or a length between 0 (off) and 20 mm");
        cf.geometry.contact_smoothing.reset();
      } else {
        const double L = c.number(g, "/geometry", "smoothing_mm");
        if (!(L >= 0) || L > 20)
          c.fail("/geometry/smoothing_mm", &v, "must be \"auto\" (from each profile's noise) or a length between 0 (off) and 20 mm");
        cf.geometry.contact_smoothing = L * units::mm;
      }
    }
    // The smoothing's uncertainty band (profiles.md §7 "Uncertainty band"): default true.
    if (g.contains("smoothing_band")) cf.geometry.smoothing_band = c.boolean(g, "/geometry", "smoothing_band");
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
    c.only_keys(m, "/material", {"E_GPa", "nu", "p_lim_MPa", "yield_MPa", "wheel", "rail"});
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
    // per-body elastic constants: a "wheel" or "rail" object that gives E_GPa or nu (an object with
    // only yield_MPa leaves the elastic constants common)
    auto gives_elastic = [&](const char* body) {
      return m.contains(body) && (!m.at(body).is_object() || m.at(body).contains("E_GPa") || m.at(body).contains("nu"));
    };
    if (gives_elastic("wheel") || gives_elastic("rail")) {
      if (m.contains("E_GPa") || m.contains("nu"))
        c.fail("/material", &m, "give E_GPa and nu either for both bodies or per body (\"wheel\", \"rail\"), not both");
      double Er = cf.material.E, nur = cf.material.nu;
      for (const char* body : {"wheel", "rail"}) {
        if (!m.contains(body)) continue;
        const json& b = m.at(body);
        const std::string path = std::string("/material/") + body;
        if (!b.is_object()) c.fail(path, &b, "must be an object {\"E_GPa\": ..., \"nu\": ..., \"yield_MPa\": ...}");
        c.only_keys(b, path, {"E_GPa", "nu", "yield_MPa"});
        if (std::string(body) == "wheel") elastic(b, path, &cf.material.E, &cf.material.nu);
        else elastic(b, path, &Er, &nur);
      }
      cf.material.E_rail = Er;
      cf.material.nu_rail = nur;
    }
    for (const char* body : {"wheel", "rail"}) {
      if (!m.contains(body) || gives_elastic(body)) continue;  // checked above
      c.only_keys(m.at(body), std::string("/material/") + body, {"E_GPa", "nu", "yield_MPa"});
    }
    // The yield stress: "yield_MPa" for both bodies, or per body in "wheel"/"rail" (not both).
    const bool yield_per_body = (m.contains("wheel") && m.at("wheel").is_object() && m.at("wheel").contains("yield_MPa")) ||
                                (m.contains("rail") && m.at("rail").is_object() && m.at("rail").contains("yield_MPa"));
    if (m.contains("yield_MPa") && yield_per_body)
      c.fail("/material/yield_MPa", &m.at("yield_MPa"),
             "give yield_MPa either for both bodies or per body (\"wheel\", \"rail\"), not both");
    if (m.contains("yield_MPa"))
      cf.material.yield = c.plausible(m, "/material", "yield_MPa", plausible::kYield_MPa) * units::MPa;
    if (yield_per_body) {
      for (const char* body : {"wheel", "rail"}) {
        if (!m.contains(body) || !m.at(body).contains("yield_MPa")) continue;
        const std::string path = std::string("/material/") + body;
        const double y = c.plausible(m.at(body), path, "yield_MPa", plausible::kYield_MPa) * units::MPa;
        (std::string(body) == "wheel" ? cf.material.yield : cf.material.yield_rail) = y;
      }
      if (std::isnan(cf.material.yield) || std::isnan(cf.material.yield_rail))
        c.fail(std::isnan(cf.material.yield) ? "/material/wheel/yield_MPa" : "/material/rail/yield_MPa", nullptr,
               "required: give yield_MPa for both \"wheel\" and \"rail\", or one common \"yield_MPa\"");
    }
    if (m.contains("p_lim_MPa")) {
      if (cf.model != Model::Plastic)
        c.fail("/material/p_lim_MPa", &m.at("p_lim_MPa"), "is used by the plastic model only",
               "set \"model\": \"plastic\" or remove p_lim_MPa");
      const double p = c.plausible(m, "/material", "p_lim_MPa", plausible::kPlim_MPa);
      cf.material.p_lim = p * units::MPa;
    }
  }
  // p_lim_MPa when given (it takes precedence: the user's own limit pressure, the capped law).
  // Otherwise the yield law from the softer body's yield stress: the ellipse leaves Hertz at first
  // yield 1.6 σ_y, the grid methods cap at p_lim = kPlimPerYield σ_y (docs/method.md §5.1). The
  // yield stress stays in Material for the indicators that need it.
  if (cf.model == Model::Plastic && !derive_plastic_law(cf.material))
    c.fail("/material/p_lim_MPa", nullptr, "required for the plastic model: give the steel's yield stress "
           "\"yield_MPa\" (p_lim is derived from it) or your own \"p_lim_MPa\"");
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
  // RCF indicators (docs/outputs.md "RCF columns"; case_tangential_rcf.cpp), then the tangential
  // problem (docs/tangential.md): friction and the wheelset's motion or the creepages.
  detail::parse_rcf(c, j, cf);
  detail::parse_tangential(c, j, cf);
  // strip method options (docs/method.md §9)
  if (j.contains("strips")) {
    const json& h = j.at("strips");
    c.only_keys(h, "/strips", {"ds_mm", "d_comb_mm", "force_rtol", "gauss_points", "outlier_factor", "end_gap_tol"});
    StripMethodOptions& o = cf.strips;
    if (h.contains("ds_mm")) o.ds = c.positive(h, "/strips", "ds_mm") * units::mm;
    if (h.contains("d_comb_mm")) o.d_comb = c.number(h, "/strips", "d_comb_mm") * units::mm;
    if (h.contains("force_rtol")) o.force_rtol = c.positive(h, "/strips", "force_rtol");
    if (h.contains("outlier_factor")) o.strips.outlier_factor = c.positive(h, "/strips", "outlier_factor");
    if (h.contains("end_gap_tol")) {
      o.strips.end_gap_tol = c.number(h, "/strips", "end_gap_tol");
      if (!(o.strips.end_gap_tol >= 0))
        c.fail("/strips/end_gap_tol", &h.at("end_gap_tol"), "must be >= 0 (0 refines every patch's strip extents)");
    }
    if (h.contains("gauss_points")) {
      const long long g = c.integer(h, "/strips", "gauss_points", 2, 256, "must be an even integer in [2, 256]");
      if (g % 2 != 0) c.fail("/strips/gauss_points", &h.at("gauss_points"), "must be an even integer in [2, 256]");
      o.strips.gauss_points = static_cast<int>(g);
    }
    std::string why;
    if (!o.valid(&why)) c.fail("/strips", &h, why);
  }
  // cases
  detail::parse_sweep_or_cases(c, j, cf);
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
      // The profile of a multi-profile file: shards that read different sections differ.
      if (s.read.section > 0) o["section"] = s.read.section;
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
                   {"noise", {{"wheel", to_string(geometry.wheel_noise)}, {"rail", to_string(geometry.rail_noise)}}},
                   {"smoothing_mm", geometry.contact_smoothing ? json(*geometry.contact_smoothing * units::per_mm) : json("auto")},
                   {"smoothing_band", geometry.smoothing_band}};
  json mat = {{"E_GPa", material.E / units::GPa}, {"nu", material.nu}};
  if (!std::isnan(material.E_rail))
    mat = {{"wheel", {{"E_GPa", material.E / units::GPa}, {"nu", material.nu}}},
           {"rail", {{"E_GPa", material.E_rail / units::GPa}, {"nu", material.nu_rail}}}};
  // The yield law is re-read from yield_MPa alone (a p_lim_MPa would select the capped law).
  if (model == Model::Plastic && !material.yield_law) mat["p_lim_MPa"] = material.p_lim / units::MPa;
  if (!std::isnan(material.yield) && std::isnan(material.yield_rail)) {
    mat["yield_MPa"] = material.yield / units::MPa;
  } else if (!std::isnan(material.yield_rail)) {  // per body (the reader requires both)
    mat["wheel"]["yield_MPa"] = material.yield / units::MPa;
    mat["rail"]["yield_MPa"] = material.yield_rail / units::MPa;
  }
  j["material"] = mat;
  j["model"] = to_string(model);
  j["method"] = to_string(method);
  if (tangential.enabled()) {
    const TangentialOptions& t = tangential;
    j["friction"] = {{"coefficient", t.mu}};
    if (t.source == TangentialOptions::Source::Creepages) {
      j["creepages"] = {{"xi", t.creep.xi}, {"eta", t.creep.eta}, {"phi_per_mm", t.creep.phi * units::mm}};
    } else {
      j["kinematics"] = {{"speed_m_s", t.kin.V}};
      // One of the two yaw keys (they exclude each other): the one that is not zero.
      if (t.yaw_per_tY != 0) j["kinematics"]["yaw_mrad_per_mm"] = t.yaw_per_tY;
      else j["kinematics"]["yaw_mrad"] = t.kin.yaw * 1e3;
      j["kinematics"]["lateral_velocity_m_s"] = t.kin.lateral_velocity;
      j["kinematics"]["yaw_rate_rad_s"] = t.kin.yaw_rate;
      j["kinematics"]["pitch_rate_rad_s"] = std::isnan(t.kin.pitch_rate) ? json("nominal") : json(t.kin.pitch_rate);
    }
    j["fastsim"] = {{"nx", t.fastsim.nx}, {"ny", t.fastsim.ny},
                    {"bound", t.fastsim.bound == TractionBound::Elliptical ? "elliptical" : "parabolic"},
                    {"blend", t.fastsim.blend}};
  }
  if (rcf.enabled()) {
    j["rcf"] = json::object();
    if (!rcf.actual) j["rcf"]["traction_coefficient"] = rcf.f;
    if (std::isfinite(rcf.k)) j["rcf"]["shear_yield_MPa"] = rcf.k / units::MPa;
    if (rcf.actual) {
      const BurstowOptions& b = rcf.burstow;
      j["rcf"]["burstow"] = {{"Tgamma_threshold_N", b.Tgamma_threshold_N}, {"Tgamma_peak_N", b.Tgamma_peak_N},
                             {"damage_peak", b.damage_peak}, {"Tgamma_zero_N", b.Tgamma_zero_N}};
      const UsfdWearOptions& u = rcf.usfd;
      j["rcf"]["usfd_wear"] = {{"K1", u.K1}, {"x1_N_per_mm2", u.x1}, {"K2", u.K2}, {"x2_N_per_mm2", u.x2}, {"K3", u.K3}};
    }
    if (rcf.subsurface) {
      j["rcf"]["subsurface"] = json::object();
      if (std::isfinite(rcf.dang_van_c)) j["rcf"]["subsurface"]["dang_van_c"] = rcf.dang_van_c;
      j["rcf"]["subsurface"]["grid"] = rcf.subsurface_grid;
    }
    if (std::isfinite(rcf.tY_sd))
      j["rcf"]["tY_distribution"] = {{"mean_mm", rcf.tY_mean * units::per_mm}, {"sd_mm", rcf.tY_sd * units::per_mm}};
  }
  if (method == Method::HalfSpace)
    j["half_space"] = {{"dx_mm", half_space.dx * units::per_mm}, {"ds_mm", half_space.ds * units::per_mm},
                       {"d_comb_mm", half_space.d_comb * units::per_mm}, {"force_rtol", half_space.force_rtol},
                       {"tol", half_space.cg.tol}, {"max_iterations", half_space.cg.max_iterations}};
  if (method == Method::Strips || method == Method::Auto)
    j["strips"] = {{"ds_mm", strips.ds * units::per_mm}, {"d_comb_mm", strips.d_comb * units::per_mm},
                   {"force_rtol", strips.force_rtol}, {"gauss_points", strips.strips.gauss_points},
                   {"outlier_factor", strips.strips.outlier_factor}, {"end_gap_tol", strips.strips.end_gap_tol}};
  j["solver"] = {{"rtol", solver.rtol}, {"max_iterations", solver.max_iterations},
                 {"exact_coefficients", solver.exact_coefficients}};
  j["case_order"] = cases.empty() ? "sweep: tY_mm outer, Q_kN inner" : "as listed";
  j["case_count"] = case_count();
  return j;
}

}  // namespace mh
