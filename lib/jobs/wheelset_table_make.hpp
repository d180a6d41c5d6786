#pragma once
// `mhcontact table-wheelset LEFT.csv RIGHT.csv -o FILE` (docs/tables.md "A wheelset table"): the
// tables of a wheelset's two pairs, each made by `mhcontact table` (threads, shards, the cluster
// routes), joined into one wheelset table file (input/wheelset_table.hpp) under a header of its
// own: the two tables' text copied byte for byte, their checksums, placements and ranges.
#include <iosfwd>
#include <string>

namespace mh {

/// Read and check both tables (each must be a pair table with its wheelset placement; both the
/// same method, model and flange-back distance), write the wheelset table atomically (`-` for
/// standard output), print what it holds. Returns 0. Throws InputError naming the file and rule.
int wheelset_table_job(const std::string& left_path, const std::string& right_path, const std::string& out_path,
                       std::ostream& out, std::ostream& err, bool quiet);

}  // namespace mh
