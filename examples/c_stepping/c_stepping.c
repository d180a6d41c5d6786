/* c_stepping: a wheel stepped through a lateral motion, the contact solved at every step as a
 * vehicle-dynamics code would call it (docs/c-api.md).
 *
 *   c_stepping [CASE.json]
 *
 * Without an argument the pair is S1002 on 60E1 canted 1:40, generated from the standards; with
 * a case file (e.g. cases/manchester.json) it is that file's pair, as `mhcontact run` builds it.
 * The wheel moves laterally t_Y(t) = 7 mm sin(2 pi t / 1 s) for one second at 1 kHz under
 * Q = 50 kN; every 50th step is printed (forces, contacts, contact angle of the main contact).
 * Then the same pair as a penetration-driven force element: the approach dz found at t_Y = 0
 * prescribed, the force and the stiffness dFz/d(dz) an implicit integrator needs.
 * Exit 0 on success, 1 on an error (its message on stderr). */
#include <math.h>
#include <stdio.h>

#include <mhcontact.h>

static int check(mhc_error e, const char* what) {
  if (e == MHC_OK) return 0;
  fprintf(stderr, "c_stepping: %s: %s: %s\n", what, mhc_error_name(e), mhc_last_message());
  return 1;
}

int main(int argc, char** argv) {
  const double pi = 3.14159265358979323846;
  mhc_pair* pair = NULL;
  mhc_workspace* ws = NULL;
  mhc_result r;
  int k, n_steps = 1000, rc = 1;

  if (mhc_abi_version() != MHC_ABI_VERSION) {
    fprintf(stderr, "c_stepping: libmhcontact ABI %d, header %d\n", (int)mhc_abi_version(), MHC_ABI_VERSION);
    return 1;
  }
  if (argc > 1) {
    if (check(mhc_pair_from_case_file(argv[1], &pair), argv[1])) return 1;
  } else {
    mhc_profile *wheel = NULL, *rail = NULL;
    mhc_pair_options opt;
    mhc_pair_options_init(&opt);  /* standard track, steel, multi-Hertzian */
    opt.rail_inclination = 40;    /* 60E1 canted 1:40 */
    if (check(mhc_profile_standard("S1002", &wheel), "S1002") || check(mhc_profile_standard("60E1", &rail), "60E1"))
      return 1;
    rc = check(mhc_pair_create(wheel, rail, &opt, &pair), "pair");
    mhc_profile_free(wheel); /* the pair keeps its own copies */
    mhc_profile_free(rail);
    if (rc) return 1;
    rc = 1;
  }
  if (check(mhc_workspace_create(pair, &ws), "workspace")) goto done;

  printf("mhcontact %s (ABI %d, FFT %s)\n", mhc_version(), (int)mhc_abi_version(), mhc_fft_backend());
  printf("t_s,tY_mm,status,n_contacts,Fz_kN,Fy_kN,pmax_MPa,gamma_main_deg,dFz_ddz_kN_per_mm\n");
  r.struct_size = sizeof r;
  for (k = 0; k <= n_steps; ++k) {
    const double t = (double)k / n_steps;             /* [s] */
    const double tY = 7e-3 * sin(2 * pi * t);         /* [m] */
    if (check(mhc_solve_load(pair, ws, tY, 0.0, 50e3, &r), "solve")) goto done;
    if (k % 50 == 0)
      printf("%.3f,%.3f,%s,%d,%.3f,%.3f,%.1f,%.3f,%.1f\n", t, tY * 1e3, mhc_status_name(r.status), (int)r.n_contacts,
             r.Fz_N / 1e3, r.Fy_N / 1e3, r.p_max_Pa / 1e6, r.gamma_main_rad * 180 / pi, r.dFz_ddz_N_per_m / 1e6);
  }

  /* Penetration-driven: prescribe the approach that carried 50 kN at t_Y = 0, then 10 % more. */
  if (check(mhc_solve_load(pair, ws, 0.0, 0.0, 50e3, &r), "solve")) goto done;
  {
    const double dz = r.dz_m;
    for (k = 0; k < 2; ++k) {
      const double dzk = dz * (k ? 1.1 : 1.0);
      if (check(mhc_solve_approach(pair, ws, 0.0, 0.0, dzk, &r), "solve_approach")) goto done;
      printf("approach %.6f mm: Fz %.3f kN, stiffness %.1f kN/mm\n", dzk * 1e3, r.Fz_N / 1e3,
             r.dFz_ddz_N_per_m / 1e6);
    }
  }
  /* The wheel rolled 1 mrad against the rail (towards its field side); a roll out of range is
     refused, never ignored. */
  if (check(mhc_solve_load(pair, ws, 0.0, 1e-3, 50e3, &r), "solve with roll")) goto done;
  printf("roll 1 mrad: Fz %.3f kN, Fy %.3f kN, contact angle %.3f deg\n", r.Fz_N / 1e3, r.Fy_N / 1e3,
         r.gamma_main_rad * 180 / pi);
  if (mhc_solve_load(pair, ws, 0.0, 0.1, 50e3, &r) != MHC_OK)
    printf("roll refused: %s\n", mhc_last_message());
  rc = 0;
done:
  mhc_workspace_free(ws);
  mhc_pair_free(pair);
  return rc;
}
