#pragma once
// A contact table against direct solves (docs/tables.md "How it is made", steps 4 and 6): the
// error of the interpolant at one point, its summaries for the table's header (`error` at the
// check points, `validation` at the random points), and the validation points themselves.
#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "input/contact_table.hpp"
#include "jobs/contact_table_solves.hpp"

namespace mh {

/// The error of the interpolant at one check point against the direct solve there.
struct TableCheckError {
  double tY = 0, Q = 0, roll = 0;   ///< [m], [N], [rad]
  bool compared = false;  ///< both answered (else the statuses say why)
  double e_N = 0;         ///< max |ΔN| over the contacts, / Q
  double e_pmax = 0;      ///< |Δ pmax| / pmax
  double e_area = 0;      ///< |Δ area| / area
  double e_position = 0;  ///< [m] max |Δ y_rail| over the contacts carrying ≥ 5 % of Q
  double e_Fy = 0;        ///< |Δ Fy| / Q
  CaseStatus direct = CaseStatus::Ok, table = CaseStatus::Ok;
};

/// The tolerances a table is made to (TableMakeOptions::tol_*).
struct TableTolerances {
  double N = 0.01;            ///< a contact's normal force, fraction of Q (also Fy's)
  double pmax = 0.03;         ///< peak pressure, relative
  double area = 0.05;         ///< total area, relative
  double position_mm = 0.5;   ///< contact position on the rail [mm] (reported only)
};

/// The seed of the validation points (TableMakeOptions::validate): fixed, so that a table is the
/// same bytes wherever and in however many shards it is made.
constexpr std::uint64_t kTableValidationSeed = 1;

/// The table's answer T against the direct solve D at point p: each direct contact matched to the
/// nearest table contact in rail y (larger N first), the errors of N, peak pressure, area,
/// position and Fy; not compared where either has no answer.
TableCheckError table_check_error(const TableAnswer& T, const NodeSolve& D, const TablePoint& p);

/// The worst of a point's errors in units of its tolerances (N, peak pressure, area): > 1 missed.
double table_tolerance_ratio(const TableCheckError& e, const TableTolerances& tol);

/// The header's `error`: per quantity over the compared check points (check_points 1 or 3 a
/// cell) the count, how many beyond, median, 95th percentile, largest; and the statuses.
nlohmann::json table_error_summary(const std::vector<TableCheckError>& checks, const TableTolerances& tol, int check_points);

/// The header's `validation`: the statuses both ways, the same per-quantity figures where both
/// answers are `ok` (what an `ok` lookup claims), `beyond` (those beyond a tolerance of N, peak
/// pressure or area), the five `worst` of them, and the first five points where the table answers
/// ok and the direct solve does not.
nlohmann::json table_validation_summary(const std::vector<TableCheckError>& v, const TableTolerances& tol);

/// The validation points of a table whose initial nodes span tY_mm, Q_kN and roll_mrad: n of
/// them, uniform over the ranges, seed kTableValidationSeed (the first n of a longer sequence are
/// the same points); the roll the one node's without a roll axis; in mm, kN and mrad.
std::vector<TablePoint> table_validation_points(const std::vector<double>& tY_mm, const std::vector<double>& Q_kN,
                                                const std::vector<double>& roll_mrad, int n);

}  // namespace mh
