// The C interface's RCF, damage and wear accessors (include/mhcontact.h, the last section): one
// contact of a workspace's last case by the same functions as the output columns
// (contact/rcf/), and the subsurface peaks of a Hertzian ellipse.
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "capi/handles.hpp"
#include "contact/rcf/contact_damage.hpp"
#include "contact/rcf/shakedown.hpp"
#include "contact/rcf/subsurface.hpp"
#include "core/units.hpp"

using mh::capi::fail;
using mh::capi::need;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

template <class T>
mhc_error check_size(T* out, const char* type) {
  if (out->struct_size < sizeof(T))
    return fail(MHC_ERR_ARGUMENT, "out->struct_size = " + std::to_string(out->struct_size) + ": set it to sizeof(" +
                                      type + ") (" + std::to_string(sizeof(T)) + ")");
  return MHC_OK;
}

}  // namespace

mhc_error mhc_result_rcf(const mhc_workspace* ws, int32_t i, double k_Pa, mhc_rcf_contact* out) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(ws, "ws")) return e;
  if (mhc_error e = need(out, "out")) return e;
  if (mhc_error e = check_size(out, "mhc_rcf_contact")) return e;
  const mh::CaseResult& r = ws->r;
  const std::size_t n = r.loaded.size() + r.patches.size();
  if (i < 0 || static_cast<std::size_t>(i) >= n)
    return fail(MHC_ERR_ARGUMENT, "contact " + std::to_string(i) + ": the case has " + std::to_string(n) + " (0-based index)");
  double N, a_el, b_el, A;
  const mh::TangentialResult* t;
  if (!r.loaded.empty()) {
    const mh::LoadedEllipse& L = r.loaded[static_cast<std::size_t>(i)];
    N = L.s.N, a_el = L.s.a_el, b_el = L.s.b_el, A = mh::wear_area(L), t = &L.t;
  } else {
    const mh::PatchResult& P = r.patches[static_cast<std::size_t>(i)];
    N = P.N, a_el = P.a_el, b_el = P.b_el, A = P.area, t = &P.t;
  }
  const std::size_t size = out->struct_size;
  std::memset(static_cast<void*>(out), 0, sizeof(mhc_rcf_contact));
  out->struct_size = size;
  mh::RcfOptions o;
  o.actual = true;
  o.k = std::isfinite(k_Pa) ? k_Pa : mh::material_yield(ws->pair->material) / std::sqrt(3.0);
  const double f = o.traction(N, t->Fx, t->Fy, t->solved);
  const mh::RcfPoint p = mh::rcf_point(f, o.k, N, a_el, b_el, ws->pair->material.nur());
  const mh::ContactDamage d = mh::contact_damage(*t, N, A);  // the published defaults (damage.hpp)
  out->N_N = N;
  out->traction = f;
  out->Tgamma_N = t->solved ? t->Tgamma : kNaN;
  out->Tgamma_spin_N = t->solved ? t->Tgamma_spin : kNaN;
  out->damage_per_axle = d.damage;
  out->wear_rate_kg_per_m3 = d.wear_rate;
  out->wear_kg_per_m = d.wear_per_metre;
  out->p0_el_Pa = N > 0 && a_el > 0 && b_el > 0 ? 1.5 * N / (mh::units::pi * a_el * b_el) : kNaN;
  out->p0_el_over_k = p.p0_el_over_k;
  out->elastic_limit = p.elastic_limit;
  out->shakedown_limit = p.shakedown_limit;
  out->FI_surf_el = p.fi_surf_el;
  out->shakedown_regime = std::isfinite(p.p0_el_over_k) ? static_cast<int32_t>(p.regime) : -1;
  return MHC_OK;
}

mhc_error mhc_hertz_subsurface(double a_m, double b_m, double p0_Pa, double fx, double fy, double nu,
                               mhc_subsurface* out) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(out, "out")) return e;
  if (mhc_error e = check_size(out, "mhc_subsurface")) return e;
  if (!(a_m > 0 && b_m > 0 && p0_Pa > 0))
    return fail(MHC_ERR_ARGUMENT, "a_m, b_m, p0_Pa = " + std::to_string(a_m) + ", " + std::to_string(b_m) + ", " +
                                      std::to_string(p0_Pa) + ": must all be > 0 (m, m, Pa)");
  if (!(std::isfinite(fx) && std::isfinite(fy) && std::hypot(fx, fy) <= 1))
    return fail(MHC_ERR_ARGUMENT, "traction (fx, fy) = (" + std::to_string(fx) + ", " + std::to_string(fy) +
                                      "): |f| must be at most 1");
  if (!(nu > 0 && nu < 0.5))
    return fail(MHC_ERR_ARGUMENT, "nu = " + std::to_string(nu) + ": must be in (0, 0.5)");
  mh::HertzLoad L;
  L.a = a_m, L.b = b_m, L.p0 = p0_Pa, L.fx = fx, L.fy = fy, L.nu = nu;
  mh::SubsurfacePeaks P;
  if (mhc_error e = mh::capi::guarded([&] { P = mh::subsurface_peaks(L); return MHC_OK; })) return e;
  const std::size_t size = out->struct_size;
  std::memset(static_cast<void*>(out), 0, sizeof(mhc_subsurface));
  out->struct_size = size;
  out->vm_max_Pa = P.vm_max, out->vm_depth_m = P.vm_z;
  out->tau_max_Pa = P.tau_max, out->tau_depth_m = P.tau_z;
  out->tau_orth_amp_Pa = P.tau_orth_amp, out->tau_orth_depth_m = P.tau_orth_z;
  out->tau_eq_amp_Pa = P.tau_eq_amp, out->sigma_h_Pa = P.sigma_h;
  return MHC_OK;
}
