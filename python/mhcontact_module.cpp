// mhcontact._core: the Python module over the C interface (include/mhcontact.h, lib/capi). The
// pure-Python package python/mhcontact/__init__.py wraps it (broadcasting, status names). Columns
// carry the names and units of cases.csv (lib/output/case_tables.cpp), converted the same way
// (x * 1e3 for mm, x / 1e3 for kN, ...), so they equal the table's numbers bit for bit.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <mhcontact.h>

#include "capi/handles.hpp"
#include "core/units.hpp"

namespace py = pybind11;

void bind_fleet(py::module_& m, py::object input_error);  // python/mhcontact_fleet.cpp
using mh::units::deg;

/// The Wheelset class (python/wheelset_module.cpp).
void bind_wheelset(py::module_& m, void (*check)(mhc_error));
void bind_rcf(py::module_& m, void (*check)(mhc_error));  // python/rcf_module.cpp
void bind_grids(py::module_& m, void (*check)(mhc_error));  // python/grids_module.cpp

namespace {

py::object g_input_error, g_unsupported_error;

[[noreturn]] void raise(mhc_error e) {
  const std::string msg = mhc_last_message();
  switch (e) {
    case MHC_ERR_INPUT: PyErr_SetString(g_input_error.ptr(), msg.c_str()); break;
    case MHC_ERR_UNSUPPORTED: PyErr_SetString(g_unsupported_error.ptr(), msg.c_str()); break;
    case MHC_ERR_ARGUMENT: PyErr_SetString(PyExc_ValueError, msg.c_str()); break;
    case MHC_ERR_MEMORY: PyErr_SetString(PyExc_MemoryError, msg.c_str()); break;
    default: PyErr_SetString(PyExc_RuntimeError, msg.c_str()); break;
  }
  throw py::error_already_set();
}
void check(mhc_error e) {
  if (e != MHC_OK) raise(e);
}

struct Profile {
  mhc_profile* p = nullptr;
  ~Profile() { mhc_profile_free(p); }
};

struct Pair {
  mhc_pair* p = nullptr;
  ~Pair() { mhc_pair_free(p); }
};

int32_t kind_of(const std::string& k) {
  if (k == "wheel") return MHC_WHEEL;
  if (k == "rail") return MHC_RAIL;
  throw py::value_error("kind = \"" + k + "\": must be \"wheel\" or \"rail\"");
}

py::dict contact_dict(const mhc_contact& c) {
  py::dict d;
  d["ellipse"] = c.index;
  d["y_rail_mm"] = c.y_rail_m * 1e3;
  d["z_rail_mm"] = c.z_rail_m * 1e3;
  d["y_wheel_mm"] = c.y_wheel_m * 1e3;
  d["z_wheel_mm"] = c.z_wheel_m * 1e3;
  d["gamma_deg"] = c.gamma_rad / deg;
  d["r_roll_mm"] = c.r_roll_m * 1e3;
  d["h0_mm"] = c.h0_m * 1e3;
  d["N_kN"] = c.N_N / 1e3;
  d["Fz_kN"] = c.Fz_N / 1e3;
  d["Fy_kN"] = c.Fy_N / 1e3;
  d["a_mm"] = c.a_m * 1e3;
  d["b_mm"] = c.b_m * 1e3;
  d["A_per_mm"] = c.A_per_m * 1e-3;
  d["B_per_mm"] = c.B_per_m * 1e-3;
  d["pmax_MPa"] = c.p_max_Pa / 1e6;
  d["area_mm2"] = c.area_m2 * 1e6;
  d["approach_mm"] = c.approach_m * 1e3;
  d["dN_ddz_kN_per_mm"] = c.dN_ddz_N_per_m / 1e6;
  d["plastic"] = (c.flags & MHC_CONTACT_PLASTIC) != 0;
  d["hertz_valid"] = (c.flags & MHC_CONTACT_NON_HERTZIAN) == 0;
  d["off_profile"] = (c.flags & MHC_CONTACT_OFF_PROFILE) != 0;
  return d;
}

/// A number option of Pair: a Python int or float (not a bool, a str, None), else a TypeError
/// naming the option and the type expected (not pybind11's "Unable to cast").
double option_number(const std::string& key, const py::handle& v) {
  if ((py::isinstance<py::float_>(v) || py::isinstance<py::int_>(v)) && !py::isinstance<py::bool_>(v))
    return v.cast<double>();
  if (PyObject_HasAttrString(v.ptr(), "__float__") && !py::isinstance<py::bool_>(v) && !py::isinstance<py::str>(v))
    return py::float_(py::reinterpret_borrow<py::object>(v)).cast<double>();  // numpy scalars
  throw py::type_error("Pair option " + key + " = " + std::string(py::repr(v)) + ": expected a number (int or float, SI "
                       "units as its suffix says), got " + std::string(py::str(py::type::of(v).attr("__name__"))));
}

/// A text option of Pair (method, positioning): a str, else a TypeError naming the option.
std::string option_text(const std::string& key, const py::handle& v, const char* choices) {
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  throw py::type_error("Pair option " + key + " = " + std::string(py::repr(v)) + ": expected a str (" + choices +
                       "), got " + std::string(py::str(py::type::of(v).attr("__name__"))));
}

const char* method_name(int32_t m) {
  static const char* names[] = {"multi-hertzian", "half-space", "strips", "auto"};
  return m >= 0 && m <= 3 ? names[m] : "?";
}

/// The warnings of the last case solved with `ws`, as data and text (mhc_result_warning,
/// mhc_warning_text): read without the GIL, turned into dicts with it.
struct CaseWarning {
  mhc_warning w;
  std::string text;
};
std::vector<CaseWarning> case_warnings(const mhc_workspace* ws) {
  std::vector<CaseWarning> v(static_cast<std::size_t>(mhc_result_n_warnings(ws)));
  for (std::size_t k = 0; k < v.size(); ++k) {
    v[k].w.struct_size = sizeof(mhc_warning);
    mhc_result_warning(ws, static_cast<int32_t>(k), &v[k].w);
    v[k].text = mhc_warning_text(ws, static_cast<int32_t>(k));
  }
  return v;
}

/// One warning as a dict: class, outside_validity, contact_kind ("case", "ellipse", "patch",
/// "ellipses"), contact, contact2, measures (name, value_si, limit_si, relation, unit), text.
py::list warnings_list(const std::vector<CaseWarning>& ws) {
  static const char* kinds[] = {"case", "ellipse", "patch", "ellipses"};
  py::list out;
  for (const CaseWarning& c : ws) {
    py::dict d;
    d["class"] = c.w.class_name ? c.w.class_name : "";
    d["outside_validity"] = c.w.outside_validity != 0;
    d["contact_kind"] = c.w.contact_kind >= 0 && c.w.contact_kind <= 3 ? kinds[c.w.contact_kind] : "?";
    d["contact"] = c.w.contact;
    d["contact2"] = c.w.contact2;
    py::list ms;
    for (int k = 0; k < c.w.n_measures && k < MHC_WARNING_MAX_MEASURES; ++k) {
      const mhc_warning_measure& m = c.w.measure[k];
      py::dict md;
      md["name"] = m.name;
      md["value_si"] = m.value_si;
      md["limit_si"] = m.limit_si;
      md["relation"] = m.relation ? std::string(1, static_cast<char>(m.relation)) : std::string();
      md["unit"] = m.unit;
      ms.append(md);
    }
    d["measures"] = ms;
    d["text"] = c.text;
    out.append(d);
  }
  return out;
}

py::dict result_dict(const mhc_result& r) {
  py::dict d;
  d["tY_mm"] = r.tY_m * 1e3;
  d["Q_kN"] = r.Q_N / 1e3;
  d["status"] = mhc_status_name(r.status);
  d["method"] = method_name(r.method);
  d["dz_virtual_mm"] = r.dz_m * 1e3;
  d["approach_mm"] = r.approach_m * 1e3;
  d["iterations"] = r.iterations;
  d["residual"] = r.residual;
  d["n_contacts"] = r.n_contacts;
  d["Fz_kN"] = r.Fz_N / 1e3;
  d["Fy_kN"] = r.Fy_N / 1e3;
  d["Y_over_Q"] = r.Fz_N > 0 ? r.Fy_N / r.Fz_N : NAN;  // the Nadal ratio (cases.csv Y_over_Q)
  d["pmax_MPa"] = r.p_max_Pa / 1e6;
  d["area_mm2"] = r.area_m2 * 1e6;
  d["gamma_main_deg"] = r.gamma_main_rad / deg;
  d["r_roll_main_mm"] = r.r_roll_main_m * 1e3;
  d["plastic"] = r.plastic;
  d["n_warnings"] = r.n_warnings;
  d["dFz_ddz_kN_per_mm"] = r.dFz_ddz_N_per_m / 1e6;
  d["message"] = r.status == MHC_STATUS_OK ? std::string() : std::string(mhc_last_message());
  py::list cs;
  for (int k = 0; k < std::min<int>(r.n_contacts, MHC_MAX_CONTACTS); ++k) cs.append(contact_dict(r.contact[k]));
  d["contacts"] = cs;
  return d;
}

/// The creep forces of the case just solved with ws (friction given: mhc_result_tangential) into
/// its dict and its contacts' dicts, named as the tangential columns of cases.csv and
/// ellipses.csv / patches.csv (docs/tangential.md; a contact's Fy_kN there is Fs_kN here, the
/// contact dict's Fy_kN being N sin(gamma)); Y_over_Q then includes them, as in cases.csv.
void add_tangential(const mhc_workspace* ws, const mhc_result& r, py::dict& d) {
  mhc_tangential t;
  t.struct_size = sizeof t;
  if (mhc_result_tangential(ws, &t) != MHC_OK || !t.asked) return;
  d["Fx_kN"] = t.Fx_N / 1e3;
  d["Fy_creep_kN"] = t.Fy_creep_N / 1e3;
  d["Mz_Nm"] = t.Mz_Nm;
  d["F_over_muN"] = t.F_over_muN;
  d["Y_kN"] = t.Y_N / 1e3;
  d["Fz_creep_kN"] = t.Fz_creep_N / 1e3;
  if (t.solved) d["Y_over_Q"] = r.Fz_N > 0 ? t.Y_N / r.Fz_N : NAN;
  py::list cs = d["contacts"];
  for (int k = 0; k < t.n_contacts && k < static_cast<int>(cs.size()); ++k) {
    py::dict c = cs[static_cast<std::size_t>(k)];
    const mhc_contact_tangential& x = t.contact[k];
    c["xi"] = x.xi;
    c["eta"] = x.eta;
    c["phi_per_mm"] = x.phi_per_m / 1e3;
    c["Fx_kN"] = x.Fx_N / 1e3;
    c["Fs_kN"] = x.Fy_N / 1e3;  // ellipses.csv's tangential Fy_kN (this dict's Fy_kN is N sin(gamma))
    c["Mz_Nm"] = x.Mz_Nm;
    c["adhesion_fraction"] = x.adhesion_fraction;
    c["Tgamma_N"] = x.Tgamma_N;
    c["Tgamma_spin_N"] = x.Tgamma_spin_N;
  }
}

/// The tangential columns of solve_many (cases.csv's, after the others), with friction only.
const char* kTangentialCols[] = {"Fx_kN", "Fy_creep_kN", "Mz_Nm", "F_over_muN", "Y_kN", "Fz_creep_kN"};
constexpr int kNTangential = sizeof kTangentialCols / sizeof kTangentialCols[0];

/// When the case's creep forces were solved, its Y_over_Q is that of cases.csv: Y (with them) / Fz.
void fill_tangential_columns(const mhc_workspace* ws, const mhc_result& r, std::size_t i, double* const* f, double* y_over_q) {
  mhc_tangential t;
  t.struct_size = sizeof t;
  if (mhc_result_tangential(ws, &t) != MHC_OK) return;
  const double v[kNTangential] = {t.Fx_N / 1e3, t.Fy_creep_N / 1e3, t.Mz_Nm, t.F_over_muN, t.Y_N / 1e3, t.Fz_creep_N / 1e3};
  for (int c = 0; c < kNTangential; ++c) f[c][i] = v[c];
  if (t.solved) y_over_q[i] = r.Fz_N > 0 ? t.Y_N / r.Fz_N : NAN;
}

/// The smoothing's uncertainty band of the case just solved with ws (mhc_result_smoothing_band),
/// in the units of cases.csv's band columns (NaN where not computed).
const char* kBandCols[] = {"pmax_half_L_MPa", "pmax_double_L_MPa", "area_half_L_mm2", "area_double_L_mm2"};
constexpr int kNBand = sizeof kBandCols / sizeof kBandCols[0];
struct SmoothingBand {
  double v[kNBand];
};
SmoothingBand smoothing_band(const mhc_workspace* ws) {
  mhc_smoothing_band b;
  b.struct_size = sizeof b;
  SmoothingBand out{{NAN, NAN, NAN, NAN}};
  if (mhc_result_smoothing_band(ws, &b) == MHC_OK)
    out = {{b.p_max_half_L_Pa / 1e6, b.p_max_double_L_Pa / 1e6, b.area_half_L_m2 * 1e6, b.area_double_L_m2 * 1e6}};
  return out;
}

/// The float columns of solve_many, in the order of cases.csv, then the stiffness.
const char* kFloatCols[] = {"tY_mm",    "Q_kN",     "dz_virtual_mm", "approach_mm",    "iterations",
                            "residual", "Fz_kN",    "Fy_kN",         "Y_over_Q",       "pmax_MPa",       "area_mm2",
                            "gamma_main_deg", "r_roll_main_mm", "dFz_ddz_kN_per_mm"};
constexpr int kNFloat = sizeof kFloatCols / sizeof kFloatCols[0];

void fill_columns(const mhc_result& r, std::size_t i, double* const* f, int8_t* status, int8_t* method,
                  int32_t* n_contacts, int8_t* plastic, int32_t* n_warnings) {
  const bool failed = r.status == MHC_STATUS_NO_CONTACT || r.status == MHC_STATUS_OUT_OF_RANGE;
  const double v[kNFloat] = {r.tY_m * 1e3,       r.Q_N / 1e3,     r.dz_m * 1e3,
                             r.approach_m * 1e3, failed ? NAN : static_cast<double>(r.iterations),
                             r.residual,         r.Fz_N / 1e3,    r.Fy_N / 1e3,
                             r.Fz_N > 0 ? r.Fy_N / r.Fz_N : NAN,
                             r.p_max_Pa / 1e6,   r.area_m2 * 1e6, r.gamma_main_rad / deg,
                             r.r_roll_main_m * 1e3, r.dFz_ddz_N_per_m / 1e6};
  for (int c = 0; c < kNFloat; ++c) f[c][i] = v[c];
  status[i] = static_cast<int8_t>(r.status);
  method[i] = static_cast<int8_t>(r.method);
  n_contacts[i] = r.n_contacts;
  plastic[i] = static_cast<int8_t>(failed ? -1 : r.plastic);
  n_warnings[i] = r.n_warnings;
}

constexpr const char* kInclinationChoice =
    "\"as-is\" (the rail profile is already laid as used) or \"1:N\" (cant the rail 1:N, e.g. \"1:40\")";

/// The rail's inclination as the case file spells it ("as-is", "1:N"), into mhc_pair_options'
/// N (0: as-is). A bare number is refused: 40 and 0 read as a cant or as none depending on who
/// wrote them, and the case file asks for the word.
double rail_inclination_of(const py::handle& v) {
  if (!py::isinstance<py::str>(v)) {
    const std::string shown = py::str(py::repr(v));
    throw py::value_error("rail_inclination = " + shown + ": give " + kInclinationChoice +
                          " as a string, as the case file's rail.inclination");
  }
  const std::string s = py::str(v);
  if (s == "as-is") return 0;
  if (s.size() > 2 && s.compare(0, 2, "1:") == 0) {
    char* end = nullptr;
    const double N = std::strtod(s.c_str() + 2, &end);
    if (end && *end == '\0' && std::isfinite(N) && N >= 5) return N;
  }
  throw py::value_error("rail_inclination = \"" + s + "\": must be " + kInclinationChoice + ", N >= 5");
}

}  // namespace

void add_tables(py::module_& m, void (*raise)(mhc_error));  // python/tables_module.cpp

PYBIND11_MODULE(_core, m) {
  m.doc() = "mhcontact: wheel-rail normal contact (multi-Hertzian, half-space, strips); docs/python.md";
  g_input_error = py::reinterpret_borrow<py::object>(
      PyErr_NewException("mhcontact.InputError", PyExc_ValueError, nullptr));
  g_unsupported_error = py::reinterpret_borrow<py::object>(
      PyErr_NewException("mhcontact.UnsupportedError", PyExc_NotImplementedError, nullptr));
  m.attr("InputError") = g_input_error;
  m.attr("UnsupportedError") = g_unsupported_error;
  bind_fleet(m, g_input_error);
  m.attr("__version__") = mhc_version();
  m.attr("abi_version") = mhc_abi_version();
  m.attr("fft_backend") = mhc_fft_backend();
  m.attr("STATUS_NAMES") = py::make_tuple("ok", "no_contact", "out_of_range", "not_converged", "outside_validity", "derailed");
  m.attr("METHOD_NAMES") = py::make_tuple("multi-hertzian", "half-space", "strips", "auto");
  add_tables(m, [](mhc_error e) { raise(e); });

  py::class_<Profile>(m, "Profile", "A wheel or rail profile (immutable).")
      .def_static("read", [](const std::string& path, const std::string& kind) {
            auto p = std::make_unique<Profile>();
            check(mhc_profile_read(path.c_str(), kind_of(kind), &p->p));
            return p;
          }, py::arg("path"), py::arg("kind"), "Read a profile file in any format the command reads.")
      .def_static("standard", [](const std::string& name) {
            auto p = std::make_unique<Profile>();
            check(mhc_profile_standard(name.c_str(), &p->p));
            return p;
          }, py::arg("name"), "\"S1002\", \"60E1\" or \"54E1\".")
      .def_static("from_points", [](py::array_t<double, py::array::c_style | py::array::forcecast> y_m,
                                    py::array_t<double, py::array::c_style | py::array::forcecast> z_m,
                                    const std::string& kind) {
            if (y_m.ndim() != 1 || z_m.ndim() != 1 || y_m.size() != z_m.size())
              throw py::value_error("y_m and z_m must be 1-D arrays of the same length");
            auto p = std::make_unique<Profile>();
            check(mhc_profile_from_points(y_m.data(), z_m.data(), static_cast<size_t>(y_m.size()), kind_of(kind), &p->p));
            return p;
          }, py::arg("y_m"), py::arg("z_m"), py::arg("kind"), "A profile from points [m] in the canonical frame.")
      .def("points", [](const Profile& p) {
            size_t n = 0;
            check(mhc_profile_points(p.p, &n, nullptr, nullptr, 0));
            py::array_t<double> y(n), z(n);
            check(mhc_profile_points(p.p, &n, y.mutable_data(), z.mutable_data(), n));
            return py::make_tuple(y, z);
          }, "(y_m, z_m) as used, after the clean-up.");

  py::class_<Pair>(m, "Pair", "A wheel-rail pair: geometry tables, material, model, method (immutable).")
      // The C handle, for the Wheelset class of its own source (python/wheelset_module.cpp).
      .def("_capsule", [](const Pair& p) { return py::capsule(static_cast<const void*>(p.p)); })
      .def(py::init([](const Profile& wheel, const Profile& rail, py::dict kw) {
             mhc_pair_options o;
             mhc_pair_options_init(&o);
             bool have_inclination = false;
             int band = -1;  // smoothing_band: -1 the default (on), else 0 / 1
             for (auto item : kw) {
               const std::string k = py::str(item.first);
               if (k == "smoothing_band") {
                 if (!py::isinstance<py::bool_>(item.second))
                   throw py::type_error("Pair option smoothing_band = " + std::string(py::repr(item.second)) +
                                        ": expected a bool, got " +
                                        std::string(py::str(py::type::of(item.second).attr("__name__"))));
                 band = item.second.cast<bool>() ? 1 : 0;
                 continue;
               }
               if (k == "rail_inclination") {
                 o.rail_inclination = rail_inclination_of(item.second);
                 have_inclination = true;
                 continue;
               }
               if (k == "method") {
                 const std::string v = option_text(k, item.second, "multi-hertzian, half-space, strips or auto");
                 int mth = -1;
                 for (int i = 0; i < 4; ++i)
                   if (v == method_name(i)) mth = i;
                 if (mth < 0) throw py::value_error("method = \"" + v + "\": must be multi-hertzian, half-space, strips or auto");
                 o.method = mth;
                 continue;
               }
               if (k == "positioning") {
                 const std::string v = option_text(k, item.second, "\"gauge\" or \"explicit\"");
                 if (v == "gauge") o.positioning = MHC_POSITIONING_GAUGE;
                 else if (v == "explicit") o.positioning = MHC_POSITIONING_EXPLICIT;
                 else throw py::value_error("positioning = \"" + v + "\": must be \"gauge\" (default) or \"explicit\"");
                 continue;
               }
               const double v = option_number(k, item.second);
               if (k == "gauge_m") o.gauge_m = v;
               else if (k == "gauge_height_m") o.gauge_height_m = v;
               else if (k == "flange_back_distance_m") o.flange_back_distance_m = v;
               else if (k == "flange_back_position_m") o.flange_back_position_m = v;
               else if (k == "nominal_radius_m") o.nominal_radius_m = v;
               else if (k == "rail_inclination") o.rail_inclination = v;
               else if (k == "E_wheel_Pa") o.E_wheel_Pa = v;
               else if (k == "nu_wheel") o.nu_wheel = v;
               else if (k == "E_rail_Pa") o.E_rail_Pa = v;
               else if (k == "nu_rail") o.nu_rail = v;
               else if (k == "p_lim_Pa") o.p_lim_Pa = v;
               else if (k == "yield_wheel_Pa") o.yield_wheel_Pa = v;
               else if (k == "yield_rail_Pa") o.yield_rail_Pa = v;
               else if (k == "tY_min_m") o.tY_min_m = v;
               else if (k == "tY_max_m") o.tY_max_m = v;
               else if (k == "tY_step_m") o.tY_step_m = v;
               else if (k == "grid_dx_m") o.grid_dx_m = v;
               else if (k == "grid_ds_m") o.grid_ds_m = v;
               else if (k == "lateral_offset_m") o.lateral_offset_m = v;
               else throw py::type_error("Pair: unknown option " + k + " (the fields of mhc_pair_options, docs/c-api.md)");
             }
             if (!have_inclination)
               throw py::value_error(std::string("rail_inclination: required: ") + kInclinationChoice +
                                     " (the same choice as the case file's rail.inclination)");
             auto p = std::make_unique<Pair>();
             {
               py::gil_scoped_release nogil;
               mhc_error e = mhc_pair_create(wheel.p, rail.p, &o, &p->p);
               if (e == MHC_OK && band >= 0) e = mhc_pair_set_smoothing_band(p->p, band);
               if (e != MHC_OK) {
                 py::gil_scoped_acquire gil;
                 raise(e);
               }
             }
             return p;
           }), py::arg("wheel"), py::arg("rail"), py::arg("options") = py::dict(),
           "Pair(wheel, rail, options={}): options are fields of mhc_pair_options, SI (docs/python.md):\n"
           "gauge_m, gauge_height_m, flange_back_distance_m, flange_back_position_m, nominal_radius_m,\n"
           "rail_inclination (required: \"as-is\" or \"1:N\", as a case file), E_wheel_Pa, nu_wheel, E_rail_Pa, nu_rail, p_lim_Pa, yield_wheel_Pa,\n"
           "yield_rail_Pa, method (a name), tY_min_m, tY_max_m, tY_step_m, grid_dx_m, grid_ds_m,\n"
           "positioning (\"gauge\" or \"explicit\"), lateral_offset_m (explicit: the rail y of the wheel's\n"
           "taping line at t_Y = 0), smoothing_band (bool, default True: the smoothing's uncertainty band\n"
           "of a grid method on a measured profile, as a case file's geometry.smoothing_band).\n"
           "Values outside the case file's plausible ranges raise ValueError.\n"
           "yield_wheel_Pa (and yield_rail_Pa when the rail's differs), as a case file's\n"
           "material.yield_MPa: the plastic model with the yield law of docs/method.md 5.1 (grid\n"
           "methods: p_lim = 2.1 sigma_y); p_lim_Pa, when given, takes precedence (the capped law).")
      .def_static("from_case_file", [](const std::string& path) {
            auto p = std::make_unique<Pair>();
            check(mhc_pair_from_case_file(path.c_str(), &p->p));
            return p;
          }, py::arg("path"), "The pair of a case file, exactly as `mhcontact run` builds it.")
      .def_property_readonly("tY_range_m", [](const Pair& p) {
            double lo = 0, hi = 0;
            check(mhc_pair_tY_range(p.p, &lo, &hi));
            return py::make_tuple(lo, hi);
          })
      .def_property_readonly("n_ellipses", [](const Pair& p) { return mhc_pair_n_ellipses(p.p); })
      .def_property_readonly("warnings", [](const Pair& p) {
            py::list l;
            for (int32_t i = 0; i < mhc_pair_n_warnings(p.p); ++i) l.append(mhc_pair_warning(p.p, i));
            return l;
          }, "The pair's warnings, as the command prints them (mhc_pair_warning): profiles, rail cant, placement.")
      .def("set_smoothing_band", [](Pair& p, bool on) {
            py::gil_scoped_release nogil;
            const mhc_error e = mhc_pair_set_smoothing_band(p.p, on ? 1 : 0);
            if (e != MHC_OK) {
              py::gil_scoped_acquire gil;
              raise(e);
            }
          }, py::arg("on"),
          "set_smoothing_band(on): whether later solves compute the smoothing's uncertainty band\n"
          "(pmax_half_L_MPa ...; mhc_pair_set_smoothing_band). Not while another thread solves with the pair.")
      .def("set_tangential", [](Pair& p, const py::dict& options) {
            mhc_tangential_options o;
            mhc_tangential_options_init(&o);
            for (const auto& item : options) {
              const std::string k = py::str(item.first);
              if (k == "vertical_equilibrium") {
                o.vertical_equilibrium = item.second.cast<bool>() ? 1 : 0;
                continue;
              }
              const double v = option_number(k, item.second);
              if (k == "mu") o.mu = v;
              else if (k == "speed_m_s") o.speed_m_s = v;
              else if (k == "yaw_rad") o.yaw_rad = v;
              else if (k == "yaw_rad_per_m") o.yaw_rad_per_m = v;
              else if (k == "lateral_velocity_m_s") o.lateral_velocity_m_s = v;
              else if (k == "yaw_rate_rad_s") o.yaw_rate_rad_s = v;
              else if (k == "pitch_rate_rad_s") o.pitch_rate_rad_s = v;
              else if (k == "xi" || k == "eta" || k == "phi_per_m") {
                o.creepages_given = 1;
                (k == "xi" ? o.xi : k == "eta" ? o.eta : o.phi_per_m) = v;
              } else {
                throw py::type_error("set_tangential: unknown option " + k +
                                     " (the fields of mhc_tangential_options, docs/python.md)");
              }
            }
            check(mhc_pair_set_tangential(p.p, &o));
          }, py::arg("options"),
          "set_tangential({'mu': 0.3, 'speed_m_s': 30, 'yaw_rad': 2e-3, ...}) or with creepages\n"
          "{'mu': 0.3, 'xi': ..., 'eta': ..., 'phi_per_m': ...}: the tangential problem of every later\n"
          "solve (docs/tangential.md; fields of mhc_tangential_options, SI). Not while another thread\n"
          "solves with the pair.")
      .def("_solve", [](const Pair& p, double tY_m, double value, bool approach, double roll_rad) {
            mhc_workspace* ws = nullptr;
            check(mhc_workspace_create(p.p, &ws));
            mhc_result r;
            r.struct_size = sizeof r;
            const mhc_error e = approach ? mhc_solve_approach(p.p, ws, tY_m, roll_rad, value, &r)
                                         : mhc_solve_load(p.p, ws, tY_m, roll_rad, value, &r);
            const std::vector<CaseWarning> w = e == MHC_OK ? case_warnings(ws) : std::vector<CaseWarning>();
            if (e != MHC_OK) mhc_workspace_free(ws);
            check(e);
            py::dict d = result_dict(r);
            d["warnings"] = warnings_list(w);
            add_tangential(ws, r, d);
            const SmoothingBand b = smoothing_band(ws);
            for (int c = 0; c < kNBand; ++c) d[kBandCols[c]] = b.v[c];
            mhc_workspace_free(ws);
            return d;
          })
      .def("_solve_many", [](const Pair& p, py::array_t<double, py::array::c_style | py::array::forcecast> tY_m,
                             py::array_t<double, py::array::c_style | py::array::forcecast> value, bool approach,
                             int threads) {
            const std::size_t n = static_cast<std::size_t>(tY_m.size());
            if (static_cast<std::size_t>(value.size()) != n) throw py::value_error("tY and Q (or dz) differ in length");
            std::vector<py::array_t<double>> fcols;
            std::vector<double*> f;
            for (int c = 0; c < kNFloat; ++c) {
              fcols.emplace_back(n);
              f.push_back(fcols.back().mutable_data());
            }
            py::array_t<int8_t> status(n), method(n), plastic(n);
            py::array_t<int32_t> n_contacts(n), n_warnings(n);
            int8_t* st = status.mutable_data();
            int8_t* me = method.mutable_data();
            int8_t* pl = plastic.mutable_data();
            int32_t* nc = n_contacts.mutable_data();
            int32_t* nw = n_warnings.mutable_data();
            const double* t = tY_m.data();
            const double* v = value.data();
            std::vector<std::vector<CaseWarning>> warns(n);
            // With friction, the tangential columns of cases.csv (NaN where not solved).
            const bool tangential = mh::capi::pair_has_friction(*p.p);
            std::vector<py::array_t<double>> tcols;
            std::vector<double*> tf;
            for (int c = 0; tangential && c < kNTangential; ++c) {
              tcols.emplace_back(n);
              tf.push_back(tcols.back().mutable_data());
            }
            std::vector<py::array_t<double>> bcols;
            std::vector<double*> bf;
            for (int c = 0; c < kNBand; ++c) {
              bcols.emplace_back(n);
              bf.push_back(bcols.back().mutable_data());
            }
            double* yq = f[8];  // Y_over_Q
            mhc_error e;
            {
              py::gil_scoped_release nogil;  // the solve runs without the GIL
              e = mh::capi::for_each_case(*p.p, n, threads, [&](std::size_t i, mhc_workspace& ws) {
                mhc_result r;
                r.struct_size = sizeof r;
                const mhc_error c = mh::capi::solve_case(*p.p, ws, approach, t[i], 0.0, v[i], &r);
                if (c == MHC_OK) {
                  fill_columns(r, i, f.data(), st, me, nc, pl, nw);
                  warns[i] = case_warnings(&ws);
                  if (tangential) fill_tangential_columns(&ws, r, i, tf.data(), yq);
                }
                const SmoothingBand b = c == MHC_OK ? smoothing_band(&ws) : SmoothingBand{{NAN, NAN, NAN, NAN}};
                for (int k = 0; k < kNBand; ++k) bf[static_cast<std::size_t>(k)][i] = b.v[k];
                return c;
              });
            }
            check(e);
            py::dict d;
            for (int c = 0; c < kNFloat; ++c) d[kFloatCols[c]] = fcols[static_cast<std::size_t>(c)];
            for (int c = 0; tangential && c < kNTangential; ++c) d[kTangentialCols[c]] = tcols[static_cast<std::size_t>(c)];
            for (int c = 0; c < kNBand; ++c) d[kBandCols[c]] = bcols[static_cast<std::size_t>(c)];
            d["status_code"] = status;
            d["method_code"] = method;
            d["n_contacts"] = n_contacts;
            d["plastic"] = plastic;
            d["n_warnings"] = n_warnings;
            py::list wl;
            for (const auto& w : warns) wl.append(warnings_list(w));
            d["warnings"] = wl;
            return d;
          });
  bind_wheelset(m, &check);
  bind_rcf(m, &check);
  bind_grids(m, &check);
}
