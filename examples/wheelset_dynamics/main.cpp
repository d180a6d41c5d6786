// wheelset_dynamics: the three checks of the dynamics example (docs/wheelset-dynamics.md).
//   wheelset_dynamics klingel  [--amplitude-mm A] [--speed V] [--distance D] [--csv FILE] [--half-cycles FILE]
//   wheelset_dynamics critical [--perturbation-mm A] [--distance D] [--csv FILE]
//   wheelset_dynamics worn     --wheel FILE [--speed V] [--amplitude-mm A] [--distance D] [--csv FILE]
// Exit 0 when the check's figures are printed, 1 on a failed run, 2 on a bad argument or input
// file (mh::InputError: the file, the value and the rule).
#include <cstdio>
#include <cmath>
#include <cstring>
#include <exception>
#include <fstream>
#include <map>
#include <string>

#include "core/errors.hpp"
#include "experiments.hpp"

using namespace wsdyn;

namespace {

struct BadArgument : std::runtime_error {
  using std::runtime_error::runtime_error;
};

int usage(const char* why) {
  std::fprintf(stderr,
               "wheelset_dynamics: %s\n"
               "usage: wheelset_dynamics klingel  [--amplitude-mm A] [--speed V] [--distance D] [--csv FILE] [--half-cycles FILE]\n"
               "       wheelset_dynamics critical [--perturbation-mm A] [--distance D] [--csv FILE]\n"
               "       wheelset_dynamics worn     --wheel FILE [--speed V] [--amplitude-mm A] [--distance D] [--csv FILE]\n"
               "units: mm, m/s, m\n",
               why);
  return 2;
}

void write_samples(std::ofstream& f, const std::string& run, const RunResult& R) {
  for (const Sample& s : R.samples)
    f << run << ',' << s.t * R.V << ',' << s.y * 1e3 << ',' << s.psi * 1e3 << '\n';
}

void print_cost(const char* what, const RunResult& R) {
  std::printf("%s: %ld steps, %ld right-hand sides (%ld wheelset calls, 1 per side), %.3f s CPU: %.1f us per step, "
              "%.2f us per wheelset call\n",
              what, R.steps, R.rhs_evals, R.contact_calls, R.cpu_seconds, R.us_per_step(), R.us_per_call());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage("a command is required: klingel, critical or worn");
  const std::string cmd = argv[1];
  std::map<std::string, std::string> a;
  for (int i = 2; i < argc; i += 2) {
    if (std::strncmp(argv[i], "--", 2) != 0 || i + 1 >= argc)
      return usage((std::string("expected --option value, got '") + argv[i] + "'").c_str());
    a[argv[i] + 2] = argv[i + 1];
  }
  auto num = [&](const char* k, double def) {
    auto it = a.find(k);
    if (it == a.end()) return def;
    size_t pos = 0;
    double v = NAN;
    try {
      v = std::stod(it->second, &pos);
    } catch (const std::exception&) {
      pos = 0;
    }
    if (pos == 0 || pos != it->second.size() || !(v > 0))
      throw BadArgument(std::string("--") + k + " " + it->second + ": expected a positive number");
    a.erase(it);
    return v;
  };
  try {
    std::string csv = a.count("csv") ? a["csv"] : "";
    a.erase("csv");
    std::ofstream out;
    if (!csv.empty()) {
      out.open(csv);
      if (!out) return usage(("cannot write " + csv).c_str());
      out << "run,distance_m,y_mm,psi_mrad\n";
    }
    if (cmd == "klingel") {
      const double A = num("amplitude-mm", 3) * 1e-3, V = num("speed", 2), D = num("distance", 60);
      const std::string hc = a.count("half-cycles") ? a["half-cycles"] : "";
      a.erase("half-cycles");
      if (!a.empty()) return usage(("unknown option --" + a.begin()->first).c_str());
      std::ofstream hf;
      if (!hc.empty()) {
        hf.open(hc);
        if (!hf) return usage(("cannot write " + hc).c_str());
      }
      ContactAdapter c(standard_setup());
      const KlingelResult K = klingel(c, A, V, D);
      std::printf("Klingel, S1002 on 60E1 1:40, free wheelset released at %.3g mm, V = %g m/s: %s\n", A * 1e3, V,
                  K.run.status.c_str());
      std::printf("  r0 %.5f m, s %.5f m (wheelset geometry, centred); %zu half cycles:\n", K.r0, K.s,
                  K.half_cycles.size());
      std::printf("  %9s %9s %10s %10s %10s %8s\n", "s_m", "peak_mm", "tan_ge", "L_sim_m", "L_Klingel_m", "error_%");
      for (const HalfCycle& h : K.half_cycles)
        std::printf("  %9.3f %9.4f %10.5f %10.4f %10.4f %+8.2f\n", h.s0, h.peak * 1e3, h.lambda, h.L_sim,
                    h.L_klingel, 100 * h.error());
      std::printf("  mean error %+.2f %%, largest %.2f %%; linear model with creep at the mean peak %.4f mm: "
                  "%.4f m\n",
                  100 * K.mean_error(), 100 * K.max_error(), K.amplitude * 1e3, K.L_linear);
      print_cost("  cost", K.run);
      if (out.is_open()) write_samples(out, "klingel", K.run);
      if (hf.is_open()) {
        hf << "s0_m,s1_m,peak_mm,tan_gamma_e,L_sim_m,L_klingel_m,error_pct\n";
        for (const HalfCycle& h : K.half_cycles)
          hf << h.s0 << ',' << h.s1 << ',' << h.peak * 1e3 << ',' << h.lambda << ',' << h.L_sim << ',' << h.L_klingel
             << ',' << 100 * h.error() << '\n';
      }
      return K.run.status == "ok" ? 0 : 1;
    }
    if (cmd == "critical") {
      const double A = num("perturbation-mm", 0.5) * 1e-3, D = num("distance", 200);
      if (!a.empty()) return usage(("unknown option --" + a.begin()->first).c_str());
      ContactAdapter c(standard_setup(mh::Inclination::In20));
      const WheelsetBody b = suspended_body();
      const CriticalResult C = critical_speed(c, b, A, D);
      std::printf("Critical speed, S1002 on 60E1 1:20, m %g kg, I_z %g kg m2, k_y %g N/m, k_psi %g N m/rad\n", b.m,
                  b.I_z, b.k_y, b.k_psi);
      std::printf("  ellipse a %.3f mm b %.3f mm, C11 %.4f C22 %.4f C23 %.4f, G %.4g Pa nu %.3f\n", C.in.a * 1e3,
                  C.in.b * 1e3, C.in.C11, C.in.C22, C.in.C23, C.in.G, C.in.nu);
      std::printf("  tan gamma_e at %.3g mm %.5f, k_grav %.4g N/m, k_spin %.4g N/m, r0 %.5f m, l0 %.5f m\n",
                  A * 1e3, C.in.lambda, C.in.k_grav, C.in.k_spin, C.in.r0, C.in.l0);
      std::printf("  linear (eigenvalues): %.2f m/s; nonlinear (growth of %.3g mm, %d runs): %.2f m/s "
                  "(decays at %.2f, grows at %.2f); nonlinear / linear - 1 = %+.2f %%\n",
                  C.V_linear, A * 1e3, C.runs, C.V_nonlinear, C.V_lo, C.V_hi, 100 * C.error());
      if (out.is_open()) {
        for (double f : {0.95, 1.05}) {
          RunResult R;
          const double g = growth_at(c, b, A, f * C.V_linear, D, &R);
          std::printf("  at %.2f m/s (%.2f V_linear): growth %+.4f 1/m\n", f * C.V_linear, f, g);
          char name[32];
          std::snprintf(name, sizeof name, "V=%.3gVlin", f);
          write_samples(out, name, R);
        }
      }
      return 0;
    }
    if (cmd == "worn") {
      if (!a.count("wheel")) return usage("worn needs --wheel FILE");
      const std::string wheel = a["wheel"];
      a.erase("wheel");
      const double A = num("amplitude-mm", 3) * 1e-3, V = num("speed", 2), D = num("distance", 40);
      if (!a.empty()) return usage(("unknown option --" + a.begin()->first).c_str());
      const WornResult W = worn_pair(wheel, A, V, D);
      std::printf("Worn wheel %s on 60E1 1:40, free wheelset released at %.3g mm, V = %g m/s\n", wheel.c_str(), A * 1e3, V);
      for (const KlingelResult* K : {&W.elastic, &W.plastic}) {
        const bool plastic = K == &W.plastic;
        std::printf("%s: %s, %zu half cycles, mean peak %.3f mm, wavelength against Klingel: mean %+.2f %%, largest "
                    "%.2f %%; largest pressure %.0f MPa, plastic in %ld of %ld right-hand sides\n",
                    plastic ? "plastic (yield law, sigma_y 500 MPa)" : "elastic (Hertz)", K->run.status.c_str(),
                    K->half_cycles.size(), K->amplitude * 1e3, 100 * K->mean_error(), 100 * K->max_error(),
                    K->run.p_max * 1e-6, K->run.plastic_rhs, K->run.rhs_evals);
        print_cost("  cost", K->run);
        if (out.is_open()) write_samples(out, plastic ? "plastic" : "elastic", K->run);
      }
      return W.elastic.run.status == "ok" && W.plastic.run.status == "ok" ? 0 : 1;
    }
    return usage(("unknown command " + cmd).c_str());
  } catch (const BadArgument& e) {
    return usage(e.what());
  } catch (const mh::InputError& e) {
    std::fprintf(stderr, "wheelset_dynamics: %s\n", e.what());
    return mh::kExitInputError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "wheelset_dynamics: %s\n", e.what());
    return 1;
  }
}
