// mhcontact._core's pressure and traction grids (docs/python.md "Pressure and traction grids"):
// one case solved with mhc_workspace_keep_grids and read by mhc_result_grid (include/mhcontact.h,
// its last section), returned as numpy arrays named and scaled as the columns of pressure.csv
// (docs/outputs.md: x * 1e3 for mm, p / 1e6 for MPa, the writer's conversions).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <vector>

#include <mhcontact.h>

#include "capi/handles.hpp"

namespace py = pybind11;

void bind_grids(py::module_& m, void (*check)(mhc_error));

namespace {

struct Workspace {
  mhc_workspace* ws = nullptr;
  ~Workspace() { mhc_workspace_free(ws); }
};

}  // namespace

void bind_grids(py::module_& m, void (*check)(mhc_error)) {
  m.def("_pair_pressure_grid", [check](const py::object& pair, double tY_m, double value, bool approach, double roll_rad,
                                       int n) {
        // mhcontact.Pair's handle (python/mhcontact_module.cpp, Pair._capsule).
        const py::capsule c = pair.attr("_capsule")();
        const mhc_pair* p = static_cast<const mhc_pair*>(c.get_pointer());
        Workspace w;
        check(mhc_workspace_create(p, &w.ws));
        check(mhc_workspace_keep_grids(w.ws, 1));
        mhc_result r;
        r.struct_size = sizeof r;
        mhc_grid g{};
        g.struct_size = sizeof g;
        std::vector<int32_t> contact, slip;
        std::vector<double> x, s, y_rail, pr, p_el, px, py;
        mhc_error e;
        {
          py::gil_scoped_release nogil;  // the solve runs without the GIL
          e = approach ? mhc_solve_approach(p, w.ws, tY_m, roll_rad, value, &r)
                       : mhc_solve_load(p, w.ws, tY_m, roll_rad, value, &r);
          if (e == MHC_OK) e = mhc_result_grid(w.ws, n, &g);  // the size query
          if (e == MHC_OK) {
            const std::size_t k = g.n_points;
            contact.resize(k), slip.resize(k), x.resize(k), s.resize(k), y_rail.resize(k), pr.resize(k), p_el.resize(k),
                px.resize(k), py.resize(k);
            g.capacity = k;
            g.contact = contact.data(), g.slip = slip.data(), g.x_m = x.data(), g.s_m = s.data();
            g.y_rail_m = y_rail.data(), g.p_Pa = pr.data(), g.p_elastic_Pa = p_el.data();
            g.px_Pa = px.data(), g.py_Pa = py.data();
            e = mhc_result_grid(w.ws, n, &g);
          }
        }
        check(e);
        const std::size_t k = g.n_points;
        auto scaled = [k](const std::vector<double>& v, double per_unit, bool divide) {
          py::array_t<double> a(k);
          double* d = a.mutable_data();
          for (std::size_t i = 0; i < k; ++i) d[i] = divide ? v[i] / per_unit : v[i] * per_unit;
          return a;
        };
        auto ints = [k](const std::vector<int32_t>& v) {
          py::array_t<int32_t> a(k);
          int32_t* d = a.mutable_data();
          for (std::size_t i = 0; i < k; ++i) d[i] = v[i];
          return a;
        };
        const bool ellipses = g.method == MHC_METHOD_MULTI_HERTZIAN;
        py::dict d;
        d["method"] = ellipses ? "multi-hertzian" : g.method == MHC_METHOD_HALF_SPACE ? "half-space" : "strips";
        d["status"] = mhc_status_name(r.status);
        d[ellipses ? "ellipse" : "patch"] = ints(contact);
        d["x_mm"] = scaled(x, 1e3, false);
        d[ellipses ? "y_mm" : "s_mm"] = scaled(s, 1e3, false);
        if (!ellipses) d["y_rail_mm"] = scaled(y_rail, 1e3, false);
        d["p_MPa"] = scaled(pr, 1e6, true);
        if (ellipses && p->plastic) d["p_elastic_MPa"] = scaled(p_el, 1e6, true);
        if (mh::capi::pair_has_friction(*p)) {
          d["px_MPa"] = scaled(px, 1e6, true);
          d["py_MPa"] = scaled(py, 1e6, true);
          d["slip"] = ints(slip);
        }
        return d;
      }, py::arg("pair"), py::arg("tY_m"), py::arg("value"), py::arg("approach"), py::arg("roll_rad"), py::arg("n"));
}
