// mhcontact_bench: figures, not assertions (the machines are shared and noisy). Prints medians
// over repeated runs. Usage: mhcontact_bench [SOURCE_DIR] [REPEATS] [MODEL [judge]]
// MODEL (elastic, capped or yield) solves only that model's cases, once, for an instruction count:
//   valgrind --tool=callgrind --toggle-collect='mh::solve_multi_hertz(*' build/mhcontact_bench . 1 yield
// with `judge`, through solve_contact (the solve and the judge, docs/status.md), as the command:
//   valgrind --tool=callgrind --toggle-collect='mh::solve_contact(*' build/mhcontact_bench . 1 elastic judge
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <thread>
#include <vector>

#include "input/case_file.hpp"
#include "geometry/contact_geometry.hpp"
#include "jobs/run.hpp"
#include "contact/multi_hertz/multi_hertz.hpp"
#include "contact/solve.hpp"

using namespace mh;
using clk = std::chrono::steady_clock;

static double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// [s] CPU time of this process (the machine is shared: wall time counts the others' work too).
static double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

int main(int argc, char** argv) {
  const std::string src = argc > 1 ? argv[1] : ".";
  const int reps = argc > 2 ? std::atoi(argv[2]) : 7;
  const std::string only = argc > 3 ? argv[3] : "";
  const bool judge_only = argc > 4 && std::string(argv[4]) == "judge";
  const char* names[3] = {"elastic", "capped", "yield"};
  int only_model = -1;
  for (int k = 0; k < 3; ++k)
    if (only == names[k]) only_model = k;
  if (!only.empty() && only_model < 0) {
    std::fprintf(stderr, "mhcontact_bench: MODEL '%s' is none of elastic, capped, yield\n", only.c_str());
    return 2;
  }
  const CaseFile cf = load_case_file(src + "/cases/manchester.json", true);
  std::printf("machine: %u hardware threads\n", std::thread::hardware_concurrency());

  // 1. Geometry build of one profile pair, default grid (-10 … 12 mm, 0.01 mm, strips 0.1 mm),
  //    profiles already read.
  const Profile W = load_profile(cf.wheel, ProfileKind::Wheel);
  const Profile R = load_profile(cf.rail, ProfileKind::Rail, cf.inclination);
  std::vector<double> tg;
  ContactGeometry G;
  for (int r = 0; r < (only_model < 0 ? reps : 1); ++r) {
    const auto t0 = clk::now();
    G = build_geometry(W, R, cf.track, GeometryOptions{});
    tg.push_back(std::chrono::duration<double>(clk::now() - t0).count());
  }
  if (only_model < 0)
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
  const Material* mats[3] = {&el, &pl, &yl};
  const int n = 200000;
  auto tY_of = [](int i) { return (-6.0 + 16.0 * (i % 1000) / 999.0) * 1e-3; };
  auto Q_of = [](int i) { return (10.0 + 140.0 * (i / 1000) / 199.0) * 1e3; };
  double sink = 0;
  const MethodOptions mo;  // the multi-Hertzian method, default options
  if (only_model >= 0) {
    if (judge_only)
      for (int i = 0; i < n; ++i) sink += solve_contact(G, *mats[only_model], tY_of(i), Q_of(i), mo).dz;
    else
      for (int i = 0; i < n; ++i) sink += solve_multi_hertz(G, *mats[only_model], tY_of(i), Q_of(i)).dz;
    std::printf("%d cases, %s%s%s\n", n, names[only_model], judge_only ? ", judged" : "", sink == 42 ? " " : "");
    return 0;
  }
  // Alternated models in each repeat, so that a slow spell of the shared machine falls on all three.
  std::vector<double> t[3];
  for (int r = 0; r < reps; ++r) {
    for (int model = 0; model < 3; ++model) {
      const auto t0 = cpu_seconds();
      for (int i = 0; i < n; ++i) {
        const CaseResult res = solve_multi_hertz(G, *mats[model], tY_of(i), Q_of(i));
        sink += res.dz;
      }
      t[model].push_back((cpu_seconds() - t0) * 1e9 / n);
    }
  }
  std::printf("one case from the table (%d cases per run, CPU time): elastic median %.0f ns, plastic median %.0f ns, "
              "plastic/elastic %.2f; yield law median %.0f ns, yield/elastic %.2f\n", n, median(t[0]), median(t[1]),
              median(t[1]) / median(t[0]), median(t[2]), median(t[2]) / median(t[0]));
  // 3. The same cases through solve_contact: the solve and the judge (the gap-corner test on every
  //    row that passes the other Hertz tests, docs/status.md), what the command, the C interface
  //    and Python run per case.
  std::vector<double> tj[3];
  for (int r = 0; r < reps; ++r) {
    for (int model = 0; model < 3; ++model) {
      const auto t0 = cpu_seconds();
      for (int i = 0; i < n; ++i) sink += solve_contact(G, *mats[model], tY_of(i), Q_of(i), mo).dz;
      tj[model].push_back((cpu_seconds() - t0) * 1e9 / n);
    }
  }
  std::printf("one case judged (solve_contact, CPU time): elastic median %.0f ns, plastic median %.0f ns, "
              "plastic/elastic %.2f; yield law median %.0f ns, yield/elastic %.2f\n", median(tj[0]), median(tj[1]),
              median(tj[1]) / median(tj[0]), median(tj[2]), median(tj[2]) / median(tj[0]));
  // The case mix (not timed): a plastic law costs more per plastic contact, so the share of
  // plastic contacts explains part of a ratio.
  for (int model = 0; model < 3; ++model) {
    long contacts = 0, plastic = 0, plastic_cases = 0, iterations = 0;
    for (int i = 0; i < n; ++i) {
      const CaseResult res = solve_multi_hertz(G, *mats[model], tY_of(i), Q_of(i));
      contacts += res.n_contacts;
      iterations += res.iterations;
      int p = 0;
      for (const LoadedEllipse& L : res.loaded) p += L.s.plastic ? 1 : 0;
      plastic += p;
      plastic_cases += p > 0 ? 1 : 0;
    }
    std::printf("  %-7s per case: %.3f contacts, %.3f plastic, %.1f %% of cases with a plastic contact, "
                "%.2f Newton iterations\n", names[model], double(contacts) / n, double(plastic) / n,
                100.0 * plastic_cases / n, double(iterations) / n);
  }
  if (sink == 42) std::printf(" ");
  return 0;
}
