#include "wheelset_model.hpp"

#include <algorithm>
#include <ctime>
#include <cmath>
#include <stdexcept>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

namespace wsdyn {

double RunResult::wavelength(std::size_t skip) const {
  if (zero_times.size() < skip + 2) return NAN;
  const double t0 = zero_times[skip], t1 = zero_times.back();
  const double half_periods = static_cast<double>(zero_times.size() - 1 - skip);
  return V * 2 * (t1 - t0) / half_periods;
}

double RunResult::mean_amplitude(std::size_t skip) const {
  if (peak_values.size() <= skip) return NAN;
  double s = 0;
  for (std::size_t i = skip; i < peak_values.size(); ++i) s += std::abs(peak_values[i]);
  return s / static_cast<double>(peak_values.size() - skip);
}

double RunResult::growth_per_metre(std::size_t skip) const {
  if (peak_values.size() < skip + 2) return NAN;
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
  for (std::size_t i = skip; i < peak_values.size(); ++i) {
    const double x = V * peak_times[i], y = std::log(std::abs(peak_values[i]));
    sx += x; sy += y; sxx += x * x; sxy += x * y; n += 1;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

double centred_rolling_radius(ContactAdapter& contact) {
  WheelsetMotion m;
  m.V = 1;
  m.Omega = 1 / contact.setup().track.nominal_radius;
  const WheelsetForces f = contact.evaluate(m);
  if (!f.right.ok) throw std::runtime_error("the centred wheelset has no contact answer");
  return f.right.r;
}

namespace {

struct Ode {
  ContactAdapter* contact;
  WheelsetBody body;
  double V;
  bool failed = false;
  double p_max = 0;
  long plastic_rhs = 0;
};

WheelsetMotion motion_of(const Ode& o, const sunrealtype* x) {
  WheelsetMotion m;
  m.y = x[0];
  m.y_dot = x[1];
  m.psi = x[2];
  m.psi_dot = x[3];
  m.V = o.V;
  m.Omega = x[4];
  return m;
}

int rhs(sunrealtype, N_Vector X, N_Vector Xdot, void* user) {
  Ode& o = *static_cast<Ode*>(user);
  const sunrealtype* x = N_VGetArrayPointer(X);
  sunrealtype* d = N_VGetArrayPointer(Xdot);
  const WheelsetForces f = o.contact->evaluate(motion_of(o, x));
  if (!f.ok()) {
    o.failed = true;
    return -1;  // unrecoverable: CVODE stops with CV_RHSFUNC_FAIL
  }
  o.p_max = std::max({o.p_max, f.left.p_max, f.right.p_max});
  if (f.left.plastic || f.right.plastic) ++o.plastic_rhs;
  d[0] = x[1];
  d[1] = (f.F_Y - o.body.k_y * x[0]) / o.body.m;
  d[2] = x[3];
  d[3] = (f.M_Z - o.body.k_psi * x[2]) / o.body.I_z;
  d[4] = f.M_axle / o.body.I_y;
  return 0;
}

// Root functions: y (zero crossings) and ẏ (extremes).
int roots(sunrealtype, N_Vector X, sunrealtype* g, void*) {
  const sunrealtype* x = N_VGetArrayPointer(X);
  g[0] = x[0];
  g[1] = x[1];
  return 0;
}

void check(int flag, const char* what) {
  if (flag < 0) throw std::runtime_error(std::string(what) + " failed: " + CVodeGetReturnFlagName(flag));
}

}  // namespace

RunResult simulate(ContactAdapter& contact, const WheelsetBody& body, const RunOptions& opt) {
  RunResult R;
  R.V = opt.V;
  R.r_c = centred_rolling_radius(contact);
  R.Omega = opt.V / R.r_c;
  Ode o{&contact, body, opt.V};
  const long calls0 = contact.calls();

  SUNContext ctx = nullptr;
  if (SUNContext_Create(nullptr, &ctx) != 0) throw std::runtime_error("SUNContext_Create failed");
  N_Vector X = N_VNew_Serial(5, ctx);
  N_Vector atol = N_VNew_Serial(5, ctx);
  sunrealtype* x = N_VGetArrayPointer(X);
  x[0] = opt.y0;
  x[1] = x[2] = x[3] = 0;
  x[4] = R.Omega;
  sunrealtype* at = N_VGetArrayPointer(atol);
  at[0] = opt.atol_y;               // y [m]
  at[1] = opt.atol_y * opt.V;       // ẏ [m/s]: y's tolerance over 1 m run
  at[2] = opt.atol_y;               // ψ [rad]: y's over 1 m
  at[3] = opt.atol_y * opt.V;       // ψ̇
  at[4] = opt.atol_y * R.Omega / R.r_c;  // Ω: the slip of y's tolerance at the rolling radius
  void* mem = CVodeCreate(CV_BDF, ctx);
  SUNMatrix A = SUNDenseMatrix(5, 5, ctx);
  SUNLinearSolver LS = SUNLinSol_Dense(X, A, ctx);
  try {
    check(CVodeInit(mem, rhs, 0.0, X), "CVodeInit");
    check(CVodeSVtolerances(mem, opt.rtol, atol), "CVodeSVtolerances");
    check(CVodeSetUserData(mem, &o), "CVodeSetUserData");
    check(CVodeSetLinearSolver(mem, LS, A), "CVodeSetLinearSolver");
    check(CVodeSetMaxNumSteps(mem, opt.max_steps), "CVodeSetMaxNumSteps");
    check(CVodeRootInit(mem, 2, roots), "CVodeRootInit");
    // No root at the start: ẏ = 0 there by construction.
    check(CVodeSetNoInactiveRootWarn(mem), "CVodeSetNoInactiveRootWarn");

    const double t_end = opt.distance / opt.V;
    const double dt_sample = opt.sample_distance > 0 ? opt.sample_distance / opt.V : t_end;
    double t = 0, t_next = std::min(dt_sample, t_end);
    auto store = [&](double tt) {
      if (opt.sample_distance > 0)
        R.samples.push_back({tt, x[0], x[2], x[1], x[3], x[4]});
    };
    store(0);
    // The process's CPU time (one thread): on a shared machine the wall time measures the load.
    const std::clock_t c0 = std::clock();
    while (t < t_end) {
      sunrealtype tr = 0;
      const int flag = CVode(mem, t_next, X, &tr, CV_NORMAL);
      t = tr;
      if (flag == CV_ROOT_RETURN) {
        int found[2] = {0, 0};
        CVodeGetRootInfo(mem, found);
        if (found[0]) R.zero_times.push_back(t);
        if (found[1]) {
          R.peak_times.push_back(t);
          R.peak_values.push_back(x[0]);
        }
        if (std::abs(x[0]) > opt.y_stop) { R.status = "y_stop"; break; }
        continue;
      }
      if (flag < 0) {
        R.status = o.failed ? "contact_failed" : std::string("cvode: ") + CVodeGetReturnFlagName(flag);
        break;
      }
      store(t);
      if (std::abs(x[0]) > opt.y_stop) { R.status = "y_stop"; break; }
      t_next = std::min(t + dt_sample, t_end);
    }
    R.cpu_seconds = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    long v = 0;
    CVodeGetNumSteps(mem, &v);
    R.steps = v;
    CVodeGetNumRhsEvals(mem, &v);
    R.rhs_evals = v;
    CVodeGetNumLinRhsEvals(mem, &v);  // the difference-quotient Jacobian's evaluations
    R.rhs_evals += v;
    CVodeGetNumJacEvals(mem, &v);
    R.jac_evals = v;
  } catch (...) {
    CVodeFree(&mem);
    SUNLinSolFree(LS);
    SUNMatDestroy(A);
    N_VDestroy(atol);
    N_VDestroy(X);
    SUNContext_Free(&ctx);
    throw;
  }
  R.contact_calls = contact.calls() - calls0;
  R.p_max = o.p_max;
  R.plastic_rhs = o.plastic_rhs;
  CVodeFree(&mem);
  SUNLinSolFree(LS);
  SUNMatDestroy(A);
  N_VDestroy(atol);
  N_VDestroy(X);
  SUNContext_Free(&ctx);
  return R;
}

}  // namespace wsdyn
