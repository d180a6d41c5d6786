// The C interface's results (include/mhcontact.h): a solved case converted into mhc_result, its
// status, method and warning codes, and the accessors of its structured warnings.
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <string>

#include "capi/handles.hpp"
#include "contact/judge/status.hpp"

namespace mh::capi {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::uint32_t warning_bit(const Warning& w) {
  switch (w.cls) {
    case WarningClass::FlangeClimb: return MHC_WARN_FLANGE_CLIMB;
    case WarningClass::NonHertzianExcluded: return MHC_WARN_NON_HERTZIAN_EXCLUDED;
    case WarningClass::NonHertzian: return MHC_WARN_NON_HERTZIAN;
    case WarningClass::OffProfile: return MHC_WARN_OFF_PROFILE;
    case WarningClass::Interacting: return MHC_WARN_INTERACTING;
    case WarningClass::PressureSpike: return MHC_WARN_PRESSURE_SPIKE;
    case WarningClass::StripOutlier: return MHC_WARN_STRIP_OUTLIER;
    default: return MHC_WARN_OTHER;
  }
}


int32_t method_code(Method m) {
  switch (m) {
    case Method::MultiHertzian: return MHC_METHOD_MULTI_HERTZIAN;
    case Method::HalfSpace: return MHC_METHOD_HALF_SPACE;
    case Method::Strips: return MHC_METHOD_STRIPS;
    case Method::Auto: return MHC_METHOD_AUTO;
  }
  return MHC_METHOD_AUTO;
}

}  // namespace

int32_t status_code(CaseStatus s) {
  switch (s) {
    case CaseStatus::Ok: return MHC_STATUS_OK;
    case CaseStatus::NoContact: return MHC_STATUS_NO_CONTACT;
    case CaseStatus::OutOfRange: return MHC_STATUS_OUT_OF_RANGE;
    case CaseStatus::NotConverged: return MHC_STATUS_NOT_CONVERGED;
    case CaseStatus::OutsideValidity: return MHC_STATUS_OUTSIDE_VALIDITY;
    case CaseStatus::Derailed: return MHC_STATUS_DERAILED;
  }
  return MHC_STATUS_NOT_CONVERGED;
}

bool result_ok(const mhc_result* out, std::size_t result_size) {
  if (!out) return fail(MHC_ERR_ARGUMENT, "result: null pointer"), false;
  if (result_size < sizeof(mhc_result))
    return fail(MHC_ERR_ARGUMENT, "result: struct_size = " + std::to_string(result_size) +
                                      ": must be sizeof(mhc_result) = " + std::to_string(sizeof(mhc_result)) +
                                      " (a header older than the library, or struct_size not set)"),
           false;
  return true;
}

bool warning_size_ok(std::size_t size, const char* field) {
  if (size >= sizeof(mhc_warning)) return true;
  return fail(MHC_ERR_ARGUMENT, std::string(field) + " = " + std::to_string(size) + ": set it to sizeof(mhc_warning) (" +
                                    std::to_string(sizeof(mhc_warning)) + ")"),
         false;
}

void fill_result(const CaseResult& r, double tY, double Q, bool plastic, mhc_result* out) {
  // Every field is set below; of the ~1 kB contact array only the slots left unused are cleared
  // (so that equal cases give equal bytes).
  out->status = status_code(r.status);
  out->method = method_code(r.method);
  out->n_contacts = r.n_contacts;
  out->iterations = r.iterations;
  out->n_warnings = static_cast<int32_t>(r.warnings.size());
  out->warnings = 0;
  for (const Warning& w : r.warnings) out->warnings |= warning_bit(w);
  out->tY_m = tY;
  out->Q_N = std::isnan(Q) ? r.Fz : Q;
  // A case without a solution leaves every result field NaN (empty in cases.csv).
  const bool failed = r.status == CaseStatus::NoContact || r.status == CaseStatus::OutOfRange;
  out->dz_m = failed ? kNaN : r.dz;
  out->approach_m = failed ? kNaN : r.approach;
  out->residual = failed ? kNaN : r.residual;
  out->Fz_N = failed ? kNaN : r.Fz;
  out->Fy_N = failed ? kNaN : r.Fy;
  out->p_max_Pa = failed ? kNaN : r.pmax;
  out->area_m2 = failed ? kNaN : r.area;
  out->gamma_main_rad = kNaN;
  out->r_roll_main_m = kNaN;
  out->dFz_ddz_N_per_m = failed ? kNaN : 0.0;
  out->plastic = 0;
  out->reserved = 0;
  if (r.n_contacts > MHC_MAX_CONTACTS) out->warnings |= MHC_WARN_TRUNCATED;
  const LoadedEllipse* main = nullptr;
  int k = 0;
  for (const LoadedEllipse& L : r.loaded) {
    if (!main || L.s.N > main->s.N) main = &L;
    const double cg = L.cos_gamma, sg = L.sin_gamma;
    const double dN_dh0 = normal_stiffness(L);
    out->dFz_ddz_N_per_m += dN_dh0 * cg * cg;  // d(N cos γ)/dδz with dh0/dδz = cos γ (eq. 11)
    if (plastic && L.s.plastic) out->plastic = 1;
    if (k >= MHC_MAX_CONTACTS) continue;
    mhc_contact& c = out->contact[k++];
    c.index = L.ellipse;
    c.flags = (plastic && L.s.plastic ? MHC_CONTACT_PLASTIC : 0u) | (L.validity.valid ? 0u : MHC_CONTACT_NON_HERTZIAN) |
              (L.g.off_profile ? MHC_CONTACT_OFF_PROFILE : 0u);
    c.y_rail_m = L.g.y_r;
    c.z_rail_m = L.z_r;
    c.y_wheel_m = L.g.y_w;
    c.z_wheel_m = L.z_w;
    c.gamma_rad = L.g.gamma;
    c.r_roll_m = L.g.r_roll;
    c.N_N = L.s.N;
    c.Fz_N = L.s.N * cg;
    c.Fy_N = L.s.N * sg;
    c.a_m = L.s.a;
    c.b_m = L.s.b;
    c.A_per_m = L.A;
    c.B_per_m = L.B;
    c.p_max_Pa = L.s.p_max;
    c.area_m2 = units::pi * L.s.a * L.s.b;
    c.h0_m = L.s.h0;
    c.approach_m = L.s.approach;
    c.dN_ddz_N_per_m = dN_dh0 * cg;
  }
  if (main) {
    out->gamma_main_rad = main->g.gamma;
    out->r_roll_main_m = main->g.r_roll;
  }
  // Grid methods: patches (no ellipse law: no curvature sums, no stiffness).
  const PatchResult* main_patch = nullptr;
  for (const PatchResult& P : r.patches) {
    if (!main_patch || P.N > main_patch->N) main_patch = &P;
    if (plastic && P.plastic_area > 0) out->plastic = 1;
    if (k >= MHC_MAX_CONTACTS) continue;
    mhc_contact& c = out->contact[k++];
    c.index = P.patch;
    c.flags = plastic && P.plastic_area > 0 ? MHC_CONTACT_PLASTIC : 0u;
    c.y_rail_m = P.y_r;
    c.z_rail_m = P.z_r;
    c.y_wheel_m = P.y_w;
    c.z_wheel_m = kNaN;
    c.gamma_rad = P.gamma;
    c.r_roll_m = P.r_roll;
    c.N_N = P.N;
    c.Fz_N = P.N * std::cos(P.gamma);
    c.Fy_N = P.N * std::sin(P.gamma);
    c.a_m = 0.5 * P.length_x;
    c.b_m = 0.5 * P.width_s;
    c.A_per_m = c.B_per_m = kNaN;
    c.p_max_Pa = P.pmax;
    c.area_m2 = P.area;
    c.h0_m = kNaN;
    c.approach_m = P.approach;
    c.dN_ddz_N_per_m = kNaN;
  }
  if (k < MHC_MAX_CONTACTS)
    std::memset(static_cast<void*>(&out->contact[k]), 0, sizeof(mhc_contact) * static_cast<std::size_t>(MHC_MAX_CONTACTS - k));
  if (!failed && r.method != Method::MultiHertzian) out->dFz_ddz_N_per_m = kNaN;
  if (main_patch) {
    out->gamma_main_rad = main_patch->gamma;
    out->r_roll_main_m = main_patch->r_roll;
  }
}

void fill_warning(const Warning& w, mhc_warning* out) {
  const std::size_t size = out->struct_size;
  std::memset(static_cast<void*>(out), 0, sizeof(mhc_warning));
  out->struct_size = size;
  out->class_name = to_string(w.cls);
  out->outside_validity = is_validity_class(w.cls) ? 1 : 0;
  out->contact_kind = static_cast<int32_t>(w.kind);
  out->contact = w.contact;
  out->contact2 = w.contact2;
  out->n_measures = w.n;
  for (int k = 0; k < w.n && k < MHC_WARNING_MAX_MEASURES; ++k) {
    const Measure& m = w.m[static_cast<std::size_t>(k)];
    mhc_warning_measure& o = out->measure[k];
    o.name = name(m.q);
    o.unit = si_unit(m.q);
    o.value_si = m.value;
    o.limit_si = m.rel ? m.limit : std::numeric_limits<double>::quiet_NaN();
    o.relation = m.rel;
  }
}

}  // namespace mh::capi

using namespace mh;
using mh::capi::fail;
using mh::capi::need;

int32_t mhc_result_n_warnings(const mhc_workspace* ws) {
  return ws ? static_cast<int32_t>(ws->r.warnings.size()) : 0;
}

mhc_error mhc_result_warning(const mhc_workspace* ws, int32_t i, mhc_warning* out) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(ws, "ws")) return e;
  if (mhc_error e = need(out, "out")) return e;
  if (!mh::capi::warning_size_ok(out->struct_size, "out->struct_size")) return MHC_ERR_ARGUMENT;
  if (i < 0 || static_cast<std::size_t>(i) >= ws->r.warnings.size())
    return fail(MHC_ERR_ARGUMENT, "warning " + std::to_string(i) + ": the case has " +
                                      std::to_string(ws->r.warnings.size()) + " (0-based index)");
  mh::capi::fill_warning(ws->r.warnings[static_cast<std::size_t>(i)], out);
  return MHC_OK;
}

const char* mhc_warning_text(const mhc_workspace* ws, int32_t i) {
  thread_local std::string text;
  text.clear();
  if (ws && i >= 0 && static_cast<std::size_t>(i) < ws->r.warnings.size())
    text = warning_text(ws->r.warnings[static_cast<std::size_t>(i)]);
  return text.c_str();
}
