// Tangential benchmark (figures printed, never asserted; docs/tangential.md, issue 33 §5):
//  1. FASTSIM on one ellipse at the default grid (32 × 32) and at 64 × 64, over 2000 creepage
//     sets (a = 8, b = 4 mm, FN = 82 kN, CONTACT's fastsim example with its spin scaled 0 … 1):
//     the median over 11 repetitions of the time per ellipse;
//  2. a whole multi-Hertzian case of cases/manchester-tangential.json (t_Y = −6 … 10 mm,
//     Q = 10 … 150 kN, 1000 cases) solved with and without the tangential problem: the median
//     time per case of each, 11 repetitions, one thread.
// Run: build/mhcontact_bench_tangential SOURCE_DIR
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "contact/solve.hpp"
#include "contact/tangential/fastsim.hpp"
#include "input/case_file.hpp"
#include "jobs/run.hpp"

using namespace mh;
using Clock = std::chrono::steady_clock;

static double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

int main(int argc, char** argv) {
  const std::string src = argc > 1 ? argv[1] : ".";
  volatile double sink = 0;
  for (int n : {32, 64}) {
    FastsimOptions o;
    o.nx = o.ny = n;
    std::vector<double> t;
    for (int rep = 0; rep < 11; ++rep) {
      const auto t0 = Clock::now();
      for (int i = 0; i < 2000; ++i)
        sink = sink + fastsim({1e-4 * (i % 7), -6.25e-4, 0.625 * i / 2000.0}, 8e-3, 4e-3, 82e3, 0.3, 82e9, 0.28, o).Fy;
      t.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / 2000);
    }
    std::printf("FASTSIM, one ellipse, %d x %d: median %.2f us\n", n, n, median(t));
  }
  const CaseFile cf = load_case_file(src + "/cases/manchester-tangential.json", true);
  const PairGeometry pg = build_pair_geometry(cf);
  for (bool tang : {false, true}) {
    MethodOptions mo = cf.method_options();
    if (!tang) mo.tangential.mu = NAN;
    CaseResult r;
    std::vector<double> t;
    for (int rep = 0; rep < 11; ++rep) {
      const auto t0 = Clock::now();
      for (int i = 0; i < 1000; ++i) {
        const double tY = -6e-3 + 16e-3 * (i % 40) / 39.0, Q = 10e3 + 140e3 * (i / 40) / 24.0;
        solve_contact(pg.geo, cf.material, tY, Q, mo, r);
        sink = sink + r.Fz;
      }
      t.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / 1000);
    }
    std::printf("multi-Hertzian case, Manchester pair, %s tangential: median %.2f us per case\n", tang ? "with" : "without",
                median(t));
  }
  return 0;
}
