// The C interface (include/mhcontact.h): handles, error codes and the entry points; results are
// converted in result.cpp.
// Nothing here throws across extern "C": every entry point runs inside guarded().
#include "capi/handles.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <exception>
#include <limits>
#include <memory>
#include <new>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include "capi/checks.hpp"
#include "contact/half_space/influence.hpp"
#include "contact/solve.hpp"
#include "contact/tangential/tangential_solve.hpp"
#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "input/case_file.hpp"
#include "profile/formats/formats.hpp"
#include "profile/rail_cant.hpp"
#include "profile/read.hpp"
#include "profile/standard_profiles.hpp"

#ifndef MHCONTACT_VERSION
#define MHCONTACT_VERSION "unknown"
#endif

namespace mh::capi {

mhc_error fail(mhc_error e, const std::string& msg) {
  last_message() = msg;
  return e;
}

mhc_error need(const void* p, const char* what) {
  if (p) return MHC_OK;
  return fail(MHC_ERR_ARGUMENT, std::string(what) + ": null pointer");
}

std::string& last_message() {
  thread_local std::string m;
  return m;
}

mhc_error guarded(GuardedBody f) noexcept {
  try {
    try {
      return f();
    } catch (const InputError& e) {
      return fail(MHC_ERR_INPUT, e.what());
    } catch (const std::invalid_argument& e) {
      return fail(MHC_ERR_ARGUMENT, e.what());
    } catch (const std::bad_alloc&) {
      return fail(MHC_ERR_MEMORY, "out of memory");
    } catch (const std::exception& e) {
      return fail(MHC_ERR_INTERNAL, std::string("internal error: ") + e.what() +
                                        " (a bug: please report it with the input)");
    } catch (...) {
      return fail(MHC_ERR_INTERNAL, "internal error: unknown exception (a bug: please report it with the input)");
    }
  } catch (...) {  // the message itself could not be allocated
    return MHC_ERR_MEMORY;
  }
}

mhc_error solve_case(const mhc_pair& pair, mhc_workspace& ws, bool approach, double tY, double roll, double value,
                     mhc_result* out) {
  if (!(std::fabs(roll) <= 0.05))
    return fail(MHC_ERR_ARGUMENT, "roll = " + format_number(roll) +
                                      " rad: the relative roll must be finite and within [-0.05, 0.05] rad");
  if (!std::isfinite(tY)) return fail(MHC_ERR_ARGUMENT, "t_Y = " + format_number(tY) + " m: must be finite");
  // The wheel rolled by δ against the rail (docs/method.md §3 item 8): its candidates and its spin.
  // With mhc_workspace_keep_grids: the grid methods' element pressures and the tractions per
  // element kept (nothing otherwise: the options are copied only then).
  MethodOptions rolled;
  const MethodOptions* opt = &pair.options;
  if (roll != 0.0 || ws.keep_grids) {
    rolled = pair.options;
    if (roll != 0.0) {
      rolled.multi_hertzian.roll = roll;
      rolled.tangential.kin.roll = roll;
    }
    if (ws.keep_grids)  // and the strips for a strip patch's stresses without friction (capi/subsurface.cpp)
      rolled.half_space.keep_pressure = rolled.tangential.keep_traction = rolled.strips.keep_strips = true;
    opt = &rolled;
  }
  ws.grids_kept = false;
  if (approach) {
    if (pair.options.method != Method::MultiHertzian)
      return fail(MHC_ERR_UNSUPPORTED, std::string("the approach-prescribed solve needs the multi-hertzian method, "
                                                   "not ") + to_string(pair.options.method));
    solve_multi_hertz_approach(pair.pg.geo, pair.material, tY, value, opt->multi_hertzian, ws.approach, ws.r);
    // As solve_contact: the tangential problem (a case file with friction), then the one judge.
    solve_tangential(ws.r, pair.material, tY, opt->tangential);
    judge_case(ws.r, pair.pg.geo, pair.material, tY, *opt);
    fill_result(ws.r, tY, std::numeric_limits<double>::quiet_NaN(), pair.plastic, out);
  } else {
    if (const std::string bad = check_load(value); !bad.empty()) return fail(MHC_ERR_ARGUMENT, bad);
    solve_contact(pair.pg.geo, pair.material, tY, value, *opt, ws.r, &ws.grid);
    // The smoothing's uncertainty band, as the command's sweep: before the result is filled (its
    // warning counts).
    add_smoothing_band(ws.r, pair.pg.band, pair.material, tY, value, *opt);
    fill_result(ws.r, tY, value, pair.plastic, out);
  }
  ws.grids_kept = ws.keep_grids;
  if (ws.r.status != CaseStatus::Ok) last_message() = ws.r.message;
  return MHC_OK;
}

mhc_error for_each_case(const mhc_pair& pair, std::size_t n, int n_threads,
                        const std::function<mhc_error(std::size_t, mhc_workspace&)>& body) {
  return guarded([&] {
    return for_each_index(
        n, n_threads,
        [&] {
          auto ws = std::make_unique<mhc_workspace>();
          ws->pair = &pair;
          return ws;
        },
        [&](std::size_t i, std::unique_ptr<mhc_workspace>& ws) { return body(i, *ws); });
  });
}

}  // namespace mh::capi

using namespace mh;
using mh::capi::fail;
using mh::capi::guarded;
using mh::capi::need;

namespace {

ProfileKind to_kind(int32_t kind) {
  if (kind == MHC_WHEEL) return ProfileKind::Wheel;
  if (kind == MHC_RAIL) return ProfileKind::Rail;
  throw std::invalid_argument("kind = " + std::to_string(kind) + ": must be MHC_WHEEL (1) or MHC_RAIL (2)");
}

/// Profiles, cant check and geometry, as jobs/run.cpp's build_pair_geometry; `band`: the
/// smoothing's uncertainty band's tables too for `method`'s rows, where a profile is smoothed for
/// contact.
void place_pair(mhc_pair& pair, Profile wheel, Profile rail, const Inclination& incl, const TrackSetup& track,
                const GeometryOptions& geo, bool band, Method method) {
  pair.pg.wheel = std::move(wheel);
  pair.pg.rail = std::move(rail);
  pair.pg.cant = check_rail_cant(pair.pg.rail, incl);
  for (const auto& w : pair.pg.cant.warnings) pair.pg.rail.warnings.push_back(w);
  pair.pg.geo = build_geometry(pair.pg.wheel, pair.pg.rail, track, geo);
  set_pair_band(pair.pg, track, geo, band, method);
  pair.track = track;
  pair.geometry = geo;
  // The warnings the command prints for this pair (jobs/run.cpp build_pair_geometry, warn_profiles).
  for (const auto& w : pair.pg.geo.warnings) pair.pg.wheel.warnings.push_back(w);
  for (const Profile* p : {&pair.pg.wheel, &pair.pg.rail})
    for (const auto& w : p->warnings) pair.warnings.push_back(p->source + ": " + w);
}

}  // namespace

extern "C" {

const char* mhc_version(void) { return MHCONTACT_VERSION; }
int32_t mhc_abi_version(void) { return MHC_ABI_VERSION; }
const char* mhc_fft_backend(void) { return mh::fft_backend(); }

const char* mhc_last_message(void) { return mh::capi::last_message().c_str(); }

const char* mhc_error_name(mhc_error e) {
  switch (e) {
    case MHC_OK: return "ok";
    case MHC_ERR_ARGUMENT: return "argument";
    case MHC_ERR_INPUT: return "input";
    case MHC_ERR_UNSUPPORTED: return "unsupported";
    case MHC_ERR_MEMORY: return "memory";
    case MHC_ERR_INTERNAL: return "internal";
  }
  return "unknown";
}

const char* mhc_status_name(int32_t status) {
  switch (status) {
    case MHC_STATUS_OK: return "ok";
    case MHC_STATUS_NO_CONTACT: return "no_contact";
    case MHC_STATUS_OUT_OF_RANGE: return "out_of_range";
    case MHC_STATUS_NOT_CONVERGED: return "not_converged";
    case MHC_STATUS_OUTSIDE_VALIDITY: return "outside_validity";
    case MHC_STATUS_DERAILED: return "derailed";
  }
  return "unknown";
}

mhc_error mhc_profile_read(const char* path, int32_t kind, mhc_profile** out) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(path, "path")) return e;
  if (mhc_error e = need(out, "out")) return e;
  *out = nullptr;
  return guarded([&] {
    ProfileReadOptions o;
    o.kind = to_kind(kind);
    auto p = std::make_unique<mhc_profile>();
    p->profile = read_profile(path, o);
    *out = p.release();
    return MHC_OK;
  });
}

mhc_error mhc_profile_from_points(const double* y_m, const double* z_m, size_t n, int32_t kind, mhc_profile** out) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(y_m, "y_m")) return e;
  if (mhc_error e = need(z_m, "z_m")) return e;
  if (mhc_error e = need(out, "out")) return e;
  *out = nullptr;
  return guarded([&] {
    ProfileReadOptions o;
    o.kind = to_kind(kind);
    // The readers' clean-up and checks work in mm (profile/formats/formats.hpp).
    formats::RawProfile r;
    r.kind = o.kind;
    r.format = "points";
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(y_m[i]) || !std::isfinite(z_m[i]))
        throw InputError("points[" + std::to_string(i) + "]", format_number(y_m[i]) + ", " + format_number(z_m[i]),
                         "coordinates must be finite");
      r.add(y_m[i] * 1000, z_m[i] * 1000, i + 1);
    }
    const std::string where = "points";
    formats::clean_and_check(r, where, o);
    auto p = std::make_unique<mhc_profile>();
    p->profile.kind = r.kind;
    p->profile.source = where;
    p->profile.format = r.format;
    p->profile.warnings = r.warnings;
    p->profile.cleanup = r.cleanup;
    p->profile.y.resize(r.size());
    p->profile.z.resize(r.size());
    for (std::size_t k = 0; k < r.size(); ++k) p->profile.y[k] = r.y[k] / 1000, p->profile.z[k] = r.z[k] / 1000;
    *out = p.release();
    return MHC_OK;
  });
}

mhc_error mhc_profile_standard(const char* name, mhc_profile** out) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(name, "name")) return e;
  if (mhc_error e = need(out, "out")) return e;
  *out = nullptr;
  return guarded([&] {
    auto p = std::make_unique<mhc_profile>();
    p->profile = make_standard_profile(name, Inclination::None);
    p->standard = name;
    *out = p.release();
    return MHC_OK;
  });
}

mhc_error mhc_profile_points(const mhc_profile* p, size_t* n, double* y_m, double* z_m, size_t capacity) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(p, "profile")) return e;
  if (mhc_error e = need(n, "n")) return e;
  *n = p->profile.size();
  const std::size_t m = std::min(capacity, p->profile.size());
  if (y_m) std::copy(p->profile.y.begin(), p->profile.y.begin() + static_cast<std::ptrdiff_t>(m), y_m);
  if (z_m) std::copy(p->profile.z.begin(), p->profile.z.begin() + static_cast<std::ptrdiff_t>(m), z_m);
  return MHC_OK;
}

void mhc_profile_free(mhc_profile* p) { delete p; }

void mhc_pair_options_init(mhc_pair_options* o) {
  if (!o) return;
  std::memset(static_cast<void*>(o), 0, sizeof *o);
  o->struct_size = sizeof *o;
  const TrackSetup t;
  o->gauge_m = t.gauge;
  o->gauge_height_m = t.gauge_height;
  o->flange_back_distance_m = t.flange_back_distance;
  o->flange_back_position_m = t.flange_back_position;
  o->nominal_radius_m = t.nominal_radius;
  o->rail_inclination = 0;
  const Material m;
  o->E_wheel_Pa = m.E;
  o->nu_wheel = m.nu;
  o->E_rail_Pa = m.E_rail;
  o->nu_rail = m.nu_rail;
  o->p_lim_Pa = m.p_lim;
  o->yield_wheel_Pa = m.yield;
  o->yield_rail_Pa = m.yield_rail;
  o->method = MHC_METHOD_MULTI_HERTZIAN;
  const GeometryOptions g;
  o->tY_min_m = g.tY_min;
  o->tY_max_m = g.tY_max;
  o->tY_step_m = g.tY_step;
  const HalfSpaceOptions h;
  o->grid_dx_m = h.dx;
  o->grid_ds_m = h.ds;
  o->positioning = MHC_POSITIONING_GAUGE;
  o->lateral_offset_m = 0;
}

mhc_error mhc_pair_create(const mhc_profile* wheel, const mhc_profile* rail, const mhc_pair_options* opt,
                          mhc_pair** out) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(wheel, "wheel")) return e;
  if (mhc_error e = need(rail, "rail")) return e;
  if (mhc_error e = need(opt, "options")) return e;
  if (mhc_error e = need(out, "out")) return e;
  *out = nullptr;
  // The struct of a header before the yield stress ends where yield_wheel_Pa begins: its fields
  // are read, the later ones (not in the caller's memory) are taken as not given.
  // The struct of a header before explicit positioning ends where positioning begins: gauge
  // positioning.
  constexpr std::size_t kSizeBeforeYield = mh::capi::kOptionsSizeBeforeYield;
  constexpr std::size_t kSizeBeforePositioning = mh::capi::kOptionsSizeBeforePositioning;
  const bool has_yield = opt->struct_size == sizeof(mhc_pair_options) || opt->struct_size == kSizeBeforePositioning;
  const bool has_positioning = opt->struct_size == sizeof(mhc_pair_options);
  if (!has_yield && opt->struct_size != kSizeBeforeYield)
    return fail(MHC_ERR_ARGUMENT, "options: struct_size = " + std::to_string(opt->struct_size) +
                                      ": must be sizeof(mhc_pair_options) = " +
                                      std::to_string(sizeof(mhc_pair_options)) + ", " +
                                      std::to_string(kSizeBeforePositioning) +
                                      " of a header without explicit positioning, or " +
                                      std::to_string(kSizeBeforeYield) +
                                      " of a header without the yield stress (call mhc_pair_options_init)");
  return guarded([&] {
    const double not_given = std::numeric_limits<double>::quiet_NaN();
    const double yield_wheel = has_yield ? opt->yield_wheel_Pa : not_given;
    const double yield_rail = has_yield ? opt->yield_rail_Pa : not_given;
    for (const auto& [field, v] : {std::pair<const char*, double>{"yield_wheel_Pa", yield_wheel}, {"yield_rail_Pa", yield_rail}})
      if (!std::isnan(v) && !(v > 0 && std::isfinite(v)))
        return fail(MHC_ERR_ARGUMENT, std::string("options.") + field + " = " + format_number(v) +
                                          " Pa: a yield stress must be > 0 and finite, or NaN (not given); "
                                          "give it in Pa (350 MPa: 350e6)");
    if (std::isnan(yield_wheel) && !std::isnan(yield_rail))
      return fail(MHC_ERR_ARGUMENT, "options.yield_rail_Pa = " + format_number(yield_rail) +
                                        " Pa without yield_wheel_Pa: give the wheel's yield stress too "
                                        "(one value for both bodies: yield_wheel_Pa alone)");
    // The case file's plausible ranges on the SI fields (capi/checks.hpp, core/plausible.hpp).
    if (const std::string bad = mh::capi::check_pair_options(*opt, opt->struct_size); !bad.empty())
      return fail(MHC_ERR_ARGUMENT, bad);
    if (wheel->profile.kind != ProfileKind::Wheel)
      return fail(MHC_ERR_ARGUMENT, "wheel: " + wheel->profile.source + " is a " + to_string(wheel->profile.kind) +
                                        " profile, but a wheel is needed here");
    if (rail->profile.kind != ProfileKind::Rail)
      return fail(MHC_ERR_ARGUMENT, "rail: " + rail->profile.source + " is a " + to_string(rail->profile.kind) +
                                        " profile, but a rail is needed here");
    auto pair = std::make_unique<mhc_pair>();
    std::string why;
    Material& m = pair->material;
    m.E = opt->E_wheel_Pa;
    m.nu = opt->nu_wheel;
    m.E_rail = opt->E_rail_Pa;
    m.nu_rail = opt->nu_rail;
    m.p_lim = opt->p_lim_Pa;
    m.yield = yield_wheel;
    m.yield_rail = yield_rail;
    if (!m.valid(&why)) return fail(MHC_ERR_ARGUMENT, "material: " + why);
    // As the case file's plastic model (docs/method.md §5.1): p_lim_Pa given, the capped law;
    // else a yield stress gives the yield law (ellipse) and p_lim = 2.1 sigma_y (grid methods).
    pair->plastic = derive_plastic_law(m);
    if (opt->method < MHC_METHOD_MULTI_HERTZIAN || opt->method > MHC_METHOD_AUTO)
      return fail(MHC_ERR_ARGUMENT, "method = " + std::to_string(opt->method) + ": must be an mhc_method (0 to 3)");
    MethodOptions& mo = pair->options;
    mo.method = static_cast<Method>(opt->method);  // same order as mhc_method
    mo.half_space.dx = opt->grid_dx_m;
    mo.half_space.ds = opt->grid_ds_m;
    mo.strips.ds = opt->grid_ds_m;
    if (!mo.half_space.valid(&why) || !mo.strips.valid(&why)) return fail(MHC_ERR_ARGUMENT, why);
    if (!(opt->rail_inclination == 0 || opt->rail_inclination >= 5) || !std::isfinite(opt->rail_inclination))
      return fail(MHC_ERR_ARGUMENT, "rail_inclination = " + format_number(opt->rail_inclination) +
                                        ": must be 0 (as given) or N >= 5 of a cant 1:N");
    const Inclination incl = opt->rail_inclination > 0 ? Inclination{Inclination::Mode::Ratio, opt->rail_inclination}
                                                       : Inclination::AsIs;
    TrackSetup track;
    track.gauge = opt->gauge_m;
    track.gauge_height = opt->gauge_height_m;
    track.flange_back_distance = opt->flange_back_distance_m;
    track.flange_back_position = opt->flange_back_position_m;
    track.nominal_radius = opt->nominal_radius_m;
    // The creepages' track data, as the case file's reader sets them (mhc_pair_set_tangential).
    mo.tangential.r0 = track.nominal_radius;
    mo.tangential.l_origin = 0.5 * track.flange_back_distance - track.flange_back_position;
    if (has_positioning && opt->positioning == MHC_POSITIONING_EXPLICIT) {
      track.positioning = TrackSetup::Positioning::Explicit;
      track.lateral_offset = opt->lateral_offset_m;
    }
    GeometryOptions geo;
    geo.tY_min = opt->tY_min_m;
    geo.tY_max = opt->tY_max_m;
    geo.tY_step = opt->tY_step_m;
    if (!geo.valid(&why)) return fail(MHC_ERR_ARGUMENT, why);
    // The cant as the case loader applies it (input/profile_source.cpp load_profile): a standard
    // rail is generated with it, a read one rotated.
    Profile r = rail->standard.empty() ? rail->profile : make_standard_profile(rail->standard, incl);
    if (rail->standard.empty()) rotate_towards_track_centre(r, inclination_angle(incl));
    place_pair(*pair, wheel->profile, std::move(r), incl, track, geo, true, mo.method);
    *out = pair.release();
    return MHC_OK;
  });
}

mhc_error mhc_pair_from_case_file(const char* path, mhc_pair** out) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(path, "path")) return e;
  if (mhc_error e = need(out, "out")) return e;
  *out = nullptr;
  return guarded([&] {
    const CaseFile cf = load_case_file(path, false);
    auto pair = std::make_unique<mhc_pair>();
    place_pair(*pair, load_profile(cf.wheel, ProfileKind::Wheel), load_profile(cf.rail, ProfileKind::Rail, cf.inclination),
               cf.inclination, cf.track, cf.geometry, cf.geometry.smoothing_band, cf.method);
    pair->material = cf.material;
    pair->options = cf.method_options();
    pair->plastic = cf.model == Model::Plastic;
    *out = pair.release();
    return MHC_OK;
  });
}

mhc_error mhc_pair_tY_range(const mhc_pair* pair, double* tY_min_m, double* tY_max_m) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(pair, "pair")) return e;
  if (tY_min_m) *tY_min_m = pair->pg.geo.tY.front();
  if (tY_max_m) *tY_max_m = pair->pg.geo.tY.back();
  return MHC_OK;
}

int32_t mhc_pair_n_ellipses(const mhc_pair* pair) {
  return pair ? static_cast<int32_t>(pair->pg.geo.n_ellipses()) : 0;
}

void mhc_pair_free(mhc_pair* pair) { delete pair; }

mhc_error mhc_workspace_create(const mhc_pair* pair, mhc_workspace** out) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(pair, "pair")) return e;
  if (mhc_error e = need(out, "out")) return e;
  *out = nullptr;
  return guarded([&] {
    auto ws = std::make_unique<mhc_workspace>();
    ws->pair = pair;
    ws->approach.geo.reserve(pair->pg.geo.n_ellipses());
    ws->r.loaded.reserve(pair->pg.geo.n_ellipses());
    *out = ws.release();
    return MHC_OK;
  });
}

void mhc_workspace_free(mhc_workspace* ws) { delete ws; }

static mhc_error solve_one(const mhc_pair* pair, mhc_workspace* ws, bool approach, double tY_m, double roll_rad,
                           double value, mhc_result* out) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(pair, "pair")) return e;
  if (mhc_error e = need(ws, "workspace")) return e;
  if (!mh::capi::result_ok(out, out ? out->struct_size : 0)) return MHC_ERR_ARGUMENT;
  if (ws->pair != pair) return fail(MHC_ERR_ARGUMENT, "workspace: made for another pair (mhc_workspace_create)");
  return guarded([&] { return mh::capi::solve_case(*pair, *ws, approach, tY_m, roll_rad, value, out); });
}

mhc_error mhc_solve_load(const mhc_pair* pair, mhc_workspace* ws, double tY_m, double roll_rad, double Q_N,
                         mhc_result* out) {
  return solve_one(pair, ws, false, tY_m, roll_rad, Q_N, out);
}

mhc_error mhc_solve_approach(const mhc_pair* pair, mhc_workspace* ws, double tY_m, double roll_rad, double dz_m,
                             mhc_result* out) {
  return solve_one(pair, ws, true, tY_m, roll_rad, dz_m, out);
}

mhc_error mhc_solve_many_warnings(const mhc_pair* pair, int32_t prescribe, size_t n, const double* tY_m,
                                  const double* roll_rad, const double* value, mhc_result* out, size_t result_size,
                                  mhc_warning* warnings, size_t warning_size, size_t per_case, int32_t n_threads) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(pair, "pair")) return e;
  if (n == 0) return MHC_OK;
  if (mhc_error e = need(tY_m, "tY_m")) return e;
  if (mhc_error e = need(value, "value")) return e;
  if (!mh::capi::result_ok(out, result_size)) return MHC_ERR_ARGUMENT;
  if (prescribe != MHC_PRESCRIBE_LOAD && prescribe != MHC_PRESCRIBE_APPROACH)
    return fail(MHC_ERR_ARGUMENT, "prescribe = " + std::to_string(prescribe) +
                                      ": must be MHC_PRESCRIBE_LOAD (0) or MHC_PRESCRIBE_APPROACH (1)");
  if (n_threads < 0) return fail(MHC_ERR_ARGUMENT, "n_threads = " + std::to_string(n_threads) + ": must be >= 0");
  const bool with_warnings = warnings != nullptr && per_case > 0;
  if (with_warnings && !mh::capi::warning_size_ok(warning_size, "warning_size")) return MHC_ERR_ARGUMENT;
  const bool approach = prescribe == MHC_PRESCRIBE_APPROACH;
  return mh::capi::for_each_case(*pair, n, n_threads, [&](std::size_t i, mhc_workspace& ws) {
    auto* r = reinterpret_cast<mhc_result*>(reinterpret_cast<char*>(out) + i * result_size);
    r->struct_size = result_size;
    const mhc_error e = mh::capi::solve_case(*pair, ws, approach, tY_m[i], roll_rad ? roll_rad[i] : 0.0, value[i], r);
    if (with_warnings) {
      const std::size_t m = std::min(per_case, ws.r.warnings.size());
      for (std::size_t k = 0; k < m; ++k) {
        auto* w = reinterpret_cast<mhc_warning*>(reinterpret_cast<char*>(warnings) + (i * per_case + k) * warning_size);
        w->struct_size = warning_size;
        mh::capi::fill_warning(ws.r.warnings[k], w);
      }
    }
    return e;
  });
}

mhc_error mhc_pair_set_smoothing_band(mhc_pair* pair, int32_t on) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(pair, "pair")) return e;
  if (on != 0 && on != 1) return fail(MHC_ERR_ARGUMENT, "on = " + std::to_string(on) + ": must be 0 (off) or 1 (on)");
  return guarded([&] {
    set_pair_band(pair->pg, pair->track, pair->geometry, on == 1, pair->options.method);
    return MHC_OK;
  });
}

mhc_error mhc_result_smoothing_band(const mhc_workspace* ws, mhc_smoothing_band* out) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(ws, "workspace")) return e;
  if (mhc_error e = need(out, "out")) return e;
  if (out->struct_size < sizeof(mhc_smoothing_band))
    return fail(MHC_ERR_ARGUMENT, "out->struct_size = " + std::to_string(out->struct_size) +
                                      ": set it to sizeof(mhc_smoothing_band) (" +
                                      std::to_string(sizeof(mhc_smoothing_band)) + ")");
  const CaseResult& r = ws->r;
  out->p_max_half_L_Pa = r.pmax_half_L;
  out->p_max_double_L_Pa = r.pmax_double_L;
  out->area_half_L_m2 = r.area_half_L;
  out->area_double_L_m2 = r.area_double_L;
  return MHC_OK;
}

mhc_error mhc_solve_many(const mhc_pair* pair, int32_t prescribe, size_t n, const double* tY_m, const double* roll_rad,
                         const double* value, mhc_result* out, size_t result_size, int32_t n_threads) {
  return mhc_solve_many_warnings(pair, prescribe, n, tY_m, roll_rad, value, out, result_size, nullptr, 0, 0, n_threads);
}

}  // extern "C"
