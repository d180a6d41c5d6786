#include "profile/print_regions.hpp"

#include <algorithm>
#include <cmath>

namespace mh {

std::vector<PrintRegion> print_regions(const Profile& p, const PrintRegionOptions& opt) {
  const std::size_t n = p.size();
  std::vector<PrintRegion> out;
  if (n == 0) return out;
  if (p.point_step.size() != n) {
    out.push_back({0, n - 1, p.print_step});
    return out;
  }
  // Each point's precision: the finest non-zero step within ±window points among those at most
  // opt.dropped_zeros finer than its own (a point printed short by dropped zeros takes its
  // neighbours' precision; a neighbour of another printing, 10^11 finer, is not one of them).
  const std::size_t w = static_cast<std::size_t>(std::max(opt.window, 0));
  std::vector<double> q(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const double own = p.point_step[k];
    const std::size_t a = k >= w ? k - w : 0, b = std::min(n - 1, k + w);
    q[k] = own;
    for (std::size_t i = a; i <= b; ++i) {
      const double qi = p.point_step[i];
      if (qi > 0 && (q[k] == 0 || qi < q[k]) && (own == 0 || qi * opt.dropped_zeros >= own)) q[k] = qi;
    }
    // Full precision (17 significant digits: a step that varies with the magnitude) is one class.
    if (q[k] > 0) q[k] = std::max(q[k], opt.full_precision);
  }
  // Runs of one precision (within opt.factor of the run's finest; unknown steps join any run).
  for (std::size_t k = 0; k < n; ++k) {
    if (!out.empty()) {
      PrintRegion& r = out.back();
      const bool same = q[k] == 0 || r.step == 0 || (q[k] < r.step * opt.factor && r.step < q[k] * opt.factor);
      if (same) {
        r.last = k;
        if (q[k] > 0 && (r.step == 0 || q[k] < r.step)) r.step = q[k];
        continue;
      }
    }
    out.push_back({k, k, q[k]});
  }
  // Short runs merged into the longer neighbour, shortest first, until none is left.
  const std::size_t min_pts = static_cast<std::size_t>(std::max(opt.min_points, 1));
  while (out.size() > 1) {
    std::size_t s = 0;
    for (std::size_t i = 1; i < out.size(); ++i)
      if (out[i].last - out[i].first < out[s].last - out[s].first) s = i;
    if (out[s].last - out[s].first + 1 >= min_pts) break;
    const bool left = s > 0 && (s + 1 == out.size() || out[s - 1].last - out[s - 1].first >= out[s + 1].last - out[s + 1].first);
    const std::size_t into = left ? s - 1 : s + 1;
    out[into].first = std::min(out[into].first, out[s].first);
    out[into].last = std::max(out[into].last, out[s].last);
    out.erase(out.begin() + static_cast<std::ptrdiff_t>(s));
    // Neighbours of one precision after the merge become one region.
    for (std::size_t i = 1; i < out.size();) {
      const double a = out[i - 1].step, b = out[i].step;
      if (a == 0 || b == 0 || (a < b * opt.factor && b < a * opt.factor)) {
        out[i - 1].last = out[i].last;
        if (b > 0 && (a == 0 || b < a)) out[i - 1].step = b;
        out.erase(out.begin() + static_cast<std::ptrdiff_t>(i));
      } else {
        ++i;
      }
    }
  }
  return out;
}

}  // namespace mh
