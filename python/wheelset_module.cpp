// mhcontact._core.Wheelset: the wheelset call (include/mhcontact.h, its last section) for Python,
// many steps at once: arrays in (one value per step), arrays out, the steps solved with the GIL
// released by mhc_wheelset_step_many. python/mhcontact/__init__.py broadcasts the inputs.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include <mhcontact.h>

namespace py = pybind11;

void bind_wheelset(py::module_& m, void (*check)(mhc_error));

namespace {

using Arr = py::array_t<double, py::array::c_style | py::array::forcecast>;

struct Wheelset {
  mhc_wheelset* w = nullptr;
  ~Wheelset() { mhc_wheelset_free(w); }
};

const mhc_pair* pair_of(const py::object& pair) {
  // mhcontact.Pair's handle (python/mhcontact_module.cpp, Pair._capsule).
  const py::capsule c = pair.attr("_capsule")();
  return static_cast<const mhc_pair*>(c.get_pointer());
}

/// The scalar columns of a step, per step: name and how to read it from a result.
struct Column {
  const char* name;
  double (*get)(const mhc_wheelset_result&);
};
/// Vector columns: 3 components per step.
struct Column3 {
  const char* name;
  const double* (*get)(const mhc_wheelset_result&);
};

template <int S>
const mhc_wheelset_contact* main_contact(const mhc_wheelset_result& r) {
  const mhc_wheelset_wheel& w = r.wheel[S];
  const int n = std::min<int>(w.n_contacts, MHC_MAX_CONTACTS);
  const mhc_wheelset_contact* best = nullptr;
  for (int i = 0; i < n; ++i)
    if (!best || w.contact[i].N_N > best->N_N) best = &w.contact[i];
  return best;
}

#define MAIN(S, field) \
  [](const mhc_wheelset_result& r) { const auto* c = main_contact<S>(r); return c ? c->field : NAN; }

const Column kColumns[] = {
    {"roll_rad", [](const mhc_wheelset_result& r) { return r.roll_rad; }},
    {"Z_m", [](const mhc_wheelset_result& r) { return r.Z_m; }},
    {"left_tY_m", [](const mhc_wheelset_result& r) { return r.wheel[0].tY_m; }},
    {"right_tY_m", [](const mhc_wheelset_result& r) { return r.wheel[1].tY_m; }},
    {"left_dz_m", [](const mhc_wheelset_result& r) { return r.wheel[0].dz_m; }},
    {"right_dz_m", [](const mhc_wheelset_result& r) { return r.wheel[1].dz_m; }},
    {"left_h_m", [](const mhc_wheelset_result& r) { return r.wheel[0].h_m; }},
    {"right_h_m", [](const mhc_wheelset_result& r) { return r.wheel[1].h_m; }},
    // The contact carrying the largest N of each wheel (NaN: none).
    {"left_y_track_m", MAIN(0, y_track_m)},
    {"right_y_track_m", MAIN(1, y_track_m)},
    {"left_gamma_rad", MAIN(0, gamma_rad)},
    {"right_gamma_rad", MAIN(1, gamma_rad)},
    {"left_r_roll_m", MAIN(0, r_roll_m)},
    {"right_r_roll_m", MAIN(1, r_roll_m)},
    {"left_N_N", MAIN(0, N_N)},
    {"right_N_N", MAIN(1, N_N)},
    {"left_a_m", MAIN(0, a_m)},
    {"right_a_m", MAIN(1, a_m)},
    {"left_b_m", MAIN(0, b_m)},
    {"right_b_m", MAIN(1, b_m)},
};
const Column3 kColumns3[] = {
    {"F_N", [](const mhc_wheelset_result& r) { return r.F_N; }},
    {"M_N_m", [](const mhc_wheelset_result& r) { return r.M_N_m; }},
    {"dF_dy_N_per_m", [](const mhc_wheelset_result& r) { return r.dF_dy_N_per_m; }},
    {"dF_droll_N_per_rad", [](const mhc_wheelset_result& r) { return r.dF_droll_N_per_rad; }},
    {"dF_dvertical", [](const mhc_wheelset_result& r) { return r.dF_dvertical; }},
    {"left_F_N", [](const mhc_wheelset_result& r) { return r.wheel[0].F_N; }},
    {"right_F_N", [](const mhc_wheelset_result& r) { return r.wheel[1].F_N; }},
    {"left_M_N_m", [](const mhc_wheelset_result& r) { return r.wheel[0].M_N_m; }},
    {"right_M_N_m", [](const mhc_wheelset_result& r) { return r.wheel[1].M_N_m; }},
};

/// The inputs of _step_many, in mhc_wheelset_pose's order.
const char* const kInputs[] = {"y_m", "yaw_rad", "Q_left_N", "Q_right_N", "Z_m", "roll_rad", "V_m_per_s",
                               "lateral_velocity_m_per_s", "yaw_rate_rad_per_s", "pitch_rate_rad_per_s"};

}  // namespace

void bind_wheelset(py::module_& m, void (*check)(mhc_error)) {
  m.attr("INTERFACE_VERSION") = mhc_interface_version(nullptr);
  py::class_<Wheelset>(m, "Wheelset", "Both wheels of a wheelset on their rails (docs/python.md).")
      .def(py::init([check](const py::object& left, const py::object& right, double mu, int fastsim_nx,
                            int fastsim_ny, bool roll_in_geometry) {
             mhc_wheelset_options o;
             mhc_wheelset_options_init(&o);
             o.mu = mu;
             o.fastsim_nx = fastsim_nx;
             o.fastsim_ny = fastsim_ny;
             o.roll_in_geometry = roll_in_geometry ? 1 : 0;
             auto w = std::make_unique<Wheelset>();
             check(mhc_wheelset_create(pair_of(left), pair_of(right), &o, &w->w));
             return w;
           }),
           py::arg("left"), py::arg("right"), py::arg("mu") = NAN, py::arg("fastsim_nx") = 16,
           py::arg("fastsim_ny") = 16, py::arg("roll_in_geometry") = true)
      .def("_step_many",
           [check](const Wheelset& w, const std::map<std::string, Arr>& in, int vertical, bool solve_roll,
                   bool derivatives, int threads) {
             std::vector<const double*> col;
             py::ssize_t n = -1;
             for (const char* k : kInputs) {
               const auto it = in.find(k);
               if (it == in.end()) throw py::value_error(std::string("missing input ") + k);
               if (it->second.ndim() != 1) throw py::value_error(std::string(k) + ": must be one-dimensional");
               if (n >= 0 && it->second.shape(0) != n) throw py::value_error(std::string(k) + ": length differs");
               n = it->second.shape(0);
               col.push_back(it->second.data());
             }
             const std::size_t N = static_cast<std::size_t>(n);
             py::dict d;
             std::vector<double*> out;
             for (const Column& c : kColumns) {
               py::array_t<double> a(n);
               out.push_back(a.mutable_data());
               d[c.name] = a;
             }
             std::vector<double*> out3;
             for (const Column3& c : kColumns3) {
               py::array_t<double> a({n, py::ssize_t{3}});
               out3.push_back(a.mutable_data());
               d[c.name] = a;
             }
             py::array_t<int8_t> status(n), left_status(n), right_status(n);
             py::array_t<uint32_t> ws_warn(n), left_warn(n), right_warn(n);
             py::array_t<int32_t> left_nc(n), right_nc(n);
             py::array_t<bool> analytic(n);  // dF_dvertical analytic on both wheels
             mhc_error e = MHC_OK;
             {
               py::gil_scoped_release nogil;  // the steps run without the GIL
               // In chunks: a result is a few kilobytes; the chunk's are converted to columns.
               const std::size_t kChunk = threads == 1 ? 512 : 8192;
               std::vector<mhc_wheelset_pose> poses(std::min(N, kChunk));
               std::vector<mhc_wheelset_result> res(poses.size());
               for (std::size_t b = 0; b < N && e == MHC_OK; b += kChunk) {
                 const std::size_t m = std::min(kChunk, N - b);
                 for (std::size_t i = 0; i < m; ++i) {
                   mhc_wheelset_pose& p = poses[i];
                   std::memset(&p, 0, sizeof p);
                   p.struct_size = sizeof p;
                   p.vertical = vertical;
                   p.solve_roll = solve_roll ? 1 : 0;
                   p.derivatives = derivatives ? 1 : 0;
                   const std::size_t k = b + i;
                   p.y_m = col[0][k], p.yaw_rad = col[1][k], p.Q_left_N = col[2][k], p.Q_right_N = col[3][k];
                   p.Z_m = col[4][k], p.roll_rad = col[5][k], p.V_m_per_s = col[6][k];
                   p.lateral_velocity_m_per_s = col[7][k], p.yaw_rate_rad_per_s = col[8][k];
                   p.pitch_rate_rad_per_s = col[9][k];
                 }
                 res[0].struct_size = sizeof(mhc_wheelset_result);
                 e = mhc_wheelset_step_many(w.w, m, poses.data(), res.data(), threads);
                 if (e != MHC_OK) break;
                 for (std::size_t i = 0; i < m; ++i) {
                   const mhc_wheelset_result& r = res[i];
                   const std::size_t k = b + i;
                   for (std::size_t c = 0; c < std::size(kColumns); ++c) out[c][k] = kColumns[c].get(r);
                   for (std::size_t c = 0; c < std::size(kColumns3); ++c)
                     std::memcpy(out3[c] + 3 * k, kColumns3[c].get(r), 3 * sizeof(double));
                   status.mutable_data()[k] = static_cast<int8_t>(r.status);
                   left_status.mutable_data()[k] = static_cast<int8_t>(r.wheel[0].status);
                   right_status.mutable_data()[k] = static_cast<int8_t>(r.wheel[1].status);
                   ws_warn.mutable_data()[k] = r.wheelset_warnings;
                   left_warn.mutable_data()[k] = r.wheel[0].warnings;
                   right_warn.mutable_data()[k] = r.wheel[1].warnings;
                   left_nc.mutable_data()[k] = r.wheel[0].n_contacts;
                   right_nc.mutable_data()[k] = r.wheel[1].n_contacts;
                   analytic.mutable_data()[k] = r.wheel[0].dF_dvertical_analytic && r.wheel[1].dF_dvertical_analytic;
                 }
               }
             }
             check(e);
             d["status_code"] = status;
             d["left_status_code"] = left_status;
             d["right_status_code"] = right_status;
             d["wheelset_warnings"] = ws_warn;
             d["left_warnings"] = left_warn;
             d["right_warnings"] = right_warn;
             d["left_n_contacts"] = left_nc;
             d["right_n_contacts"] = right_nc;
             d["dF_dvertical_analytic"] = analytic;
             return d;
           });
}
