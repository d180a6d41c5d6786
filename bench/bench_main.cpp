// mhcontact_bench: figures, not assertions (the machines are shared and noisy). Prints medians
// over repeated runs. Usage: mhcontact_bench [SOURCE_DIR] [REPEATS]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "input/case_file.hpp"
#include "geometry/contact_geometry.hpp"
#include "jobs/run.hpp"
#include "contact/multi_hertz/multi_hertz.hpp"

using namespace mh;
using clk = std::chrono::steady_clock;

static double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

int main(int argc, char** argv) {
  const std::string src = argc > 1 ? argv[1] : ".";
  const int reps = argc > 2 ? std::atoi(argv[2]) : 7;
  const CaseFile cf = load_case_file(src + "/cases/manchester.json", true);
  std::printf("machine: %u hardware threads\n", std::thread::hardware_concurrency());

  // 1. Geometry build of one profile pair, default grid (-10 … 12 mm, 0.01 mm, strips 0.1 mm),
  //    profiles already read.
  const Profile W = load_profile(cf.wheel, ProfileKind::Wheel);
  const Profile R = load_profile(cf.rail, ProfileKind::Rail, cf.inclination);
  std::vector<double> tg;
  ContactGeometry G;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = clk::now();
    G = build_geometry(W, R, cf.track, GeometryOptions{});
    tg.push_back(std::chrono::duration<double>(clk::now() - t0).count());
  }
  std::printf("geometry build, Manchester pair, %zu grid points x %zu strips: median %.1f ms (%d runs)\n",
              G.tY.size(), G.strip_y.size(), median(tg) * 1e3, reps);

  // 2. One case solved from the table, elastic and plastic: t_Y over −6 … 10 mm, Q 10 … 150 kN.
  //    Plastic: the capped law (p_lim 900 MPa) and the yield law (σ_y = 900/2.1 MPa: the same
  //    grid cap, first yield at 1.6 σ_y = 686 MPa; method.md §5.1).
  Material el = cf.material, pl = cf.material, yl = cf.material;
  pl.p_lim = 900e6;
  yl.yield = 900e6 / kPlimPerYield;
  yl.p_lim = p_lim_from_yield(yl.yield);
  yl.yield_law = true;
  const int n = 200000;
  std::vector<double> te, tp, ty;
  double sink = 0;
  for (int r = 0; r < reps; ++r) {
    for (int model = 0; model < 3; ++model) {
      const Material& m = model == 2 ? yl : model ? pl : el;
      const auto t0 = clk::now();
      for (int i = 0; i < n; ++i) {
        const double tY = (-6.0 + 16.0 * (i % 1000) / 999.0) * 1e-3;
        const double Q = (10.0 + 140.0 * (i / 1000) / 199.0) * 1e3;
        const CaseResult res = solve_multi_hertz(G, m, tY, Q);
        sink += res.dz;
      }
      const double ns = std::chrono::duration<double, std::nano>(clk::now() - t0).count() / n;
      (model == 2 ? ty : model ? tp : te).push_back(ns);
    }
  }
  std::printf("one case from the table (%d cases per run): elastic median %.0f ns, plastic median %.0f ns, "
              "plastic/elastic %.2f; yield law median %.0f ns, yield/elastic %.2f\n", n, median(te), median(tp),
              median(tp) / median(te), median(ty), median(ty) / median(te));
  if (sink == 42) std::printf(" ");
  return 0;
}
