// The C interface of contact tables (include/mhcontact.h, "contact tables"; docs/tables.md):
// a table read by input/contact_table and its lookup converted into mhc_table_result.
#include <cstddef>
#include <cstring>
#include <memory>
#include <string>

#include <mhcontact.h>

#include "capi/handles.hpp"
#include "input/contact_table.hpp"
#include "input/wheelset_table.hpp"

struct mhc_wheelset_table {
  explicit mhc_wheelset_table(mh::WheelsetTableData d) : look(std::move(d)), header(look.header().dump()) {}
  mh::WheelsetTableLookup look;
  std::string header;
};

struct mhc_table {
  explicit mhc_table(mh::ContactTableData d) : look(std::move(d)), header(look.data().header.dump()) {}
  mh::ContactTableLookup look;
  std::string header;
};

namespace {

using mh::capi::guarded;
using mh::capi::need;

int32_t status_code(mh::CaseStatus s) {
  switch (s) {
    case mh::CaseStatus::Ok: return MHC_STATUS_OK;
    case mh::CaseStatus::NoContact: return MHC_STATUS_NO_CONTACT;
    case mh::CaseStatus::OutOfRange: return MHC_STATUS_OUT_OF_RANGE;
    case mh::CaseStatus::NotConverged: return MHC_STATUS_NOT_CONVERGED;
    case mh::CaseStatus::OutsideValidity: return MHC_STATUS_OUTSIDE_VALIDITY;
    case mh::CaseStatus::Derailed: return MHC_STATUS_DERAILED;
  }
  return MHC_STATUS_NOT_CONVERGED;
}

// mhc_table_contact holds the table's quantities in kTableColumns order after track, reserved.
static_assert(sizeof(mhc_table_contact) == 8 + sizeof(double) * mh::kTableQuantities, "mhc_table_contact layout");
static_assert(MHC_MAX_CONTACTS == mh::kTableMaxContacts, "contact slots");

void put(mhc_table_contact& c, int track, const std::array<double, mh::kTableQuantities>& v) {
  c.track = track;
  c.reserved = 0;
  std::memcpy(&c.N_N, v.data(), sizeof(double) * mh::kTableQuantities);
}

// A lookup's answer into the C struct (with_roll: the fields after d_dQ too).
void fill(const mh::TableAnswer& a, double tY_m, double Q_N, double roll_rad, bool with_roll, mhc_table_result* out) {
  out->status = status_code(a.status);
  out->n_contacts = a.n_contacts;
  out->coarse = a.coarse ? 1 : 0;
  out->reserved = 0;
  out->tY_m = tY_m;
  out->Q_N = Q_N;
  out->Fz_N = a.Fz;
  out->Fy_N = a.Fy;
  out->dFy_dtY_N_per_m = a.dFy_dtY;
  out->dFy_dQ = a.dFy_dQ;
  const int n = a.n_contacts < MHC_MAX_CONTACTS ? a.n_contacts : MHC_MAX_CONTACTS;
  for (int k = 0; k < n; ++k) {
    const mh::TableContact& c = a.c[static_cast<std::size_t>(k)];
    put(out->contact[k], c.track, c.v);
    put(out->d_dtY[k], c.track, c.d_dtY);
    put(out->d_dQ[k], c.track, c.d_dQ);
    if (with_roll) put(out->d_droll[k], c.track, c.d_droll);
  }
  if (n < MHC_MAX_CONTACTS) {
    const std::size_t rest = sizeof(mhc_table_contact) * static_cast<std::size_t>(MHC_MAX_CONTACTS - n);
    std::memset(static_cast<void*>(&out->contact[n]), 0, rest);
    std::memset(static_cast<void*>(&out->d_dtY[n]), 0, rest);
    std::memset(static_cast<void*>(&out->d_dQ[n]), 0, rest);
    if (with_roll) std::memset(static_cast<void*>(&out->d_droll[n]), 0, rest);
  }
  if (with_roll) {
    out->roll_rad = roll_rad;
    out->dFy_droll_N_per_rad = a.dFy_droll;
    out->off_roll = a.off_roll ? 1 : 0;
    out->reserved2 = 0;
  }
}

// A table's node ranges into the pointers that are not null.
void node_ranges(const mh::ContactTableData& d, double* tY_min, double* tY_max, double* Q_min, double* Q_max,
                 double* roll_min, double* roll_max) {
  if (tY_min) *tY_min = d.tY.front();
  if (tY_max) *tY_max = d.tY.back();
  if (Q_min) *Q_min = d.Q.front();
  if (Q_max) *Q_max = d.Q.back();
  if (roll_min) *roll_min = d.roll.front();
  if (roll_max) *roll_max = d.roll.back();
}

// A handle H made from the file `path` by `read` into *out (null on an error, the message kept).
template <class H, class Read>
mhc_error read_handle(const char* path, H** out, Read&& read) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(path, "path")) return e;
  if (mhc_error e = need(out, "out")) return e;
  *out = nullptr;
  return guarded([&] {
    *out = new H(read(path));
    return MHC_OK;
  });
}

}  // namespace

extern "C" {

mhc_error mhc_table_read(const char* path, mhc_table** out) {
  return read_handle(path, out, [](const char* p) { return mh::read_contact_table(p); });
}

mhc_error mhc_table_range(const mhc_table* t, double* tY_min_m, double* tY_max_m, double* Q_min_N, double* Q_max_N) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(t, "table")) return e;
  node_ranges(t->look.data(), tY_min_m, tY_max_m, Q_min_N, Q_max_N, nullptr, nullptr);
  return MHC_OK;
}

mhc_error mhc_table_roll_range(const mhc_table* t, double* roll_min_rad, double* roll_max_rad, int32_t* roll_nodes) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(t, "table")) return e;
  const auto& d = t->look.data();
  if (roll_min_rad) *roll_min_rad = d.roll.front();
  if (roll_max_rad) *roll_max_rad = d.roll.back();
  if (roll_nodes) *roll_nodes = static_cast<int32_t>(d.nR());
  return MHC_OK;
}

const char* mhc_table_header(const mhc_table* t) { return t ? t->header.c_str() : nullptr; }

mhc_error mhc_table_lookup(const mhc_table* t, double tY_m, double Q_N, mhc_table_result* out) {
  return mhc_table_lookup_rolled(t, tY_m, Q_N, 0.0, out);
}

mhc_error mhc_table_lookup_rolled(const mhc_table* t, double tY_m, double Q_N, double roll_rad, mhc_table_result* out) {
  if (mhc_error e = need(t, "table")) return e;
  if (mhc_error e = need(out, "result")) return e;
  // The layout before the roll fields (ending at d_dQ) is still served: those fields only.
  constexpr std::size_t kBeforeRoll = offsetof(mhc_table_result, roll_rad);
  const bool with_roll = out->struct_size >= sizeof(mhc_table_result);
  if (out->struct_size != kBeforeRoll && !with_roll)
    return mh::capi::fail(MHC_ERR_ARGUMENT, "result: struct_size = " + std::to_string(out->struct_size) +
                                                ": must be sizeof(mhc_table_result) = " +
                                                std::to_string(sizeof(mhc_table_result)));
  thread_local mh::TableAnswer a;
  t->look.lookup(tY_m, Q_N, roll_rad, a);
  fill(a, tY_m, Q_N, roll_rad, with_roll, out);
  return MHC_OK;
}

void mhc_table_free(mhc_table* t) { delete t; }

mhc_error mhc_wheelset_table_read(const char* path, mhc_wheelset_table** out) {
  return read_handle(path, out, [](const char* p) { return mh::read_wheelset_table(p); });
}

const char* mhc_wheelset_table_header(const mhc_wheelset_table* t) { return t ? t->header.c_str() : nullptr; }

mhc_error mhc_wheelset_table_pair_range(const mhc_wheelset_table* t, int32_t side, double* tY_min_m, double* tY_max_m,
                                        double* Q_min_N, double* Q_max_N, double* roll_min_rad, double* roll_max_rad) {
  mh::capi::last_message().clear();
  if (mhc_error e = need(t, "table")) return e;
  if (side != 0 && side != 1)
    return mh::capi::fail(MHC_ERR_ARGUMENT, "side = " + std::to_string(side) + ": must be 0 (left) or 1 (right)");
  node_ranges(t->look.pair(side).data(), tY_min_m, tY_max_m, Q_min_N, Q_max_N, roll_min_rad, roll_max_rad);
  return MHC_OK;
}

mhc_error mhc_wheelset_table_lookup(const mhc_wheelset_table* t, double y_m, double roll_rad, double Q_left_N,
                                    double Q_right_N, mhc_wheelset_table_result* out) {
  if (mhc_error e = need(t, "table")) return e;
  if (mhc_error e = need(out, "result")) return e;
  if (out->struct_size != sizeof(mhc_wheelset_table_result))
    return mh::capi::fail(MHC_ERR_ARGUMENT, "result: struct_size = " + std::to_string(out->struct_size) +
                                                ": must be sizeof(mhc_wheelset_table_result) = " +
                                                std::to_string(sizeof(mhc_wheelset_table_result)));
  thread_local mh::WheelsetTableAnswer a;
  mh::WheelsetTablePose p;
  p.y = y_m, p.roll = roll_rad, p.Q_left = Q_left_N, p.Q_right = Q_right_N;
  t->look.lookup(p, a);
  out->status = status_code(a.status);
  out->reserved = 0;
  out->y_m = y_m;
  out->roll_rad = roll_rad;
  out->Fy_N = a.Fy;
  out->Fz_N = a.Fz;
  out->Mx_Nm = a.Mx;
  out->dFy_dy_N_per_m = a.dFy_dy;
  out->dFy_droll_N_per_rad = a.dFy_droll;
  for (int s = 0; s < 2; ++s) {
    const mh::WheelsetTableWheel& w = a.wheel[static_cast<std::size_t>(s)];
    out->wheel_Fy_N[s] = w.Fy;
    out->wheel_Fz_N[s] = w.Fz;
    out->wheel_Mx_Nm[s] = w.Mx;
    out->wheel_dFy_dy_N_per_m[s] = w.dFy_dy;
    out->wheel_dFy_droll_N_per_rad[s] = w.dFy_droll;
    out->wheel_dFy_dQ[s] = w.dFy_dQ;
    out->wheel[s].struct_size = sizeof(mhc_table_result);
    fill(w.pair, w.tY, s == 0 ? Q_left_N : Q_right_N, w.delta, true, &out->wheel[s]);
  }
  return MHC_OK;
}

void mhc_wheelset_table_free(mhc_wheelset_table* t) { delete t; }

}  // extern "C"
