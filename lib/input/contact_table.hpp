#pragma once
// Contact tables (docs/tables.md): the answers of a grid method (strips, half-space, auto) on a
// tensor grid of nodes in t_Y, load Q and (optionally) the wheel's roll δ against the rail, read
// back and interpolated for a time-stepping caller.
// This is the light half: the file format's names, the reader and the lookup (the C interface
// uses it). Making a table (the solves, the contact matching, the error check) is
// jobs/contact_table_make.hpp.
//
// Interpolation: per contact track and quantity, a bicubic (tricubic with a roll axis) Hermite
// surface on the node grid with node slopes from the monotone piecewise-cubic rule (PCHIP:
// Fritsch & Carlson, SIAM J. Numer. Anal. 17 (1980) 238–246, with the weighted harmonic mean of
// Fritsch & Butland, SIAM J. Sci. Stat. Comput. 5 (1984) 300–304) along each axis and zero cross
// slopes: continuous values and first derivatives in t_Y, Q and δ across cells. A contact absent at a node carries N = 0 there
// (and zero size and pressure); a zero node between loaded ones is a local minimum, where PCHIP
// puts a zero slope, so a contact appearing between nodes grows from zero force without a step.
#include <algorithm>
#include <array>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "contact/judge/status.hpp"

namespace mh {

/// The schema tag of the table's JSON header; bumped on any incompatible change.
constexpr const char* kContactTableSchema = "mhcontact.table/2";
/// The schema tag of a table's export on a regular grid (`mhcontact table-export`, docs/tables.md).
constexpr const char* kContactTableExportSchema = "mhcontact.table-export/2";
/// The schema tag of a wheelset table (two pairs' tables in one file, input/wheelset_table.hpp).
constexpr const char* kWheelsetTableSchema = "mhcontact.wheelset-table/1";

/// The per-contact quantities of a table, in the order of their CSV columns.
enum TableQuantity : int {
  kTabN,        ///< normal force
  kTabYRail,    ///< contact reference point on the rail, lateral
  kTabZRail,    ///< its height on the rail profile
  kTabYWheel,   ///< facing wheel-profile point
  kTabGamma,    ///< contact angle
  kTabRRoll,    ///< wheel rolling radius there
  kTabPmax,     ///< peak pressure
  kTabArea,     ///< contact area
  kTabA,        ///< half the contact length along x
  kTabB,        ///< half the contact width across, in the contact plane
  kTabAEl,      ///< equivalent ellipse semi-axis along x (elastic Hertz of N on the patch's curvatures)
  kTabBEl,      ///< ... across
  kTabC11,      ///< Kalker's creepage coefficients at a_el/b_el (contact/tangential/kalker.hpp)
  kTabC22,
  kTabC23,
  kTableQuantities
};

/// A column of the CSV: its name (with its unit) and the factor from the column's unit to SI.
struct TableColumn {
  const char* name;
  double to_si;
  bool non_negative;  ///< a size, force or pressure: the interpolant is clamped at 0
  bool fades;         ///< 0 where the contact is absent (else: carried from the nearest node with it)
};
extern const std::array<TableColumn, kTableQuantities> kTableColumns;

/// The node columns before the per-contact ones: "tY_mm,Q_kN,roll_mrad,status,contact,present".
constexpr int kTableNodeColumns = 6;

/// A table in memory, SI. Node (m, i, j) is (roll[m], tY[i], Q[j]), the roll outermost: layer m
/// is a (t_Y, Q) table of its own layout. Track k is one contact followed across nodes
/// (docs/tables.md "Contacts across nodes"). One roll node: no roll axis (a layer made at that
/// roll). Cells: (m, i, j) with m < nRc() (one layer of cells without a roll axis).
struct ContactTableData {
  nlohmann::json header;                 ///< the JSON header as read or made
  std::vector<double> tY;                ///< [m] increasing
  std::vector<double> Q;                 ///< [N] increasing
  std::vector<double> roll{0.0};         ///< [rad] increasing; one node: no roll axis
  int n_tracks = 0;
  std::vector<CaseStatus> node_status;   ///< [node(m, i, j)]
  std::vector<std::uint8_t> cell_coarse; ///< [cell(m, i, j)]: the cell missed its error tolerance after refinement
  std::vector<std::uint8_t> present;     ///< [node(m, i, j) * n_tracks + k]
  std::vector<double> v;                 ///< [at(m, i, j, k) + q], SI
  std::size_t nT() const { return tY.size(); }
  std::size_t nQ() const { return Q.size(); }
  std::size_t nR() const { return roll.size(); }
  /// Cell layers along the roll: nR() - 1, or 1 without a roll axis.
  std::size_t nRc() const { return nR() > 1 ? nR() - 1 : 1; }
  std::size_t node(std::size_t m, std::size_t i, std::size_t j) const { return (m * nT() + i) * nQ() + j; }
  std::size_t cell(std::size_t m, std::size_t i, std::size_t j) const { return (m * (nT() - 1) + i) * (nQ() - 1) + j; }
  std::size_t at(std::size_t m, std::size_t i, std::size_t j, int k) const {
    return (node(m, i, j) * static_cast<std::size_t>(n_tracks) + static_cast<std::size_t>(k)) * kTableQuantities;
  }
  /// Layer 0 (a table without a roll axis).
  std::size_t at(std::size_t i, std::size_t j, int k) const { return at(0, i, j, k); }
};

/// Read a table file (CSV with its JSON header line) whose header's schema is `schema` (a table,
/// or with kContactTableExportSchema its export: the same layout). Throws InputError naming the
/// file and line.
ContactTableData read_contact_table(const std::string& path, const char* schema = kContactTableSchema);
/// One table section of a stream: its header line, column line and rows up to the end or the
/// next line starting with '#' (a wheelset table's next section). `ln` counts the lines read
/// (for the messages: `path` line ln + 1 is the header).
ContactTableData read_contact_table(std::istream& in, const std::string& path, std::size_t& ln,
                                    const char* schema = kContactTableSchema);

/// At most this many contacts in a lookup answer (the C interface's MHC_MAX_CONTACTS).
constexpr int kTableMaxContacts = 6;

/// One contact of a lookup: the interpolated quantities and their partial derivatives.
struct TableContact {
  int track = 0;                                   ///< 1-based track of the table
  std::array<double, kTableQuantities> v{};        ///< SI
  std::array<double, kTableQuantities> d_dtY{};    ///< per m
  std::array<double, kTableQuantities> d_dQ{};     ///< per N
  std::array<double, kTableQuantities> d_droll{};  ///< per rad (0 without a roll axis)
};

/// The answer at one (t_Y, Q, roll).
struct TableAnswer {
  CaseStatus status = CaseStatus::OutOfRange;
  bool coarse = false;       ///< the cell missed the interpolation tolerance (status outside_validity)
  /// A table without a roll axis asked at another roll than its layer's (status at best
  /// outside_validity: its evidence is at its own roll; docs/tables.md "Roll").
  bool off_roll = false;
  int n_contacts = 0;        ///< contacts with N > 0 (may exceed kTableMaxContacts: the rest omitted)
  double Fz = 0, Fy = 0;     ///< [N] Σ N cos γ, Σ N sin γ
  double dFy_dtY = 0, dFy_dQ = 0, dFy_droll = 0;  ///< [N/m], [-], [N/rad]
  std::array<TableContact, kTableMaxContacts> c;
};

/// A table's values of one track at a point and their derivatives along t_Y, Q and the roll.
struct TableTrackValues {
  std::array<double, kTableQuantities> v, d_dtY, d_dQ, d_droll;
};

/// Add one contact of track k (0-based) with its values and their derivatives to `out`:
/// Fz += N cos γ, Fy += N sin γ, ∂Fy/∂t_Y, ∂Fy/∂Q and ∂Fy/∂δ by the product rule, and the
/// contact's slot while there is room (n_contacts counts it either way). The one per-contact
/// summation of the lookup and of the export's linear reading.
void add_table_contact(TableAnswer& out, int k, const TableTrackValues& t);

/// Roll nodes closer than this [rad] are one (a table without a roll axis answers at its own roll
/// within it).
constexpr double kTableRollTolerance = 1e-6;

/// The interpolant of a table: node slopes made once; lookups allocate nothing and may run on
/// any number of threads at once.
class ContactTableLookup {
 public:
  explicit ContactTableLookup(ContactTableData data);
  const ContactTableData& data() const { return d_; }
  /// The answer at (tY [m], Q [N], roll [rad]); outside the node ranges (or a roll not finite):
  /// status out_of_range, no contact. A table without a roll axis answers at any roll with its one layer, the status
  /// at best outside_validity away from that layer's roll (TableAnswer::off_roll).
  void lookup(double tY, double Q, double roll, TableAnswer& out) const;
  /// The interpolant of one track k (0-based) at (tY, Q, roll) inside the node ranges, whether
  /// its N is above 0 or not (sizes, forces and pressures clamped at 0): what an export writes
  /// for every track at every point.
  void track_values(double tY, double Q, double roll, int k, std::array<double, kTableQuantities>& v) const;

 private:
  ContactTableData d_;
  std::vector<double> dx_, dy_, dz_;  ///< node slopes along t_Y, Q and roll, laid out as d_.v (dz_ 0 without a roll axis)
  std::vector<int> cell_tracks_; ///< per cell, the tracks present at one of its corners ...
  std::vector<int> cell_first_;  ///< ... cell_tracks_[cell_first_[c] .. cell_first_[c+1])
  /// The Hermite basis of the cell holding (tY, Q, roll), inside the node ranges: made once a lookup.
  struct Basis {
    std::size_t i = 0, j = 0, m = 0;  ///< the cell (m, i, j)
    int nc = 1;                       ///< roll corners: 2 with a roll axis, else 1 (R0[0] = 1, the rest 0)
    double H0[2], H1[2], G0[2], G1[2], R0[2], R1[2], dH0[2], dH1[2], dG0[2], dG1[2], dR0[2], dR1[2];
  };
  void basis(double tY, double Q, double roll, Basis& B) const;
  /// Track k's Hermite surface at the basis's point: values and their derivatives.
  void hermite(const Basis& B, int k, TableTrackValues& t) const;
};

/// The cell of v among increasing nodes x (at least two; v inside [x.front(), x.back()]): i with
/// x[i] ≤ v < x[i+1], the last cell at v = x.back(). The one cell search of the lookup and of the
/// export's linear reading.
inline std::size_t table_interval(const std::vector<double>& x, double v) {
  return std::min<std::size_t>(x.size() - 2,
                               static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), v) - x.begin()) - 1);
}

/// Severity order of statuses for a cell (the worst of its corners): ok < outside_validity <
/// derailed < the statuses without an answer.
int status_severity(CaseStatus s);

}  // namespace mh
