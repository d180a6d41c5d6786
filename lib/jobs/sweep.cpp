#include "jobs/sweep.hpp"

#include <algorithm>
#include <thread>
#include <vector>

#include "contact/solve.hpp"
#include "output/case_tables.hpp"

namespace mh {

void put_prefixed(std::ostream& o, const std::string& prefix, const std::string& lines) {
  if (prefix.empty()) { o << lines; return; }
  std::size_t a = 0;
  while (a < lines.size()) {
    const std::size_t b = lines.find('\n', a);
    o << prefix;
    o.write(lines.data() + a, static_cast<std::streamsize>((b == std::string::npos ? lines.size() : b + 1) - a));
    a = b == std::string::npos ? lines.size() : b + 1;
  }
}

// Solve cases [first, end) of `cf` on `G` in parallel chunks and write them in order.
void solve_cases(const CaseFile& cf, const ContactGeometry& G, std::uint64_t first, std::uint64_t end,
                 const RunOptions& opt, const Sinks& out, SweepCounts* counts, std::ostream& err) {
  const bool plastic = cf.model == Model::Plastic;
  const bool want_csv = out.cases != nullptr, want_json = out.json != nullptr;
  const int np = out.pressure ? opt.pressure_grid : 0;
  MethodOptions mo = cf.method_options();
  mo.half_space.keep_pressure = np > 0;
  mo.strips.keep_strips = out.strips != nullptr;
  const bool grid_method = mo.method != Method::MultiHertzian;
  const std::uint64_t n = end - first;
  const unsigned threads = opt.threads ? opt.threads : std::max(1u, std::thread::hardware_concurrency());
  const std::size_t chunk = std::max<std::size_t>(opt.chunk, 1);
  std::vector<Formatted> fmt(std::max<std::uint64_t>(1, std::min<std::uint64_t>(chunk, n)));
  std::vector<CaseStatus> status(fmt.size());
  int last_pct = -1;
  for (std::uint64_t c0 = first; c0 < end; c0 += chunk) {
    const std::size_t m = static_cast<std::size_t>(std::min<std::uint64_t>(chunk, end - c0));
    auto work = [&](unsigned t, unsigned nt) {
      for (std::size_t i = t; i < m; i += nt) {
        const CasePoint cp = cf.case_at(c0 + i);
        CaseResult r;
        try {
          r = solve_method(G, cf.material, cp.tY, cp.Q, mo);
        } catch (const std::exception& ex) {
          // Never let one case end the sweep (or a worker thread): report it in its row.
          r = CaseResult{};
          r.status = CaseStatus::NotConverged;
          r.message = std::string("internal error: ") + ex.what();
        }
        status[i] = r.status;
        format_case(c0 + i, cp, r, plastic, want_csv, want_json, fmt[i]);
        if (grid_method) {
          if (want_csv) format_patches(c0 + i, cp, r, plastic, fmt[i].ellipses);
          if (out.strips) format_strips(c0 + i, cp, r, fmt[i].strips);
          if (np) format_patch_pressure(c0 + i, r, fmt[i].pressure);
        } else if (np) {
          format_pressure(c0 + i, r, cf.material, plastic, np, fmt[i].pressure);
        }
      }
    };
    const unsigned nt = static_cast<unsigned>(std::min<std::size_t>(threads, m));
    if (nt <= 1) {
      work(0, 1);
    } else {
      std::vector<std::thread> pool;
      for (unsigned t = 1; t < nt; ++t) pool.emplace_back(work, t, nt);
      work(0, nt);
      for (auto& th : pool) th.join();
    }
    for (std::size_t i = 0; i < m; ++i) {
      ++counts->by_status[to_string(status[i])];
      if (status[i] != CaseStatus::Ok) ++counts->failed;
      if (want_csv) {
        put_prefixed(*out.cases, out.prefix, fmt[i].cases);
        put_prefixed(*out.ellipses, out.prefix, fmt[i].ellipses);
      }
      if (want_json) out.json->element(fmt[i].json);
      if (np) put_prefixed(*out.pressure, out.prefix, fmt[i].pressure);
      if (out.strips) put_prefixed(*out.strips, out.prefix, fmt[i].strips);
    }
    if (opt.progress && !opt.quiet) {
      const int pct = static_cast<int>(100.0 * static_cast<double>(c0 + m - first) / static_cast<double>(n));
      if (pct != last_pct) {
        err << "\rmhcontact run: " << (c0 + m - first) << "/" << n << " cases (" << pct << " %)" << std::flush;
        last_pct = pct;
      }
    }
  }
}


}  // namespace mh
