#pragma once
// The rolled wheel's candidates (method.md §3.8): ContactGeometry::candidates_at(t, δ) and the
// tables that speed it up (RolledMinima, in contact_geometry.hpp with the geometry that holds
// them), built at once (build_rolled_minima) or on demand (RolledMinimaOnDemand).

#include <memory>
#include <atomic>
#include <mutex>

#include "geometry/contact_geometry.hpp"

namespace mh {

/// RolledMinima of a geometry built by the first rolled call that can use them (|δ| ≤ roll_max),
/// once, whichever thread makes it (std::call_once); a geometry made and solved upright never
/// pays for them (about the cost of build_geometry again: 0.1 s and 3 MB on the Manchester pair).
/// Copies of one geometry (same build_id) may share one.
class RolledMinimaOnDemand {
 public:
  explicit RolledMinimaOnDemand(double roll_max);
  /// [-] sin of the largest |δ| the table will cover.
  double sigma_max() const { return sigma_max_; }
  /// The table of G (built from G at the first call; G must be the geometry, or a copy of the
  /// geometry, this was made for); null if G has no grid to tabulate.
  const RolledMinima* get(const ContactGeometry& G) const;
  /// Whether the table has been built (for tests and measurements).
  bool built() const;

 private:
  double roll_max_, sigma_max_;
  mutable std::once_flag once_;
  mutable std::shared_ptr<const RolledMinima> table_;
  mutable std::atomic<bool> built_{false};
};

/// Give G a RolledMinimaOnDemand for |δ| ≤ roll_max [rad] (none if G already holds a built table).
void tabulate_rolled_minima_on_demand(ContactGeometry& G, double roll_max);

}  // namespace mh
