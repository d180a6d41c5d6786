#pragma once
// The direct solves a contact table is made of (docs/tables.md "How it is made"): what is kept
// of one solve at a point (t_Y, Q, roll) in the table's quantities, the solves of many points on the
// jobs' thread pool, and their JSON form for the shards of `mhcontact table --shard K/N`
// (contact_table_shards.hpp). Internal to the jobs layer.
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include <nlohmann/json.hpp>

#include "contact/case_result.hpp"
#include "core/parallel.hpp"
#include "geometry/contact_geometry.hpp"
#include "input/case_file.hpp"
#include "input/contact_table.hpp"

namespace mh {

/// One contact of a solved node, in the table's quantities, with its extent on the rail.
struct NodeContact {
  std::array<double, kTableQuantities> v{};
  double y_lo = 0, y_hi = 0;  ///< [m] rail y of its lateral ends
};

/// What is kept of one direct solve.
struct NodeSolve {
  CaseStatus status = CaseStatus::NotConverged;
  double pmax = 0, area = 0, Fy = 0;
  std::vector<NodeContact> contacts;  ///< in increasing rail y
};

/// A point of a table's grid, in the units of its file: t_Y [mm], Q [kN], roll δ [mrad].
struct TablePoint {
  double tY_mm = 0, Q_kN = 0, roll_mrad = 0;
  bool operator<(const TablePoint& o) const {
    if (tY_mm != o.tY_mm) return tY_mm < o.tY_mm;
    if (Q_kN != o.Q_kN) return Q_kN < o.Q_kN;
    return roll_mrad < o.roll_mrad;
  }
  bool operator==(const TablePoint& o) const { return tY_mm == o.tY_mm && Q_kN == o.Q_kN && roll_mrad == o.roll_mrad; }
};

/// A point coordinate (mm, kN or mrad) rounded to 1e-9 of its unit, where the maker rounds a point
/// it makes (t_Y and roll midpoints, check and validation points): a short number, the same key
/// however it was computed.
inline double table_point_rounded(double v) { return std::round(v * 1e9) / 1e9; }

/// The solves of a table by point: the nodes' and the check points'.
using TableSolves = std::map<TablePoint, NodeSolve>;

/// What a table keeps of the case result `r` (nu: the pair's combined Poisson ratio).
NodeSolve extract(const CaseResult& r, double nu);

/// Solve the points by the case's method on the pool (the wheel rolled by each point's δ), one
/// workspace per thread. The answers do not depend on the thread count.
std::vector<NodeSolve> solve_points(const CaseFile& cf, const PairGeometry& pg, const std::vector<TablePoint>& pts,
                                    Pool& pool);

/// A solve as JSON and back, every number exact (non-finite numbers as null and back as NaN).
/// from_json throws InputError naming `where` for a malformed solve.
nlohmann::json solve_to_json(const NodeSolve& s);
NodeSolve solve_from_json(const nlohmann::json& j, const std::string& where);

}  // namespace mh
