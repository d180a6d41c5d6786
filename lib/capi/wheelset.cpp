// The wheelset call of the C interface (include/mhcontact.h, its last section; docs/c-api.md "The
// wheelset call"): handles over wheelset_contact/wheelset_contact.hpp, the conversion of a step's
// result into mhc_wheelset_result (versioned by size both ways), the interface version.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "capi/handles.hpp"
#include "core/numfmt.hpp"
#include "wheelset_contact/wheelset_contact.hpp"

struct mhc_wheelset {
  std::unique_ptr<mh::WheelsetContact> model;
  bool plastic = false;
};

struct mhc_wheelset_workspace {
  const mhc_wheelset* wheelset = nullptr;
  mh::WheelsetWorkspace ws;
  mh::WheelsetResult r;
  mhc_result scratch;  ///< a wheel's pair result, converted by fill_result (flags, warning bits)
};

namespace {

using mh::capi::fail;
using mh::capi::guarded;
using mh::capi::need;

constexpr int32_t kOldestInterface = 1;
/// The wheelset result of interface 2 ends here at the least: a caller's struct may stop after
/// the wheelset's own fields (the wheels omitted) or hold any later layout.
constexpr std::size_t kResultMinSize = offsetof(mhc_wheelset_result, wheel);
constexpr std::size_t kOptionsMinSize = offsetof(mhc_wheelset_options, fastsim_nx);

void copy3(double* to, const std::array<double, 3>& a) { std::copy(a.begin(), a.end(), to); }

mh::WheelsetPose to_pose(const mhc_wheelset_pose& p) {
  mh::WheelsetPose o;
  if (p.vertical != MHC_VERTICAL_LOADS && p.vertical != MHC_VERTICAL_POSITION)
    throw std::invalid_argument("pose.vertical = " + std::to_string(p.vertical) +
                                ": must be MHC_VERTICAL_LOADS (0) or MHC_VERTICAL_POSITION (1)");
  o.vertical = p.vertical == MHC_VERTICAL_LOADS ? mh::WheelsetVertical::Loads : mh::WheelsetVertical::Position;
  // LOADS: the roll is always solved (the wheel loads and a rigid axle fix it; solve_roll applies
  // to POSITION only, as documented).
  o.solve_roll = o.vertical == mh::WheelsetVertical::Loads || p.solve_roll != 0;
  o.y = p.y_m;
  o.yaw = p.yaw_rad;
  o.Q_left = p.Q_left_N;
  o.Q_right = p.Q_right_N;
  o.Z = p.Z_m;
  o.roll = p.roll_rad;
  o.V = p.V_m_per_s;
  o.lateral_velocity = p.lateral_velocity_m_per_s;
  o.yaw_rate = p.yaw_rate_rad_per_s;
  o.pitch_rate = p.pitch_rate_rad_per_s;
  return o;
}

void fill_wheel(const mh::WheelResult& w, bool plastic, mhc_result& scratch, mhc_wheelset_wheel& o) {
  scratch.struct_size = sizeof(mhc_result);
  const double Q = std::numeric_limits<double>::quiet_NaN();
  mh::capi::fill_result(w.r, w.tY, Q, plastic, &scratch);
  o.status = scratch.status;
  o.warnings = scratch.warnings;
  o.n_warnings = scratch.n_warnings;
  o.n_contacts = static_cast<int32_t>(w.contacts.size());
  o.plastic = scratch.plastic;
  o.dF_dvertical_analytic = w.dF_dvertical_analytic ? 1 : 0;
  o.tY_m = w.tY;
  o.h_m = w.h;
  o.dz_m = w.r.dz;
  o.Fz_pair_N = w.r.Fz;
  copy3(o.F_N, w.on_wheelset.F);
  copy3(o.M_N_m, w.on_wheelset.M);
  copy3(o.dF_dy_N_per_m, w.dF_dy);
  copy3(o.dF_droll_N_per_rad, w.dF_droll);
  copy3(o.dF_dvertical, w.dF_dvertical);
  const int n = std::min<int>(MHC_MAX_CONTACTS, static_cast<int>(w.contacts.size()));
  for (int i = 0; i < MHC_MAX_CONTACTS; ++i) {
    mhc_wheelset_contact& c = o.contact[i];
    std::memset(static_cast<void*>(&c), 0, sizeof c);
    if (i >= n) continue;
    const mh::ContactPoint& p = w.contacts[static_cast<std::size_t>(i)];
    c.index = p.index;
    // The pair result's flags of the same ellipse or patch.
    const int m = std::min<int>(MHC_MAX_CONTACTS, scratch.n_contacts);
    for (int k = 0; k < m; ++k)
      if (scratch.contact[k].index == p.index) c.flags = scratch.contact[k].flags;
    c.y_track_m = p.Y;
    c.z_track_m = p.Z;
    c.y_wheelset_m = p.Y_ws;
    c.z_wheelset_m = p.Z_ws;
    c.gamma_rad = p.gamma;
    c.r_roll_m = p.r_roll;
    c.N_N = p.N;
    c.a_m = p.a;
    c.b_m = p.b;
    c.Fx_N = p.Fx;
    c.Fs_N = p.Fs;
    c.Mn_N_m = p.Mn;
    copy3(c.F_N, p.on_wheelset.F);
    copy3(c.M_N_m, p.on_wheelset.M);
  }
}

/// The step's answer into *out, the fields that fit its struct_size (at least kResultMinSize):
/// built whole in `full`, then copied.
void fill_wheelset_result(const mh::WheelsetResult& r, bool plastic, mhc_result& scratch, mhc_wheelset_result* out) {
  mhc_wheelset_result full;
  std::memset(static_cast<void*>(&full), 0, sizeof full);
  full.status = mh::capi::status_code(r.status);
  for (const mh::WheelsetWarning& w : r.warnings) {
    switch (w.kind) {
      case mh::WheelsetWarning::Kind::RollInGeometryNeglected: full.wheelset_warnings |= MHC_WHEELSET_WARN_ROLL_IN_GEOMETRY; break;
      case mh::WheelsetWarning::Kind::RollNearFlange: full.wheelset_warnings |= MHC_WHEELSET_WARN_ROLL_NEAR_FLANGE; break;
      case mh::WheelsetWarning::Kind::YawLeadNotModelled:
        full.wheelset_warnings |= w.side > 0 ? MHC_WHEELSET_WARN_YAW_LEAD_LEFT : MHC_WHEELSET_WARN_YAW_LEAD_RIGHT;
        break;
    }
  }
  full.roll_rad = r.roll;
  full.Z_m = r.Z;
  copy3(full.F_N, r.total.F);
  copy3(full.M_N_m, r.total.M);
  copy3(full.dF_dy_N_per_m, r.dF_dy);
  copy3(full.dF_droll_N_per_rad, r.dF_droll);
  copy3(full.dF_dvertical, r.dF_dvertical);
  fill_wheel(r.left, plastic, scratch, full.wheel[0]);
  fill_wheel(r.right, plastic, scratch, full.wheel[1]);
  const std::size_t n = std::min(out->struct_size, sizeof full);
  full.struct_size = n;
  std::memcpy(static_cast<void*>(out), &full, n);
}

mhc_error check_result(const mhc_wheelset_result* out) {
  if (mhc_error e = need(out, "out")) return e;
  if (out->struct_size < kResultMinSize)
    return fail(MHC_ERR_ARGUMENT, "out->struct_size = " + std::to_string(out->struct_size) +
                                      ": must be at least " + std::to_string(kResultMinSize) +
                                      " (set it to sizeof(mhc_wheelset_result) = " +
                                      std::to_string(sizeof(mhc_wheelset_result)) + ")");
  return MHC_OK;
}

mhc_error check_pose(const mhc_wheelset_pose* pose) {
  if (mhc_error e = need(pose, "pose")) return e;
  if (pose->struct_size != sizeof(mhc_wheelset_pose))
    return fail(MHC_ERR_ARGUMENT, "pose->struct_size = " + std::to_string(pose->struct_size) +
                                      ": must be sizeof(mhc_wheelset_pose) = " + std::to_string(sizeof(mhc_wheelset_pose)));
  return MHC_OK;
}

/// One step with ws into out; the message of the first wheel that is not ok.
mhc_error step_one(const mhc_wheelset& w, mhc_wheelset_workspace& ws, const mhc_wheelset_pose& pose,
                   mhc_wheelset_result* out) {
  const mh::WheelsetPose p = to_pose(pose);
  if (p.vertical == mh::WheelsetVertical::Position && w.model->setup().method.method != mh::Method::MultiHertzian)
    return fail(MHC_ERR_UNSUPPORTED, "pose.vertical = MHC_VERTICAL_POSITION needs the multi-hertzian method, not " +
                                         std::string(mh::to_string(w.model->setup().method.method)) +
                                         " (give the loads: MHC_VERTICAL_LOADS)");
  mh::WheelsetStepOptions o;
  o.derivatives = pose.derivatives != 0;
  w.model->step(p, o, ws.r, ws.ws);
  fill_wheelset_result(ws.r, w.plastic, ws.scratch, out);
  for (const mh::WheelResult* wr : {&ws.r.left, &ws.r.right})
    if (wr->r.status != mh::CaseStatus::Ok) {
      mh::capi::last_message() = wr->r.message;
      break;
    }
  return MHC_OK;
}

const std::vector<mh::Warning>* wheel_warnings(const mhc_wheelset_workspace* ws, int32_t side) {
  if (!ws || (side != 0 && side != 1)) return nullptr;
  return side == 0 ? &ws->r.left.r.warnings : &ws->r.right.r.warnings;
}

}  // namespace

extern "C" {

int32_t mhc_interface_version(int32_t* oldest) {
  if (oldest) *oldest = kOldestInterface;
  return MHC_INTERFACE_VERSION;
}

void mhc_wheelset_options_init(mhc_wheelset_options* o) {
  if (!o) return;
  std::memset(static_cast<void*>(o), 0, sizeof *o);
  o->struct_size = sizeof *o;
  o->mu = std::numeric_limits<double>::quiet_NaN();
  o->fastsim_nx = o->fastsim_ny = mh::kWheelsetFastsimCells;  // the wheelset call's default (wheelset_contact.hpp)
  o->roll_in_geometry = 1;
}

mhc_error mhc_wheelset_create(const mhc_pair* left, const mhc_pair* right, const mhc_wheelset_options* opt,
                              mhc_wheelset** out) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(left, "left")) return e;
  if (mhc_error e = need(right, "right")) return e;
  if (mhc_error e = need(out, "out")) return e;
  *out = nullptr;
  mhc_wheelset_options o;
  mhc_wheelset_options_init(&o);
  if (opt) {
    if (opt->struct_size < kOptionsMinSize || opt->struct_size > sizeof o)
      return fail(MHC_ERR_ARGUMENT, "options: struct_size = " + std::to_string(opt->struct_size) +
                                        ": must be sizeof(mhc_wheelset_options) = " + std::to_string(sizeof o) +
                                        " or an earlier size (call mhc_wheelset_options_init)");
    std::memcpy(static_cast<void*>(&o), opt, opt->struct_size);
  }
  return guarded([&] {
    // Both wheels of one wheelset: the same material, method and flange-back data.
    const mh::Material &ml = left->material, &mr = right->material;
    auto same = [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); };
    if (!same(ml.E, mr.E) || !same(ml.nu, mr.nu) || !same(ml.E_rail, mr.E_rail) || !same(ml.nu_rail, mr.nu_rail) ||
        !same(ml.p_lim, mr.p_lim) || ml.yield_law != mr.yield_law)
      return fail(MHC_ERR_ARGUMENT, "right: its material differs from the left pair's: build both pairs with the "
                                    "same E, nu, p_lim and yield stresses");
    if (left->options.method != right->options.method)
      return fail(MHC_ERR_ARGUMENT, std::string("right: method ") + mh::to_string(right->options.method) +
                                        ", the left pair's " + mh::to_string(left->options.method) +
                                        ": build both pairs with the same method");
    const mh::TrackSetup &tl = left->track, &tr = right->track;
    if (tl.flange_back_distance != tr.flange_back_distance || tl.flange_back_position != tr.flange_back_position)
      return fail(MHC_ERR_ARGUMENT, "right: flange_back_distance_m = " + mh::format_number(tr.flange_back_distance) +
                                        ", flange_back_position_m = " + mh::format_number(tr.flange_back_position) +
                                        ": one wheelset has one flange-back distance and position (left: " +
                                        mh::format_number(tl.flange_back_distance) + ", " +
                                        mh::format_number(tl.flange_back_position) + ")");
    mh::MethodOptions method = left->options;
    if (!std::isnan(o.mu)) {
      if (!(o.mu > 0 && o.mu <= 2))
        return fail(MHC_ERR_ARGUMENT, "options.mu = " + mh::format_number(o.mu) +
                                          ": a friction coefficient must be in (0, 2], or NaN (no creep forces)");
      method.tangential.mu = o.mu;
    }
    // The wheelset call's tangential defaults (wheelset_contact.hpp), the grid as the options say
    // (an older caller's, without the fields: the default of mhc_wheelset_options_init).
    method = mh::wheelset_method_options(method);
    if (o.fastsim_nx < 2 || o.fastsim_nx > mh::kFastsimMaxN || o.fastsim_ny < 2 || o.fastsim_ny > mh::kFastsimMaxN)
      return fail(MHC_ERR_ARGUMENT, "options.fastsim_nx, fastsim_ny = " + std::to_string(o.fastsim_nx) + ", " +
                                        std::to_string(o.fastsim_ny) + ": must be 2 to " +
                                        std::to_string(mh::kFastsimMaxN));
    method.tangential.fastsim.nx = o.fastsim_nx;
    method.tangential.fastsim.ny = o.fastsim_ny;
    if (o.roll_in_geometry != 0 && o.roll_in_geometry != 1)
      return fail(MHC_ERR_ARGUMENT, "options.roll_in_geometry = " + std::to_string(o.roll_in_geometry) +
                                        ": must be 1 (the wheels rolled in the geometry) or 0 (upright)");
    std::vector<std::string> warnings = left->warnings;
    warnings.insert(warnings.end(), right->warnings.begin(), right->warnings.end());
    auto w = std::make_unique<mhc_wheelset>();
    w->model = std::make_unique<mh::WheelsetContact>(left->pg.geo, right->pg.geo, tl, ml, method, std::move(warnings),
                                                    o.roll_in_geometry == 1);
    w->plastic = left->plastic;
    *out = w.release();
    return MHC_OK;
  });
}

void mhc_wheelset_free(mhc_wheelset* w) { delete w; }

mhc_error mhc_wheelset_workspace_create(const mhc_wheelset* w, mhc_wheelset_workspace** out) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(w, "wheelset")) return e;
  if (mhc_error e = need(out, "out")) return e;
  *out = nullptr;
  return guarded([&] {
    auto ws = std::make_unique<mhc_wheelset_workspace>();
    ws->wheelset = w;
    *out = ws.release();
    return MHC_OK;
  });
}

void mhc_wheelset_workspace_free(mhc_wheelset_workspace* ws) { delete ws; }

mhc_error mhc_wheelset_step(const mhc_wheelset* w, mhc_wheelset_workspace* ws, const mhc_wheelset_pose* pose,
                            mhc_wheelset_result* out) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(w, "wheelset")) return e;
  if (mhc_error e = need(ws, "ws")) return e;
  if (mhc_error e = check_pose(pose)) return e;
  if (mhc_error e = check_result(out)) return e;
  if (ws->wheelset != w) return fail(MHC_ERR_ARGUMENT, "ws: a workspace of another wheelset");
  return guarded([&] { return step_one(*w, *ws, *pose, out); });
}

mhc_error mhc_wheelset_step_many(const mhc_wheelset* w, size_t n, const mhc_wheelset_pose* pose,
                                 mhc_wheelset_result* out, int32_t n_threads) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(w, "wheelset")) return e;
  if (n == 0) return MHC_OK;
  if (mhc_error e = need(pose, "pose")) return e;
  if (mhc_error e = need(out, "out")) return e;
  if (mhc_error e = check_pose(pose)) return e;
  if (mhc_error e = check_result(out)) return e;
  const std::size_t pose_size = pose->struct_size, result_size = out->struct_size;
  return guarded([&]() -> mhc_error {
    auto pose_at = [&](std::size_t i) {
      return reinterpret_cast<const mhc_wheelset_pose*>(reinterpret_cast<const char*>(pose) + i * pose_size);
    };
    auto out_at = [&](std::size_t i) {
      return reinterpret_cast<mhc_wheelset_result*>(reinterpret_cast<char*>(out) + i * result_size);
    };
    return mh::capi::for_each_index(n, n_threads, [&]() {
      auto ws = std::make_unique<mhc_wheelset_workspace>();
      ws->wheelset = w;
      return ws;
    }, [&](std::size_t i, std::unique_ptr<mhc_wheelset_workspace>& ws) {
      mhc_wheelset_result* o = out_at(i);
      o->struct_size = result_size;
      return step_one(*w, *ws, *pose_at(i), o);
    });
  });
}

int32_t mhc_wheelset_n_warnings(const mhc_wheelset_workspace* ws, int32_t side) {
  const auto* v = wheel_warnings(ws, side);
  return v ? static_cast<int32_t>(v->size()) : 0;
}

mhc_error mhc_wheelset_warning(const mhc_wheelset_workspace* ws, int32_t side, int32_t i, mhc_warning* out) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(ws, "ws")) return e;
  if (mhc_error e = need(out, "out")) return e;
  if (!mh::capi::warning_size_ok(out->struct_size, "out->struct_size")) return MHC_ERR_ARGUMENT;
  const auto* v = wheel_warnings(ws, side);
  if (!v) return fail(MHC_ERR_ARGUMENT, "side = " + std::to_string(side) + ": must be 0 (left) or 1 (right)");
  if (i < 0 || static_cast<std::size_t>(i) >= v->size())
    return fail(MHC_ERR_ARGUMENT, "warning " + std::to_string(i) + ": the wheel has " + std::to_string(v->size()) +
                                      " (0-based index)");
  mh::capi::fill_warning((*v)[static_cast<std::size_t>(i)], out);
  return MHC_OK;
}

const char* mhc_wheelset_warning_text(const mhc_wheelset_workspace* ws, int32_t side, int32_t i) {
  thread_local std::string text;
  text.clear();
  if (ws && side == -1 && i >= 0 && static_cast<std::size_t>(i) < ws->r.warnings.size())
    text = mh::to_string(ws->r.warnings[static_cast<std::size_t>(i)]);
  else if (const auto* v = wheel_warnings(ws, side); v && i >= 0 && static_cast<std::size_t>(i) < v->size())
    text = mh::warning_text((*v)[static_cast<std::size_t>(i)]);
  return text.c_str();
}

int32_t mhc_wheelset_n_wheelset_warnings(const mhc_wheelset_workspace* ws) {
  return ws ? static_cast<int32_t>(ws->r.warnings.size()) : 0;
}

}  // extern "C"
