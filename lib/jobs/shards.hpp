#pragma once
// Sharded runs: `run --shard K/N` runs one deterministic slice; `mhcontact merge` joins the shard
// directories into exactly the tables one run would have written.
#include <iosfwd>
#include <string>
#include <vector>

namespace mh {

/// Parse "K/N" (1 ≤ K ≤ N ≤ 100000). Throws InputError naming `--shard`.
void parse_shard(const std::string& text, unsigned* index, unsigned* count);

/// `mhcontact merge DIR... -o OUT`: join the outputs of all N shards of one run (in any order
/// on the command line) into OUT. Checks that every shard 1..N is there once, that all come from
/// the same inputs and that their slices tile the case list. Returns 0 if every case is ok, 1 if
/// some are not (as the unsharded run would), throws InputError otherwise.
int merge_job(const std::vector<std::string>& dirs, const std::string& out_dir, std::ostream& err, bool quiet);

}  // namespace mh
