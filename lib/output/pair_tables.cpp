// What a run writes about its profile pair: the profiles as used (profiles.csv), the CAF
// (caf.csv), and the JSON records of the profiles, the potential ellipses and the inputs.
#include "output/pair_tables.hpp"

#include <cmath>
#include <filesystem>

#include "core/units.hpp"
#include "output/cells.hpp"
#include "output/output_file.hpp"

namespace mh {

using namespace cells;

nlohmann::json noise_json(const NoiseDecision& d) {
  nlohmann::json j = {{"class", d.class_name()}, {"forced", d.forced},
                      {"median_residual_um", d.median_residual * 1e6}, {"print_step_mm", d.print_step * units::per_mm},
                      {"rounding_rms_um", d.rounding_rms * 1e6}, {"threshold_um", d.threshold * 1e6},
                      {"sigma_um", std::round(d.sigma * 1e9) / 1e3}, {"reason", d.reason}};
  if (d.mixed()) {
    nlohmann::json a = nlohmann::json::array();
    for (const NoiseRegion& r : d.regions)
      a.push_back({{"class", r.measured ? "measured" : "exact"},
                   {"y_from_mm", std::isfinite(r.y_from) ? nlohmann::json(r.y_from * units::per_mm) : nlohmann::json(nullptr)},
                   {"y_to_mm", std::isfinite(r.y_to) ? nlohmann::json(r.y_to * units::per_mm) : nlohmann::json(nullptr)},
                   {"print_step_mm", r.print_step * units::per_mm}, {"median_residual_um", r.median_residual * 1e6},
                   {"threshold_um", r.threshold * 1e6}, {"sigma_um", std::round(r.sigma * 1e9) / 1e3}});
    j["regions"] = a;
  }
  return j;
}

nlohmann::json cant_json(const RailCant& c) {
  if (!c.found) return {{"found", false}, {"why", c.why}};
  nlohmann::json j = {{"found", true}, {"angle_deg", c.angle / units::deg}, {"ratio", cant_ratio(c.angle)},
                      {"std_error_deg", c.std_error / units::deg}, {"residual_mm", c.residual * units::per_mm},
                      {"levels", c.levels}, {"confident", c.confident}};
  if (!c.confident) j["why"] = c.why;
  return j;
}

nlohmann::json profile_json(const Profile& p, const ProfileCurve* curve) {
  nlohmann::json j = {{"source", p.source}, {"format", p.format}, {"kind", to_string(p.kind)},
                      {"sha256", p.checksum}, {"points", p.size()}, {"y_min_mm", p.y.front() * units::per_mm},
                      {"y_max_mm", p.y.back() * units::per_mm}};
  if (curve) {
    j["fit_window_mm"] = curve->window_used() * units::per_mm;
    j["noise"] = noise_json(curve->noise());
  }
  j["warnings"] = p.warnings;
  return j;
}

nlohmann::json ellipses_json(const ContactGeometry& G) {
  nlohmann::json a = nlohmann::json::array();
  for (const PotentialEllipse& P : G.ellipses)
    a.push_back({{"ellipse", P.index}, {"tY_min_mm", grid_mm(P.tY_min)}, {"tY_max_mm", grid_mm(P.tY_max)},
                 {"y_rail_min_mm", P.y_r_min * units::per_mm}, {"y_rail_max_mm", P.y_r_max * units::per_mm},
                 {"y_wheel_min_mm", P.y_w_min * units::per_mm}, {"y_wheel_max_mm", P.y_w_max * units::per_mm}});
  return a;
}

namespace {
nlohmann::json axis_json(const SweepAxis& a) {
  if (!a.list.empty()) return a.list;
  return {{"from", a.from}, {"to", a.at(a.n - 1)}, {"step", a.step}};
}
}  // namespace

nlohmann::json inputs_json(const CaseFile& cf, const std::string& base_dir) {
  nlohmann::json j = cf.resolved_json();
  for (const char* k : {"case_count", "case_file", "case_order"}) j.erase(k);
  for (const char* side : {"wheel", "rail"}) {
    nlohmann::json& p = j[side]["profile"];
    if (p.is_object() && p.contains("file") && p["file"].is_string()) {
      std::error_code ec;
      const std::filesystem::path abs = std::filesystem::absolute(p["file"].get<std::string>(), ec);
      std::filesystem::path rel;
      if (!base_dir.empty()) rel = std::filesystem::relative(abs, std::filesystem::absolute(base_dir, ec), ec);
      p["file"] = (base_dir.empty() || ec || rel.empty()) ? abs.lexically_normal().string() : rel.string();
    }
  }
  if (cf.has_cases) {
    if (!cf.cases.empty()) {
      nlohmann::json c = nlohmann::json::array();
      for (const CasePoint& cp : cf.cases) c.push_back({{"tY_mm", cp.tY_mm}, {"Q_kN", cp.Q_kN}});
      j["cases"] = c;
    } else {
      j["sweep"] = {{"tY_mm", axis_json(cf.sweep_tY_mm)}, {"Q_kN", axis_json(cf.sweep_Q_kN)}};
      if (cf.sweep_roll_mrad.size() > 0) j["sweep"]["roll_mrad"] = axis_json(cf.sweep_roll_mrad);
    }
  }
  return j;
}

nlohmann::json profiles_json(const PairGeometry& pg) {
  nlohmann::json j = {{"wheel", profile_json(pg.wheel, pg.geo.wheel_curve.get())},
                      {"rail", profile_json(pg.rail, pg.geo.rail_curve.get())}};
  // The rail's cant as used (after the case's inclination) and as in its file (profiles.md §3).
  j["rail"]["cant"] = cant_json(pg.cant.used);
  j["rail"]["cant"]["file_angle_deg"] = pg.cant.file_angle / units::deg;
  j["rail"]["cant"]["inclination_deg"] = pg.cant.inclination / units::deg;
  return j;
}

// The profiles as used (rail with its inclination), canonical frame, mm: for plots.
void write_profiles_csv(const PairGeometry& pg, const std::string& path) {
  OutputFile f(path);
  std::string s = "kind,y_mm,z_mm,z_contact_mm\n";
  // z_contact_mm: the surface the grid methods solve on (geometry/gap.hpp) at the point's y, i.e.
  // a measured profile smoothed for contact (profiles.md, "Smoothing for contact"), else the
  // profile's smooth curve; what an independent solver must be given to solve the same problem.
  // Empty where the curve was not built (a wheel's flange back, beyond where it can meet the rail).
  const ProfileCurve* gap_curve[2] = {pg.geo.wheel_gap_curve.get(), pg.geo.rail_gap_curve.get()};
  const Profile* prof[2] = {&pg.wheel, &pg.rail};
  for (int k = 0; k < 2; ++k) {
    const Profile* p = prof[k];
    for (std::size_t i = 0; i < p->size(); ++i) {
      s += to_string(p->kind);
      cnum(s, p->y[i] * units::per_mm);
      cnum(s, p->z[i] * units::per_mm);
      s += ',';
      if (gap_curve[k] && gap_curve[k]->contains(p->y[i])) num(s, gap_curve[k]->z(p->y[i]) * units::per_mm);
      s += '\n';
    }
  }
  f.stream() << s;
  f.commit();
}


void write_caf_csv(const ContactGeometry& G, const std::string& path) {
  OutputFile f(path);
  std::string s = "tY_mm,y_rail_mm,y_wheel_mm,gamma_deg,R_rxx_mm,R_wxx_mm,R_wyy_mm,r_roll_mm,wheel_dz_mm,strip,ellipse\n";
  for (std::size_t k = 0; k < G.tY.size(); ++k) {
    const CandidateGeom& c = G.main_at(k);
    num(s, grid_mm(G.tY[k]));
    cnum(s, c.y_r * units::per_mm);
    cnum(s, c.y_w * units::per_mm);
    cnum(s, c.gamma / units::deg);
    cnum(s, radius_mm(c.k_rxx));
    cnum(s, radius_mm(c.k_wxx));
    cnum(s, c.R_wyy() * units::per_mm);
    cnum(s, c.r_roll * units::per_mm);
    cnum(s, -G.z_contact[k] * units::per_mm);
    s += ','; append_number(s, static_cast<long long>(G.main_strip[k]));
    s += ','; append_number(s, static_cast<long long>(G.main_ellipse[k] + 1));
    s += '\n';
  }
  f.stream() << s;
  f.commit();
}

}  // namespace mh
