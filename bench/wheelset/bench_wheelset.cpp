// Wheelset benchmark (figures printed, never asserted):
//  1. one pair, EN 15302 wheel A on rail A: smoothing both profiles, Δr over y = −8 … 8 mm at
//     0.01 mm (1601 rows) and tan γe at 33 amplitudes; median of 11 runs, 1 and 2 threads;
//  2. a fleet: N wheels (default 10000; the argument) on one rail pair, each smoothed, swept over
//     y = −8 … 8 mm at 0.02 mm and evaluated at 3 mm and 3 more amplitudes, on 2 threads (the
//     wheels are wheel A scaled in height by 0.9 … 1.1 so that no two are equal).
// Wall-clock figures are medians; on a shared machine the fleet's CPU time (process CPU time over
// 2 threads: what 2 free cores would take) is printed beside its wall-clock time.
// Run: build/mhcontact_bench_wheelset [N]
#include <algorithm>
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
  std::vector<double> yf;
  for (int k = -400; k <= 400; ++k) yf.push_back(k * 2e-5);
  const Wheelset track(w, w, r, r, P, O);
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> ok{0};
  const auto t0 = Clock::now();
  const double cpu0 = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID);
  auto work = [&]() {
    for (std::size_t i; (i = next++) < N;) {
      Profile q = w;
      const double f = 0.9 + 0.2 * static_cast<double>(i) / static_cast<double>(std::max<std::size_t>(N - 1, 1));
      for (double& z : q.z) z *= f;
      const Wheelset ws(track, q, q);
      const auto st = ws.sweep(yf, 1);
      std::vector<double> dr;
      for (const auto& x : st) dr.push_back(x.delta_r());
      const EquivalentConicity C(yf, dr);
      bool good = C.at(3e-3).status == "ok";
      for (double A : {2e-3, 4e-3, 6e-3}) good = good && C.at(A).status == "ok";
      ok += good;
    }
  };
  std::thread th(work);
  work();
  th.join();
  const double sec = ms_since(t0) / 1e3, cpu = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID) - cpu0;
  std::printf("fleet: %zu wheels on one rail pair (801 rows each, tan γe at 4 amplitudes), 2 threads: %.1f s wall "
              "(%.2f ms per wheel per thread); CPU %.1f s (%.2f ms per wheel; %.1f s on 2 free cores), %zu ok\n",
              N, sec, 2e3 * sec / static_cast<double>(N), cpu, 1e3 * cpu / static_cast<double>(N), cpu / 2, ok.load());
  return 0;
}
