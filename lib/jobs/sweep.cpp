#include "jobs/sweep.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <memory>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <unordered_set>
#include <exception>
#include <iterator>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <vector>

#include "contact/judge/judge.hpp"
#include "contact/solve.hpp"
#include "contact/rcf/contact_damage.hpp"
#include "contact/rcf/ty_weighting.hpp"
#include "core/errors.hpp"
#include "core/parallel.hpp"
#include "output/case_tables.hpp"
#include "output/cells.hpp"
#include "output/output_file.hpp"

namespace mh {

namespace {
std::function<void(std::uint64_t)> g_case_hook;
}  // namespace

void set_case_hook_for_tests(std::function<void(std::uint64_t)> hook) { g_case_hook = std::move(hook); }

bool CaseSelection::contains(std::uint64_t c) const {
  if (ranges.empty()) return true;
  auto it = std::upper_bound(ranges.begin(), ranges.end(), c,
                             [](std::uint64_t v, const std::pair<std::uint64_t, std::uint64_t>& r) { return v < r.first; });
  return it != ranges.begin() && c <= std::prev(it)->second;
}

std::uint64_t CaseSelection::count_in(std::uint64_t first, std::uint64_t end) const {
  if (ranges.empty()) return end - first;
  std::uint64_t n = 0;
  for (const auto& [a, b] : ranges) {
    const std::uint64_t lo = std::max(a, first), hi = std::min(b + 1, end);
    if (hi > lo) n += hi - lo;
  }
  return n;
}

CaseSelection parse_case_selection(const std::string& text) {
  auto bad = [&](const std::string& rule) {
    return InputError("--pressure-cases", text, rule, "give case numbers and ranges, e.g. 3,17,40-45");
  };
  auto number = [&](const std::string& t) {
    std::uint64_t v = 0;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size()) throw bad("'" + t + "' is not a case number");
    return v;
  };
  CaseSelection sel;
  std::size_t a = 0;
  while (a <= text.size()) {
    const std::size_t b = std::min(text.find(',', a), text.size());
    const std::string item = text.substr(a, b - a);
    const std::size_t dash = item.find('-');
    const std::uint64_t lo = number(item.substr(0, dash));
    const std::uint64_t hi = dash == std::string::npos ? lo : number(item.substr(dash + 1));
    if (hi < lo) throw bad("the range " + item + " runs backwards");
    sel.ranges.emplace_back(lo, hi);
    a = b + 1;
  }
  // Sorted and merged: overlapping or touching ranges become one.
  std::sort(sel.ranges.begin(), sel.ranges.end());
  std::vector<std::pair<std::uint64_t, std::uint64_t>> merged;
  for (const auto& r : sel.ranges) {
    if (!merged.empty() && r.first <= merged.back().second + 1) merged.back().second = std::max(merged.back().second, r.second);
    else merged.push_back(r);
  }
  sel.ranges = merged;
  return sel;
}

void check_pressure_cases(const RunOptions& opt, std::uint64_t cases) {
  if (opt.pressure_cases.all()) return;
  if (!opt.pressure_grid)
    throw InputError("--pressure-cases", "", "selects the cases of the pressure grid: needs --pressure-grid N");
  if (opt.pressure_cases.largest() >= cases)
    throw InputError("--pressure-cases", std::to_string(opt.pressure_cases.largest()),
                     "no such case: the case file has " + std::to_string(cases) + " cases (0 to " +
                         std::to_string(cases - 1) + ")");
}

void check_pressure_grid(int N, std::uint64_t cases, bool plastic, bool force, bool tangential) {
  if (N == 0) return;
  if (N < 2 || N > 1000)
    throw InputError("--pressure-grid", std::to_string(N), "must be between 2 and 1000 points per axis");
  // A lower bound: one loaded ellipse per case, rows of about 52 bytes (64 plastic), 36 more
  // with the traction columns (friction given).
  const double row = (plastic ? 64 : 52) + (tangential ? 36 : 0);
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

std::vector<std::string> parse_fail_on(const std::string& text) {
  std::string known;
  for (const WarningClassInfo& c : warning_classes()) known += std::string(c.name) + ", ";
  known += "cant";
  std::vector<std::string> classes;
  std::size_t a = 0;
  while (true) {
    const std::size_t b = text.find(',', a);
    const std::string c = text.substr(a, b == std::string::npos ? std::string::npos : b - a);
    bool ok = c == "cant";
    for (const WarningClassInfo& k : warning_classes()) ok = ok || c == k.name;
    if (!ok)
      throw InputError("--fail-on", "\"" + c + "\"", c.empty() ? "empty warning class" : "not a warning class",
                       "the classes are " + known + "; --fail-on-warning fails on any");
    if (std::find(classes.begin(), classes.end(), c) == classes.end()) classes.push_back(c);
    if (b == std::string::npos) break;
    a = b + 1;
  }
  return classes;
}

nlohmann::json SweepCounts::rcf_ty_json() const {
  auto number_or_null = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  std::map<double, std::vector<const DamagePoint*>> by_Q;
  for (const DamagePoint& d : damage_points) by_Q[d.Q_kN].push_back(&d);
  nlohmann::json a = nlohmann::json::array();
  for (const auto& [Q, pts] : by_Q) {
    std::vector<std::pair<double, double>> D, W;
    double lo = INFINITY, hi = -INFINITY;
    std::uint64_t unsolved = 0;
    for (const DamagePoint* d : pts) {
      if (!d->solved) {
        ++unsolved;
        continue;
      }
      D.emplace_back(d->tY_mm, d->damage), W.emplace_back(d->tY_mm, d->wear_ug_per_m);
      lo = std::min(lo, d->tY_mm), hi = std::max(hi, d->tY_mm);
    }
    const double nan = NAN;
    const bool any = !D.empty();
    a.push_back({{"Q_kN", Q}, {"tY_mean_mm", tY_mean_mm}, {"tY_sd_mm", tY_sd_mm},
                 {"tY_from_mm", any ? nlohmann::json(lo) : nlohmann::json()}, {"tY_to_mm", any ? nlohmann::json(hi) : nlohmann::json()},
                 {"cases", D.size()}, {"cases_unsolved", unsolved},
                 {"D_burstow_per_axle", number_or_null(any ? ty_weighted(D, tY_mean_mm, tY_sd_mm) : nan)},
                 {"wear_ug_per_m", number_or_null(any ? ty_weighted(W, tY_mean_mm, tY_sd_mm) : nan)}});
  }
  return a;
}

std::string warnings_failure(const RunOptions& opt, const SweepCounts& counts, std::uint64_t cant_warnings) {
  if (opt.fail_on_warning) {
    if (!counts.with_warnings && !cant_warnings) return {};
    return "mhcontact run: " + std::to_string(counts.with_warnings) + " cases with warnings, " +
           std::to_string(cant_warnings) + " cant warning(s) (--fail-on-warning): exit 1\n";
  }
  std::string found;
  for (const std::string& c : opt.fail_on) {
    std::uint64_t n = 0;
    if (c == "cant") n = cant_warnings;
    else if (auto it = counts.warnings.find(c); it != counts.warnings.end()) n = it->second;
    if (n) found += (found.empty() ? "" : ", ") + std::to_string(n) + (c == "cant" ? " cant warning(s)" : " cases with " + c);
  }
  return found.empty() ? std::string() : "mhcontact run: " + found + " (--fail-on): exit 1\n";
}

std::string progress_line(std::uint64_t done, std::uint64_t total, double secs) {
  char buf[160];
  const double rate = secs > 0 ? static_cast<double>(done) / secs : 0;
  const int pct = total ? static_cast<int>(100.0 * static_cast<double>(done) / static_cast<double>(total)) : 100;
  std::string left = "?";
  if (rate > 0) {
    const double s = static_cast<double>(total - done) / rate;
    char l[32];
    if (s < 60) std::snprintf(l, sizeof l, "%.0f s", std::ceil(s));
    else if (s < 3600) std::snprintf(l, sizeof l, "%d min %02d s", static_cast<int>(s) / 60, static_cast<int>(s) % 60);
    else std::snprintf(l, sizeof l, "%d h %02d min", static_cast<int>(s) / 3600, static_cast<int>(s) / 60 % 60);
    left = l;
  }
  std::snprintf(buf, sizeof buf, "mhcontact run: %llu/%llu cases (%d %%), %.0f cases/s, %s left   ",
                static_cast<unsigned long long>(done), static_cast<unsigned long long>(total), pct, rate, left.c_str());
  return buf;
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

namespace {

// Append `lines` to `s`, each line preceded by `prefix`.
void append_prefixed(std::string& s, const std::string& prefix, const std::string& lines) {
  if (prefix.empty()) { s += lines; return; }
  std::size_t a = 0;
  while (a < lines.size()) {
    const std::size_t b = lines.find('\n', a);
    const std::size_t e = b == std::string::npos ? lines.size() : b + 1;
    s += prefix;
    s.append(lines, a, e - a);
    a = e;
  }
}

// The rows of one slice of a chunk (kSlice cases, one case for the grid methods), formatted and
// prefixed.
struct Block {
  std::string cases, ellipses, patches, pressure, strips;
  std::vector<std::string> json;
  void clear() { cases.clear(); ellipses.clear(); patches.clear(); pressure.clear(); strips.clear(); json.clear(); }
};

// One chunk in flight: the blocks of its slices, in case order.
struct Slot {
  std::vector<Block> blocks;
  std::vector<CaseStatus> status;
  std::vector<std::vector<std::string>> warning_kinds;  ///< per case, each kind once
  std::vector<SweepCounts::DamagePoint> damage;          ///< per case, when SweepCounts collects them
  std::size_t m = 0;
  std::size_t n_blocks = 0;  ///< blocks filled for this chunk (the last chunk may use fewer)
};

// The writer thread: writes a finished slot while the workers fill the other one.
class Writer {
 public:
  explicit Writer(const Sinks& out) : out_(out), th_([this] { loop(); }) {}
  ~Writer() { finish(); }
  // Wait until `slot` is written (free to refill).
  void wait_free(const Slot* slot) {
    std::unique_lock<std::mutex> l(m_);
    cv_.wait(l, [&] { return queue_ != slot || error_; });
  }
  void submit(const Slot* slot) {
    std::unique_lock<std::mutex> l(m_);
    cv_.wait(l, [&] { return queue_ == nullptr; });
    queue_ = slot;
    cv_.notify_all();
  }
  void finish() {
    {
      std::unique_lock<std::mutex> l(m_);
      cv_.wait(l, [&] { return queue_ == nullptr; });
      stop_ = true;
    }
    cv_.notify_all();
    if (th_.joinable()) th_.join();
  }
  bool error() {
    std::lock_guard<std::mutex> l(m_);
    return error_;
  }

 private:
  void loop() {
    for (;;) {
      const Slot* s;
      {
        std::unique_lock<std::mutex> l(m_);
        cv_.wait(l, [&] { return stop_ || queue_ != nullptr; });
        if (queue_ == nullptr) return;
        s = queue_;
      }
      const bool ok = write_slot(out_, *s);
      std::lock_guard<std::mutex> l(m_);
      if (!ok) error_ = true;
      queue_ = nullptr;
      cv_.notify_all();
    }
  }
 public:
  static bool write_slot(const Sinks& out, const Slot& s) {
    for (std::size_t k = 0; k < s.n_blocks; ++k) {
      const Block& b = s.blocks[k];
      if (out.cases) out.cases->write(b.cases.data(), static_cast<std::streamsize>(b.cases.size()));
      if (out.ellipses) out.ellipses->write(b.ellipses.data(), static_cast<std::streamsize>(b.ellipses.size()));
      if (out.patches) out.patches->write(b.patches.data(), static_cast<std::streamsize>(b.patches.size()));
      if (out.pressure) out.pressure->write(b.pressure.data(), static_cast<std::streamsize>(b.pressure.size()));
      if (out.strips) out.strips->write(b.strips.data(), static_cast<std::streamsize>(b.strips.size()));
      if (out.json) for (const auto& j : b.json) out.json->element(j);
    }
    for (OutputFile* f : out.files) f->start_writeback();
    return !((out.cases && !*out.cases) || (out.ellipses && !*out.ellipses) || (out.patches && !*out.patches) ||
             (out.pressure && !*out.pressure) ||
             (out.strips && !*out.strips) || (out.json && !out.json->good()));
  }
 private:
  const Sinks& out_;
  std::mutex m_;
  std::condition_variable cv_;
  const Slot* queue_ = nullptr;
  bool stop_ = false, error_ = false;
  std::thread th_;
};

}  // namespace

void write_geometry(const CaseFile& cf, const ContactGeometry& G, std::uint64_t first, std::uint64_t end,
                    std::ostream* csv, const std::string& prefix, JsonObjectStream* json) {
  if (!csv && !json) return;
  const MultiHertzOptions so = cf.method_options().multi_hertzian;
  std::unordered_set<std::string> seen;  // t_Y as written in the tables
  std::vector<CandidateEllipse> cands;
  std::vector<std::string> records;
  std::string key, rows;
  bool have_last = false;
  std::uint64_t last_bits = 0;
  // A sweep runs Q inside t_Y (case i has t_Y number i / nQ): one case per t_Y is enough, so the
  // pass costs the number of t_Y, not of cases. A case list: every case, skipping a t_Y equal to
  // the previous case's.
  const std::uint64_t stride = cf.cases.empty() ? std::max<std::uint64_t>(cf.sweep_Q_kN.size(), 1) : 1;
  for (std::uint64_t i = first; i < end; i = (i / stride + 1) * stride) {
    const CasePoint cp = cf.case_at(i);
    std::uint64_t b;
    std::memcpy(&b, &cp.tY_mm, sizeof b);
    if (have_last && b == last_bits) continue;
    have_last = true;
    last_bits = b;
    if (!G.covers(cp.tY)) continue;  // out_of_range cases have no candidates
    key.clear();
    cells::num(key, cp.tY_mm);
    if (!seen.insert(key).second) continue;
    candidate_ellipses(G, cf.material, cp.tY, so, cands);
    format_geometry(cp.tY_mm, cands, csv != nullptr, json != nullptr, rows, json ? &records : nullptr);
    if (csv) put_prefixed(*csv, prefix, rows);
    if (json) for (const std::string& r : records) json->element(r);
  }
}

// Solve cases [first, end) of `cf` on `G` and write them in order. A persistent pool of workers
// fills one chunk (each worker a contiguous slice, formatted into its own block) while a writer
// thread writes the previous chunk (double buffers); the bytes are the same for any thread count.
void solve_cases(const CaseFile& cf, const ContactGeometry& G, std::uint64_t first, std::uint64_t end,
                 const RunOptions& opt, const Sinks& out, SweepCounts* counts, std::ostream& err,
                 const BandGeometries* band) {
  const bool plastic = cf.model == Model::Plastic;
  const bool want_csv = out.cases != nullptr, want_json = out.json != nullptr;
  const int np = out.pressure ? opt.pressure_grid : 0;
  MethodOptions mo = cf.method_options();
  // The subsurface columns of a grid patch from its own pressure ("subsurface": {"grid": true}).
  const bool grid_stresses = cf.rcf.enabled() && cf.rcf.subsurface && cf.rcf.subsurface_grid;
  mo.half_space.keep_pressure = np > 0 || grid_stresses;
  mo.strips.keep_strips = out.strips != nullptr || grid_stresses;
  const bool grid_method = mo.method != Method::MultiHertzian;
  // The band's solves (add_smoothing_band) keep nothing but the case summary (pmax, area).
  const MethodOptions mo_band = cf.method_options();
  const bool with_band = band && band->any();
  RcfOptions rcf = cf.rcf;  // the RCF columns, k resolved (contact/rcf/shakedown.hpp)
  if (rcf.enabled()) rcf.k = rcf_shear_yield(cf.material, cf.rcf);
  rcf.nu = cf.material.nur();  // the subsurface stresses are the rail's
  const bool tang = cf.tangential.enabled();  // the tangential columns (docs/tangential.md)
  // The cases whose pressure grid is written keep their tractions per element too (the traction
  // columns of pressure.csv), and so does every case whose grid patches' stresses take their
  // solved traction, and every case whose ellipses' stresses take FASTSIM's traction
  // (contact/rcf/contact_stresses.hpp); every other case keeps nothing
  // (TangentialOptions::keep_traction).
  const bool any_stresses = cf.rcf.enabled() && cf.rcf.subsurface;
  mo.tangential.keep_traction = tang && (grid_stresses || any_stresses);
  MethodOptions mo_grid = mo;
  mo_grid.tangential.keep_traction = tang && (np > 0 || grid_stresses || any_stresses);
  const std::uint64_t n = end - first;
  if (n == 0) return;
  const unsigned threads = std::max(1u, opt.threads ? opt.threads : std::thread::hardware_concurrency());
  const std::size_t chunk = opt.chunk ? opt.chunk : std::max<std::size_t>(2048, std::size_t{1024} * threads);
  const unsigned nt = static_cast<unsigned>(std::min<std::uint64_t>(threads, std::min<std::uint64_t>(chunk, n)));
  // Workers take the slices of a chunk from a shared counter, so a worker slowed down (by the
  // writer thread sharing its core, or by an expensive case) does not leave the others waiting
  // at the end of the chunk; the slices' blocks are written in case order, so the bytes do not
  // depend on who solved what. Grid-method cases cost 0.2 ms to 1 s each: one case per slice.
  const std::size_t slice = grid_method ? 1 : 256;
  const std::size_t n_slices = (static_cast<std::size_t>(std::min<std::uint64_t>(chunk, n)) + slice - 1) / slice;
  // Two slots with a writer thread (one filled while the other is written), one without.
  const int n_slots = nt > 1 ? 2 : 1;
  Slot slots[2];
  for (int k = 0; k < n_slots; ++k) {
    Slot& s = slots[k];
    s.blocks.resize(n_slices);
    s.status.resize(static_cast<std::size_t>(std::min<std::uint64_t>(chunk, n)));
    s.warning_kinds.resize(s.status.size());
    s.damage.resize(s.status.size());
  }
  const bool collect_damage = counts->tY_sd_mm > 0 && tang;
  std::mutex fail_mutex;
  std::uint64_t fail_case = UINT64_MAX;
  std::string fail_what;
  std::vector<Formatted> scratch(nt);
  // Each worker's result and grid memory, reused case after case (solve_contact's workspace form:
  // the same bytes; no allocation per case once their vectors have grown).
  std::vector<CaseResult> results(nt);
  std::vector<GridWorkspace> grid_ws(nt);
  Pool pool(nt);
  // --threads 1: everything on this thread, no writer thread; otherwise a writer overlaps.
  std::unique_ptr<Writer> writer = nt > 1 ? std::make_unique<Writer>(out) : nullptr;
  auto write_failed = [&] { return OutputError(out.cases ? "cases.csv" : out.json_where, "output could not be written", "disk full?"); };
  const auto t_start = std::chrono::steady_clock::now();
  auto last_shown = t_start - std::chrono::seconds(1);
  int cur = 0;
  for (std::uint64_t c0 = first; c0 < end; c0 += chunk, cur = (cur + 1) % n_slots) {
    Slot& S = slots[cur];
    if (writer) {
      writer->wait_free(&S);
      if (writer->error()) throw write_failed();
    }
    const std::size_t m = static_cast<std::size_t>(std::min<std::uint64_t>(chunk, end - c0));
    S.m = m;
    std::atomic<std::size_t> next_slice{0};
    const std::size_t slices = (m + slice - 1) / slice;
    const std::function<void(unsigned)> work = [&](unsigned t) {
      Formatted& f = scratch[t];
      CaseResult& r = results[t];
      for (std::size_t k; (k = next_slice.fetch_add(1)) < slices;) {
      Block& B = S.blocks[k];
      B.clear();
      const std::size_t a = k * slice, b = std::min(m, a + slice);
      for (std::size_t i = a; i < b; ++i) {
        const CasePoint cp = cf.case_at(c0 + i);
        try {
          if (g_case_hook) g_case_hook(c0 + i);
          const bool grid_case = np && opt.pressure_cases.contains(c0 + i);
          solve_contact(G, cf.material, cp.tY, cp.Q, grid_case ? mo_grid : mo, r, &grid_ws[t]);
          if (with_band) add_smoothing_band(r, *band, cf.material, cp.tY, cp.Q, mo_band);
          damage_step(r, rcf.burstow, rcf.usfd);  // the damage and wear of the Tγ columns, once per case
          S.status[i] = r.status;
          if (collect_damage)
            S.damage[i] = {cp.Q_kN, cp.tY_mm, r.damage.damage, r.damage.wear_per_metre * 1e9 /* kg/m → µg/m */,
                           !is_failure(r.status) && r.tangential.solved};
          auto& kinds = S.warning_kinds[i];
          kinds.clear();
          for (const Warning& w : r.warnings) {
            std::string k = to_string(w.cls);
            if (std::find(kinds.begin(), kinds.end(), k) == kinds.end()) kinds.push_back(std::move(k));
          }
          format_case(c0 + i, cp, r, plastic, want_csv, want_json, f, nullptr, rcf, tang);
          // The per-contact tables: ellipses (multi-Hertzian) and patches (grid methods); "auto"
          // writes each case into the table of the method that solved it.
          if (want_csv) {
            append_prefixed(B.cases, out.prefix, f.cases);
            if (out.ellipses) append_prefixed(B.ellipses, out.prefix, f.ellipses);
            if (out.patches) {
              format_patches(c0 + i, cp, r, plastic, f.patches, rcf, tang);
              append_prefixed(B.patches, out.prefix, f.patches);
            }
          }
          if (want_json) B.json.push_back(std::move(f.json));
          if (grid_case) {
            if (grid_method) format_patch_pressure(c0 + i, r, f.pressure, tang);
            else format_pressure(c0 + i, r, plastic, np, f.pressure, tang);
            append_prefixed(B.pressure, out.prefix, f.pressure);
          }
          if (out.strips) {
            format_strips(c0 + i, cp, r, f.strips);
            append_prefixed(B.strips, out.prefix, f.strips);
          }
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
      }
    };
    S.n_blocks = slices;
    pool.run(work);
    if (fail_case != UINT64_MAX) {
      if (writer) writer->finish();
      throw std::runtime_error("case " + std::to_string(fail_case) + ": " + fail_what);
    }
    for (std::size_t i = 0; i < m; ++i) {
      ++counts->by_status[to_string(S.status[i])];
      if (is_failure(S.status[i])) ++counts->failed;
      for (const std::string& k : S.warning_kinds[i]) ++counts->warnings[k];
      if (!S.warning_kinds[i].empty()) ++counts->with_warnings;
      if (collect_damage) counts->damage_points.push_back(S.damage[i]);
    }
    if (writer) {
      writer->submit(&S);
    } else if (!Writer::write_slot(out, S)) {
      // Stop at the first failed write (a full disk) rather than solve millions more cases.
      throw write_failed();
    }
    if (opt.progress && !opt.quiet) {
      // At most 4 refreshes a second, and at least one a second while chunks keep finishing.
      const auto now = std::chrono::steady_clock::now();
      const std::uint64_t done = c0 + m - first;
      if (now - last_shown >= std::chrono::milliseconds(250) || done == n) {
        err << "\r" << progress_line(done, n, std::chrono::duration<double>(now - t_start).count()) << std::flush;
        last_shown = now;
      }
    }
  }
  if (writer) {
    writer->finish();
    if (writer->error()) throw write_failed();
  }
}

}  // namespace mh
