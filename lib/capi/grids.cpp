// The C interface's pressure and traction grids (include/mhcontact.h, the last section): the
// points of pressure.csv for the last case a workspace solved, from the one visitor the command's
// writer uses (contact/pressure_grid.hpp), in SI.
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

#include "capi/handles.hpp"
#include "contact/pressure_grid.hpp"

using mh::capi::fail;
using mh::capi::need;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

mhc_error mhc_workspace_keep_grids(mhc_workspace* ws, int32_t keep) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(ws, "ws")) return e;
  if (keep != 0 && keep != 1)
    return fail(MHC_ERR_ARGUMENT, "keep = " + std::to_string(keep) + ": must be 1 (keep the grids of the "
                                      "following solves) or 0 (keep nothing, the default)");
  ws->keep_grids = keep == 1;
  return MHC_OK;
}

mhc_error mhc_result_grid(const mhc_workspace* ws, int32_t n, mhc_grid* out) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(ws, "ws")) return e;
  if (mhc_error e = need(out, "out")) return e;
  if (out->struct_size != sizeof(mhc_grid))
    return fail(MHC_ERR_ARGUMENT, "out->struct_size = " + std::to_string(out->struct_size) +
                                      ": set it to sizeof(mhc_grid) (" + std::to_string(sizeof(mhc_grid)) + ")");
  out->n_points = 0;
  out->method = MHC_METHOD_MULTI_HERTZIAN;
  out->traction = 0;
  if (!ws->grids_kept)
    return fail(MHC_ERR_ARGUMENT, "ws: the last solve kept no grid: call mhc_workspace_keep_grids(ws, 1) "
                                  "before mhc_solve_load or mhc_solve_approach");
  const mh::CaseResult& r = ws->r;
  const bool ellipses = r.method == mh::Method::MultiHertzian;
  if (ellipses && !(n >= 2 && n <= 1000))
    return fail(MHC_ERR_ARGUMENT, "n = " + std::to_string(n) + ": must be between 2 and 1000 points per axis "
                                      "(as --pressure-grid)");
  const bool tangential = r.tangential.asked;
  if (r.method == mh::Method::Strips && !tangential && !r.patches.empty())
    return fail(MHC_ERR_UNSUPPORTED, "the strip method has no element grid without friction (the command writes no "
                                     "pressure grid for it either): give the pair a friction coefficient, or use "
                                     "the half-space method");
  out->method = ellipses ? MHC_METHOD_MULTI_HERTZIAN
                         : (r.method == mh::Method::HalfSpace ? MHC_METHOD_HALF_SPACE : MHC_METHOD_STRIPS);
  const bool plastic = ws->pair && ws->pair->plastic;
  // Count, then fill: the first pass is the size query (every array NULL) or the capacity check.
  std::size_t count = 0;
  bool any_traction = false;
  auto counter = [&](const mh::GridPoint& g) {
    ++count;
    any_traction = any_traction || g.traction;
  };
  if (ellipses) mh::for_each_ellipse_grid_point(r, plastic, n, tangential, counter);
  else mh::for_each_patch_grid_point(r, tangential, counter);
  out->n_points = count;
  out->traction = any_traction ? 1 : 0;
  const bool wants = out->contact || out->x_m || out->s_m || out->y_rail_m || out->p_Pa || out->p_elastic_Pa ||
                     out->px_Pa || out->py_Pa || out->slip;
  if (!wants) return MHC_OK;
  if (out->capacity < count)
    return fail(MHC_ERR_ARGUMENT, "out->capacity = " + std::to_string(out->capacity) + ": the case's grid has " +
                                      std::to_string(count) + " points (n_points): give arrays of that many (a call "
                                      "with every array NULL returns n_points)");
  std::size_t k = 0;
  auto filler = [&](const mh::GridPoint& g) {
    if (out->contact) out->contact[k] = g.contact;
    if (out->x_m) out->x_m[k] = g.x;
    if (out->s_m) out->s_m[k] = g.s;
    if (out->y_rail_m) out->y_rail_m[k] = g.y_rail;
    if (out->p_Pa) out->p_Pa[k] = g.p;
    if (out->p_elastic_Pa) out->p_elastic_Pa[k] = plastic ? g.p_elastic : kNaN;
    if (out->px_Pa) out->px_Pa[k] = g.traction ? g.px : kNaN;
    if (out->py_Pa) out->py_Pa[k] = g.traction ? g.py : kNaN;
    if (out->slip) out->slip[k] = g.traction ? (g.slip ? 1 : 0) : -1;
    ++k;
  };
  if (ellipses) mh::for_each_ellipse_grid_point(r, plastic, n, tangential, filler);
  else mh::for_each_patch_grid_point(r, tangential, filler);
  return MHC_OK;
}
