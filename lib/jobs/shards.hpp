#pragma once
// Sharded runs: `run --shard K/N` runs one deterministic slice; `mhcontact merge` joins the shard
// directories into exactly the tables one run would have written.
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace mh {

/// Parse "K/N" (1 ≤ K ≤ N ≤ 100000). Throws InputError naming `--shard`.
void parse_shard(const std::string& text, unsigned* index, unsigned* count);

/// How `--shard K/N` cuts a list of units (cases, pairs, or every pair's cases; --shard-sizes).
enum class ShardSizes {
  Equal,    ///< "equal": slice K is [⌊(K−1) u/N⌋, ⌊K u/N⌋)
  /// "tapered": slice K's share proportional to N − K + 1, [⌊u C(K−1)/C(N)⌋, ⌊u C(K)/C(N)⌋) with
  /// C(j) = j (2N − j + 1)/2: the first 2/(N+1) of the list, the last 2/(N(N+1)). For shards
  /// handed out in order as workers free up (a Dask cluster, a Slurm array with fewer CPUs than
  /// tasks): the last to start are the smallest, so the workers end close together whatever
  /// their cases cost (docs/cluster.md). Needs several shards a worker: with N no larger than
  /// the workers, equal slices end together and tapered ones do not.
  Tapered,
};
/// "equal" / "tapered"; parse_shard_sizes throws InputError naming `--shard-sizes` otherwise.
const char* to_string(ShardSizes s);
ShardSizes parse_shard_sizes(const std::string& text);
/// The slice [first, end) of `units` that shard K of N holds (1 ≤ K ≤ N). The slices of
/// K = 1 … N tile [0, units) in order.
struct ShardSlice {
  std::uint64_t first = 0, end = 0;
};
ShardSlice shard_slice(std::uint64_t units, unsigned K, unsigned N, ShardSizes sizes = ShardSizes::Equal);

/// `mhcontact merge DIR... -o OUT`: join the outputs of all N shards of one run (in any order
/// on the command line) into OUT. Checks that every shard 1..N is there once, that all come from
/// the same inputs and that their slices tile the case list. Returns 0 if every case is ok, 1 if
/// some are not (as the unsharded run would), throws InputError otherwise.
int merge_job(const std::vector<std::string>& dirs, const std::string& out_dir, std::ostream& err, bool quiet);

}  // namespace mh
