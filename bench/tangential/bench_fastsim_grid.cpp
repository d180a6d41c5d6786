// FASTSIM's grid: accuracy against independent references and cost, per grid (figures printed,
// never asserted; docs/tangential.md "Grid of FASTSIM", docs/performance.md "The wheelset call").
// For n × n cells, n = 8 … 128:
//  - lin: the largest relative error against Kalker's linear theory (kalker.hpp) for pure ξ, η
//    and φ at 1e-3 of the saturating creepage, a/b = 0.2, 0.5, 1, 2, 5 (issue 33 §4: ≤ 0.5 %);
//  - exact: against CONTACT's exact solution on its 30 Hertzian module-3 cases
//    (tests/data/contact_tangential/module3_hertz.csv), the median and 95th percentile of
//    |ΔFx|/(μN), |ΔFy|/(μN) (issue 33 §4: median ≤ 3 %, 95th ≤ 10 %) and |ΔMz|/(μN c);
//  - grid: the grid's own error on those 30 cases, max |ΔF|/(μN) against FASTSIM at 512 × 512;
//  - µs: CPU time of the thread per ellipse over the 30 cases (median of 11 repeats; a shared
//    machine's waiting not counted).
// Run: build/mhcontact_bench_fastsim_grid SOURCE_DIR
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "contact/tangential/fastsim.hpp"
#include "contact/tangential/kalker.hpp"

using namespace mh;

namespace {

struct Case {
  double a, b, N, mu, nu, G;
  Creepages c;
  double Fx, Fy, Mz;  // CONTACT exact [N], [N m]
};

std::vector<Case> read_cases(const std::string& path) {
  std::ifstream f(path);
  if (!f) {
    std::fprintf(stderr, "mhcontact_bench_fastsim_grid: cannot read %s (give the source directory)\n", path.c_str());
    std::exit(2);
  }
  std::string line, cell;
  std::getline(f, line);
  std::vector<std::string> head;
  for (std::istringstream h(line); std::getline(h, cell, ',');) head.push_back(cell);
  auto col = [&](const std::vector<double>& v, const char* k) {
    return v.at(static_cast<std::size_t>(std::find(head.begin(), head.end(), k) - head.begin()));
  };
  std::vector<Case> out;
  while (std::getline(f, line)) {
    std::vector<double> v;
    for (std::istringstream in(line); std::getline(in, cell, ',');) v.push_back(std::stod(cell));
    out.push_back({col(v, "a_mm") * 1e-3, col(v, "b_mm") * 1e-3, col(v, "FN_N"), col(v, "mu"), col(v, "nu"),
                   col(v, "G_MPa") * 1e6, {col(v, "xi"), col(v, "eta"), col(v, "phi_per_mm") * 1e3},
                   col(v, "exact_Fx_N"), col(v, "exact_Fy_N"), col(v, "exact_Mz_Nmm") * 1e-3});
  }
  return out;
}

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const std::size_t k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size()))) - 1;
  return v[std::min(k, v.size() - 1)];
}

double cpu_us() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e6 * static_cast<double>(t.tv_sec) + 1e-3 * static_cast<double>(t.tv_nsec);
}

// Largest relative error against linear theory, pure ξ, η, φ, a/b 0.2 … 5 (the ellipse of
// tests/unit/contact/test_fastsim.cpp: c = 6 mm, N 80 kN, μ 0.3, G 82 GPa, ν 0.28).
double linear_error(const FastsimOptions& o) {
  const double G = 82e9, nu = 0.28, mu = 0.3, N = 80e3;
  double worst = 0;
  for (double aob : {0.2, 0.5, 1.0, 2.0, 5.0}) {
    const double c = 6e-3, a = c * std::sqrt(aob), b = c / std::sqrt(aob);
    const KalkerCoefficients k = kalker_coefficients(aob, nu);
    const double xi = 1e-3 * mu * N / (G * c * c * k.C11), eta = 1e-3 * mu * N / (G * c * c * k.C22);
    const double phi = 1e-3 * mu * N / (G * c * c * c * k.C23);
    worst = std::max(worst, std::fabs(fastsim({xi, 0, 0}, a, b, N, mu, G, nu, o).Fx / (-G * c * c * k.C11 * xi) - 1));
    worst = std::max(worst, std::fabs(fastsim({0, eta, 0}, a, b, N, mu, G, nu, o).Fy / (-G * c * c * k.C22 * eta) - 1));
    worst = std::max(worst, std::fabs(fastsim({0, 0, phi}, a, b, N, mu, G, nu, o).Fy / (-G * c * c * c * k.C23 * phi) - 1));
  }
  return worst;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string src = argc > 1 ? argv[1] : ".";
  const std::vector<Case> cases = read_cases(src + "/tests/data/contact_tangential/module3_hertz.csv");
  FastsimOptions fine;
  fine.nx = fine.ny = 512;
  std::vector<TangentialResult> conv;
  for (const Case& k : cases) conv.push_back(fastsim(k.c, k.a, k.b, k.N, k.mu, k.G, k.nu, fine));
  std::printf("| n x n | lin. theory, max err | vs exact: Fx median, p95 | Fy median, p95 | Mz median, p95 | "
              "grid error max |dF|/muN | us per ellipse |\n|---|---|---|---|---|---|---|\n");
  volatile double sink = 0;
  for (int n : {8, 12, 16, 20, 24, 32, 48, 64, 128}) {
    FastsimOptions o;
    o.nx = o.ny = n;
    std::vector<double> ex, ey, em;
    double grid = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const Case& k = cases[i];
      const TangentialResult r = fastsim(k.c, k.a, k.b, k.N, k.mu, k.G, k.nu, o);
      const double muN = k.mu * k.N, c = std::sqrt(k.a * k.b);
      ex.push_back(std::fabs(r.Fx - k.Fx) / muN);
      ey.push_back(std::fabs(r.Fy - k.Fy) / muN);
      em.push_back(std::fabs(r.Mz - k.Mz) / (muN * c));
      grid = std::max(grid, std::hypot(r.Fx - conv[i].Fx, r.Fy - conv[i].Fy) / muN);
    }
    std::vector<double> t;
    for (int rep = 0; rep < 11; ++rep) {
      const double t0 = cpu_us();
      for (const Case& k : cases) sink = sink + fastsim(k.c, k.a, k.b, k.N, k.mu, k.G, k.nu, o).Fy;
      t.push_back((cpu_us() - t0) / static_cast<double>(cases.size()));
    }
    std::printf("| %d | %.3f %% | %.2f %%, %.2f %% | %.2f %%, %.2f %% | %.2f %%, %.2f %% | %.3f %% | %.2f |\n", n,
                100 * linear_error(o), 100 * quantile(ex, 0.5), 100 * quantile(ex, 0.95), 100 * quantile(ey, 0.5),
                100 * quantile(ey, 0.95), 100 * quantile(em, 0.5), 100 * quantile(em, 0.95), 100 * grid,
                quantile(t, 0.5));
  }
  return 0;
}
