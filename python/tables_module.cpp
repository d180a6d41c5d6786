// mhcontact._core's contact tables (docs/tables.md): the class Table over the C interface's
// mhc_table_* (include/mhcontact.h, "contact tables"). SI in and out (m, N, Pa, rad).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <vector>

#include <mhcontact.h>

namespace py = pybind11;

namespace {

struct Table {
  mhc_table* t = nullptr;
  ~Table() { mhc_table_free(t); }
};

// The fields of mhc_table_contact after track and reserved, in their order.
const char* kFields[] = {"N_N", "y_rail_m", "z_rail_m", "y_wheel_m", "gamma_rad", "r_roll_m", "p_max_Pa", "area_m2",
                         "a_m", "b_m", "a_el_m", "b_el_m", "C11", "C22", "C23"};
constexpr int kNFields = sizeof kFields / sizeof kFields[0];
static_assert(sizeof(mhc_table_contact) == 8 + 8 * kNFields, "mhc_table_contact fields");

const double* fields(const mhc_table_contact& c) { return &c.N_N; }

py::dict contact_dict(const mhc_table_contact& c, const mhc_table_contact& dt, const mhc_table_contact& dq) {
  py::dict d, ddt, ddq;
  d["track"] = c.track;
  for (int f = 0; f < kNFields; ++f) {
    d[kFields[f]] = fields(c)[f];
    ddt[kFields[f]] = fields(dt)[f];
    ddq[kFields[f]] = fields(dq)[f];
  }
  d["d_dtY"] = ddt;
  d["d_dQ"] = ddq;
  return d;
}

}  // namespace

/// Called from the module's PYBIND11_MODULE (python/mhcontact_module.cpp); `raise` turns a C
/// error code into the module's exception.
void add_tables(py::module_& m, void (*raise)(mhc_error)) {
  py::class_<Table>(m, "Table", "A contact table made by `mhcontact table` (docs/tables.md), read once; lookups are "
                                "thread-safe and allocate nothing in the C library.")
      .def(py::init([raise](const std::string& path) {
             auto t = std::make_unique<Table>();
             const mhc_error e = mhc_table_read(path.c_str(), &t->t);
             if (e != MHC_OK) raise(e);
             return t;
           }),
           py::arg("path"))
      .def_property_readonly("header", [](const Table& t) { return std::string(mhc_table_header(t.t)); },
                             "The JSON header (a string: json.loads it)")
      .def_property_readonly("range", [](const Table& t) {
            double a, b, c, d;
            mhc_table_range(t.t, &a, &b, &c, &d);
            return py::make_tuple(a, b, c, d);
          }, "(tY_min_m, tY_max_m, Q_min_N, Q_max_N)")
      .def("lookup", [](const Table& t, double tY_m, double Q_N) {
            mhc_table_result r;
            r.struct_size = sizeof r;
            mhc_table_lookup(t.t, tY_m, Q_N, &r);
            py::dict d;
            d["status"] = mhc_status_name(r.status);
            d["coarse"] = r.coarse != 0;
            d["n_contacts"] = r.n_contacts;
            d["Fz_N"] = r.Fz_N;
            d["Fy_N"] = r.Fy_N;
            d["dFy_dtY_N_per_m"] = r.dFy_dtY_N_per_m;
            d["dFy_dQ"] = r.dFy_dQ;
            py::list cs;
            for (int k = 0; k < r.n_contacts && k < MHC_MAX_CONTACTS; ++k)
              cs.append(contact_dict(r.contact[k], r.d_dtY[k], r.d_dQ[k]));
            d["contacts"] = cs;
            return d;
          }, py::arg("tY_m"), py::arg("Q_N"),
          "The answer at one point: status, coarse, n_contacts, Fz_N, Fy_N, dFy_dtY_N_per_m, dFy_dQ and the contacts "
          "(each with d_dtY and d_dQ of its fields)")
      .def("lookup_many", [](const Table& t, py::array_t<double, py::array::c_style | py::array::forcecast> tY_m,
                             py::array_t<double, py::array::c_style | py::array::forcecast> Q_N) {
            const std::size_t n = static_cast<std::size_t>(tY_m.size());
            if (static_cast<std::size_t>(Q_N.size()) != n) throw py::value_error("tY_m and Q_N differ in length");
            const std::size_t K = MHC_MAX_CONTACTS;
            py::array_t<int8_t> status(n);
            py::array_t<int32_t> nc(n);
            py::array_t<double> Fz(n), Fy(n), dFy(n);
            std::vector<py::array_t<double>> per;
            for (int f = 0; f < kNFields + 2; ++f) per.emplace_back(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(K)});
            py::array_t<int32_t> track(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(K)});
            const double* ty = tY_m.data();
            const double* q = Q_N.data();
            int8_t* st = status.mutable_data();
            int32_t* n_c = nc.mutable_data();
            int32_t* tr = track.mutable_data();
            double *fz = Fz.mutable_data(), *fy = Fy.mutable_data(), *dfy = dFy.mutable_data();
            std::vector<double*> p;
            for (auto& a : per) p.push_back(a.mutable_data());
            {
              py::gil_scoped_release nogil;
              mhc_table_result r;
              r.struct_size = sizeof r;
              for (std::size_t i = 0; i < n; ++i) {
                mhc_table_lookup(t.t, ty[i], q[i], &r);
                st[i] = static_cast<int8_t>(r.status);
                n_c[i] = r.n_contacts;
                fz[i] = r.Fz_N;
                fy[i] = r.Fy_N;
                dfy[i] = r.dFy_dtY_N_per_m;
                for (std::size_t k = 0; k < K; ++k) {
                  const bool on = static_cast<int>(k) < r.n_contacts;
                  tr[i * K + k] = on ? r.contact[k].track : 0;
                  for (int f = 0; f < kNFields; ++f) p[static_cast<std::size_t>(f)][i * K + k] = on ? fields(r.contact[k])[f] : 0.0;
                  p[kNFields][i * K + k] = on ? r.d_dtY[k].N_N : 0.0;
                  p[kNFields + 1][i * K + k] = on ? r.d_dQ[k].N_N : 0.0;
                }
              }
            }
            py::dict d;
            d["status"] = status;
            d["n_contacts"] = nc;
            d["Fz_N"] = Fz;
            d["Fy_N"] = Fy;
            d["dFy_dtY_N_per_m"] = dFy;
            d["track"] = track;
            for (int f = 0; f < kNFields; ++f) d[kFields[f]] = per[static_cast<std::size_t>(f)];
            d["dN_dtY_N_per_m"] = per[kNFields];
            d["dN_dQ"] = per[kNFields + 1];
            return d;
          }, py::arg("tY_m"), py::arg("Q_N"),
          "Many points at once (numpy arrays of one length): status (codes of STATUS_NAMES), n_contacts, Fz_N, Fy_N, "
          "dFy_dtY_N_per_m, and per contact slot (n x 6 arrays, 0 where empty) track, the fields of lookup's "
          "contacts, dN_dtY_N_per_m and dN_dQ");
}
