#pragma once
// Shards of making a contact table (docs/tables.md "Shards"): `mhcontact table CASE.json
// --shard K/N -o PART.json` solves the K-th of N deterministic slices of the first round's points
// (the initial nodes and the centres of their cells: point p of table_first_points goes to shard
// p mod N + 1) and writes the solves; `mhcontact table CASE.json --merge PART.json... -o TABLE`
// takes them instead of solving those points, and solves the refinement's points itself (the
// refinement needs the whole grid: which cells miss, which axis to halve). The merged table is
// byte for byte the one-process table. The merge rules are those of `mhcontact merge`
// (jobs/shards.hpp): every shard 1..N there once, all from the same inputs and program, their
// slices tiling the points.
//
// The refinement's solves split into shards too: `--merge PART... --next NEXT.json` does not
// solve what the shards lack but writes those points (the next *pass*: a round's new nodes with
// their cells' centres, or the edge midpoints of its failing cells) to NEXT.json and stops
// (exit 5); `--shard K/N --points NEXT.json` solves the K-th slice of them, point p to shard
// p mod N + 1 as above; the next merge is given every part of every pass so far. When the
// parts hold every point the making needs, the merge writes the table, byte for byte the
// one-process table.
#include <iosfwd>
#include <string>
#include <vector>

#include "jobs/contact_table_make.hpp"
#include "jobs/contact_table_solves.hpp"

namespace mh {

/// The schema tag of a shard file.
constexpr const char* kContactTableShardSchema = "mhcontact.table-shard/1";

/// The schema tag of the points of a refinement pass, written by a merge with `--next`.
constexpr const char* kContactTablePointsSchema = "mhcontact.table-points/1";

/// `mhcontact table CASE.json --shard K/N -o FILE`: solve shard K's points, write them atomically
/// (`-` for standard output). With `points_path` (`--points NEXT.json`), the points are those of
/// that refinement pass instead of the first round's. Returns 0.
int table_shard_job(const CaseFile& cf, const TableMakeOptions& opt, const std::string& shard, const std::string& out_path,
                    std::ostream& out, std::ostream& err, const std::string& points_path = {});

/// The solves of the shard files of `cf`'s table, checked: each a shard file of the same inputs,
/// profiles (checksums), check option and program; per pass (0: the first round's points, else
/// a refinement pass's, as its points file listed them) shards 1..N each once, their slices
/// tiling the pass's points. `passes` (if given) receives the index of the next pass: one above
/// the highest pass held. Throws InputError naming the file and the rule.
TableSolves read_table_shards(const CaseFile& cf, const PairGeometry& pg, const TableMakeOptions& opt,
                              const std::vector<std::string>& files, unsigned* passes = nullptr);

/// Write the points of refinement pass `pass` of `cf`'s table atomically to
/// `path` (kContactTablePointsSchema, with the inputs, profiles, check option and program that
/// the shards and the merge check).
void write_table_points(const CaseFile& cf, const PairGeometry& pg, const TableMakeOptions& opt, unsigned pass,
                        const std::vector<TablePoint>& points, const std::string& path);

}  // namespace mh
