// The C interface's tangential problem (include/mhcontact.h, section "tangential contact"): a
// pair's friction and kinematics, and the creep forces of the last case a workspace solved.
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <string>

#include "capi/handles.hpp"
#include "core/numfmt.hpp"

using namespace mh;
using mh::capi::fail;
using mh::capi::need;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The first version's fields end here: a smaller struct_size cannot hold the creepages.
constexpr std::size_t kTangentialOptionsMinSize = offsetof(mhc_tangential_options, vertical_equilibrium);

void fill_contact(const TangentialResult& t, mhc_contact_tangential& c) {
  c.solved = t.solved ? 1 : 0;
  c.reserved = 0;
  c.xi = t.c.xi;
  c.eta = t.c.eta;
  c.phi_per_m = t.c.phi;
  // On the rail (the tables' convention; TangentialResult holds the forces on the wheel).
  c.Fx_N = t.solved ? -t.Fx : kNaN;
  c.Fy_N = t.solved ? -t.Fy : kNaN;
  c.Mz_Nm = t.solved ? -t.Mz : kNaN;
  c.adhesion_fraction = t.solved ? t.adhesion_fraction : kNaN;
  c.Tgamma_N = t.solved ? t.Tgamma : kNaN;
  c.Tgamma_spin_N = t.solved ? t.Tgamma_spin : kNaN;
}

}  // namespace

void mhc_tangential_options_init(mhc_tangential_options* opt) {
  if (!opt) return;
  std::memset(static_cast<void*>(opt), 0, sizeof(mhc_tangential_options));
  const TangentialOptions d;
  opt->struct_size = sizeof(mhc_tangential_options);
  opt->mu = d.mu;
  opt->creepages_given = 0;
  opt->speed_m_s = 30;
  opt->yaw_rad = 0;
  opt->yaw_rad_per_m = 0;
  opt->lateral_velocity_m_s = 0;
  opt->yaw_rate_rad_s = 0;
  opt->pitch_rate_rad_s = d.kin.pitch_rate;
  opt->xi = opt->eta = opt->phi_per_m = 0;
  opt->vertical_equilibrium = d.vertical_equilibrium ? 1 : 0;
}

mhc_error mhc_pair_set_tangential(mhc_pair* pair, const mhc_tangential_options* opt) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(pair, "pair")) return e;
  if (mhc_error e = need(opt, "options")) return e;
  if (opt->struct_size < kTangentialOptionsMinSize || opt->struct_size > sizeof(mhc_tangential_options))
    return fail(MHC_ERR_ARGUMENT, "tangential options: struct_size = " + std::to_string(opt->struct_size) +
                                      ": must be sizeof(mhc_tangential_options) = " +
                                      std::to_string(sizeof(mhc_tangential_options)) + " or that of an earlier "
                                      "header (at least " + std::to_string(kTangentialOptionsMinSize) +
                                      "); call mhc_tangential_options_init");
  // The caller's struct, its missing (later) fields at their defaults.
  mhc_tangential_options o;
  mhc_tangential_options_init(&o);
  std::memcpy(static_cast<void*>(&o), opt, opt->struct_size);
  auto bad = [](const char* field, double v, const char* rule) {
    return fail(MHC_ERR_ARGUMENT, std::string("tangential options.") + field + " = " + format_number(v) + ": " + rule);
  };
  if (!std::isnan(o.mu) && !(o.mu >= 0 && o.mu <= 2))
    return bad("mu", o.mu, "must be 0 to 2 (Coulomb's coefficient), or NaN for no tangential problem");
  if (o.creepages_given != 0 && o.creepages_given != 1)
    return bad("creepages_given", o.creepages_given, "must be 0 (from the kinematics) or 1 (xi, eta, phi_per_m)");
  if (!(o.speed_m_s > 0 && std::isfinite(o.speed_m_s))) return bad("speed_m_s", o.speed_m_s, "must be > 0 and finite");
  for (const auto& [field, v] : {std::pair<const char*, double>{"yaw_rad", o.yaw_rad}, {"yaw_rad_per_m", o.yaw_rad_per_m},
                                 {"lateral_velocity_m_s", o.lateral_velocity_m_s}, {"yaw_rate_rad_s", o.yaw_rate_rad_s},
                                 {"xi", o.xi}, {"eta", o.eta}, {"phi_per_m", o.phi_per_m}})
    if (!std::isfinite(v)) return bad(field, v, "must be finite");
  if (!std::isnan(o.pitch_rate_rad_s) && !std::isfinite(o.pitch_rate_rad_s))
    return bad("pitch_rate_rad_s", o.pitch_rate_rad_s, "must be finite, or NaN for rolling at the nominal radius");
  if (o.vertical_equilibrium != 0 && o.vertical_equilibrium != 1)
    return bad("vertical_equilibrium", o.vertical_equilibrium, "must be 0 or 1");
  TangentialOptions& t = pair->options.tangential;
  t.mu = o.mu;
  t.source = o.creepages_given ? TangentialOptions::Source::Creepages : TangentialOptions::Source::Kinematics;
  t.kin.V = o.speed_m_s;
  t.kin.yaw = o.yaw_rad;
  t.yaw_per_tY = o.yaw_rad_per_m;
  t.kin.lateral_velocity = o.lateral_velocity_m_s;
  t.kin.yaw_rate = o.yaw_rate_rad_s;
  t.kin.pitch_rate = o.pitch_rate_rad_s;
  t.creep = {o.xi, o.eta, o.phi_per_m};
  t.vertical_equilibrium = o.vertical_equilibrium != 0;
  // The grid methods keep their patch pressures when friction is given (solve.cpp).
  return MHC_OK;
}

namespace mh::capi {

void fill_tangential(const CaseResult& r, double mu, mhc_tangential* out) {
  const std::size_t size = out->struct_size;
  std::memset(static_cast<void*>(out), 0, sizeof(mhc_tangential));
  out->struct_size = size;
  const TangentialSums& s = r.tangential;
  const bool failed = is_failure(r.status);
  const bool ok = s.asked && s.solved && !failed;
  out->asked = s.asked ? 1 : 0;
  out->solved = ok ? 1 : 0;
  out->mu = s.asked ? mu : kNaN;
  out->Fx_N = ok ? s.Fx : kNaN;
  out->Fy_creep_N = ok ? s.Fy_creep : kNaN;
  out->Mz_Nm = ok ? s.Mz : kNaN;
  out->F_over_muN = ok ? s.F_over_muN : kNaN;
  out->Y_N = ok ? r.Fy + s.Fy_creep : kNaN;
  out->Fz_creep_N = ok ? s.Fz_creep : kNaN;
  int k = 0;
  if (s.asked && !failed) {
    for (const LoadedEllipse& L : r.loaded)
      if (k < MHC_MAX_CONTACTS) fill_contact(L.t, out->contact[k++]);
    for (const PatchResult& P : r.patches)
      if (k < MHC_MAX_CONTACTS) fill_contact(P.t, out->contact[k++]);
  }
  out->n_contacts = k;
}

}  // namespace mh::capi

mhc_error mhc_result_tangential(const mhc_workspace* ws, mhc_tangential* out) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(ws, "ws")) return e;
  if (mhc_error e = need(out, "out")) return e;
  if (out->struct_size != sizeof(mhc_tangential))
    return fail(MHC_ERR_ARGUMENT, "out->struct_size = " + std::to_string(out->struct_size) +
                                      ": set it to sizeof(mhc_tangential) (" + std::to_string(sizeof(mhc_tangential)) + ")");
  mh::capi::fill_tangential(ws->r, ws->pair ? ws->pair->options.tangential.mu : kNaN, out);
  return MHC_OK;
}
