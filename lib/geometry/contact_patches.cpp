#include "geometry/contact_patches.hpp"

#include <algorithm>
#include <cmath>

namespace mh {

namespace {
constexpr double kRegionStep = 0.02e-3;  // [m] sampling of g(y) for the regions and their weights
}  // namespace

std::vector<PatchRegion> find_patch_regions(const WheelRailGap& gap, double dz_ref, double dz_grid, double d_comb) {
  std::vector<PatchRegion> out;
  RegionScratch scratch;
  find_patch_regions(gap, dz_ref, dz_grid, d_comb, out, scratch);
  return out;
}

void find_patch_regions(const WheelRailGap& gap, double dz_ref, double dz_grid, double d_comb,
                        std::vector<PatchRegion>& out, RegionScratch& scratch) {
  auto& grid = scratch.grid;
  auto& cores = scratch.cores;
  auto& merged = scratch.merged;
  gap.interpenetration(dz_grid, kRegionStep, grid);
  if (dz_ref < dz_grid) gap.interpenetration(dz_ref, kRegionStep, cores);
  else cores.assign(grid.begin(), grid.end());
  // Segments of the intervals at dz_grid, each with the span of its cores (the interpenetration at
  // dz_ref inside it; NaN if none). An interval whose cores lie d_comb or more apart is split at the
  // gap's largest value between them: regions that are separate at the solution's approach stay
  // separate patches although the wider interpenetration of the grid (margin × dz_ref) joins them.
  merged.clear();
  std::size_t c = 0;
  for (const auto& G : grid) {
    double start = G.first, core_lo = NAN, core_hi = NAN;
    for (; c < cores.size() && cores[c].first <= G.second; ++c) {
      if (!std::isnan(core_lo) && cores[c].first - core_hi >= d_comb) {
        double y_cut = core_hi, g_cut = -INFINITY;  // the split: the gap's largest value between them
        for (double y = core_hi; y <= cores[c].first; y += kRegionStep) {
          const double g = gap.g(y);
          if (g > g_cut) { g_cut = g; y_cut = y; }
        }
        merged.push_back({start, y_cut, core_lo, core_hi});
        start = y_cut;
        core_lo = NAN;
      }
      if (std::isnan(core_lo)) core_lo = cores[c].first;
      core_hi = cores[c].second;
    }
    merged.push_back({start, G.second, core_lo, core_hi});
  }
  // Neighbouring segments closer than d_comb are one patch: measured between their cores where
  // both have one (the regions at the solution's approach, as CONTACT combines the regions at its
  // current position), between the intervals otherwise. (Segments split from one interval have
  // cores d_comb or more apart, so they stay apart.)
  std::size_t kept = 0;
  for (std::size_t i = 0; i < merged.size(); ++i) {
    const RegionScratch::Segment& m = merged[i];
    if (kept == 0) {
      merged[kept++] = m;
      continue;
    }
    RegionScratch::Segment& last = merged[kept - 1];
    const bool cored = !std::isnan(last.core_lo) && !std::isnan(m.core_lo);
    const double dist = cored ? m.core_lo - last.core_hi : m.y_a - last.y_b;
    if (dist < d_comb) {
      last.y_b = m.y_b;
      if (!std::isnan(m.core_lo)) {
        if (std::isnan(last.core_lo)) last.core_lo = m.core_lo;
        last.core_hi = m.core_hi;
      }
    } else {
      merged[kept++] = m;
    }
  }
  merged.resize(kept);
  out.clear();
  for (const auto& m : merged) {
    PatchRegion k;
    k.y_a = m.y_a;
    k.y_b = m.y_b;
    const int n = std::max(4, static_cast<int>((k.y_b - k.y_a) / kRegionStep));
    bool placed = false;
    for (double dz : {dz_ref, dz_grid}) {
      double w = 0, wy = 0, wz = 0, wa = 0;
      for (int i = 0; i <= n; ++i) {
        const double y = k.y_a + (k.y_b - k.y_a) * i / n;
        const double r = gap.rolling_radius(y);
        const double e0 = std::max(dz - gap.g(y), 0.0);
        if (dz == dz_grid) k.x_half = std::max(k.x_half, std::sqrt(2 * r * e0));  // g + x²/2r < dz
        if (!(e0 > 0)) continue;
        const double wr = e0 * e0 * std::sqrt(2 * r * e0);
        double slope = 0;
        const double z = gap.z_rail(y, &slope);
        w += wr; wy += wr * y; wz += wr * z; wa += wr * std::atan(slope);
      }
      if (w > 0 && !placed) {
        k.P.y_ref = wy / w;
        k.P.z_ref = wz / w;
        k.P.gamma = wa / w;
        placed = true;
      }
    }
    if (!placed) k.P = plane_at(gap, 0.5 * (k.y_a + k.y_b));
    const double c = std::cos(k.P.gamma);
    k.s_a = (k.y_a - k.P.y_ref) / c;
    k.s_b = (k.y_b - k.P.y_ref) / c;
    out.push_back(k);
  }
}

}  // namespace mh
