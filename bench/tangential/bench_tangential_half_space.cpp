// The exact half-space steady-rolling tangential solve (lib/contact/half_space/tangential_rolling.hpp)
// on CONTACT's Hertzian patch and grid (a = 8, b = 4 mm, 44 × 44 elements, CONTACT's pressure;
// tests/data/contact_tangential/hstang/README.md): time per case (best of R solves, one thread,
// the solver object built once), sweeps, and the forces beside CONTACT's; then the normal solve
// on the same grid (the gap that the Hertzian pressure of a = 8, b = 4 mm, N = 82 kN leaves, load
// control from zero, default options; best of R and CPU per solve over 10·R), to put beside
// CONTACT's "Norm: ConjGrd solver" timer on hertz44 (issue 35). Prints figures, never asserts. Usage: mhcontact_bench_tangential_half_space SOURCE_DIR [R]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "contact/half_space/normal_cg.hpp"
#include "contact/half_space/tangential_rolling.hpp"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s SOURCE_DIR [REPEATS]\n", argv[0]);
    return 2;
  }
  const std::string dir = std::string(argv[1]) + "/tests/data/contact_tangential/hstang/";
  const int reps = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
  const int mx = 44, my = 44;
  const double dx = 0.4e-3, dy = 0.2e-3, x0 = -8.6e-3, y0 = -4.3e-3, G = 82e9, nu = 0.28, mu = 0.3;
  std::vector<double> pn(mx * my, 0.0);
  std::ifstream fp(dir + "hertz44_pressure.csv"), ft(dir + "hertz44_totals.csv");
  if (!fp || !ft) {
    std::fprintf(stderr, "cannot read %shertz44_{pressure,totals}.csv\n", dir.c_str());
    return 2;
  }
  std::string line;
  std::getline(fp, line);
  while (std::getline(fp, line)) {
    int e = 0;
    double p = 0;
    char comma = 0;
    std::istringstream s(line);
    if (s >> e >> comma >> p) pn[static_cast<std::size_t>(e - 1)] = p * 1e6;
  }
  double N = 0;
  for (double p : pn) N += p * dx * dy;
  const auto t0 = std::chrono::steady_clock::now();
  mh::HalfSpaceTangentialSolver solver(mx, my, dx, dy, G, nu);
  const double setup = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::printf("tangential half-space solve, Hertzian patch 44 x 44 (1276 elements in contact), best of %d; setup %.1f ms\n",
              reps, setup);
  std::printf("case   xi        eta       phi_1/mm   ms/case  sweeps  Fx/muN here  CONTACT  Fy/muN here  CONTACT  Mz_Nm here  CONTACT  adhesion here CONTACT\n");
  std::getline(ft, line);
  double total = 0;
  while (std::getline(ft, line)) {
    std::vector<double> v;
    std::istringstream in(line);
    std::string cell;
    while (std::getline(in, cell, ',')) v.push_back(std::stod(cell));
    if (v.size() != 10) continue;
    const mh::Creepages c{v[1], v[2], v[3] * 1e3};
    double best = 1e300;
    mh::HalfSpaceTangentialResult r;
    for (int k = 0; k < reps; ++k) {
      const auto a = std::chrono::steady_clock::now();
      r = solver.solve(pn.data(), x0, y0, c, mu);
      best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - a).count());
    }
    total += best;
    std::printf("%4.0f  %+.2e %+.2e %+.2e  %7.2f  %6d  %+11.4f %+8.4f  %+11.4f %+8.4f  %+10.2f %+8.2f  %13.3f %7.3f\n", v[0],
                v[1], v[2], v[3], best, r.sweeps, r.forces.Fx / (mu * N), v[5] / (mu * N), r.forces.Fy / (mu * N),
                v[6] / (mu * N), r.forces.Mz, v[7] * 1e-3, r.forces.adhesion_fraction, v[9] / v[8]);
  }
  std::printf("total %.1f ms for the six cases\n", total);

  // The normal problem on the same grid: the gap g = max u − u of the Hertzian pressure's own
  // displacement u (zero over the ellipse, positive outside), solved for N = 82 kN.
  {
    const double a = 8e-3, b = 4e-3, FN = 82000, p0 = 3 * FN / (2 * 3.14159265358979323846 * a * b);
    mh::InfluenceGrid C(mx, my, dx, dy, (1 - nu) / (3.14159265358979323846 * G));
    std::vector<double> ph(pn.size(), 0.0), u(pn.size()), g(pn.size()), p(pn.size());
    for (int j = 0; j < my; ++j)
      for (int i = 0; i < mx; ++i) {
        const double x = x0 + i * dx, y = y0 + j * dy, q = 1 - x * x / (a * a) - y * y / (b * b);
        ph[static_cast<std::size_t>(i + mx * j)] = q > 0 ? p0 * std::sqrt(q) : 0.0;
      }
    C.apply(ph.data(), u.data());
    const double umax = *std::max_element(u.begin(), u.end());
    for (std::size_t e = 0; e < u.size(); ++e) g[e] = umax - u[e];
    double best = 1e300;
    mh::NormalCGResult nr;
    const std::clock_t c0 = std::clock();
    for (int k = 0; k < 10 * reps; ++k) {
      std::fill(p.begin(), p.end(), 0.0);
      const auto a0 = std::chrono::steady_clock::now();
      nr = mh::solve_normal_load(C, g.data(), FN, INFINITY, p.data());
      best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - a0).count());
    }
    const double cpu = 1e3 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC / (10 * reps);
    std::printf("normal solve on the same grid: best %.2f ms, CPU %.2f ms per solve, %d iterations, %d convolutions, %d elements in contact\n",
                best, cpu, nr.iterations, nr.convolutions, nr.n_contact);
  }
  return 0;
}
