// mhcontact_bench_capi: the cost of the C interface against the core solve (figures printed, never
// asserted: the machines are shared). Usage: mhcontact_bench_capi [SOURCE_DIR] [THREADS]
//  1. one multi-Hertzian case: solve_multi_hertz() directly (a fresh CaseResult per call, and into
//     one reused CaseResult), solve_contact() into a reused CaseResult (the solve plus the status
//     rule, judge_validity: what the C call runs) vs mhc_solve_load() (Manchester pair, t_Y
//     sweeping -6 … 10 mm, Q = 50 kN), median ns per case over repeats;
//  2. a time-stepping loop of 100,000 steps at slowly changing t_Y (0.1 µm per step): one reused
//     workspace vs a workspace created and freed around every call ("cold");
//  (sections 1 and 2: CPU time of the thread, medians)
//  3. 1,000,000 cases on THREADS threads: mhc_solve_many vs the command's sweep loop without its
//     file writing (solve_contact on the same threads), the reference of python solve_many.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <time.h>
#include <vector>

#include <mhcontact.h>

#include "contact/solve.hpp"
#include "input/case_file.hpp"
#include "jobs/run.hpp"

using clk = std::chrono::steady_clock;
static double seconds_since(clk::time_point t0) { return std::chrono::duration<double>(clk::now() - t0).count(); }
// Sections 1 and 2 run on one thread and are timed by its CPU time (CLOCK_THREAD_CPUTIME_ID): on
// a shared machine the time the thread waits for a core is not counted.
static double cpu_now() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
static double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

int main(int argc, char** argv) {
  const std::string src = argc > 1 ? argv[1] : ".";
  const int threads = argc > 2 ? std::atoi(argv[2]) : 2;
  const std::string cfp = src + "/cases/manchester.json";
  const mh::CaseFile cf = mh::load_case_file(cfp, true);
  const mh::PairGeometry pg = mh::build_pair_geometry(cf);
  mhc_pair* pair = nullptr;
  if (mhc_pair_from_case_file(cfp.c_str(), &pair) != MHC_OK) {
    std::fprintf(stderr, "%s\n", mhc_last_message());
    return 1;
  }
  mhc_workspace* ws = nullptr;
  mhc_workspace_create(pair, &ws);
  std::printf("mhcontact %s, FFT %s, %u hardware threads\n", mhc_version(), mhc_fft_backend(),
              std::thread::hardware_concurrency());

  // 1. One case: core vs C interface.
  const int n1 = 20000;
  std::vector<double> tY(n1);
  for (int i = 0; i < n1; ++i) tY[i] = (-6.0 + 16.0 * i / (n1 - 1)) * 1e-3;
  const mh::MultiHertzOptions mho = cf.solver;
  const mh::MethodOptions mo1 = cf.method_options();
  std::vector<double> core_ns, reuse_ns, contact_ns, c_ns;
  double sink = 0;
  mhc_result r;
  r.struct_size = sizeof r;
  mh::CaseResult cr;
  for (int rep = 0; rep < 11; ++rep) {
    double t0 = cpu_now();
    for (int i = 0; i < n1; ++i) sink += mh::solve_multi_hertz(pg.geo, cf.material, tY[i], 50e3, mho).Fy;
    core_ns.push_back((cpu_now() - t0) / n1 * 1e9);
    t0 = cpu_now();
    for (int i = 0; i < n1; ++i) {
      mh::solve_multi_hertz(pg.geo, cf.material, tY[i], 50e3, mho, cr);
      sink += cr.Fy;
    }
    reuse_ns.push_back((cpu_now() - t0) / n1 * 1e9);
    t0 = cpu_now();
    for (int i = 0; i < n1; ++i) {
      mh::solve_contact(pg.geo, cf.material, tY[i], 50e3, mo1, cr);
      sink += cr.Fy;
    }
    contact_ns.push_back((cpu_now() - t0) / n1 * 1e9);
    t0 = cpu_now();
    for (int i = 0; i < n1; ++i) {
      mhc_solve_load(pair, ws, tY[i], 0.0, 50e3, &r);
      sink += r.Fy_N;
    }
    c_ns.push_back((cpu_now() - t0) / n1 * 1e9);
  }
  std::printf("1. one multi-Hertzian case (median of 11 x %d): core solve_multi_hertz %.0f ns (into a reused result "
              "%.0f ns), solve_contact into a reused result %.0f ns, mhc_solve_load %.0f ns; difference to the core "
              "solve %+.0f ns (to the reused one %+.0f ns, to solve_contact %+.0f ns)\n",
              n1, median(core_ns), median(reuse_ns), median(contact_ns), median(c_ns), median(c_ns) - median(core_ns),
              median(c_ns) - median(reuse_ns), median(c_ns) - median(contact_ns));

  // 2. Time stepping at slowly changing t_Y: reused workspace vs cold calls.
  const int n2 = 100000;
  std::vector<double> warm, cold;
  for (int rep = 0; rep < 5; ++rep) {
    double t0 = cpu_now();
    for (int k = 0; k < n2; ++k) {
      mhc_solve_load(pair, ws, -2e-3 + 1e-7 * k, 0.0, 50e3, &r);
      sink += r.Fy_N;
    }
    warm.push_back((cpu_now() - t0) / n2 * 1e9);
    t0 = cpu_now();
    for (int k = 0; k < n2; ++k) {
      mhc_workspace* w = nullptr;
      mhc_workspace_create(pair, &w);
      mhc_solve_load(pair, w, -2e-3 + 1e-7 * k, 0.0, 50e3, &r);
      mhc_workspace_free(w);
      sink += r.Fy_N;
    }
    cold.push_back((cpu_now() - t0) / n2 * 1e9);
  }
  std::printf("2. 100,000 steps, t_Y from -2 mm by 0.1 um: reused workspace %.0f ns/step, cold (workspace per call) "
              "%.0f ns/step, cold / reused %.2f\n", median(warm), median(cold), median(cold) / median(warm));
  // The same with the approach prescribed (the penetration-driven force element).
  {
    double t0 = cpu_now();
    for (int k = 0; k < n2; ++k) {
      mhc_solve_approach(pair, ws, -2e-3 + 1e-7 * k, 0.0, 2.5e-5, &r);
      sink += r.Fy_N;
    }
    std::printf("   approach prescribed, reused workspace: %.0f ns/step\n", (cpu_now() - t0) / n2 * 1e9);
  }

  // 3. 1e6 cases on `threads` threads.
  const std::size_t n3 = 1000000;
  std::vector<double> t3(n3), q3(n3);
  for (std::size_t i = 0; i < n3; ++i) {
    t3[i] = (-6.0 + 16.0 * static_cast<double>(i / 100) / (n3 / 100 - 1)) * 1e-3;
    q3[i] = (10.0 + 90.0 * static_cast<double>(i % 100) / 99) * 1e3;
  }
  const mh::MethodOptions mo = cf.method_options();
  auto t0 = clk::now();
  {
    std::atomic<std::size_t> next{0};
    std::vector<double> fy(n3);
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
      pool.emplace_back([&] {
        for (;;) {
          const std::size_t b = next.fetch_add(256);
          if (b >= n3) break;
          for (std::size_t i = b; i < std::min(n3, b + 256); ++i)
            fy[i] = mh::solve_contact(pg.geo, cf.material, t3[i], q3[i], mo).Fy;
        }
      });
    for (auto& th : pool) th.join();
    sink += fy[n3 / 2];
  }
  const double t_core = seconds_since(t0);
  std::vector<mhc_result> many(n3);
  t0 = clk::now();
  mhc_solve_many(pair, MHC_PRESCRIBE_LOAD, n3, t3.data(), nullptr, q3.data(), many.data(), sizeof(mhc_result), threads);
  const double t_many = seconds_since(t0);
  std::printf("3. 1,000,000 cases on %d threads: the command's sweep loop without writing %.2f s, mhc_solve_many %.2f s "
              "(%.2f x)\n", threads, t_core, t_many, t_many / t_core);
  mhc_workspace_free(ws);
  mhc_pair_free(pair);
  return sink == 12345.678 ? 1 : 0;
}
