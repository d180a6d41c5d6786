// mhcontact._core's contact tables (docs/tables.md): the class Table over the C interface's
// mhc_table_* (include/mhcontact.h, "contact tables"). SI in and out (m, N, Pa, rad).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <time.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <mhcontact.h>

namespace py = pybind11;

namespace {

struct Table {
  mhc_table* t = nullptr;
  bool roll_axis = false;  ///< more than one roll node: lookup's dicts carry the roll derivatives
  ~Table() { mhc_table_free(t); }
};

struct WheelsetTable {
  mhc_wheelset_table* t = nullptr;
  ~WheelsetTable() { mhc_wheelset_table_free(t); }
};

// The answer of WheelsetTable.lookup_into, reused from call to call.
struct WheelsetTableResult {
  mhc_wheelset_table_result r;
  WheelsetTableResult() {
    std::memset(static_cast<void*>(&r), 0, sizeof r);
    r.struct_size = sizeof r;
    r.status = MHC_STATUS_OUT_OF_RANGE;
  }
};

// The fields of mhc_table_contact after track and reserved, in their order.
const char* kFields[] = {"N_N", "y_rail_m", "z_rail_m", "y_wheel_m", "gamma_rad", "r_roll_m", "p_max_Pa", "area_m2",
                         "a_m", "b_m", "a_el_m", "b_el_m", "C11", "C22", "C23"};
constexpr int kNFields = sizeof kFields / sizeof kFields[0];
static_assert(sizeof(mhc_table_contact) == 8 + 8 * kNFields, "mhc_table_contact fields");

const double* fields(const mhc_table_contact& c) { return &c.N_N; }

// lookup_many's output arrays (docs/python.md "Contact tables"): made once per call, or the
// caller's, checked for their type, shape and layout, then filled without the GIL.
struct ManyPtrs {
  int8_t* st = nullptr;
  int32_t* nc = nullptr;
  int32_t* tr = nullptr;
  double *fz = nullptr, *fy = nullptr, *dfy = nullptr, *dfyr = nullptr;
  std::vector<double*> per;  ///< the contact fields, then dN_dtY, dN_dQ, dN_droll: n x MHC_MAX_CONTACTS each
};

template <class T>
T* many_array(const py::dict& d, const char* key, std::size_t n, bool per_slot) {
  if (!d.contains(key)) throw py::value_error(std::string("out: the key ") + key + " is missing (pass a dict that "
                                              "lookup_many returned, or Table.many_result(n))");
  py::array a = d[key].cast<py::array>();
  const bool shape = per_slot ? a.ndim() == 2 && static_cast<std::size_t>(a.shape(0)) == n && a.shape(1) == MHC_MAX_CONTACTS
                              : a.ndim() == 1 && static_cast<std::size_t>(a.shape(0)) == n;
  if (!a.dtype().is(py::dtype::of<T>()) || !(a.flags() & py::array::c_style) || !shape || !a.writeable())
    throw py::value_error(std::string("out[\"") + key + "\"]: must be a writeable C-contiguous " +
                          std::string(py::str(py::dtype::of<T>())) + " array of shape (" + std::to_string(n) +
                          (per_slot ? ", " + std::to_string(MHC_MAX_CONTACTS) : std::string(",")) +
                          ") for " + std::to_string(n) + " points (Table.many_result(n) makes one)");
  return static_cast<T*>(a.mutable_data());
}

py::dict many_result(std::size_t n) {
  const py::ssize_t N = static_cast<py::ssize_t>(n), K = MHC_MAX_CONTACTS;
  py::dict d;
  d["status"] = py::array_t<int8_t>(N);
  d["n_contacts"] = py::array_t<int32_t>(N);
  d["Fz_N"] = py::array_t<double>(N);
  d["Fy_N"] = py::array_t<double>(N);
  d["dFy_dtY_N_per_m"] = py::array_t<double>(N);
  d["dFy_droll_N_per_rad"] = py::array_t<double>(N);
  d["track"] = py::array_t<int32_t>(std::vector<py::ssize_t>{N, K});
  for (int f = 0; f < kNFields; ++f) d[kFields[f]] = py::array_t<double>(std::vector<py::ssize_t>{N, K});
  d["dN_dtY_N_per_m"] = py::array_t<double>(std::vector<py::ssize_t>{N, K});
  d["dN_dQ"] = py::array_t<double>(std::vector<py::ssize_t>{N, K});
  d["dN_droll_N_per_rad"] = py::array_t<double>(std::vector<py::ssize_t>{N, K});
  return d;
}

ManyPtrs many_ptrs(const py::dict& d, std::size_t n) {
  ManyPtrs p;
  p.st = many_array<int8_t>(d, "status", n, false);
  p.nc = many_array<int32_t>(d, "n_contacts", n, false);
  p.fz = many_array<double>(d, "Fz_N", n, false);
  p.fy = many_array<double>(d, "Fy_N", n, false);
  p.dfy = many_array<double>(d, "dFy_dtY_N_per_m", n, false);
  p.dfyr = many_array<double>(d, "dFy_droll_N_per_rad", n, false);
  p.tr = many_array<int32_t>(d, "track", n, true);
  for (int f = 0; f < kNFields; ++f) p.per.push_back(many_array<double>(d, kFields[f], n, true));
  p.per.push_back(many_array<double>(d, "dN_dtY_N_per_m", n, true));
  p.per.push_back(many_array<double>(d, "dN_dQ", n, true));
  p.per.push_back(many_array<double>(d, "dN_droll_N_per_rad", n, true));
  return p;
}

// roll: one per point, or null for the wheel upright.
void many_fill(const mhc_table* t, std::size_t n, const double* ty, const double* q, const double* roll, ManyPtrs& p) {
  const std::size_t K = MHC_MAX_CONTACTS;
  mhc_table_result r;
  r.struct_size = sizeof r;
  for (std::size_t i = 0; i < n; ++i) {
    mhc_table_lookup_rolled(t, ty[i], q[i], roll ? roll[i] : 0.0, &r);
    p.st[i] = static_cast<int8_t>(r.status);
    p.nc[i] = r.n_contacts;
    p.fz[i] = r.Fz_N;
    p.fy[i] = r.Fy_N;
    p.dfy[i] = r.dFy_dtY_N_per_m;
    p.dfyr[i] = r.dFy_droll_N_per_rad;
    for (std::size_t k = 0; k < K; ++k) {
      const bool on = static_cast<int>(k) < r.n_contacts;
      p.tr[i * K + k] = on ? r.contact[k].track : 0;
      for (int f = 0; f < kNFields; ++f) p.per[static_cast<std::size_t>(f)][i * K + k] = on ? fields(r.contact[k])[f] : 0.0;
      p.per[kNFields][i * K + k] = on ? r.d_dtY[k].N_N : 0.0;
      p.per[kNFields + 1][i * K + k] = on ? r.d_dQ[k].N_N : 0.0;
      p.per[kNFields + 2][i * K + k] = on ? r.d_droll[k].N_N : 0.0;
    }
  }
}

// The dictionary keys of `lookup`, made once rather than from a C string at every call (with the
// values boxed explicitly: 3 µs a lookup before, 1.4–1.7 µs after, docs/performance.md). Never
// freed (as statics they would be destroyed after the interpreter).
struct Keys {
  py::str field[kNFields], track, d_dtY, d_dQ, d_droll, status, coarse, off_roll, n_contacts, Fz, Fy, dFy_dtY, dFy_dQ,
      dFy_droll, contacts, Mx, dFy_dy, tY, roll, left, right;
  Keys() {
    for (int f = 0; f < kNFields; ++f) field[f] = py::str(kFields[f]);
    track = py::str("track"), d_dtY = py::str("d_dtY"), d_dQ = py::str("d_dQ"), d_droll = py::str("d_droll");
    status = py::str("status"), coarse = py::str("coarse"), off_roll = py::str("off_roll");
    n_contacts = py::str("n_contacts"), Fz = py::str("Fz_N"), Fy = py::str("Fy_N");
    dFy_dtY = py::str("dFy_dtY_N_per_m"), dFy_dQ = py::str("dFy_dQ"), dFy_droll = py::str("dFy_droll_N_per_rad");
    contacts = py::str("contacts");
    Mx = py::str("Mx_Nm"), dFy_dy = py::str("dFy_dy_N_per_m"), tY = py::str("tY_m"), roll = py::str("roll_rad");
    left = py::str("left"), right = py::str("right");
  }
};
const Keys& keys() {
  static const Keys* k = new Keys();
  return *k;
}

// d[k] = x through the dict's own C API (PyDict_SetItem): pybind11's item proxy goes through the
// generic PyObject_SetItem, about a third of a dict's building time here.
void set_item(PyObject* d, const py::str& k, PyObject* v) {
  if (!v) throw py::error_already_set();
  const int rc = PyDict_SetItem(d, k.ptr(), v);
  Py_DECREF(v);
  if (rc != 0) throw py::error_already_set();
}
void set_float(PyObject* d, const py::str& k, double x) { set_item(d, k, PyFloat_FromDouble(x)); }

// The fields of one slot (a contact, or its derivatives) as a dict.
py::dict fields_dict(const Keys& K, const mhc_table_contact& c) {
  py::dict d;
  for (int f = 0; f < kNFields; ++f) set_float(d.ptr(), K.field[f], fields(c)[f]);
  return d;
}

// dr: the roll derivatives, or null for a table without a roll axis (no d_droll key: they are 0).
py::dict contact_dict(const Keys& K, const mhc_table_contact& c, const mhc_table_contact& dt, const mhc_table_contact& dq,
                      const mhc_table_contact* dr) {
  py::dict d;
  set_item(d.ptr(), K.track, PyLong_FromLong(c.track));
  for (int f = 0; f < kNFields; ++f) set_float(d.ptr(), K.field[f], fields(c)[f]);
  set_item(d.ptr(), K.d_dtY, fields_dict(K, dt).release().ptr());
  set_item(d.ptr(), K.d_dQ, fields_dict(K, dq).release().ptr());
  if (dr) set_item(d.ptr(), K.d_droll, fields_dict(K, *dr).release().ptr());
  return d;
}

// The answer of `lookup_into`: an mhc_table_result owned by Python, its scalars as properties and
// its contact slots as numpy views of the struct (no copy; valid while the result lives): the
// single-point lookup without building a dict.
struct TableResult {
  mhc_table_result r;
  TableResult() {
    std::memset(static_cast<void*>(&r), 0, sizeof r);
    r.struct_size = sizeof r;
    r.status = MHC_STATUS_OUT_OF_RANGE;
  }
};

// A (MHC_MAX_CONTACTS, kNFields) view of the fields of slots `first` (contact, d_dtY or d_dQ).
py::array slot_view(py::object self, mhc_table_contact* first) {
  return py::array(py::dtype::of<double>(), {static_cast<py::ssize_t>(MHC_MAX_CONTACTS), static_cast<py::ssize_t>(kNFields)},
                   {static_cast<py::ssize_t>(sizeof(mhc_table_contact)), static_cast<py::ssize_t>(sizeof(double))},
                   &first->N_N, self);
}

}  // namespace

/// Called from the module's PYBIND11_MODULE (python/mhcontact_module.cpp); `raise` turns a C
/// error code into the module's exception.
void add_tables(py::module_& m, void (*raise)(mhc_error)) {
  py::tuple field_names(kNFields);
  for (int f = 0; f < kNFields; ++f) field_names[static_cast<std::size_t>(f)] = py::str(kFields[f]);
  py::class_<TableResult>(m, "TableResult",
                          "The answer of Table.lookup_into, reused from call to call (docs/tables.md \"From Python\"). "
                          "values, d_dtY, d_dQ and d_droll are numpy views (MAX_CONTACTS x len(FIELDS)) of its contact slots "
                          "and track one of their tracks (0 where empty): take them once, they see every later lookup.")
      .def(py::init<>())
      .def_property_readonly_static("FIELDS", [field_names](py::object) { return field_names; },
                                    "the columns of values, d_dtY, d_dQ and d_droll (SI)")
      .def_property_readonly("status", [](const TableResult& x) { return mhc_status_name(x.r.status); })
      .def_property_readonly("status_code", [](const TableResult& x) { return x.r.status; }, "index in STATUS_NAMES")
      .def_property_readonly("coarse", [](const TableResult& x) { return x.r.coarse != 0; })
      .def_property_readonly("off_roll", [](const TableResult& x) { return x.r.off_roll != 0; },
                             "a table without a roll axis asked at another roll than its own")
      .def_property_readonly("roll_rad", [](const TableResult& x) { return x.r.roll_rad; })
      .def_property_readonly("dFy_droll_N_per_rad", [](const TableResult& x) { return x.r.dFy_droll_N_per_rad; })
      .def_property_readonly("n_contacts", [](const TableResult& x) { return x.r.n_contacts; })
      .def_property_readonly("tY_m", [](const TableResult& x) { return x.r.tY_m; })
      .def_property_readonly("Q_N", [](const TableResult& x) { return x.r.Q_N; })
      .def_property_readonly("Fz_N", [](const TableResult& x) { return x.r.Fz_N; })
      .def_property_readonly("Fy_N", [](const TableResult& x) { return x.r.Fy_N; })
      .def_property_readonly("dFy_dtY_N_per_m", [](const TableResult& x) { return x.r.dFy_dtY_N_per_m; })
      .def_property_readonly("dFy_dQ", [](const TableResult& x) { return x.r.dFy_dQ; })
      .def_property_readonly("track", [](py::object self) {
            TableResult& x = self.cast<TableResult&>();
            return py::array(py::dtype::of<int32_t>(), {static_cast<py::ssize_t>(MHC_MAX_CONTACTS)},
                             {static_cast<py::ssize_t>(sizeof(mhc_table_contact))}, &x.r.contact[0].track, self);
          })
      .def_property_readonly("values", [](py::object self) { return slot_view(self, self.cast<TableResult&>().r.contact); })
      .def_property_readonly("d_dtY", [](py::object self) { return slot_view(self, self.cast<TableResult&>().r.d_dtY); },
                             "per metre")
      .def_property_readonly("d_dQ", [](py::object self) { return slot_view(self, self.cast<TableResult&>().r.d_dQ); },
                             "per newton")
      .def_property_readonly("d_droll", [](py::object self) { return slot_view(self, self.cast<TableResult&>().r.d_droll); },
                             "per radian");
  m.attr("MAX_CONTACTS") = MHC_MAX_CONTACTS;

  py::class_<Table>(m, "Table", "A contact table made by `mhcontact table` (docs/tables.md), read once; lookups are "
                                "thread-safe and allocate nothing in the C library.")
      .def(py::init([raise](const std::string& path) {
             auto t = std::make_unique<Table>();
             const mhc_error e = mhc_table_read(path.c_str(), &t->t);
             if (e != MHC_OK) raise(e);
             int32_t n = 1;
             mhc_table_roll_range(t->t, nullptr, nullptr, &n);
             t->roll_axis = n > 1;
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
      .def_property_readonly("roll_range", [](const Table& t) {
            double a, b;
            int32_t n;
            mhc_table_roll_range(t.t, &a, &b, &n);
            return py::make_tuple(a, b, n);
          }, "(roll_min_rad, roll_max_rad, roll_nodes): one node, no roll axis")
      .def("lookup", [](const Table& t, double tY_m, double Q_N, double roll_rad) {
            mhc_table_result r;
            r.struct_size = sizeof r;
            mhc_table_lookup_rolled(t.t, tY_m, Q_N, roll_rad, &r);
            const Keys& K = keys();
            py::dict d;
            PyObject* D = d.ptr();
            set_item(D, K.status, PyUnicode_FromString(mhc_status_name(r.status)));
            set_item(D, K.coarse, PyBool_FromLong(r.coarse != 0));
            set_item(D, K.off_roll, PyBool_FromLong(r.off_roll != 0));
            set_item(D, K.n_contacts, PyLong_FromLong(r.n_contacts));
            set_float(D, K.Fz, r.Fz_N);
            set_float(D, K.Fy, r.Fy_N);
            set_float(D, K.dFy_dtY, r.dFy_dtY_N_per_m);
            set_float(D, K.dFy_dQ, r.dFy_dQ);
            if (t.roll_axis) set_float(D, K.dFy_droll, r.dFy_droll_N_per_rad);
            const int n = r.n_contacts < MHC_MAX_CONTACTS ? r.n_contacts : MHC_MAX_CONTACTS;
            py::list cs(static_cast<std::size_t>(n));
            for (int k = 0; k < n; ++k)
              PyList_SET_ITEM(cs.ptr(), k, contact_dict(K, r.contact[k], r.d_dtY[k], r.d_dQ[k],
                                                        t.roll_axis ? &r.d_droll[k] : nullptr).release().ptr());
            set_item(D, K.contacts, cs.release().ptr());
            return d;
          }, py::arg("tY_m"), py::arg("Q_N"), py::arg("roll_rad") = 0.0,
          "The answer at one point (the wheel's roll roll_rad against the rail, default upright): status, coarse, "
          "off_roll, n_contacts, Fz_N, Fy_N, dFy_dtY_N_per_m, dFy_dQ and the contacts (each with d_dtY and d_dQ of its "
          "fields); for a table with a roll axis also dFy_droll_N_per_rad and each contact's d_droll")
      .def("lookup_into", [](const Table& t, double tY_m, double Q_N, TableResult& out, double roll_rad) {
            mhc_table_lookup_rolled(t.t, tY_m, Q_N, roll_rad, &out.r);
            return out.r.status;
          }, py::arg("tY_m"), py::arg("Q_N"), py::arg("out"), py::arg("roll_rad") = 0.0,
          "The answer at one point into `out` (a TableResult, reused); returns its status code (index in "
          "STATUS_NAMES). The fast single-point lookup: no dict, no allocation")
      .def("_c_lookup_seconds", [](const Table& t, py::array_t<double, py::array::c_style | py::array::forcecast> tY_m,
                                   py::array_t<double, py::array::c_style | py::array::forcecast> Q_N, int repeats) {
            // The benchmark's reference (bench/tables/bench_table_python.py): the C lookup in a C loop
            // over the points, CPU time of the thread per lookup, one figure per repeat.
            const std::size_t n = static_cast<std::size_t>(tY_m.size());
            if (static_cast<std::size_t>(Q_N.size()) != n || n == 0) throw py::value_error("tY_m and Q_N: one non-zero length");
            const double* ty = tY_m.data();
            const double* q = Q_N.data();
            std::vector<double> per;
            {
              py::gil_scoped_release nogil;
              mhc_table_result r;
              r.struct_size = sizeof r;
              for (int rep = 0; rep < repeats; ++rep) {
                timespec a, b;
                clock_gettime(CLOCK_THREAD_CPUTIME_ID, &a);
                for (std::size_t i = 0; i < n; ++i) mhc_table_lookup(t.t, ty[i], q[i], &r);
                clock_gettime(CLOCK_THREAD_CPUTIME_ID, &b);
                per.push_back((static_cast<double>(b.tv_sec - a.tv_sec) + 1e-9 * static_cast<double>(b.tv_nsec - a.tv_nsec)) /
                              static_cast<double>(n));
              }
            }
            return per;
          }, py::arg("tY_m"), py::arg("Q_N"), py::arg("repeats") = 5)
      .def("lookup_many", [](const Table& t, py::array_t<double, py::array::c_style | py::array::forcecast> tY_m,
                             py::array_t<double, py::array::c_style | py::array::forcecast> Q_N, py::object out,
                             py::object roll_rad) {
            const std::size_t n = static_cast<std::size_t>(tY_m.size());
            if (static_cast<std::size_t>(Q_N.size()) != n) throw py::value_error("tY_m and Q_N differ in length");
            py::array_t<double, py::array::c_style | py::array::forcecast> roll;
            if (!roll_rad.is_none()) {
              roll = roll_rad.cast<py::array_t<double, py::array::c_style | py::array::forcecast>>();
              if (static_cast<std::size_t>(roll.size()) != n) throw py::value_error("roll_rad and tY_m differ in length");
            }
            py::dict d = out.is_none() ? many_result(n) : out.cast<py::dict>();
            ManyPtrs p = many_ptrs(d, n);
            const double* ty = tY_m.data();
            const double* q = Q_N.data();
            const double* r = roll_rad.is_none() ? nullptr : roll.data();
            {
              py::gil_scoped_release nogil;
              many_fill(t.t, n, ty, q, r, p);
            }
            return d;
          }, py::arg("tY_m"), py::arg("Q_N"), py::arg("out") = py::none(), py::arg("roll_rad") = py::none(),
          "Many points at once (numpy arrays of one length; roll_rad an array of the wheel's roll, default upright): "
          "status (codes of STATUS_NAMES), n_contacts, Fz_N, Fy_N, dFy_dtY_N_per_m, dFy_droll_N_per_rad, and per "
          "contact slot (n x 6 arrays, 0 where empty) track, the fields of lookup's contacts, dN_dtY_N_per_m, dN_dQ "
          "and dN_droll_N_per_rad, as a dict of arrays. With out= (a dict that lookup_many returned "
          "for as many points, or Table.many_result(n)) the answers are written into its arrays and out is "
          "returned: no allocation per call")
      .def_static("many_result", [](std::size_t n) { return many_result(n); }, py::arg("n"),
                  "The dict of output arrays of lookup_many for n points (not yet filled), to pass as out=");

  py::class_<WheelsetTableResult>(m, "WheelsetTableResult",
                                  "The answer of WheelsetTable.lookup_into, reused from call to call: the wheelset's "
                                  "forces (track frame) and per wheel (tuples: left, right) its pair's t_Y, roll and forces.")
      .def(py::init<>())
      .def_property_readonly("status", [](const WheelsetTableResult& x) { return mhc_status_name(x.r.status); })
      .def_property_readonly("status_code", [](const WheelsetTableResult& x) { return x.r.status; })
      .def_property_readonly("Fy_N", [](const WheelsetTableResult& x) { return x.r.Fy_N; })
      .def_property_readonly("Fz_N", [](const WheelsetTableResult& x) { return x.r.Fz_N; })
      .def_property_readonly("Mx_Nm", [](const WheelsetTableResult& x) { return x.r.Mx_Nm; })
      .def_property_readonly("dFy_dy_N_per_m", [](const WheelsetTableResult& x) { return x.r.dFy_dy_N_per_m; })
      .def_property_readonly("dFy_droll_N_per_rad", [](const WheelsetTableResult& x) { return x.r.dFy_droll_N_per_rad; })
      .def_property_readonly("wheel_tY_m", [](const WheelsetTableResult& x) {
            return py::make_tuple(x.r.wheel[0].tY_m, x.r.wheel[1].tY_m);
          })
      .def_property_readonly("wheel_Fy_N", [](const WheelsetTableResult& x) { return py::make_tuple(x.r.wheel_Fy_N[0], x.r.wheel_Fy_N[1]); })
      .def_property_readonly("wheel_Fz_N", [](const WheelsetTableResult& x) { return py::make_tuple(x.r.wheel_Fz_N[0], x.r.wheel_Fz_N[1]); })
      .def_property_readonly("wheel_dFy_dQ", [](const WheelsetTableResult& x) { return py::make_tuple(x.r.wheel_dFy_dQ[0], x.r.wheel_dFy_dQ[1]); });

  py::class_<WheelsetTable>(m, "WheelsetTable",
                            "A wheelset table made by `mhcontact table-wheelset` (docs/tables.md \"A wheelset table\"): "
                            "the lookup places both wheels from the wheelset's y and roll as the wheelset call does.")
      .def(py::init([raise](const std::string& path) {
             auto t = std::make_unique<WheelsetTable>();
             const mhc_error e = mhc_wheelset_table_read(path.c_str(), &t->t);
             if (e != MHC_OK) raise(e);
             return t;
           }),
           py::arg("path"))
      .def_property_readonly("header", [](const WheelsetTable& t) { return std::string(mhc_wheelset_table_header(t.t)); },
                             "The wheelset table's JSON header (a string: json.loads it)")
      .def("pair_range", [](const WheelsetTable& t, int side) {
            double v[6];
            if (side != 0 && side != 1) throw py::value_error("side: 0 (left) or 1 (right)");
            mhc_wheelset_table_pair_range(t.t, side, &v[0], &v[1], &v[2], &v[3], &v[4], &v[5]);
            return py::make_tuple(v[0], v[1], v[2], v[3], v[4], v[5]);
          }, py::arg("side"), "(tY_min_m, tY_max_m, Q_min_N, Q_max_N, roll_min_rad, roll_max_rad) of side 0 (left) or 1 (right)")
      .def("lookup", [](const WheelsetTable& t, double y_m, double roll_rad, double Q_left_N, double Q_right_N) {
            mhc_wheelset_table_result r;
            r.struct_size = sizeof r;
            mhc_wheelset_table_lookup(t.t, y_m, roll_rad, Q_left_N, Q_right_N, &r);
            const Keys& K = keys();
            py::dict d;
            PyObject* D = d.ptr();
            set_item(D, K.status, PyUnicode_FromString(mhc_status_name(r.status)));
            set_float(D, K.Fy, r.Fy_N);
            set_float(D, K.Fz, r.Fz_N);
            set_float(D, K.Mx, r.Mx_Nm);
            set_float(D, K.dFy_dy, r.dFy_dy_N_per_m);
            set_float(D, K.dFy_droll, r.dFy_droll_N_per_rad);
            for (int s = 0; s < 2; ++s) {
              const mhc_table_result& w = r.wheel[s];
              py::dict e;
              PyObject* E = e.ptr();
              set_item(E, K.status, PyUnicode_FromString(mhc_status_name(w.status)));
              set_float(E, K.tY, w.tY_m);
              set_float(E, K.roll, w.roll_rad);
              set_float(E, K.Fy, r.wheel_Fy_N[s]);
              set_float(E, K.Fz, r.wheel_Fz_N[s]);
              set_float(E, K.Mx, r.wheel_Mx_Nm[s]);
              set_float(E, K.dFy_dy, r.wheel_dFy_dy_N_per_m[s]);
              set_float(E, K.dFy_droll, r.wheel_dFy_droll_N_per_rad[s]);
              set_float(E, K.dFy_dQ, r.wheel_dFy_dQ[s]);
              set_item(E, K.coarse, PyBool_FromLong(w.coarse != 0));
              set_item(E, K.off_roll, PyBool_FromLong(w.off_roll != 0));
              set_item(E, K.n_contacts, PyLong_FromLong(w.n_contacts));
              const int n = w.n_contacts < MHC_MAX_CONTACTS ? w.n_contacts : MHC_MAX_CONTACTS;
              py::list cs(static_cast<std::size_t>(n));
              for (int k = 0; k < n; ++k)
                PyList_SET_ITEM(cs.ptr(), k, contact_dict(K, w.contact[k], w.d_dtY[k], w.d_dQ[k], &w.d_droll[k]).release().ptr());
              set_item(E, K.contacts, cs.release().ptr());
              set_item(D, s == 0 ? K.left : K.right, e.release().ptr());
            }
            return d;
          }, py::arg("y_m"), py::arg("roll_rad"), py::arg("Q_left_N"), py::arg("Q_right_N"),
          "The answer at the wheelset's lateral displacement y_m (towards the left rail) and roll roll_rad (positive "
          "raising the left wheel), the wheels' vertical loads given: status, Fy_N, Fz_N, Mx_Nm (both wheels' normal "
          "forces on the wheelset, track frame, about the axle centre), dFy_dy_N_per_m, dFy_droll_N_per_rad, and "
          "'left' / 'right': that wheel's pair answer (tY_m and roll_rad as placed, its forces in the track frame, "
          "dFy_dQ, the contacts as Table.lookup's, pair frame)")
      .def("lookup_into", [](const WheelsetTable& t, double y_m, double roll_rad, double Q_left_N, double Q_right_N,
                             WheelsetTableResult& out) {
            mhc_wheelset_table_lookup(t.t, y_m, roll_rad, Q_left_N, Q_right_N, &out.r);
            return out.r.status;
          }, py::arg("y_m"), py::arg("roll_rad"), py::arg("Q_left_N"), py::arg("Q_right_N"), py::arg("out"),
          "The answer into `out` (a WheelsetTableResult, reused); returns its status code. No dict, no allocation");
}
