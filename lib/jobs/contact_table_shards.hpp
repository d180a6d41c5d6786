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
#include <iosfwd>
#include <string>
#include <vector>

#include "jobs/contact_table_make.hpp"
#include "jobs/contact_table_solves.hpp"

namespace mh {

/// The schema tag of a shard file.
constexpr const char* kContactTableShardSchema = "mhcontact.table-shard/1";

/// `mhcontact table CASE.json --shard K/N -o FILE`: solve shard K's points, write them atomically
/// (`-` for standard output). Returns 0.
int table_shard_job(const CaseFile& cf, const TableMakeOptions& opt, const std::string& shard, const std::string& out_path,
                    std::ostream& out, std::ostream& err);

/// The solves of the shard files of `cf`'s table, checked: each a shard file of the same inputs,
/// profiles (checksums), check option and program, shards 1..N each once, their points the first
/// round's. Throws InputError naming the file and the rule.
TableSolves read_table_shards(const CaseFile& cf, const PairGeometry& pg, const TableMakeOptions& opt,
                              const std::vector<std::string>& files);

}  // namespace mh
