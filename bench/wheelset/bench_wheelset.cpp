// Wheelset benchmark (figures printed, never asserted):
//  1. one pair, EN 15302 wheel A on rail A: smoothing both profiles, Δr over y = −8 … 8 mm at
//     0.01 mm (1601 rows) and tan γe at 33 amplitudes; median of 11 runs, 1 and 2 threads;
//  2. a fleet: N wheels (default 10000; the first argument) on one rail pair, each smoothed, swept
//     over y = −8 … 8 mm every STEP mm (default 0.02: 801 rows; the second argument) and evaluated
//     at 3 mm and 3 more amplitudes, on 2 threads (the wheels are wheel A scaled in height by
//     0.9 … 1.1 so that no two are equal); the CPU time per wheel of each stage (the wheel's
//     smoothing and scan tables, the sweep, the conicity) by thread CPU clocks. Three runs:
//     "measured" wheels, their points rounded to 0.01 mm as MiniProf files print them (smoothed
//     as measured profiles: the narrow and the 3 mm window), the fleet figure; the exact wheels;
//     and the exact wheels with the plain scan (WheelsetOptions::full_scan) on N/10 wheels.
// Wall-clock figures are medians; on a shared machine the fleet's CPU time (process CPU time over
// 2 threads: what 2 free cores would take) is printed beside its wall-clock time.
// Run: build/mhcontact_bench_wheelset [N [STEP]]
#include <algorithm>
#include <cmath>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <time.h>
#include <vector>

#include "geometry/conicity.hpp"
#include "geometry/wheelset.hpp"
#include "profile/standard_profiles.hpp"

using namespace mh;
using Clock = std::chrono::steady_clock;

static double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }
static double cpu_seconds(clockid_t id) {
  timespec ts;
  clock_gettime(id, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

int main(int argc, char** argv) {
  const Profile w = make_standard_profile("EN15302-wheel-A"), r = make_standard_profile("EN15302-rail-A");
  WheelsetPlacement P;
  P.rails = WheelsetPlacement::Rails::Absolute;
  WheelsetOptions O;
  O.max_displacement = 8e-3;  // as the job sets it from the sweep
  std::vector<double> ys, amps;
  for (int k = -800; k <= 800; ++k) ys.push_back(k * 1e-5);
  for (int a = 10; a <= 74; a += 2) amps.push_back(a * 1e-4);
  for (unsigned threads : {1u, 2u}) {
    std::vector<double> t_all, t_build, t_sweep, t_con, t_cpu;
    double head = 0;
    for (int rep = 0; rep < 11; ++rep) {
      const double c0 = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID);
      const auto t0 = Clock::now();
      const Wheelset ws(w, w, r, r, P, O);
      const double b = ms_since(t0);
      const auto t1 = Clock::now();
      const auto st = ws.sweep(ys, threads);
      const double s = ms_since(t1);
      const auto t2 = Clock::now();
      std::vector<double> dr;
      for (const auto& x : st) dr.push_back(x.delta_r());
      const EquivalentConicity C(ys, dr);
      for (double A : amps) head += C.at(A).tan_gamma_e;
      const double c = ms_since(t2);
      t_build.push_back(b), t_sweep.push_back(s), t_con.push_back(c), t_all.push_back(b + s + c);
      t_cpu.push_back(1e3 * (cpu_seconds(CLOCK_PROCESS_CPUTIME_ID) - c0));
    }
    auto med = [](std::vector<double> v) { std::sort(v.begin(), v.end()); return v[v.size() / 2]; };
    std::printf("one pair (EN 15302 wheel A / rail A, 1601 rows, 33 amplitudes), %u thread(s): median %.1f ms "
                "(smoothing %.1f, delta_r %.1f, conicity %.1f); CPU %.1f ms\n",
                threads, med(t_all), med(t_build), med(t_sweep), med(t_con), med(t_cpu));
  }

  const std::size_t N = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 10000;
  const double step_mm = argc > 2 ? std::strtod(argv[2], nullptr) : 0.02;
  std::vector<double> yf;
  const int kmax = static_cast<int>(std::lround(8 / step_mm));
  for (int k = -kmax; k <= kmax; ++k) yf.push_back(k * step_mm * 1e-3);
  for (int variant : {0, 1, 2}) {  // measured, exact, exact with the plain scan
    const bool full = variant == 2, measured = variant == 0;
    WheelsetOptions Of = O;
    Of.full_scan = full;
    const Wheelset track(w, w, r, r, P, Of);
    const std::size_t n = full ? std::max<std::size_t>(N / 10, 1) : N;
    std::atomic<std::size_t> next{0};
    std::atomic<std::size_t> ok{0};
    double stage[2][3] = {};  // per thread: smoothing, sweep, conicity [s]
    const auto t0 = Clock::now();
    const double cpu0 = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID);
    auto work = [&](int t) {
      for (std::size_t i; (i = next++) < n;) {
        Profile q = w;
        const double f = 0.9 + 0.2 * static_cast<double>(i) / static_cast<double>(std::max<std::size_t>(n - 1, 1));
        for (double& z : q.z) z *= f;
        if (measured) {  // printed to 0.01 mm: points whose rounded y repeats are dropped
          Profile m = q;
          m.y.clear(), m.z.clear();
          for (std::size_t k = 0; k < q.y.size(); ++k) {
            const double yy = std::round(q.y[k] * 1e5) / 1e5, zz = std::round(q.z[k] * 1e5) / 1e5;
            if (m.y.empty() || yy > m.y.back()) m.y.push_back(yy), m.z.push_back(zz);
          }
          m.print_step = 1e-5;
          q = m;
        }
        const double c0 = cpu_seconds(CLOCK_THREAD_CPUTIME_ID);
        const Wheelset ws(track, q, q);
        const double c1 = cpu_seconds(CLOCK_THREAD_CPUTIME_ID);
        const auto st = ws.sweep(yf, 1);
        const double c2 = cpu_seconds(CLOCK_THREAD_CPUTIME_ID);
        std::vector<double> dr;
        for (const auto& x : st) dr.push_back(x.delta_r());
        const EquivalentConicity C(yf, dr);
        bool good = C.at(3e-3).status == "ok";
        for (double A : {2e-3, 4e-3, 6e-3}) good = good && C.at(A).status == "ok";
        ok += good;
        const double c3 = cpu_seconds(CLOCK_THREAD_CPUTIME_ID);
        stage[t][0] += c1 - c0, stage[t][1] += c2 - c1, stage[t][2] += c3 - c2;
      }
    };
    std::thread th(work, 1);
    work(0);
    th.join();
    const double sec = ms_since(t0) / 1e3, cpu = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID) - cpu0;
    const double per = 1e3 / static_cast<double>(n);
    std::printf("fleet%s: %zu wheels on one rail pair (%zu rows each, tan γe at 4 amplitudes), 2 threads: %.1f s wall; "
                "CPU %.1f s, %.2f ms per wheel (smoothing %.2f, sweep %.2f, conicity %.2f): %.1f s per 10,000 wheels on "
                "2 free cores; %zu ok\n",
                measured ? " (measured wheels, 0.01 mm)" : full ? " (exact wheels, plain scan)" : " (exact wheels)", n, yf.size(), sec, cpu, cpu * per, (stage[0][0] + stage[1][0]) * per,
                (stage[0][1] + stage[1][1]) * per, (stage[0][2] + stage[1][2]) * per, cpu / static_cast<double>(n) * 1e4 / 2,
                ok.load());
  }
  return 0;
}
