#pragma once
// `mhcontact run MANIFEST.json`: every case of the shared sweep on every profile pair of a fleet.
#include <iosfwd>

#include "input/manifest.hpp"
#include "jobs/sweep.hpp"

namespace mh {

/// Geometry built once per pair; tables with a leading `pair` column, plus DIR/pairs.csv. A pair
/// that cannot be read or placed gets status `invalid_pair` in pairs.csv and in each of its case
/// rows, and the batch goes on. With --shard K/N the slices are over pairs. Returns 0 if every
/// case of every pair is ok, 1 otherwise.
int batch_job(const Manifest& m, const RunOptions& opt, std::ostream& out, std::ostream& err);

/// Batch-level status of a pair (the solver's CaseStatus knows nothing of pairs).
constexpr const char* kInvalidPair = "invalid_pair";

}  // namespace mh
