// Benchmark of the grid methods (docs/method.md §8 half-space, §9 strips): the CONTACT benchmark
// sweep of the Manchester pair (t_Y = -6 ... 10 mm, Q = 50 kN, 0.2 mm elements and strips) solved
// case by case on one thread. Prints per case and method the time, solver iterations and size,
// the median and worst time per case, and the ratios to CONTACT's own time per case on this
// machine kind (tests/data/contact, wall_s) and between the methods.
// Times are CPU time, best of REPEATS per case. Figures only, never an assertion.
// Usage: mhcontact_bench_grid SOURCE_DIR [REPEATS] [half-space | workspace]; "half-space" runs the
// two half-space sweeps only (scripts/bench.sh compares them with the FFTW build's); "workspace"
// compares each grid method with a reused workspace against a new one per call (bench_workspace).
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "contact/half_space/half_space_method.hpp"
#include "contact/solve.hpp"
#include "contact/strips/strip_method.hpp"
#include "input/case_file.hpp"
#include "jobs/run.hpp"
#include "output/csv_table.hpp"

namespace {

/// CPU time of this process [ms] (one thread here; the machine is shared, so wall time would
/// count other processes' load).
double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

/// Median of v (the upper one of an even count).
double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// "workspace": each grid method on the Manchester sweep (t_Y = -6 ... 10 mm by 1, Q = 50 kN),
/// elastic and capped at the plastic case file's p_lim, solved per case by the form without a
/// workspace (a new one per call: every call makes its patches, influence operators, FFT plans and
/// vectors, as every call did before the workspace) and into a reused result with one workspace
/// for the whole sweep (solve_contact's form for an MBS), alternated, `repeats` times; per case the
/// median CPU time of each and their ratio. The two answers must be the same bytes (checked).
int bench_workspace(const std::string& src, int repeats) {
  const mh::CaseFile hs = mh::load_case_file(src + "/cases/manchester-halfspace.json", true);
  const mh::CaseFile st = mh::load_case_file(src + "/cases/manchester-strips.json", true);
  const mh::CaseFile pl = mh::load_case_file(src + "/cases/manchester-plastic.json", true);
  const mh::PairGeometry pg = mh::build_pair_geometry(hs);
  std::printf("grid methods with a reused workspace against a new one per call, Manchester pair, Q = 50 kN,\n"
              "t_Y = -6 ... 10 mm by 1, one thread, CPU time, median of %d alternated runs per case:\n"
              "  method               median_new_ms  median_reused_ms  median_ratio  min_ratio  max_ratio  differing\n",
              repeats);
  struct Run {
    const char* name;
    const mh::CaseFile* cf;
    mh::Method method;
    bool plastic;
  };
  const Run runs[] = {{"half-space elastic", &hs, mh::Method::HalfSpace, false},
                      {"half-space capped", &hs, mh::Method::HalfSpace, true},
                      {"strips elastic", &st, mh::Method::Strips, false},
                      {"strips capped", &st, mh::Method::Strips, true}};
  for (const Run& run : runs) {
    mh::MethodOptions mo = run.cf->method_options();
    mo.method = run.method;
    mh::Material mat = run.cf->material;
    if (run.plastic) mat.p_lim = pl.material.p_lim;
    mh::GridWorkspace ws;
    mh::CaseResult reused;
    std::vector<double> t_new, t_reused, ratio;
    int differing = 0;
    for (int t = -6; t <= 10; ++t) {
      std::vector<double> a, b;
      mh::CaseResult fresh;
      for (int k = 0; k < repeats; ++k) {
        double t0 = cpu_ms();
        fresh = mh::solve_contact(pg.geo, mat, t * 1e-3, 50e3, mo);
        a.push_back(cpu_ms() - t0);
        t0 = cpu_ms();
        mh::solve_contact(pg.geo, mat, t * 1e-3, 50e3, mo, reused, &ws);
        b.push_back(cpu_ms() - t0);
      }
      differing += !(fresh.Fz == reused.Fz && fresh.pmax == reused.pmax && fresh.approach == reused.approach &&
                     fresh.area == reused.area && fresh.iterations == reused.iterations && fresh.status == reused.status);
      t_new.push_back(median_of(a));
      t_reused.push_back(median_of(b));
      ratio.push_back(t_reused.back() / t_new.back());
    }
    std::printf("  %-20s %13.2f  %16.2f  %12.3f  %9.3f  %9.3f  %9d\n", run.name, median_of(t_new), median_of(t_reused),
                median_of(ratio), *std::min_element(ratio.begin(), ratio.end()),
                *std::max_element(ratio.begin(), ratio.end()), differing);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string src = argc > 1 ? argv[1] : ".";
  const int repeats = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
  if (argc > 3 && std::string(argv[3]) == "workspace") return bench_workspace(src, repeats);
  const bool half_space_only = argc > 3 && std::string(argv[3]) == "half-space";
  const mh::CaseFile cf = mh::load_case_file(src + "/cases/manchester-halfspace.json", true);
  const mh::PairGeometry pg = mh::build_pair_geometry(cf);
  const mh::CsvTable ref = mh::read_csv_file(src + "/tests/data/contact/contact_mbench_right_q50_dx0.2.csv");
  std::vector<double> ms, contact_s;
  std::printf("half-space, Manchester pair, Q = 50 kN, dx = ds = %.2f mm, one thread, best of %d runs per case:\n",
              cf.half_space.dx * 1e3, repeats);
  std::printf("  tY_mm   time_ms  passes  cg_iterations  elements  pmax_MPa\n");
  for (int t = -6; t <= 10; ++t) {
    double best = 1e99;
    mh::CaseResult r;
    for (int k = 0; k < repeats; ++k) {
      const double t0 = cpu_ms();
      r = mh::solve_half_space(pg.geo, cf.material, t * 1e-3, 50e3, cf.half_space);
      best = std::min(best, cpu_ms() - t0);
    }
    int cg = 0, n = 0;
    for (const auto& P : r.patches) { cg += P.iterations; n += P.n_elements; }
    std::printf("  %5d  %8.1f  %6d  %13d  %8d  %8.1f  %s\n", t, best, r.iterations, cg, n, r.pmax / 1e6, mh::to_string(r.status));
    ms.push_back(best);
  }
  auto mean = [](const std::vector<double>& v) { double s = 0; for (double x : v) s += x; return s / static_cast<double>(v.size()); };
  std::vector<double> ms_st;
  if (!half_space_only) {
    // The strip method on the same cases.
    const mh::CaseFile cs = mh::load_case_file(src + "/cases/manchester-strips.json", true);
    std::printf("strips, same cases, ds = %.2f mm (extents: the estimate kept, or refined to close the end gap):\n"
                "  tY_mm   time_ms  patch_solves  strips  pmax_MPa  extents (end-gap error)\n", cs.strips.ds * 1e3);
    for (int t = -6; t <= 10; ++t) {
      double best = 1e99;
      mh::CaseResult r;
      for (int k = 0; k < repeats; ++k) {
        const double t0 = cpu_ms();
        r = mh::solve_strip_method(pg.geo, cs.material, t * 1e-3, 50e3, cs.strips);
        best = std::min(best, cpu_ms() - t0);
      }
      int n = 0;
      std::string ext;
      for (const auto& P : r.patches) {
        n += P.n_elements;
        char b[48];
        std::snprintf(b, sizeof b, "%s%s (%.3f)", ext.empty() ? "" : ", ", P.refined ? "end gap" : "estimate", P.end_gap_error);
        ext += b;
      }
      std::printf("  %5d  %8.2f  %12d  %6d  %8.1f  %-24s %s\n", t, best, r.iterations, n, r.pmax / 1e6, ext.c_str(),
                  mh::to_string(r.status));
      ms_st.push_back(best);
    }
    // "auto" on the same cases: the multi-Hertzian answer where it is valid, strips elsewhere.
    // Its mean cost per case is meant to stay within a third of the strip method's.
    mh::MethodOptions mo = cs.method_options();
    mo.method = mh::Method::Auto;
    std::vector<double> ms_auto;
    int by_strips = 0;
    for (int t = -6; t <= 10; ++t) {
      double best = 1e99;
      mh::CaseResult r;
      for (int k = 0; k < repeats; ++k) {
        const double t0 = cpu_ms();
        r = mh::solve_contact(pg.geo, cs.material, t * 1e-3, 50e3, mo);
        best = std::min(best, cpu_ms() - t0);
      }
      by_strips += r.method == mh::Method::Strips;
      ms_auto.push_back(best);
    }
    std::printf("auto: %d of %zu cases by strips; mean %.3f ms per case against %.3f ms for strips on every case "
                "(ratio %.2f; the target was <= 0.33, docs/strips.md)\n",
                by_strips, ms_auto.size(), mean(ms_auto), mean(ms_st), mean(ms_auto) / mean(ms_st));
    // The same on all 99 cases of cases/manchester.json (t_Y -6 ... 10 mm by 0.5, Q = 10, 50, 100 kN).
    {
      std::vector<double> s99, a99;
      int strips99 = 0, refined99 = 0;
      for (int k = 0; k <= 32; ++k)
        for (double Q : {10e3, 50e3, 100e3}) {
          const double tY = (-6 + 0.5 * k) * 1e-3;
          double bs = 1e99, ba = 1e99;
          mh::CaseResult rs, ra;
          for (int rep = 0; rep < repeats; ++rep) {
            const double t0 = cpu_ms();
            rs = mh::solve_strip_method(pg.geo, cs.material, tY, Q, cs.strips);
            const double t1 = cpu_ms();
            ra = mh::solve_contact(pg.geo, cs.material, tY, Q, mo);
            const double t2 = cpu_ms();
            bs = std::min(bs, t1 - t0);
            ba = std::min(ba, t2 - t1);
          }
          s99.push_back(bs);
          a99.push_back(ba);
          strips99 += ra.method == mh::Method::Strips;
          for (const auto& P : rs.patches) refined99 += P.refined;
        }
      std::vector<double> sorted = s99;
      std::sort(sorted.begin(), sorted.end());
      std::printf("cases/manchester.json, 99 cases: strips median %.2f ms, mean %.2f ms, worst %.2f ms per case (%d patches "
                  "refined); auto: %d cases by strips, mean %.3f ms (ratio %.2f)\n",
                  sorted[sorted.size() / 2], mean(s99), sorted.back(), refined99, strips99, mean(a99), mean(a99) / mean(s99));
    }
  }
  // The plastic model on the same pair (cases/manchester-plastic.json: Q = 100 kN, p_lim 900 MPa,
  // t_Y -6 ... 10 mm by 0.5), half-space, one run per case (the flange cases once took > 60 s).
  const mh::CaseFile cp = mh::load_case_file(src + "/cases/manchester-plastic.json", true);
  std::vector<double> ms_pl;
  std::printf("half-space plastic, p_lim = %.0f MPa, Q = 100 kN, dx = ds = %.2f mm:\n"
              "  tY_mm   time_ms  patch_solves  cg_iterations  elements  area_mm2  pmax_MPa\n",
              cp.material.p_lim / 1e6, cp.half_space.dx * 1e3);
  for (int k = 0; k <= 32; ++k) {
    const double tY = (-6 + 0.5 * k) * 1e-3;
    const double t0 = cpu_ms();
    const mh::CaseResult r = mh::solve_half_space(pg.geo, cp.material, tY, 100e3, cp.half_space);
    const double t = cpu_ms() - t0;
    int cg = 0, n = 0;
    for (const auto& P : r.patches) { cg += P.iterations; n += P.n_elements; }
    std::printf("  %5.1f  %8.1f  %12d  %13d  %8d  %8.2f  %8.1f  %s\n", tY * 1e3, t, r.iterations, cg, n, r.area * 1e6,
                r.pmax / 1e6, mh::to_string(r.status));
    ms_pl.push_back(t);
  }
  std::vector<double> ms_pl_st;
  if (!half_space_only) {
    // The strip method on the same plastic cases (best of `repeats`; capped strips take their
    // influence by quadrature, docs/strips.md "Capped strips within their overlap").
    std::printf("strips plastic, same cases:\n  tY_mm   time_ms  strips  area_mm2  extents\n");
    for (int k = 0; k <= 32; ++k) {
      const double tY = (-6 + 0.5 * k) * 1e-3;
      double best = 1e99;
      mh::CaseResult r;
      for (int rep = 0; rep < repeats; ++rep) {
        const double t0 = cpu_ms();
        r = mh::solve_strip_method(pg.geo, cp.material, tY, 100e3, cp.strips);
        best = std::min(best, cpu_ms() - t0);
      }
      int n = 0;
      bool refined = false;
      for (const auto& P : r.patches) { n += P.n_elements; refined = refined || P.refined; }
      std::printf("  %5.1f  %8.2f  %6d  %8.2f  %-8s  %s\n", tY * 1e3, best, n, r.area * 1e6, refined ? "end gap" : "estimate",
                  mh::to_string(r.status));
      ms_pl_st.push_back(best);
    }
  }
  for (const auto& row : ref.rows) contact_s.push_back(std::stod(row[static_cast<std::size_t>(ref.column("wall_s"))]));
  auto median = [](std::vector<double> v) { std::sort(v.begin(), v.end()); return v[v.size() / 2]; };
  const double med = median(ms), worst = *std::max_element(ms.begin(), ms.end());
  if (half_space_only) {
    std::printf("half-space: median %.1f ms per case, worst %.1f ms\n", med, worst);
    std::printf("half-space plastic: median %.1f ms per case, worst %.1f ms\n", median(ms_pl),
                *std::max_element(ms_pl.begin(), ms_pl.end()));
    return 0;
  }
  const double med_st = median(ms_st), worst_st = *std::max_element(ms_st.begin(), ms_st.end());
  std::printf("half-space: median %.1f ms per case, worst %.1f ms\n", med, worst);
  std::printf("strips:     median %.2f ms per case, worst %.2f ms\n", med_st, worst_st);
  std::printf("half-space plastic: median %.1f ms per case, worst %.1f ms\n", median(ms_pl),
              *std::max_element(ms_pl.begin(), ms_pl.end()));
  std::printf("strips plastic:     median %.1f ms per case, mean %.1f ms, worst %.1f ms (half-space plastic / strips "
              "plastic, medians: %.1f)\n",
              median(ms_pl_st), mean(ms_pl_st), *std::max_element(ms_pl_st.begin(), ms_pl_st.end()),
              median(ms_pl) / median(ms_pl_st));
  std::printf("strips plastic / strips elastic, medians: %.1f ms / %.2f ms = %.1f\n", median(ms_pl_st), med_st,
              median(ms_pl_st) / med_st);
  std::printf("CONTACT (whole process, same machine kind): median %.2f s per case\n", median(contact_s));
  std::printf("ratios of the medians: CONTACT / half-space %.0f, half-space / strips %.0f, CONTACT / strips %.0f\n",
              median(contact_s) * 1e3 / med, med / med_st, median(contact_s) * 1e3 / med_st);
  return 0;
}
