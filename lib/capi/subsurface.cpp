// The C interface's subsurface stresses of one solved contact (include/mhcontact.h, "subsurface
// stresses of the last case's contacts"): the load and peaks of contact/rcf/contact_stresses.hpp,
// the one computation the command's subsurface columns format (lib/output/rcf_columns.hpp), with
// the options the case file's "rcf" gives the command, in SI.
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <string>

#include "capi/handles.hpp"
#include "contact/rcf/contact_stresses.hpp"

using mh::capi::fail;
using mh::capi::need;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The fields of mhc_subsurface_options up to and including `field` (earlier sizes are accepted).
#define MHC_SUB_HAS(opt, field) \
  ((opt)->struct_size >= offsetof(mhc_subsurface_options, field) + sizeof((opt)->field))

// mhc_subsurface_source is ContactStressSource in the same order.
static_assert(static_cast<int>(mh::ContactStressSource::None) == MHC_SUBSURFACE_NONE &&
              static_cast<int>(mh::ContactStressSource::HertzEllipse) == MHC_SUBSURFACE_HERTZ_ELLIPSE &&
              static_cast<int>(mh::ContactStressSource::GridPatch) == MHC_SUBSURFACE_GRID_PATCH &&
              static_cast<int>(mh::ContactStressSource::GridPatchSolvedTraction) ==
                  MHC_SUBSURFACE_GRID_PATCH_SOLVED_TRACTION &&
              static_cast<int>(mh::ContactStressSource::HertzEllipseFastsim) == MHC_SUBSURFACE_HERTZ_ELLIPSE_FASTSIM,
              "the C enum follows contact_stresses.hpp");

}  // namespace

void mhc_subsurface_options_init(mhc_subsurface_options* opt) {
  if (!opt) return;
  std::memset(static_cast<void*>(opt), 0, sizeof *opt);
  opt->struct_size = sizeof *opt;
  opt->grid = 1;
  opt->traction = kNaN;
  opt->dang_van_c = kNaN;
}

mhc_error mhc_result_subsurface(const mhc_workspace* ws, int32_t i, const mhc_subsurface_options* opt,
                                mhc_contact_subsurface* out) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(ws, "ws")) return e;
  if (mhc_error e = need(out, "out")) return e;
  if (out->struct_size < sizeof(mhc_contact_subsurface))
    return fail(MHC_ERR_ARGUMENT, "out->struct_size = " + std::to_string(out->struct_size) +
                                      ": set it to sizeof(mhc_contact_subsurface) (" +
                                      std::to_string(sizeof(mhc_contact_subsurface)) + ")");
  mhc_subsurface_options o;
  mhc_subsurface_options_init(&o);
  if (opt) {
    if (!MHC_SUB_HAS(opt, grid))
      return fail(MHC_ERR_ARGUMENT, "opt->struct_size = " + std::to_string(opt->struct_size) +
                                        ": set it with mhc_subsurface_options_init");
    o.grid = opt->grid;
    if (MHC_SUB_HAS(opt, traction)) o.traction = opt->traction;
    if (MHC_SUB_HAS(opt, dang_van_c)) o.dang_van_c = opt->dang_van_c;
  }
  if (o.grid != 0 && o.grid != 1)
    return fail(MHC_ERR_ARGUMENT, "subsurface options.grid = " + std::to_string(o.grid) +
                                      ": must be 1 (a grid patch from its own pressure) or 0 (its Hertz ellipse)");
  // As the case file's "rcf" (lib/input/case_tangential_rcf.cpp): each contact's own traction with
  // friction, a given f without.
  const bool friction = mh::capi::pair_has_friction(*ws->pair);
  if (friction && !std::isnan(o.traction))
    return fail(MHC_ERR_ARGUMENT, "subsurface options.traction = " + std::to_string(o.traction) +
                                      ": not an input when the pair has friction (each contact's traction is its "
                                      "own |F|/N): leave it NaN");
  if (!friction && !(o.traction >= 0 && o.traction <= 1))
    return fail(MHC_ERR_ARGUMENT, "subsurface options.traction = " + std::to_string(o.traction) +
                                      ": a pair without friction needs the full-slip traction coefficient f, 0 to 1");
  if (!std::isnan(o.dang_van_c) && !(o.dang_van_c >= 0 && o.dang_van_c <= 1))
    return fail(MHC_ERR_ARGUMENT, "subsurface options.dang_van_c = " + std::to_string(o.dang_van_c) +
                                      ": must be in [0, 1] (steels: about 0.3) or NaN");
  const mh::CaseResult& r = ws->r;
  const std::size_t n = r.loaded.size() + r.patches.size();
  if (i < 0 || static_cast<std::size_t>(i) >= n)
    return fail(MHC_ERR_ARGUMENT, "contact " + std::to_string(i) + ": the case has " + std::to_string(n) + " (0-based index)");
  mh::RcfOptions rcf;  // as lib/jobs/sweep.cpp makes the command's (k plays no part in the stresses)
  rcf.actual = friction;
  rcf.f = friction ? kNaN : o.traction;
  rcf.subsurface = true;
  rcf.subsurface_grid = o.grid == 1;
  rcf.nu = ws->pair->material.nur();  // the rail's stresses
  rcf.dang_van_c = o.dang_van_c;
  const std::size_t size = out->struct_size;
  std::memset(static_cast<void*>(out), 0, sizeof(mhc_contact_subsurface));
  out->struct_size = size;
  mh::ContactStresses S;
  bool could_use_grid = false, plastic = false;
  if (mhc_error e = mh::capi::guarded([&] {
        if (!r.loaded.empty()) {
          const mh::LoadedEllipse& L = r.loaded[static_cast<std::size_t>(i)];
          const double f = rcf.traction(L.s.N, L.t.Fx, L.t.Fy, L.t.solved);
          S = mh::contact_stresses(rcf, L.s.N, L.s.a_el, L.s.b_el, L.t, f, nullptr, mh::ellipse_cells(r, L));
          plastic = ws->pair->plastic && L.s.plastic;
          could_use_grid = friction && L.t.solved && !plastic;
        } else {
          const mh::PatchResult& P = r.patches[static_cast<std::size_t>(i)];
          const double f = rcf.traction(P.N, P.t.Fx, P.t.Fy, P.t.solved);
          S = mh::contact_stresses(rcf, P.N, P.a_el, P.b_el, P.t, f, &P);
          plastic = P.plastic_area > 0;
          could_use_grid = rcf.subsurface_grid && !plastic && std::isfinite(f);
        }
        return MHC_OK;
      }))
    return e;
  const mh::SubsurfacePeaks& P = S.peaks;
  out->source = static_cast<int32_t>(S.source);  // the enums in the same order (contact_stresses.hpp)
  if (plastic) out->warnings |= MHC_SUBSURFACE_WARN_PLASTIC;
  // Not the load the command would take: the grid (or, with friction, the solved traction) not kept.
  const bool best = S.source == (r.loaded.empty() ? (friction ? mh::ContactStressSource::GridPatchSolvedTraction
                                                              : mh::ContactStressSource::GridPatch)
                                                  : mh::ContactStressSource::HertzEllipseFastsim);
  if (could_use_grid && !best) out->warnings |= MHC_SUBSURFACE_WARN_GRID_NOT_KEPT;
  if (S.source != mh::ContactStressSource::None && P.surface) out->warnings |= MHC_SUBSURFACE_WARN_AT_SURFACE;
  out->vm_max_Pa = P.vm_max, out->vm_depth_m = P.vm_z;
  out->tau_max_Pa = P.tau_max, out->tau_depth_m = P.tau_z;
  out->tau_orth_amp_Pa = P.tau_orth_amp, out->tau_orth_depth_m = P.tau_orth_z;
  out->tau_eq_amp_Pa = P.tau_eq_amp, out->sigma_h_Pa = P.sigma_h;
  out->FI_sub_Pa = S.fi_sub;
  return MHC_OK;
}
