#pragma once
// `mhcontact run MANIFEST -o OUT --resume`: a fleet that survives an interruption. Each pair is
// run as its own shard (K/n_pairs) into OUT.parts/pairK, then the parts are merged into OUT.
// A pair's directory appears only complete (jobs write into a temporary sibling directory that
// is renamed into place once every file and its shard.json are written: output/run_dir.hpp), so
// a run killed at any moment leaves the pairs it finished and nothing half written; the next
// `--resume` run with the same inputs and output options skips them.
#include <iosfwd>

#include "input/manifest.hpp"
#include "jobs/sweep.hpp"

namespace mh {

/// The resumable fleet. Throws InputError for options it cannot honour (--shard, --fail-on,
/// --fail-on-warning, -o -). OUT.parts is kept after the merge (a later --resume with the same
/// inputs recomputes nothing); delete it once OUT is complete. Returns merge's exit code (0 every
/// case ok, 1 some not).
int resumable_batch_job(const Manifest& m, const RunOptions& opt, std::ostream& out, std::ostream& err);

/// The directory that holds the parts of the resumable run into `out_dir`: "<out_dir>.parts".
std::string resume_parts_dir(const std::string& out_dir);

}  // namespace mh
