#include "jobs/sweep.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "contact/multi_hertz.hpp"
#include "core/errors.hpp"
#include "output/case_tables.hpp"
#include "output/output_file.hpp"

namespace mh {

namespace {
std::function<void(std::uint64_t)> g_case_hook;
}  // namespace

void set_case_hook_for_tests(std::function<void(std::uint64_t)> hook) { g_case_hook = std::move(hook); }

void check_pressure_grid(int N, std::uint64_t cases, bool plastic, bool force) {
  if (N == 0) return;
  if (N < 2 || N > 1000)
    throw InputError("--pressure-grid", std::to_string(N), "must be between 2 and 1000 points per axis");
  // A lower bound: one loaded ellipse per case, rows of about 52 bytes (64 plastic).
  const double row = plastic ? 64 : 52;
  const double bytes = static_cast<double>(cases) * N * N * row;
  if (bytes > kPressureLimitBytes && !force) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3g GB", bytes / 1e9);
    throw InputError("--pressure-grid", std::to_string(N),
                     std::string("pressure.csv would be at least ") + buf + " (" + std::to_string(cases) + " cases x " +
                         std::to_string(N * N) + " points x " + std::to_string(static_cast<int>(row)) +
                         " bytes), more than the limit of 10 GB",
                     "use a coarser grid or fewer cases, or --force to write it anyway");
  }
}

int parse_digits(const std::string& text) {
  if (text == "max") return 0;
  int d = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), d);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || d < 1 || d > 17)
    throw InputError("--digits", text, "must be an integer from 1 to 17, or max", "max: the shortest text that reads back to the same double");
  return d;
}

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
  const std::uint64_t n = end - first;
  const unsigned threads = opt.threads ? opt.threads : std::max(1u, std::thread::hardware_concurrency());
  const std::size_t chunk = std::max<std::size_t>(opt.chunk, 1);
  std::vector<Formatted> fmt(std::max<std::uint64_t>(1, std::min<std::uint64_t>(chunk, n)));
  std::vector<CaseStatus> status(fmt.size());
  int last_pct = -1;
  std::mutex fail_mutex;
  std::uint64_t fail_case = UINT64_MAX;
  std::string fail_what;
  for (std::uint64_t c0 = first; c0 < end; c0 += chunk) {
    const std::size_t m = static_cast<std::size_t>(std::min<std::uint64_t>(chunk, end - c0));
    auto work = [&](unsigned t, unsigned nt) {
      for (std::size_t i = t; i < m; i += nt) {
        const CasePoint cp = cf.case_at(c0 + i);
        try {
          if (g_case_hook) g_case_hook(c0 + i);
          const CaseResult r = solve_case(G, cf.material, cp.tY, cp.Q, cf.solver);
          status[i] = r.status;
          format_case(c0 + i, cp, r, plastic, want_csv, want_json, fmt[i]);
          if (np) format_pressure(c0 + i, r, cf.material, plastic, np, fmt[i].pressure);
        } catch (const std::exception& ex) {
          // A solver reports a case's failure in its status; an exception is a bug. Keep the
          // first (by case number, so the message does not depend on the thread count) and end
          // the run as an internal error (exit 3) once the workers have stopped.
          std::lock_guard<std::mutex> lock(fail_mutex);
          if (c0 + i < fail_case) {
            fail_case = c0 + i;
            fail_what = ex.what();
          }
          return;
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
    if (fail_case != UINT64_MAX)
      throw std::runtime_error("case " + std::to_string(fail_case) + ": " + fail_what);
    for (std::size_t i = 0; i < m; ++i) {
      ++counts->by_status[to_string(status[i])];
      if (status[i] != CaseStatus::Ok) ++counts->failed;
      if (want_csv) {
        put_prefixed(*out.cases, out.prefix, fmt[i].cases);
        put_prefixed(*out.ellipses, out.prefix, fmt[i].ellipses);
      }
      if (want_json) out.json->element(fmt[i].json);
      if (np) put_prefixed(*out.pressure, out.prefix, fmt[i].pressure);
    }
    // Stop at the first failed write (a full disk) rather than solve millions more cases.
    if (out.cases && !*out.cases) throw OutputError("cases.csv", "output could not be written", "disk full?");
    if (out.ellipses && !*out.ellipses) throw OutputError("ellipses.csv", "output could not be written", "disk full?");
    if (out.pressure && !*out.pressure) throw OutputError("pressure.csv", "output could not be written", "disk full?");
    if (out.json && !out.json->good()) throw OutputError(out.json_where, "output could not be written", "disk full, or the reader closed the pipe?");
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
