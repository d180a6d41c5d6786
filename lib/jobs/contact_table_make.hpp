#pragma once
// Making a contact table (docs/tables.md): the case file's method (strips, half-space or auto)
// solved at every node of its t_Y × Q (× roll) sweep on the jobs' thread pool, each node's
// contacts matched to those of its neighbours by position into tracks, the interpolant checked
// against direct solves at every cell's centre, intervals halved where a cell misses its
// tolerance, the table made validated at random points it was not made on, and written as CSV
// with a JSON header (input/contact_table.hpp reads it).
#include <cstdint>
#include <iosfwd>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "geometry/contact_geometry.hpp"
#include "input/case_file.hpp"
#include "input/contact_table.hpp"
#include "jobs/contact_table_check.hpp"
#include "jobs/contact_table_solves.hpp"

namespace mh {

/// Options of `mhcontact table` (defaults documented in docs/tables.md).
struct TableMakeOptions {
  unsigned threads = 0;       ///< worker threads; 0 = all cores (default). The table does not depend on it.
  bool check = true;          ///< solve every cell's centre directly and measure the error (default yes)
  /// Check points a cell: 1 its centre (default), or 3: also the points a quarter and three
  /// quarters along its main diagonal, a cell missing a tolerance at any of them refined (and
  /// coarse if it still misses). The tricubic interpolant's error is largest away from the centre
  /// in some cells (docs/tables.md "Checking a table at random points").
  int check_points = 1;
  /// Points drawn uniformly over the table's t_Y, Q (and roll) ranges (seed kTableValidationSeed),
  /// solved directly and compared with the table made, after it is made: never used to refine or
  /// to mark cells, so their errors measure the table where its check points do not (header
  /// `validation`, docs/tables.md "How it is made", step 6). 0: none. Only with `check`.
  int validate = 100;
  int refine = 3;             ///< rounds of halving the t_Y and Q intervals whose cells miss a tolerance (default 3; 0: none)
  double min_step_mm = 0.05;  ///< no t_Y interval is halved below this (default 0.05 mm)
  double min_Q_step_kN = 5;   ///< no Q interval is halved below this (default 5 kN)
  double min_roll_step_mrad = 0.125;  ///< no roll interval is halved below this (default 0.125 mrad)
  double tol_N = 0.01;        ///< contact normal force: |ΔN| / Q (default 1 %)
  double tol_pmax = 0.03;     ///< peak pressure, relative (default 3 %)
  double tol_area = 0.05;     ///< total area, relative (default 5 %)
  double tol_position_mm = 0.5;  ///< contact position on the rail, mm (reported; default 0.5 mm)
  bool quiet = false;
};

/// A made table and its check.
struct TableMade {
  ContactTableData data;                 ///< with its header (the error summary included)
  std::vector<TableCheckError> checks;   ///< check_points per cell of the final grid, in cell order (check on)
  std::vector<TableCheckError> validation;  ///< at the validation points, in their order (check on, validate > 0)
  std::size_t solves = 0;                ///< direct solves made (nodes and check points)
  /// With `defer`: the points the making needs next that the presolved solves do not hold,
  /// sorted. While it is not empty the table is not made (`data` is empty): solve them (the
  /// shards of `mhcontact table --shard K/N --points FILE`) and make again with them.
  std::vector<TablePoint> pending;
};

/// The initial nodes of `cf`'s table (its sweep: t_Y from/to/step or a list, Q a list of at
/// least two values, the roll a list or range, {0} when not given), sorted, in mm, kN and mrad.
/// Throws InputError for a case file that cannot make a table (a case list, one Q, the
/// multi-Hertzian method).
void table_initial_nodes(const CaseFile& cf, std::vector<double>& tY_mm, std::vector<double>& Q_kN,
                         std::vector<double>& roll_mrad);

/// The points the first round of making solves: the initial nodes, then with `opt.check` the
/// centres of their cells and the validation points. The shards of `mhcontact table --shard K/N`
/// split them.
std::vector<TablePoint> table_first_points(const CaseFile& cf, const TableMakeOptions& opt);

/// Make the table of `cf` (its pair `pg`, method, material; its sweep gives the initial nodes).
/// `presolved` (the shards' solves, contact_table_shards.hpp) are taken instead of solving those
/// points again: the table is the same. With `defer`, points it needs that `presolved` does not
/// hold are not solved here: the making stops at the first batch of them and returns it as
/// `pending` (the refinement's solves split into shards too, docs/tables.md "Shards"). Each batch
/// is what one step of making asks for at once: a round's new nodes with the centres of their
/// cells, or the edge midpoints of its failing cells. Throws InputError as table_initial_nodes.
TableMade make_contact_table(const CaseFile& cf, const PairGeometry& pg, const TableMakeOptions& opt, std::ostream& err,
                             const TableSolves* presolved = nullptr, bool defer = false);

/// The table as its file's text (CSV with the JSON header line).
void write_contact_table(const ContactTableData& t, std::ostream& out);

/// `mhcontact table CASE.json -o FILE`: make, write atomically, print the error summary. Returns
/// 0, or 1 when some cells stay beyond tolerance (coarse), some nodes have no answer, or a
/// validation point finds the table `ok` beyond a tolerance or where the direct solve is not `ok`. With
/// `shard_files` (`--merge`), the solves are the shards' (contact_table_shards.hpp: the first
/// round's and those of refinement passes) and the rest is solved here: the table is byte for byte
/// the one-process table. With `next_path` too (`--merge ... --next FILE`), the rest is not solved
/// here: when the making needs points the shards do not hold, they are written to `next_path`
/// (the points of the next pass, for `--shard K/N --points FILE`), no table is written and the
/// return is kExitMorePoints.
int table_job(const CaseFile& cf, const TableMakeOptions& opt, const std::string& out_path, std::ostream& out,
              std::ostream& err, const std::vector<std::string>& shard_files = {}, const std::string& next_path = {});

}  // namespace mh
