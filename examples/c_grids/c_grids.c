/* c_grids: the pressure and traction grid of one case through the C interface, as pressure.csv
 * of `mhcontact run --pressure-grid` gives it (docs/c-api.md "Pressure and traction grids").
 *
 *   c_grids
 *
 * S1002 on 60E1 canted 1:40, friction 0.3, 30 m/s, yaw 2 mrad, 50 kN at t_Y = 4 mm: the grid of
 * 9 x 9 points over each loaded ellipse (the size asked first, then the arrays), its centre line
 * printed in pressure.csv's units (traction on the rail), the points in slip counted, and the
 * error of a too small array. Exit 0 on success, 1 on an error. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mhcontact.h>

static int check(mhc_error e, const char* what) {
  if (e == MHC_OK) return 0;
  fprintf(stderr, "c_grids: %s: %s: %s\n", what, mhc_error_name(e), mhc_last_message());
  return 1;
}

int main(void) {
  enum { n = 9 };
  mhc_profile *wheel = NULL, *rail = NULL;
  mhc_pair* pair = NULL;
  mhc_workspace* ws = NULL;
  mhc_pair_options po;
  mhc_tangential_options to;
  mhc_result r;
  mhc_grid g;
  int32_t *contact = NULL, *slip = NULL;
  double *x = NULL, *s = NULL, *p = NULL, *px = NULL, *py = NULL;
  size_t k, loaded = 0, slipping = 0;
  int rc = 1;
  mhc_pair_options_init(&po);
  po.rail_inclination = 40;
  mhc_tangential_options_init(&to);
  to.mu = 0.3;
  to.speed_m_s = 30;
  to.yaw_rad = 2e-3;
  if (check(mhc_profile_standard("S1002", &wheel), "S1002") || check(mhc_profile_standard("60E1", &rail), "60E1") ||
      check(mhc_pair_create(wheel, rail, &po, &pair), "pair") || check(mhc_pair_set_tangential(pair, &to), "friction") ||
      check(mhc_workspace_create(pair, &ws), "workspace"))
    goto done;
  /* Keep the grid of the next solves (nothing is kept otherwise), solve, ask the size. */
  r.struct_size = sizeof r;
  if (check(mhc_workspace_keep_grids(ws, 1), "keep") || check(mhc_solve_load(pair, ws, 4e-3, 0.0, 50e3, &r), "solve"))
    goto done;
  memset(&g, 0, sizeof g);
  g.struct_size = sizeof g;
  if (check(mhc_result_grid(ws, n, &g), "grid size")) goto done;
  printf("t_Y 4 mm, 50 kN: %s, %d contact(s), %zu points, traction %d\n", mhc_status_name(r.status), (int)r.n_contacts,
         g.n_points, (int)g.traction);
  contact = malloc(g.n_points * sizeof *contact);
  slip = malloc(g.n_points * sizeof *slip);
  x = malloc(g.n_points * sizeof *x);
  s = malloc(g.n_points * sizeof *s);
  p = malloc(g.n_points * sizeof *p);
  px = malloc(g.n_points * sizeof *px);
  py = malloc(g.n_points * sizeof *py);
  if (!contact || !slip || !x || !s || !p || !px || !py) goto done;
  g.capacity = g.n_points;
  g.contact = contact, g.slip = slip, g.x_m = x, g.s_m = s, g.p_Pa = p, g.px_Pa = px, g.py_Pa = py;
  if (check(mhc_result_grid(ws, n, &g), "grid")) goto done;
  /* The centre line across (y = 0) of the first ellipse: points j = n / 2 of each x, rows i n + j. */
  printf("ellipse,x_mm,y_mm,p_MPa,px_MPa,py_MPa,slip\n");
  for (k = 0; k < (size_t)n; ++k) {
    const size_t i = k * n + n / 2;
    printf("%d,%.3f,%.3f,%.1f,%.1f,%.1f,%d\n", (int)contact[i], x[i] * 1e3, s[i] * 1e3, p[i] / 1e6, px[i] / 1e6,
           py[i] / 1e6, (int)slip[i]);
  }
  for (k = 0; k < g.n_points; ++k)
    if (p[k] > 0) {
      ++loaded;
      if (slip[k] == 1) ++slipping;
    }
  printf("in slip: %zu of %zu loaded points\n", slipping, loaded);
  /* Arrays one point too short: refused, the message names the field and the size needed. */
  g.capacity = g.n_points - 1;
  if (mhc_result_grid(ws, n, &g) == MHC_ERR_ARGUMENT) printf("too small: %s\n", mhc_last_message());
  rc = 0;
done:
  free(contact), free(slip), free(x), free(s), free(p), free(px), free(py);
  mhc_workspace_free(ws);
  mhc_pair_free(pair);
  mhc_profile_free(rail);
  mhc_profile_free(wheel);
  return rc;
}
