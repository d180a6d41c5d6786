#pragma once
// Contact patches of the grid methods (docs/method.md §8): the separate interpenetration regions
// of the undeformed profiles at a rigid vertical approach, regions closer than d_comb merged into
// one patch, and each patch's tangent plane placed as CONTACT places it (the "interpenetration
// centre of gravity"). A geometry product: the half-space and the strip solvers build their grids
// or strips on these planes.
#include <utility>
#include <vector>

#include "geometry/gap.hpp"

namespace mh {

struct PatchRegion {
  double y_a = 0, y_b = 0;  ///< [m] rail-y extent of the interpenetration at dz_grid
  PatchPlane P;             ///< the patch's plane (placed from the interpenetration at dz_ref)
  double s_a = 0, s_b = 0;  ///< [m] that extent in plane coordinates, s = (y − y_ref) / cos γ
  double x_half = 0;        ///< [m] half-length along x of the interpenetration at dz_grid
};

/// [deg] The largest tilt of a grid patch's plane against the rail that the project's tests show
/// the planar approach good for (CONTACT's conformal runs within 10 % up to 14.7°; the judge's
/// evidence table, contact/judge/evidence.cpp, and find_patch_regions below).
constexpr double kPlanarTiltBoundDeg = 15.0;

/// Patches of the interpenetration at vertical approach dz_grid [m] (their extent), with planes
/// from the interpenetration at dz_ref ≤ dz_grid (the approach of the solution, or its estimate):
/// the mean of the rail point (y, z_r) and of the rail inclination over the interpenetration,
/// weighted by the squared interpenetration e(x, y)² = (dz − g(y) − x²/2r)², so that a row
/// weighs ∫ e² dx = (16/15) e0² √(2 r e0), e0 = dz − g(y) (CONTACT's default weighting). A region
/// that does not interpenetrate at dz_ref is weighted at dz_grid. Regions whose lateral distance
/// is below d_comb [m] form one patch, the distance measured between their interpenetrations at
/// dz_ref where both have one (the regions of the solution's approach, as CONTACT combines those
/// of its current position): two regions that only the grid's wider interpenetration joins, d_comb
/// or more apart at dz_ref, are two patches, split where the gap between them is largest. So is
/// a part of an interval reaching d_comb or more beyond its outer interpenetration at dz_ref, with
/// a minimum of the gap of its own at a contact angle flatter by more than kPlanarTiltBoundDeg
/// than the rail's at that interpenetration's deepest point; and an interval without
/// interpenetration at dz_ref whose deepest point lies d_comb or more from a neighbour's
/// interpenetration at such an angle (the tread beside the flange root near flange onset: the
/// flange's plane cannot carry both). In increasing rail y.
std::vector<PatchRegion> find_patch_regions(const WheelRailGap& gap, double dz_ref, double dz_grid, double d_comb);

/// The working storage of find_patch_regions (cleared on use, capacity kept).
struct RegionScratch {
  struct Segment {
    double y_a, y_b;          ///< [m] extent at dz_grid
    double core_lo, core_hi;  ///< [m] span of its interpenetration at dz_ref (NaN: none)
  };
  std::vector<std::pair<double, double>> grid, cores;  ///< the intervals at dz_grid and dz_ref
  std::vector<Segment> merged;
};

/// The same into `out`, with `scratch` (both cleared first, their capacity kept: a reused pair
/// allocates nothing once grown; the grid methods' workspaces).
void find_patch_regions(const WheelRailGap& gap, double dz_ref, double dz_grid, double d_comb,
                        std::vector<PatchRegion>& out, RegionScratch& scratch);

}  // namespace mh
