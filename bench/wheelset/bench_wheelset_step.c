/* mhcontact_bench_wheelset_step: the cost of one wheelset step through the C interface
 * (mhc_wheelset_step: both wheels, multi-Hertzian normal contact and FASTSIM creep forces), the
 * figure of docs/performance.md "The wheelset call" (printed, never asserted: the machines are
 * shared). Plain C: what a host program sees.
 * Usage: mhcontact_bench_wheelset_step [STEPS [ONLY]] (default 10000 steps, every figure)
 * ONLY = wet | many | fine | dry | upright | deriv runs that one figure (for callgrind's instruction counts:
 * valgrind --tool=callgrind build/mhcontact_bench_wheelset_step 200 wet).
 * S1002 on 60E1 at 1:40, mu = 0.3, V = 30 m/s, Q = 50 kN per wheel; the wheelset runs a
 * sinusoid y = 6 sin(2 pi i / STEPS) mm with yaw 2 mrad sin(...), one reused workspace. The time
 * is the thread's CPU time (a shared machine's waiting not counted), the median of 5 repeats,
 * per step, with the wheelset call's defaults (FASTSIM 16 x 16, the vertical equilibrium to
 * 1e-5 Q). Then the same steps by mhc_wheelset_step_many on one thread (the Python binding's
 * path), with FASTSIM on a 32 x 32 grid (the single pair's default), without friction, and with
 * the wheels upright (roll_in_geometry 0: the roll to first order in the heights), and with the
 * derivatives (deriv: the default wheelset, derivatives 1). */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <mhcontact.h>

static double cpu_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp(const void* a, const void* b) {
  const double x = *(const double*)a, y = *(const double*)b;
  return x < y ? -1 : x > y;
}

static void die(mhc_error e) {
  fprintf(stderr, "mhcontact_bench_wheelset_step: %s: %s\n", mhc_error_name(e), mhc_last_message());
  exit(2);
}

/* nx = 0: the default grid of mhc_wheelset_options_init; rolled: roll_in_geometry. */
static mhc_wheelset* make(const mhc_pair* pair, double mu, int nx, int rolled) {
  mhc_wheelset_options o;
  mhc_wheelset* w = NULL;
  mhc_error e;
  mhc_wheelset_options_init(&o);
  o.mu = mu;
  if (nx > 0) o.fastsim_nx = o.fastsim_ny = nx;
  o.roll_in_geometry = rolled;
  if ((e = mhc_wheelset_create(pair, pair, &o, &w)) != MHC_OK) die(e);
  return w;
}

/* Median over 5 repeats of the CPU time per step [µs]: single steps (many = 0) or one batch. */
static double run(const mhc_wheelset* w, const mhc_wheelset_pose* poses, mhc_wheelset_result* res, size_t n, int many) {
  mhc_wheelset_workspace* ws = NULL;
  double t[5];
  int k;
  size_t i;
  mhc_error e;
  if ((e = mhc_wheelset_workspace_create(w, &ws)) != MHC_OK) die(e);
  for (k = 0; k < 5; ++k) {
    const double t0 = cpu_now();
    if (many) {
      res[0].struct_size = sizeof(mhc_wheelset_result);
      if ((e = mhc_wheelset_step_many(w, n, poses, res, 1)) != MHC_OK) die(e);
    } else {
      for (i = 0; i < n; ++i) {
        res[0].struct_size = sizeof(mhc_wheelset_result);
        if ((e = mhc_wheelset_step(w, ws, &poses[i], &res[0])) != MHC_OK) die(e);
      }
    }
    t[k] = (cpu_now() - t0) / (double)n * 1e6;
  }
  mhc_wheelset_workspace_free(ws);
  qsort(t, 5, sizeof t[0], cmp);
  return t[2];
}

int main(int argc, char** argv) {
  const size_t n = argc > 1 ? (size_t)atol(argv[1]) : 10000;
  const char* only = argc > 2 ? argv[2] : "";
  mhc_profile *wheel = NULL, *rail = NULL;
  mhc_pair* pair = NULL;
  mhc_pair_options po;
  mhc_wheelset_pose* poses = calloc(n, sizeof *poses);
  mhc_wheelset_result* res = calloc(n, sizeof *res);
  mhc_wheelset *wet, *dry, *fine, *upright;
  size_t i, ok = 0;
  mhc_error e;
  if (!poses || !res || n == 0) return 2;
  if ((e = mhc_profile_standard("S1002", &wheel)) != MHC_OK) die(e);
  if ((e = mhc_profile_standard("60E1", &rail)) != MHC_OK) die(e);
  mhc_pair_options_init(&po);
  po.rail_inclination = 40;
  if ((e = mhc_pair_create(wheel, rail, &po, &pair)) != MHC_OK) die(e);
  wet = make(pair, 0.3, 0, 1);
  fine = make(pair, 0.3, 32, 1);
  dry = make(pair, NAN, 0, 1);
  upright = make(pair, 0.3, 0, 0);
  for (i = 0; i < n; ++i) {
    const double s = sin(2 * 3.141592653589793 * (double)i / (double)n);
    mhc_wheelset_pose* p = &poses[i];
    memset(p, 0, sizeof *p);
    p->struct_size = sizeof *p;
    p->vertical = MHC_VERTICAL_LOADS;
    p->y_m = 6e-3 * s;
    p->yaw_rad = 2e-3 * s;
    p->Q_left_N = p->Q_right_N = 50e3;
    p->V_m_per_s = 30;
    p->pitch_rate_rad_per_s = NAN;
  }
  printf("wheelset step, S1002/60E1 1:40, y = 6 mm sin, %zu steps (CPU time per step, median of 5)\n", n);
  if (!*only || !strcmp(only, "wet"))
    printf("  mhc_wheelset_step, normal + tangential (mu 0.3, FASTSIM 16 x 16): %.2f us\n", run(wet, poses, res, n, 0));
  if (!*only || !strcmp(only, "many")) {
    printf("  mhc_wheelset_step_many, 1 thread, same steps:                    %.2f us\n", run(wet, poses, res, n, 1));
    for (i = 0; i < n; ++i) ok += res[i].status == MHC_STATUS_OK;
  }
  if (!*only || !strcmp(only, "fine"))
    printf("  mhc_wheelset_step, FASTSIM 32 x 32:                              %.2f us\n", run(fine, poses, res, n, 0));
  if (!*only || !strcmp(only, "dry"))
    printf("  mhc_wheelset_step, normal only:                                  %.2f us\n", run(dry, poses, res, n, 0));
  if (!*only || !strcmp(only, "upright"))
    printf("  mhc_wheelset_step, the wheels upright (roll_in_geometry 0):     %.2f us\n", run(upright, poses, res, n, 0));
  if (!*only || !strcmp(only, "many"))
    printf("  steps ok: %zu of %zu (the others outside_validity: flange contact near a jump)\n", ok, n);
  if (!*only || !strcmp(only, "deriv")) {
    for (i = 0; i < n; ++i) poses[i].derivatives = 1;
    printf("  mhc_wheelset_step with the derivatives (dF/dy, dF/dQ):            %.2f us\n", run(wet, poses, res, n, 0));
    for (i = 0; i < n; ++i) poses[i].derivatives = 0;
  }
  mhc_wheelset_free(wet);
  mhc_wheelset_free(dry);
  mhc_wheelset_free(fine);
  mhc_wheelset_free(upright);
  mhc_pair_free(pair);
  mhc_profile_free(wheel);
  mhc_profile_free(rail);
  free(poses);
  free(res);
  return 0;
}
