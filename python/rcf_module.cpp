// mhcontact._core's RCF, damage and wear access (docs/python.md "RCF, damage and wear"): one case's
// contacts through mhc_result_rcf, and the stresses below a Hertzian ellipse through
// mhc_hertz_subsurface (include/mhcontact.h, its RCF section). Named and scaled as the columns of
// ellipses.csv / patches.csv (docs/outputs.md "RCF columns", "Damage and wear columns").
#include <pybind11/pybind11.h>

#include <cmath>
#include <vector>

#include <mhcontact.h>

namespace py = pybind11;

void bind_rcf(py::module_& m, void (*check)(mhc_error));

namespace {

const char* regime_name(int32_t r) {
  switch (r) {
    case 0: return "elastic";
    case 1: return "elastic_shakedown";
    case 2: return "plastic_shakedown";
    case 3: return "ratchetting";
  }
  return nullptr;
}

struct Workspace {
  mhc_workspace* ws = nullptr;
  ~Workspace() { mhc_workspace_free(ws); }
};

}  // namespace

void bind_rcf(py::module_& m, void (*check)(mhc_error)) {
  m.def("_pair_rcf", [check](const py::object& pair, double tY_m, double Q_N, double k_Pa) {
        // mhcontact.Pair's handle (python/mhcontact_module.cpp, Pair._capsule).
        const py::capsule c = pair.attr("_capsule")();
        const mhc_pair* p = static_cast<const mhc_pair*>(c.get_pointer());
        Workspace w;
        check(mhc_workspace_create(p, &w.ws));
        mhc_result r;
        r.struct_size = sizeof r;
        check(mhc_solve_load(p, w.ws, tY_m, 0.0, Q_N, &r));
        py::list out;
        for (int32_t i = 0; i < r.n_contacts; ++i) {
          mhc_rcf_contact x;
          x.struct_size = sizeof x;
          check(mhc_result_rcf(w.ws, i, k_Pa, &x));
          py::dict d;
          d["N_kN"] = x.N_N / 1e3;
          d["traction_actual"] = x.traction;
          d["Tgamma_N"] = x.Tgamma_N;
          d["Tgamma_spin_N"] = x.Tgamma_spin_N;
          d["D_burstow_per_axle"] = x.damage_per_axle;
          d["wear_rate_ug_per_m_mm2"] = x.wear_rate_kg_per_m3 / 1e-3;  // 1 µg/(m·mm²) = 1e-3 kg/m³
          d["wear_ug_per_m"] = x.wear_kg_per_m / 1e-9;
          d["p0_el_MPa"] = x.p0_el_Pa / 1e6;
          d["p0_el_over_k"] = x.p0_el_over_k;
          d["elastic_limit_p0_over_k"] = x.elastic_limit;
          d["shakedown_limit_p0_over_k"] = x.shakedown_limit;
          d["FI_surf_el"] = x.FI_surf_el;
          const char* reg = regime_name(x.shakedown_regime);
          d["shakedown_regime"] = reg ? py::object(py::str(reg)) : py::object(py::none());
          out.append(d);
        }
        return out;
      }, py::arg("pair"), py::arg("tY_m"), py::arg("Q_N"), py::arg("k_Pa"));
  m.def("_pair_subsurface", [check](const py::object& pair, double tY_m, double Q_N, int grid, double traction,
                                    double dang_van_c) {
        const py::capsule c = pair.attr("_capsule")();
        const mhc_pair* p = static_cast<const mhc_pair*>(c.get_pointer());
        Workspace w;
        check(mhc_workspace_create(p, &w.ws));
        check(mhc_workspace_keep_grids(w.ws, 1));  // the grid and FASTSIM loads, as the command's
        mhc_subsurface_options opt;
        mhc_subsurface_options_init(&opt);
        opt.grid = grid, opt.traction = traction, opt.dang_van_c = dang_van_c;
        mhc_result r;
        r.struct_size = sizeof r;
        std::vector<mhc_contact_subsurface> got;
        mhc_error e = MHC_OK;
        {
          py::gil_scoped_release release;  // seconds per grid patch
          e = mhc_solve_load(p, w.ws, tY_m, 0.0, Q_N, &r);
          for (int32_t i = 0; e == MHC_OK && i < r.n_contacts; ++i) {
            mhc_contact_subsurface s;
            s.struct_size = sizeof s;
            e = mhc_result_subsurface(w.ws, i, &opt, &s);
            got.push_back(s);
          }
        }
        check(e);
        static const char* const kSource[] = {nullptr, "hertz_ellipse", "grid_patch", "grid_patch_solved_traction",
                                              "hertz_ellipse_fastsim_traction"};
        py::list out;
        for (const mhc_contact_subsurface& s : got) {
          py::dict d;  // the subsurface columns' names and units (docs/outputs.md)
          const char* src = s.source >= 1 && s.source <= 4 ? kSource[s.source] : nullptr;
          d["sub_source"] = src ? py::object(py::str(src)) : py::object(py::none());
          d["sub_vm_max_MPa"] = s.vm_max_Pa / 1e6, d["sub_vm_depth_mm"] = s.vm_depth_m * 1e3;
          d["sub_tau_max_MPa"] = s.tau_max_Pa / 1e6, d["sub_tau_depth_mm"] = s.tau_depth_m * 1e3;
          d["sub_tau_orth_amp_MPa"] = s.tau_orth_amp_Pa / 1e6, d["sub_tau_orth_depth_mm"] = s.tau_orth_depth_m * 1e3;
          d["sub_tau_eq_amp_MPa"] = s.tau_eq_amp_Pa / 1e6, d["sub_sigma_h_MPa"] = s.sigma_h_Pa / 1e6;
          d["FI_sub_MPa"] = s.FI_sub_Pa / 1e6;
          py::list warn;
          if (s.warnings & MHC_SUBSURFACE_WARN_PLASTIC) warn.append("plastic");
          if (s.warnings & MHC_SUBSURFACE_WARN_GRID_NOT_KEPT) warn.append("grid_not_kept");
          if (s.warnings & MHC_SUBSURFACE_WARN_AT_SURFACE) warn.append("at_surface");
          d["warnings"] = warn;
          out.append(d);
        }
        return out;
      }, py::arg("pair"), py::arg("tY_m"), py::arg("Q_N"), py::arg("grid"), py::arg("traction"), py::arg("dang_van_c"));
  m.def("hertz_subsurface", [check](double a_m, double b_m, double p0_Pa, double fx, double fy, double nu) {
        mhc_subsurface s;
        s.struct_size = sizeof s;
        mhc_error e;
        {
          py::gil_scoped_release release;  // the search runs without the GIL
          e = mhc_hertz_subsurface(a_m, b_m, p0_Pa, fx, fy, nu, &s);
        }
        check(e);
        py::dict d;
        d["vm_max_Pa"] = s.vm_max_Pa, d["vm_depth_m"] = s.vm_depth_m;
        d["tau_max_Pa"] = s.tau_max_Pa, d["tau_depth_m"] = s.tau_depth_m;
        d["tau_orth_amp_Pa"] = s.tau_orth_amp_Pa, d["tau_orth_depth_m"] = s.tau_orth_depth_m;
        d["tau_eq_amp_Pa"] = s.tau_eq_amp_Pa, d["sigma_h_Pa"] = s.sigma_h_Pa;
        return d;
      }, py::arg("a_m"), py::arg("b_m"), py::arg("p0_Pa"), py::arg("fx") = 0.0, py::arg("fy") = 0.0,
      py::arg("nu") = 0.3,
      "The peaks of the elastic stresses below a Hertzian ellipse (semi-axes a_m along the rolling\n"
      "direction x and b_m, peak pressure p0_Pa) with full-slip traction (fx, fy) p, Poisson's ratio nu\n"
      "(docs/methods.md \"Subsurface stresses\"; SI; about 0.5 s): a dict of vm_max_Pa, vm_depth_m,\n"
      "tau_max_Pa, tau_depth_m, tau_orth_amp_Pa, tau_orth_depth_m, tau_eq_amp_Pa, sigma_h_Pa.\n"
      "FI_sub = tau_eq_amp_Pa + c sigma_h_Pa with the material's Dang Van parameter c.");
}
