/* c_wheelset: a wheelset stepped through a lateral and yaw motion, both contacts solved at every
 * step with their creep forces, as a vehicle-dynamics code calls it (docs/c-api.md "The wheelset
 * call").
 *
 *   c_wheelset
 *
 * S1002 wheels on 60E1 rails canted 1:40 (the same pair on both sides: the right one is its mirror
 * image), friction 0.3, 30 m/s, 50 kN per wheel. The wheelset moves y(t) = 7 mm sin(2 pi t / 1 s)
 * with yaw 2 mrad cos(2 pi t / 1 s) for one second at 1 kHz; every 100th step is printed: the
 * statuses, the forces on the wheelset in the track frame (x forward, y left, z up) and the main
 * contact of each wheel. Then one step with the axle height given and the roll solved, with the
 * derivatives an implicit integrator needs. Exit 0 on success, 1 on an error. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <mhcontact.h>

static int check(mhc_error e, const char* what) {
  if (e == MHC_OK) return 0;
  fprintf(stderr, "c_wheelset: %s: %s: %s\n", what, mhc_error_name(e), mhc_last_message());
  return 1;
}

/* The contact of a wheel carrying the largest N. */
static const mhc_wheelset_contact* main_contact(const mhc_wheelset_wheel* w) {
  const mhc_wheelset_contact* best = NULL;
  int i;
  for (i = 0; i < w->n_contacts && i < MHC_MAX_CONTACTS; ++i)
    if (!best || w->contact[i].N_N > best->N_N) best = &w->contact[i];
  return best;
}

int main(void) {
  const double pi = 3.14159265358979323846;
  mhc_profile *wheel = NULL, *rail = NULL;
  mhc_pair* pair = NULL;
  mhc_wheelset* wset = NULL;
  mhc_wheelset_workspace* ws = NULL;
  mhc_pair_options po;
  mhc_wheelset_options wo;
  mhc_wheelset_pose p;
  mhc_wheelset_result r;
  int k, oldest = 0, rc = 1;
  const int version = mhc_interface_version(&oldest);
  if (version < 2 || oldest > MHC_INTERFACE_VERSION) {
    fprintf(stderr, "c_wheelset: the library serves interfaces %d to %d, this program needs 2\n", oldest, version);
    return 1;
  }
  mhc_pair_options_init(&po);
  po.rail_inclination = 40;
  mhc_wheelset_options_init(&wo);
  wo.mu = 0.3;
  if (check(mhc_profile_standard("S1002", &wheel), "S1002") || check(mhc_profile_standard("60E1", &rail), "60E1") ||
      check(mhc_pair_create(wheel, rail, &po, &pair), "pair") ||
      check(mhc_wheelset_create(pair, pair, &wo, &wset), "wheelset") ||
      check(mhc_wheelset_workspace_create(wset, &ws), "workspace"))
    goto done;
  memset(&p, 0, sizeof p);
  p.struct_size = sizeof p;
  p.vertical = MHC_VERTICAL_LOADS;
  p.Q_left_N = p.Q_right_N = 50e3;
  p.V_m_per_s = 30;
  p.pitch_rate_rad_per_s = NAN;
  r.struct_size = sizeof r;
  printf("t_s,y_mm,yaw_mrad,status,Fx_kN,Fy_kN,Fz_kN,Mz_kNm,roll_mrad,left_gamma_deg,left_N_kN,right_gamma_deg,right_N_kN\n");
  for (k = 0; k <= 1000; ++k) {
    const double t = k / 1000.0;
    const mhc_wheelset_contact *cl, *cr;
    p.y_m = 7e-3 * sin(2 * pi * t);
    p.yaw_rad = 2e-3 * cos(2 * pi * t);
    p.lateral_velocity_m_per_s = 7e-3 * 2 * pi * cos(2 * pi * t);
    p.yaw_rate_rad_per_s = -2e-3 * 2 * pi * sin(2 * pi * t);
    if (check(mhc_wheelset_step(wset, ws, &p, &r), "step")) goto done;
    if (k % 100) continue;
    cl = main_contact(&r.wheel[0]);
    cr = main_contact(&r.wheel[1]);
    printf("%.1f,%.3f,%.3f,%s,%.3f,%.3f,%.3f,%.3f,%.3f,%.2f,%.3f,%.2f,%.3f\n", t, p.y_m * 1e3, p.yaw_rad * 1e3,
           mhc_status_name(r.status), r.F_N[0] / 1e3, r.F_N[1] / 1e3, r.F_N[2] / 1e3, r.M_N_m[2] / 1e3,
           r.roll_rad * 1e3, cl ? cl->gamma_rad * 180 / pi : NAN, cl ? cl->N_N / 1e3 : NAN,
           cr ? cr->gamma_rad * 180 / pi : NAN, cr ? cr->N_N / 1e3 : NAN);
  }
  /* The axle height given (50 um below where both wheels touch at y = 3 mm), the roll solved. */
  p.vertical = MHC_VERTICAL_POSITION;
  p.solve_roll = 1;
  p.y_m = 3e-3;
  p.yaw_rad = 0;
  p.lateral_velocity_m_per_s = p.yaw_rate_rad_per_s = 0;
  p.Z_m = 1.0; /* lifted: no contact, but each wheel's first-contact height h_m */
  if (check(mhc_wheelset_step(wset, ws, &p, &r), "step")) goto done;
  p.Z_m = 0.5 * (r.wheel[0].h_m + r.wheel[1].h_m) - 50e-6;
  p.derivatives = 1;
  if (check(mhc_wheelset_step(wset, ws, &p, &r), "step")) goto done;
  printf("position: y 3 mm, roll %.3f mrad, Fz %.3f kN, Fy %.3f kN\n", r.roll_rad * 1e3, r.F_N[2] / 1e3, r.F_N[1] / 1e3);
  printf("dFz/dZ %.1f kN/mm, dFy/dy %.1f kN/mm, dFz/droll %.1f kN/mrad\n", r.dF_dvertical[2] / 1e6,
         r.dF_dy_N_per_m[1] / 1e6, r.dF_droll_N_per_rad[2] / 1e6);
  rc = 0;
done:
  mhc_wheelset_workspace_free(ws);
  mhc_wheelset_free(wset);
  mhc_pair_free(pair);
  mhc_profile_free(rail);
  mhc_profile_free(wheel);
  return rc;
}
