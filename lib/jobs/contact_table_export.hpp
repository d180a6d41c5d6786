#pragma once
// The export of a contact table on a regular grid for table-driven contact elements of MBS codes
// (docs/tables.md "Export for MBS codes"): the table's own interpolant (contact_table.hpp)
// evaluated at every point of a regular t_Y × Q grid at each of the table's roll nodes, every
// track at every point, in the table's column layout; the error of interpolating the export
// linearly, measured against the table's nodes and against the table's interpolant between the
// export's points, in its header.
#include <iosfwd>
#include <string>

#include "input/contact_table.hpp"

namespace mh {

/// Options of `mhcontact table-export` (defaults documented in docs/tables.md).
struct TableExportOptions {
  /// The grid's t_Y step; must divide the table's t_Y range. Default 0: the table's smallest t_Y
  /// interval, at most 0.25 mm, shortened to divide the range (a coarser grid misses what the
  /// refinement found near flange onset).
  double tY_step_mm = 0;
  double Q_step_kN = 10;     ///< the grid's Q step; must divide the table's Q range (default 10 kN)
};

/// The export of `table` (as read from its file; `source` names the file, `sha256` its checksum)
/// on the regular grid of `opt`: a ContactTableData whose nodes are the grid and whose header
/// has the schema kContactTableExportSchema, the grid, the source and the measured error.
/// Throws InputError (naming `source` and the option) when a step does not divide its range.
ContactTableData export_contact_table(const ContactTableData& table, const std::string& source,
                                      const std::string& sha256, const TableExportOptions& opt);

/// The rule an export's header states for reading it between its points: per track, every
/// quantity bilinear in (t_Y, Q) on its grid cell (trilinear in (t_Y, Q, roll) with more than
/// one roll node); a contact where the interpolated N > 0; the status the worst of the cell's
/// corners, at best outside_validity away from a single roll node's roll. Outside the grid:
/// out_of_range.
void export_linear(const ContactTableData& ex, double tY, double Q, double roll, TableAnswer& out);

/// `mhcontact table-export TABLE.csv -o FILE`: read, export, write atomically (`-` for standard
/// output), print the measured error. Returns 0.
int table_export_job(const std::string& table_path, const TableExportOptions& opt, const std::string& out_path,
                     std::ostream& out, std::ostream& err, bool quiet);

}  // namespace mh
