#pragma once
// Contacts across the nodes of a contact table (docs/tables.md "Contacts across nodes"): each
// node's contacts matched to those of its neighbours in t_Y, Q and roll into tracks, and the
// table's per-track values at every node (absent contacts filled). Internal to the jobs layer;
// jobs/contact_table_make.cpp calls it after every round of solves.
#include <vector>

#include "input/contact_table.hpp"
#include "jobs/contact_table_solves.hpp"

namespace mh {

/// The table of the nodes tY [m] × Q [N] × roll [rad] whose solves are `nodes`, in
/// ContactTableData::node order (roll outer, t_Y, Q): two contacts of neighbouring nodes are one
/// track when their rail extents overlap (within 0.5 mm) and each is the other's best overlap; a
/// track holding two contacts of one node keeps the larger and the other starts a track of its
/// own; tracks numbered in increasing mean rail y. Absent nodes: N, pressure and sizes 0, the
/// positions, angle, radius and Kalker coefficients of the nearest node with the contact (the
/// same roll first, then the same Q row, then the nearest rows). No header, no coarse cells.
ContactTableData build_table(const std::vector<double>& tY, const std::vector<double>& Q, const std::vector<double>& roll,
                             const std::vector<const NodeSolve*>& nodes);

}  // namespace mh
