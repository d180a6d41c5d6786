#pragma once
// The sweep runner: solves a range of the cases of a case file on one profile pair's geometry in
// parallel chunks, formats each case's rows in its worker, and writes them to the sinks in case
// order, so the output is byte-identical whatever the thread count.
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "geometry/contact_geometry.hpp"
#include "input/case_file.hpp"
#include "jobs/shards.hpp"
#include "output/json_stream.hpp"
#include "output/output_file.hpp"

namespace mh {

/// A set of case numbers written as a list of numbers and ranges, "3,17,40-45" (--pressure-cases).
/// Empty: every case.
struct CaseSelection {
  std::vector<std::pair<std::uint64_t, std::uint64_t>> ranges;  ///< inclusive, sorted, disjoint
  bool all() const { return ranges.empty(); }
  bool contains(std::uint64_t c) const;
  /// How many of the cases [first, end) it holds.
  std::uint64_t count_in(std::uint64_t first, std::uint64_t end) const;
  std::uint64_t largest() const { return ranges.empty() ? 0 : ranges.back().second; }
};
/// Parse "3,17,40-45" (numbers >= 0, ranges a-b with a <= b). Throws InputError on --pressure-cases.
CaseSelection parse_case_selection(const std::string& text);

/// Options of `run` shared by single runs and batches.
struct RunOptions {
  std::string out_dir;          ///< output directory; "-" writes results.json to `out` only
  bool csv = true;              ///< write cases.csv and ellipses.csv (default yes)
  bool json = true;             ///< write results.json (default yes)
  unsigned threads = 0;         ///< worker threads; 0 = all cores (default)
  bool quiet = false;           ///< no summary or progress on `err`
  bool progress = false;        ///< progress display on `err` (the CLI sets it when err is a terminal)
  /// Cases solved per parallel batch; 0 (default): 1024 a thread, at least 2048. A batch's
  /// formatted rows are held until written (about 2 kB a case with results.json), twice with
  /// more than one thread (one batch solved while the other is written): a process's working set,
  /// which every shard's process maps afresh.
  std::size_t chunk = 0;
  /// N > 0: also write DIR/pressure.csv, the pressure of every loaded ellipse on an N × N grid
  /// over its patch (x along the rolling direction, y lateral in the contact plane), with friction
  /// also the tangential traction there (docs/outputs.md "pressure.csv"). Default 0.
  int pressure_grid = 0;
  /// The cases (their `case` numbers; in a batch, per pair) whose pressure grid is written;
  /// default: every case (--pressure-cases).
  CaseSelection pressure_cases;
  /// Shards: run only the K-th (1-based) of N contiguous, deterministic slices of the case list:
  /// cases [floor((K−1)·n/N), floor(K·n/N)), keeping their global case numbers, and write
  /// DIR/shard.json describing the slice. `mhcontact merge` joins the shard directories into
  /// exactly the tables one run would have written. Default 1/1 (no sharding, no shard.json).
  unsigned shard_index = 1, shard_count = 1;
  /// A batch manifest's shards slice the list of every pair's cases (pair after pair) instead of
  /// the pairs, so that one pair's cases can be spread over shards (--shard-by cases; a fleet of
  /// few pairs on more workers, or pairs of unequal cost). A case file's shards always slice its
  /// cases. Default no (slices of pairs).
  bool shard_by_cases = false;
  /// How --shard K/N cuts the list (--shard-sizes; jobs/shards.hpp, shard_slice): equal slices,
  /// or tapered, slice K's share proportional to N − K + 1, for shards handed out in order as
  /// workers free up (Dask; docs/cluster.md). Every shard of a run must be cut the same way.
  /// Default equal.
  ShardSizes shard_sizes = ShardSizes::Equal;
  /// Strip method: also write DIR/strips.csv (one row per loaded strip). Default no.
  bool strips = false;
  /// Write pressure.csv even when its estimated size is above kPressureLimitBytes (--force).
  bool force = false;
  bool fail_on_warning = false;  ///< exit 1 when any case has a warning, or the pair a cant warning (for CI)
  /// Exit 1 when any case carries a warning of one of these classes (`cant`: the pair's rail
  /// cant warning), whatever the case's status (--fail-on; docs/status.md). Empty: none.
  std::vector<std::string> fail_on;
  /// Significant digits of the numbers in the tables (--digits N), 0 = shortest round-trip (--digits max).
  int digits = 10;
};

/// Parse --digits: "max" (0) or an integer 1..17. Throws InputError.
int parse_digits(const std::string& text);

/// Parse --fail-on "non_hertzian,off_profile": comma-separated warning classes (those of
/// warning_classes() and `cant`). An unknown or empty class is an InputError naming the known
/// ones, so that a misspelt class cannot leave CI green.
std::vector<std::string> parse_fail_on(const std::string& text);

/// pressure.csv is refused before anything is solved when its estimated size (at least one
/// contact per case) is above this, unless forced (docs/outputs.md).
constexpr double kPressureLimitBytes = 10e9;

/// Refuse (InputError on --pressure-grid) a pressure grid of N×N points for `cases` cases whose
/// estimated pressure.csv is larger than kPressureLimitBytes, unless `force`. Also checks 2 <= N <= 1000.
/// `tangential`: its rows carry the traction columns.
void check_pressure_grid(int N, std::uint64_t cases, bool plastic, bool force, bool tangential = false);
/// Refuse --pressure-cases without --pressure-grid, or naming a case beyond the `cases` of the
/// case file (InputError on --pressure-cases).
void check_pressure_cases(const RunOptions& opt, std::uint64_t cases);

/// Where the formatted rows go; `prefix` is put in front of every CSV line (the batch's "pair,").
struct Sinks {
  std::ostream* cases = nullptr;
  std::ostream* ellipses = nullptr;  ///< ellipses.csv: the loaded ellipses of multi-Hertzian cases
  std::ostream* patches = nullptr;   ///< patches.csv: the contact patches of grid-method cases
  std::ostream* pressure = nullptr;
  std::ostream* strips = nullptr;    ///< strips.csv (strip method, --strips)
  JsonObjectStream* json = nullptr;  ///< with its case array open
  std::string prefix;
  std::string json_where = "results.json";  ///< names the JSON sink in a write error
  /// The files behind the sinks: each chunk, once written, is started on its way to the disk
  /// (OutputFile::start_writeback), so the final fsync does not flush the whole run serially.
  std::vector<OutputFile*> files;
};

/// Counts of a sweep by status.
struct SweepCounts {
  std::map<std::string, std::uint64_t> by_status;
  /// Cases without an answer (no_contact, out_of_range, not_converged; in a batch invalid_pair):
  /// the run exits 1 for them. `outside_validity` cases are answers and are not counted here.
  std::uint64_t failed = 0;
  /// Cases with at least one warning of each kind (the text before the first ':' of a warning,
  /// e.g. "non_hertzian_excluded"); a case with several warnings of one kind counts once.
  std::map<std::string, std::uint64_t> warnings;
  std::uint64_t with_warnings = 0;  ///< cases with any warning
  /// "rcf": {"tY_distribution"} with friction: the damage and wear of every case, for the
  /// summary's "rcf_tY_weighted" (rcf_ty_json()). Collected by solve_cases when tY_sd_mm > 0,
  /// which the caller sets for a whole sweep only (not for one shard of it: the weights need
  /// every t_Y).
  double tY_mean_mm = NAN, tY_sd_mm = NAN;
  struct DamagePoint {
    double Q_kN, tY_mm;
    double damage;         ///< [-] per axle, Σ over the case's contacts (cases.csv D_burstow_per_axle)
    double wear_ug_per_m;  ///< [µg/m] Σ over the contacts (cases.csv wear_ug_per_m)
    bool solved;           ///< an answer with every contact's tangential problem solved
  };
  std::vector<DamagePoint> damage_points;
  /// The summary object of results.json, run.json and shard.json.
  nlohmann::json summary_json(std::uint64_t cases) const {
    nlohmann::json j = {{"cases", cases}, {"failed", failed}, {"by_status", by_status},
                        {"cases_with_warnings", with_warnings}, {"warnings", warnings}};
    if (tY_sd_mm > 0) j["rcf_tY_weighted"] = rcf_ty_json();
    return j;
  }
  /// Per load Q of the sweep (ascending): the damage and wear weighted over its t_Y by the normal
  /// distribution N(tY_mean_mm, tY_sd_mm) (contact/rcf/ty_weighting.hpp), over the cases solved.
  nlohmann::json rcf_ty_json() const;
};

/// --fail-on-warning and --fail-on: "" when the run need not exit 1 for its warnings, else the
/// line that says why ("mhcontact run: 12 cases with off_profile (--fail-on): exit 1\n").
/// `cant_warnings`: pairs (or the single pair) whose rail cant is warned about.
std::string warnings_failure(const RunOptions& opt, const SweepCounts& counts, std::uint64_t cant_warnings);

/// geometry.csv and results.json's "geometry" records: for each distinct t_Y of
/// the cases [first, end) of `cf` that lies inside `G` (distinct as written in the tables), in
/// order of first appearance, every potential ellipse of G as a candidate there
/// (format_geometry()). CSV rows go to `csv` (each preceded by `prefix`), JSON records to `json`
/// (with an array open); either may be null. One pass over the case list before the sweep;
/// memory: the set of t_Y seen.
void write_geometry(const CaseFile& cf, const ContactGeometry& G, std::uint64_t first, std::uint64_t end,
                    std::ostream* csv, const std::string& prefix, JsonObjectStream* json);

/// Solve cases [first, end) of `cf` on `G` in parallel chunks and write them in order. With
/// `band` given (PairGeometry::band), each case with an answer gets the smoothing's uncertainty
/// band (add_smoothing_band: the band columns).
void solve_cases(const CaseFile& cf, const ContactGeometry& G, std::uint64_t first, std::uint64_t end,
                 const RunOptions& opt, const Sinks& out, SweepCounts* counts, std::ostream& err,
                 const BandGeometries* band = nullptr);

/// Tests only: a function called in the worker before each case is solved (it may throw, to
/// check that an exception inside a worker ends the run as an internal error). Empty: none.
void set_case_hook_for_tests(std::function<void(std::uint64_t)> hook);

/// The progress display: "mhcontact run: DONE/TOTAL cases (P %), R cases/s, T left".
std::string progress_line(std::uint64_t done, std::uint64_t total, double secs);

/// Write `lines` (one or more '\n'-terminated lines) to `o`, each preceded by `prefix`.
void put_prefixed(std::ostream& o, const std::string& prefix, const std::string& lines);

}  // namespace mh
