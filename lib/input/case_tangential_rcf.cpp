// Friction, kinematics or creepages, FASTSIM and the RCF keys of a case file (case_tangential_rcf.hpp).
#include "input/case_tangential_rcf.hpp"

#include <cmath>

#include "core/numfmt.hpp"
#include "core/units.hpp"

namespace mh {
namespace detail {

using nlohmann::json;

// "friction", "kinematics" | "creepages", "fastsim" (docs/case-file.md, docs/tangential.md). One
// rule per option, each error at its JSON path. Reads the track setup already parsed (l, r0).
void parse_tangential(const Ctx& c, const json& j, CaseFile& cf) {
  TangentialOptions& t = cf.tangential;
  const bool fr = j.contains("friction"), ki = j.contains("kinematics"), cr = j.contains("creepages");
  if (!fr) {
    if (ki) c.fail("/kinematics", &j.at("kinematics"), "needs friction.coefficient", "add \"friction\": {\"coefficient\": 0.3}, or remove kinematics");
    if (cr) c.fail("/creepages", &j.at("creepages"), "needs friction.coefficient", "add \"friction\": {\"coefficient\": 0.3}, or remove creepages");
    if (j.contains("fastsim")) c.fail("/fastsim", &j.at("fastsim"), "needs friction.coefficient", "add \"friction\": {\"coefficient\": 0.3}, or remove fastsim");
    return;
  }
  const json& f = j.at("friction");
  c.only_keys(f, "/friction", {"coefficient"});
  if (!f.contains("coefficient")) c.fail("/friction/coefficient", nullptr, "required: the Coulomb friction coefficient (e.g. 0.3)");
  t.mu = c.number(f, "/friction", "coefficient");
  if (!(t.mu > 0 && t.mu <= 1)) c.fail("/friction/coefficient", &f.at("coefficient"), "must be in (0, 1]", "wheel-rail friction is about 0.1 (wet) to 0.5 (dry)");
  if (ki == cr)
    c.fail(ki ? "/creepages" : "/friction", ki ? &j.at("creepages") : &f,
           ki ? "kinematics and creepages exclude each other" : "needs kinematics or creepages",
           ki ? "give the wheelset's motion or the creepages, not both"
              : "add \"kinematics\": {\"speed_m_s\": 30} or \"creepages\": {\"xi\": 0, \"eta\": 0, \"phi_per_mm\": 0}");
  if (cr) {
    const json& k = j.at("creepages");
    c.only_keys(k, "/creepages", {"xi", "eta", "phi_per_mm"});
    t.source = TangentialOptions::Source::Creepages;
    if (k.contains("xi")) t.creep.xi = c.number(k, "/creepages", "xi");
    if (k.contains("eta")) t.creep.eta = c.number(k, "/creepages", "eta");
    if (k.contains("phi_per_mm")) t.creep.phi = c.number(k, "/creepages", "phi_per_mm") / units::mm;
    for (const char* key : {"xi", "eta"})
      if (k.contains(key) && std::abs(c.number(k, "/creepages", key)) > 0.5)
        c.fail(std::string("/creepages/") + key, &k.at(key), "must lie within -0.5 … 0.5 (a creepage, not per cent)");
    if (std::abs(t.creep.phi) > 1000.0)
      c.fail("/creepages/phi_per_mm", &k.at("phi_per_mm"), "must lie within -1 … 1 rad/mm", "is it in rad/m?");
  } else {
    const json& k = j.at("kinematics");
    c.only_keys(k, "/kinematics", {"speed_m_s", "yaw_mrad", "yaw_mrad_per_mm", "lateral_velocity_m_s", "yaw_rate_rad_s", "pitch_rate_rad_s"});
    t.source = TangentialOptions::Source::Kinematics;
    if (!k.contains("speed_m_s")) c.fail("/kinematics/speed_m_s", nullptr, "required: the forward speed V [m/s] (> 0)");
    t.kin.V = c.positive(k, "/kinematics", "speed_m_s");
    if (t.kin.V > 200) c.fail("/kinematics/speed_m_s", &k.at("speed_m_s"), "must be at most 200 m/s", "is it in km/h?");
    if (k.contains("yaw_mrad") && k.contains("yaw_mrad_per_mm"))
      c.fail("/kinematics/yaw_mrad_per_mm", &k.at("yaw_mrad_per_mm"), "yaw_mrad and yaw_mrad_per_mm exclude each other",
             "give the yaw angle, or the yaw per mm of t_Y");
    if (k.contains("yaw_mrad")) t.kin.yaw = c.number(k, "/kinematics", "yaw_mrad") * 1e-3;
    if (std::abs(t.kin.yaw) > 0.1) c.fail("/kinematics/yaw_mrad", &k.at("yaw_mrad"), "must lie within -100 … 100 mrad", "is it in µrad?");
    if (k.contains("yaw_mrad_per_mm")) t.yaw_per_tY = c.number(k, "/kinematics", "yaw_mrad_per_mm");  // mrad/mm = rad/m
    if (std::abs(t.yaw_per_tY) > 20) c.fail("/kinematics/yaw_mrad_per_mm", &k.at("yaw_mrad_per_mm"), "must lie within -20 … 20 mrad/mm");
    if (k.contains("lateral_velocity_m_s")) t.kin.lateral_velocity = c.number(k, "/kinematics", "lateral_velocity_m_s");
    if (std::abs(t.kin.lateral_velocity) > 0.1 * t.kin.V)
      c.fail("/kinematics/lateral_velocity_m_s", &k.at("lateral_velocity_m_s"), "must be at most 0.1 x speed_m_s (a creepage of 0.1)");
    if (k.contains("yaw_rate_rad_s")) t.kin.yaw_rate = c.number(k, "/kinematics", "yaw_rate_rad_s");
    if (std::abs(t.kin.yaw_rate) > 10) c.fail("/kinematics/yaw_rate_rad_s", &k.at("yaw_rate_rad_s"), "must lie within -10 … 10 rad/s");
    if (k.contains("pitch_rate_rad_s")) {
      if (k.at("pitch_rate_rad_s").is_string() && k.at("pitch_rate_rad_s") == "nominal") {
        t.kin.pitch_rate = NAN;
      } else {
        t.kin.pitch_rate = c.positive(k, "/kinematics", "pitch_rate_rad_s");
        const double nominal = t.kin.V / cf.track.nominal_radius;
        if (std::abs(t.kin.pitch_rate / nominal - 1) > 0.1)
          c.fail("/kinematics/pitch_rate_rad_s", &k.at("pitch_rate_rad_s"),
                 "must lie within 10 % of rolling at the nominal radius (" + format_number(nominal) + " rad/s)",
                 "omit it (or give \"nominal\") for rolling at the nominal radius");
      }
    }
  }
  if (j.contains("fastsim")) {
    const json& o = j.at("fastsim");
    c.only_keys(o, "/fastsim", {"nx", "ny", "bound", "blend"});
    if (o.contains("nx")) t.fastsim.nx = static_cast<int>(c.integer(o, "/fastsim", "nx", 2, kFastsimMaxN));
    if (o.contains("ny")) t.fastsim.ny = static_cast<int>(c.integer(o, "/fastsim", "ny", 2, kFastsimMaxN));
    if (o.contains("bound")) {
      const std::string b = c.string(o, "/fastsim", "bound");
      if (b == "parabolic") t.fastsim.bound = TractionBound::Parabolic;
      else if (b != "elliptical") c.fail("/fastsim/bound", &o.at("bound"), "must be \"elliptical\" (default) or \"parabolic\"");
    }
    if (o.contains("blend")) t.fastsim.blend = c.boolean(o, "/fastsim", "blend");
  }
  t.r0 = cf.track.nominal_radius;
  t.l_origin = 0.5 * cf.track.flange_back_distance - cf.track.flange_back_position;
}


// RCF indicators (docs/outputs.md "RCF columns"): f (the contacts' own |F|/N when friction is
// given), and k or the material's yield; the damage and wear functions' constants and the
// t_Y distribution of the damage (docs/outputs.md "Damage and wear columns").
void parse_rcf(const Ctx& c, const json& j, CaseFile& cf) {
  if (!j.contains("rcf")) return;
  const json& h = j.at("rcf");
  c.only_keys(h, "/rcf", {"traction_coefficient", "shear_yield_MPa", "burstow", "usfd_wear", "tY_distribution", "subsurface"});
  const bool friction = j.contains("friction");
  if (friction) {
    if (h.contains("traction_coefficient"))
      c.fail("/rcf/traction_coefficient", &h.at("traction_coefficient"),
             "not an input when friction is given: each contact's traction coefficient is its own |F|/N from the creep forces",
             "remove rcf.traction_coefficient, or remove friction to use a given f");
    cf.rcf.actual = true;
  } else {
    if (!h.contains("traction_coefficient"))
      c.fail("/rcf", &h, "needs traction_coefficient (f = T/N) when friction is not given",
             "add \"traction_coefficient\": 0.3, or give \"friction\" to use each contact's own |F|/N");
    cf.rcf.f = c.number(h, "/rcf", "traction_coefficient");
    if (!(cf.rcf.f >= 0 && cf.rcf.f <= 1))
      c.fail("/rcf/traction_coefficient", &h.at("traction_coefficient"), "must be in [0, 1]");
  }
  if (h.contains("shear_yield_MPa")) cf.rcf.k = c.positive(h, "/rcf", "shear_yield_MPa") * units::MPa;
  if (!std::isfinite(rcf_shear_yield(cf.material, cf.rcf)))
    c.fail("/rcf", &h, "needs shear_yield_MPa (k = sigma_y/sqrt(3)): the material gives no yield stress");
  for (const char* key : {"burstow", "usfd_wear"})
    if (h.contains(key) && !friction)
      c.fail(std::string("/rcf/") + key, &h.at(key), "needs friction.coefficient: Tgamma comes from the creep forces",
             "add \"friction\": {\"coefficient\": 0.3}, or remove rcf." + std::string(key));
  if (h.contains("burstow")) {
    const json& b = h.at("burstow");
    c.only_keys(b, "/rcf/burstow", {"Tgamma_threshold_N", "Tgamma_peak_N", "damage_peak", "Tgamma_zero_N"});
    BurstowOptions& o = cf.rcf.burstow;
    if (b.contains("Tgamma_threshold_N")) o.Tgamma_threshold_N = c.number(b, "/rcf/burstow", "Tgamma_threshold_N");
    if (b.contains("Tgamma_peak_N")) o.Tgamma_peak_N = c.number(b, "/rcf/burstow", "Tgamma_peak_N");
    if (b.contains("damage_peak")) o.damage_peak = c.positive(b, "/rcf/burstow", "damage_peak");
    if (b.contains("Tgamma_zero_N")) o.Tgamma_zero_N = c.number(b, "/rcf/burstow", "Tgamma_zero_N");
    const std::string why = o.invalid();
    if (!why.empty()) c.fail("/rcf/burstow", &b, why, "the published defaults are 15, 65, 175 J/m and 1e-5");
  }
  if (h.contains("usfd_wear")) {
    const json& u = h.at("usfd_wear");
    c.only_keys(u, "/rcf/usfd_wear", {"K1", "x1_N_per_mm2", "K2", "x2_N_per_mm2", "K3"});
    UsfdWearOptions& o = cf.rcf.usfd;
    if (u.contains("K1")) o.K1 = c.number(u, "/rcf/usfd_wear", "K1");
    if (u.contains("x1_N_per_mm2")) o.x1 = c.number(u, "/rcf/usfd_wear", "x1_N_per_mm2");
    if (u.contains("K2")) o.K2 = c.number(u, "/rcf/usfd_wear", "K2");
    if (u.contains("x2_N_per_mm2")) o.x2 = c.number(u, "/rcf/usfd_wear", "x2_N_per_mm2");
    if (u.contains("K3")) o.K3 = c.number(u, "/rcf/usfd_wear", "K3");
    const std::string why = o.invalid();
    if (!why.empty()) c.fail("/rcf/usfd_wear", &u, why, "the published defaults are K1 5.3, x1 10.4, K2 55.0, x2 77.2, K3 61.9");
  }
  if (h.contains("subsurface")) {
    const json& u = h.at("subsurface");
    c.only_keys(u, "/rcf/subsurface", {"dang_van_c", "grid"});
    cf.rcf.subsurface = true;
    if (u.contains("grid")) cf.rcf.subsurface_grid = c.boolean(u, "/rcf/subsurface", "grid");
    if (u.contains("dang_van_c")) cf.rcf.dang_van_c = c.number(u, "/rcf/subsurface", "dang_van_c");
    if (u.contains("dang_van_c") && !(cf.rcf.dang_van_c >= 0 && cf.rcf.dang_van_c <= 1))
      c.fail("/rcf/subsurface/dang_van_c", &u.at("dang_van_c"), "must be in [0, 1]", "steels: about 0.3");
  }
  if (h.contains("tY_distribution")) {
    const json& d = h.at("tY_distribution");
    c.only_keys(d, "/rcf/tY_distribution", {"mean_mm", "sd_mm"});
    if (!d.contains("mean_mm") || !d.contains("sd_mm"))
      c.fail("/rcf/tY_distribution", &d, "needs mean_mm and sd_mm (a normal distribution of t_Y)",
             "e.g. \"tY_distribution\": {\"mean_mm\": 0, \"sd_mm\": 2}");
    cf.rcf.tY_mean = c.number(d, "/rcf/tY_distribution", "mean_mm") * units::mm;
    cf.rcf.tY_sd = c.positive(d, "/rcf/tY_distribution", "sd_mm") * units::mm;
  }
}

}  // namespace detail
}  // namespace mh
