#include "geometry/contact_patches.hpp"

#include <algorithm>
#include <cmath>

namespace mh {

namespace {
constexpr double kRegionStep = 0.02e-3;  // [m] sampling of g(y) for the regions and their weights
}  // namespace

std::vector<PatchRegion> find_patch_regions(const WheelRailGap& gap, double dz_ref, double dz_grid, double d_comb) {
  std::vector<PatchRegion> out;
  std::vector<std::pair<double, double>> scratch;
  find_patch_regions(gap, dz_ref, dz_grid, d_comb, out, scratch);
  return out;
}

void find_patch_regions(const WheelRailGap& gap, double dz_ref, double dz_grid, double d_comb,
                        std::vector<PatchRegion>& out, std::vector<std::pair<double, double>>& merged) {
  // The intervals merged in place: an interval closer than d_comb to the last kept one extends it.
  gap.interpenetration(dz_grid, kRegionStep, merged);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < merged.size(); ++i) {
    if (kept > 0 && merged[i].first - merged[kept - 1].second < d_comb) merged[kept - 1].second = merged[i].second;
    else merged[kept++] = merged[i];
  }
  merged.resize(kept);
  out.clear();
  for (const auto& m : merged) {
    PatchRegion k;
    k.y_a = m.first;
    k.y_b = m.second;
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
