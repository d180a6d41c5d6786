#pragma once
// The jobs behind `mhcontact geometry` and `mhcontact run`: build the geometry of the case's
// profile pair once, solve every case, stream the tables to their files (never held in memory,
// never half written: OutputFile), byte-identical whatever the thread count.
#include <iosfwd>
#include <string>
#include <vector>

#include "mhcontact/case_file.hpp"
#include "mhcontact/geometry.hpp"

namespace mh {

struct RunOptions {
  std::string out_dir;          ///< output directory; "-" writes results.json to `out` only
  bool csv = true;              ///< write cases.csv and ellipses.csv (default yes)
  bool json = true;             ///< write results.json (default yes)
  unsigned threads = 0;         ///< worker threads; 0 = all cores (default)
  bool quiet = false;           ///< no summary or progress on `err`
  bool progress = false;        ///< progress display on `err` (the CLI sets it when err is a terminal)
  std::size_t chunk = 8192;     ///< cases solved per parallel batch (default 8192)
  /// N > 0: also write DIR/pressure.csv, the pressure of every loaded ellipse on an N × N grid
  /// over its patch (x along the rolling direction, y lateral in the contact plane). Default 0.
  int pressure_grid = 0;
  /// Shards: run only the K-th (1-based) of N contiguous, deterministic slices of the case list:
  /// cases [floor((K−1)·n/N), floor(K·n/N)), keeping their global case numbers, and write
  /// DIR/shard.json describing the slice. `mhcontact merge` joins the shard directories into
  /// exactly the tables one run would have written. Default 1/1 (no sharding, no shard.json).
  unsigned shard_index = 1, shard_count = 1;
};

struct Manifest;
/// `mhcontact run MANIFEST.json`: every case of the shared sweep on every profile pair, geometry
/// built once per pair; tables with a leading `pair` column, plus DIR/pairs.csv. A pair that cannot
/// be read or placed gets status `invalid_pair` in pairs.csv and in each of its case rows, and the
/// batch goes on. With --shard K/N the slices are over pairs. Returns 0 if every case of every
/// pair is ok, 1 otherwise.
int batch_job(const Manifest& m, const RunOptions& opt, std::ostream& out, std::ostream& err);

/// Parse "K/N" (1 ≤ K ≤ N ≤ 100000). Throws InputError naming `--shard`.
void parse_shard(const std::string& text, unsigned* index, unsigned* count);

/// `mhcontact merge DIR... -o OUT`: join the outputs of all N shards of one run (in any order
/// on the command line) into OUT. Checks that every shard 1..N is there once, that all come from
/// the same inputs and that their slices tile the case list. Returns 0 if every case is ok, 1 if
/// some are not (as the unsharded run would), throws InputError otherwise.
int merge_job(const std::vector<std::string>& dirs, const std::string& out_dir, std::ostream& err, bool quiet);

/// Everything a geometry build produced, with the profiles it was built from.
struct PairGeometry {
  Profile wheel, rail;
  ContactGeometry geo;
};
PairGeometry build_pair_geometry(const CaseFile& cf);

/// `mhcontact geometry`: writes DIR/caf.csv and DIR/geometry.json. Returns the exit code.
int geometry_job(const CaseFile& cf, const std::string& out_dir, std::ostream& out, std::ostream& err, bool quiet);

/// `mhcontact run`: returns 0 when every case is ok, 1 when some are not (kExitCasesFailed).
int run_job(const CaseFile& cf, const RunOptions& opt, std::ostream& out, std::ostream& err);

/// The column names of the tables (README "Output tables").
std::string cases_csv_header();
std::string ellipses_csv_header(bool plastic);
std::string pressure_csv_header(bool plastic);

}  // namespace mh
