// Shape checks and clean-up of a profile as read (canonical frame, mm): units, flange side,
// upside-down rails, duplicated points, jitter and folds where contact can happen.
#include "profile/formats/formats.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/numfmt.hpp"

namespace mh::formats {

namespace {
using L = ProfileCheckLimits;

// ---------------------------------------------------------------------------------------------
// Shape tests, all in the canonical frame (mm), points sorted by file order with y increasing
// on the whole.
struct Shape {
  std::size_t i_min = 0, i_max = 0;  // lowest and highest point
  double y0 = 0, y1 = 0, width = 0;  // y range
  double z_first = 0, z_last = 0;    // z at the two ends (file order)
  double z_at_ymin = 0, z_at_ymax = 0;
};

Shape shape_of(const RawProfile& r) {
  Shape s;
  const auto n = r.size();
  s.i_min = static_cast<std::size_t>(std::min_element(r.z.begin(), r.z.end()) - r.z.begin());
  s.i_max = static_cast<std::size_t>(std::max_element(r.z.begin(), r.z.end()) - r.z.begin());
  const auto iy0 = static_cast<std::size_t>(std::min_element(r.y.begin(), r.y.end()) - r.y.begin());
  const auto iy1 = static_cast<std::size_t>(std::max_element(r.y.begin(), r.y.end()) - r.y.begin());
  s.y0 = r.y[iy0]; s.y1 = r.y[iy1]; s.width = s.y1 - s.y0;
  s.z_at_ymin = r.z[iy0]; s.z_at_ymax = r.z[iy1];
  s.z_first = r.z[0]; s.z_last = r.z[n - 1];
  return s;
}

double frac(const Shape& s, double y) { return s.width > 0 ? (y - s.y0) / s.width : 0.5; }

/// A flange on the gauge side (negative y): the lowest point in the inner 35 % of the width and
/// at least kFlangeHeight_mm below the field-side end.
/// The tip must be a true minimum: the nearer end (the flange back) at least 2 mm higher, so a
/// plain cone (flat_ang200.prw) is not taken for a flange.
bool flange_on_gauge_side(const RawProfile& r, const Shape& s) {
  const double zt = r.z[s.i_min];
  return frac(s, r.y[s.i_min]) < 0.35 && zt <= s.z_at_ymax - L::kFlangeHeight_mm && zt <= s.z_at_ymin - 2.0;
}
bool flange_on_field_side(const RawProfile& r, const Shape& s) {
  const double zt = r.z[s.i_min];
  return frac(s, r.y[s.i_min]) > 0.65 && zt <= s.z_at_ymin - L::kFlangeHeight_mm && zt <= s.z_at_ymax - 2.0;
}
/// A rail head: the highest point inside (5 %…95 % of the width) and both ends at least 5 mm lower.
bool rail_like(const RawProfile& r, const Shape& s) {
  const double f = frac(s, r.y[s.i_max]);
  return f > 0.05 && f < 0.95 && r.z[s.i_max] - s.z_first >= 5.0 && r.z[s.i_max] - s.z_last >= 5.0;
}
/// An upside-down rail head: the lowest point inside (10 %…90 %), both ends ≥ 5 mm higher and a
/// wide bottom (points within 1 mm of the lowest span ≥ 15 mm: a crown of radius ≥ ~30 mm; a
/// conformal groove such as groove_r1002.prr, R = 10 mm, is narrower and passes).
bool upside_down_rail(const RawProfile& r, const Shape& s) {
  const double f = frac(s, r.y[s.i_min]);
  const double zmin = r.z[s.i_min];
  if (!(f > 0.1 && f < 0.9 && s.z_first - zmin >= 5.0 && s.z_last - zmin >= 5.0)) return false;
  double a = 1e300, b = -1e300;
  for (std::size_t k = 0; k < r.size(); ++k)
    if (r.z[k] <= zmin + 1.0) a = std::min(a, r.y[k]), b = std::max(b, r.y[k]);
  return b - a >= 15.0;
}

void reverse_raw(RawProfile& r) {
  std::reverse(r.y.begin(), r.y.end());
  std::reverse(r.z.begin(), r.z.end());
  std::reverse(r.line.begin(), r.line.end());
}

void keep_range(RawProfile& r, std::size_t a, std::size_t b) {  // keep [a, b]
  r.y = std::vector<double>(r.y.begin() + a, r.y.begin() + b + 1);
  r.z = std::vector<double>(r.z.begin() + a, r.z.begin() + b + 1);
  r.line = std::vector<std::size_t>(r.line.begin() + a, r.line.begin() + b + 1);
}

/// Folds and loops inside [i0, i1] (file order) replaced by the outer envelope of the surface
/// that the other body can touch: a rail is touched from above (upper envelope z(y)), a wheel
/// from below in the canonical frame (lower envelope). Vertices hidden under the envelope are
/// dropped, the points where a loop crosses itself are added; the rest is kept as read. Throws
/// InputError for what an envelope cannot honestly repair (ProfileCheckLimits). i0, i1 are
/// updated to the new indices.
void outer_envelope(RawProfile& r, const std::string& path, std::size_t& i0, std::size_t& i1) {
  const double sgn = r.kind == ProfileKind::Wheel ? -1.0 : 1.0;  // outer = larger sgn·z
  // Fold runs: consecutive segments that step back in y (or not forward).
  struct Zone { double lo, hi; std::size_t first_line; };
  std::vector<Zone> zones;
  double largest = 0;
  std::size_t largest_line = 0;
  std::size_t nfolds = 0;
  for (std::size_t k = i0 + 1; k <= i1; ++k) {
    if (r.y[k] > r.y[k - 1]) continue;
    std::size_t e = k;
    while (e + 1 <= i1 && !(r.y[e + 1] > r.y[e])) ++e;
    const double ystart = r.y[k - 1];
    double ymin = ystart;
    for (std::size_t j = k; j <= e; ++j) ymin = std::min(ymin, r.y[j]);
    ++nfolds;
    if (ystart - ymin > largest) largest = ystart - ymin, largest_line = r.line[k];
    zones.push_back({ymin, ystart, r.line[k]});
    k = e;
  }
  if (zones.empty()) return;
  const double width = r.y[i1] - r.y[i0];
  if (largest > L::kMaxFold_mm)
    throw InputError(at_line(path, largest_line), "y steps back by " + mm(largest),
                     "a fold deeper than " + mm(L::kMaxFold_mm) +
                         " where contact can happen is not a measurement artefact that the clean-up may remove",
                     "check the measurement there (a misplaced gauge, a wrong side?) or edit the points");
  // Each zone widened to every segment that overlaps it (the forward layers around the fold);
  // overlapping zones merged.
  std::sort(zones.begin(), zones.end(), [](const Zone& a, const Zone& b) { return a.lo < b.lo; });
  bool grown = true;
  while (grown) {
    grown = false;
    for (auto& zn : zones)
      for (std::size_t k = i0 + 1; k <= i1; ++k) {
        const double a = std::min(r.y[k - 1], r.y[k]), b = std::max(r.y[k - 1], r.y[k]);
        if (b > zn.lo && a < zn.hi && (a < zn.lo || b > zn.hi) && !(r.y[k] > r.y[k - 1])) {
          zn.lo = std::min(zn.lo, a), zn.hi = std::max(zn.hi, b), grown = true;
        }
      }
    std::vector<Zone> merged;
    for (const auto& zn : zones) {
      if (!merged.empty() && zn.lo <= merged.back().hi) merged.back().hi = std::max(merged.back().hi, zn.hi);
      else merged.push_back(zn);
    }
    zones = merged;
  }
  double covered = 0;
  for (const auto& zn : zones) covered += zn.hi - zn.lo;
  if (width > 0 && covered > L::kMaxFoldFraction * width)
    throw InputError(path, "folds over " + mm(covered) + " of " + mm(width),
                     "the profile folds over most of the width that can touch; an envelope would invent the surface",
                     "check the measurement (wrong axis order or sign? --mirror-y / --format), or measure again");
  auto in_zone = [&zones](double y) {
    for (const auto& zn : zones)
      if (y >= zn.lo && y <= zn.hi) return true;
    return false;
  };
  // The segments that lie (partly) in a zone: the only ones that can hide a point.
  std::vector<std::size_t> segs;
  for (std::size_t k = i0 + 1; k <= i1; ++k) {
    const double a = std::min(r.y[k - 1], r.y[k]), b = std::max(r.y[k - 1], r.y[k]);
    for (const auto& zn : zones)
      if (b >= zn.lo && a <= zn.hi) { segs.push_back(k); break; }
  }
  auto envelope_at = [&](double y) {  // sgn·z of the outer envelope at y
    double best = -1e300;
    for (std::size_t k : segs) {
      const double ya = r.y[k - 1], yb = r.y[k], za = r.z[k - 1], zb = r.z[k];
      if (y < std::min(ya, yb) || y > std::max(ya, yb)) continue;
      if (ya == yb) best = std::max({best, sgn * za, sgn * zb});
      else best = std::max(best, sgn * (za + (zb - za) * (y - ya) / (yb - ya)));
    }
    return best;
  };
  struct Pt { double y, z; std::size_t line; };
  std::vector<Pt> kept;
  std::size_t dropped = 0;
  double dlo = 1e300, dhi = -1e300;
  const double tol = 1e-9;  // mm
  for (std::size_t k = i0; k <= i1; ++k) {
    if (!in_zone(r.y[k]) || sgn * r.z[k] >= envelope_at(r.y[k]) - tol) {
      kept.push_back({r.y[k], r.z[k], r.line[k]});
    } else {
      ++dropped;
      dlo = std::min(dlo, r.y[k]), dhi = std::max(dhi, r.y[k]);
    }
  }
  // Crossings of two segments in a zone (a loop crossing itself) that lie on the envelope.
  std::size_t crossings = 0;
  for (std::size_t x = 0; x < segs.size(); ++x)
    for (std::size_t w = x + 1; w < segs.size(); ++w) {
      const std::size_t p = segs[x], q = segs[w];
      if (q == p + 1) continue;  // neighbours share a vertex
      const double y1 = r.y[p - 1], z1 = r.z[p - 1], y2 = r.y[p], z2 = r.z[p];
      const double y3 = r.y[q - 1], z3 = r.z[q - 1], y4 = r.y[q], z4 = r.z[q];
      const double den = (y2 - y1) * (z4 - z3) - (z2 - z1) * (y4 - y3);
      if (std::abs(den) < 1e-15) continue;
      const double t = ((y3 - y1) * (z4 - z3) - (z3 - z1) * (y4 - y3)) / den;
      const double u = ((y3 - y1) * (z2 - z1) - (z3 - z1) * (y2 - y1)) / den;
      if (t <= 1e-9 || t >= 1 - 1e-9 || u <= 1e-9 || u >= 1 - 1e-9) continue;
      const double yc = y1 + t * (y2 - y1), zc = z1 + t * (z2 - z1);
      if (sgn * zc >= envelope_at(yc) - tol) {
        kept.push_back({yc, zc, r.line[p]});
        ++crossings;
      }
    }
  std::stable_sort(kept.begin(), kept.end(), [](const Pt& a, const Pt& b) { return a.y < b.y; });
  // Equal y (a vertical piece of the envelope): keep the outer point only.
  std::vector<Pt> env;
  for (const Pt& p : kept) {
    if (!env.empty() && p.y - env.back().y <= tol) {
      if (sgn * p.z > sgn * env.back().z) env.back() = p;
      ++dropped;
      dlo = std::min(dlo, p.y), dhi = std::max(dhi, p.y);
      continue;
    }
    env.push_back(p);
  }
  // A loop that does not cross itself leaves a notch in the envelope z(y) (a vertical drop where
  // one layer ends and the next, lower one goes on). The other body, whose radius is many times
  // the width of a fold, bridges it: around each fold (the zone, widened by its width and at
  // least 0.5 mm each side) only the points on the outer convex hull are kept. On a smooth
  // surface that removes nothing: the head is convex, and a concave wheel root of R 13 mm
  // sags 0.01 mm over 1 mm.
  for (const auto& zn : zones) {
    const double m = std::max(0.5, zn.hi - zn.lo);
    std::size_t a = 0;
    while (a < env.size() && env[a].y < zn.lo - m) ++a;
    std::size_t b = a;
    while (b < env.size() && env[b].y <= zn.hi + m) ++b;
    if (b - a < 3) continue;
    std::vector<Pt> hull;
    for (std::size_t j = a; j < b; ++j) {
      const Pt& p = env[j];
      while (hull.size() >= 2) {
        const Pt& o = hull[hull.size() - 2];
        const Pt& q = hull.back();
        const double cross = (q.y - o.y) * (p.z - o.z) - (q.z - o.z) * (p.y - o.y);
        if (sgn * cross >= 0) {  // q lies under the chord o–p (rail) / above it (wheel)
          ++dropped;
          dlo = std::min(dlo, q.y), dhi = std::max(dhi, q.y);
          hull.pop_back();
        } else {
          break;
        }
      }
      hull.push_back(p);
    }
    std::vector<Pt> next(env.begin(), env.begin() + static_cast<std::ptrdiff_t>(a));
    next.insert(next.end(), hull.begin(), hull.end());
    next.insert(next.end(), env.begin() + static_cast<std::ptrdiff_t>(b), env.end());
    env.swap(next);
  }
  for (std::size_t j = 1; j < env.size(); ++j)
    if (in_zone(env[j].y) && env[j].y - env[j - 1].y > L::kMaxBridge_mm)
      throw InputError(at_line(path, env[j].line), "a gap of " + mm(env[j].y - env[j - 1].y),
                       "the clean-up of a fold would leave a gap wider than " + mm(L::kMaxBridge_mm) +
                           " where contact can happen",
                       "check the measurement there, or edit the points");
  // Splice: points before i0, the envelope, points after i1.
  RawProfile c = r;
  c.y.clear(); c.z.clear(); c.line.clear();
  for (std::size_t k = 0; k < i0; ++k) c.add(r.y[k], r.z[k], r.line[k]);
  const std::size_t n0 = c.size();
  for (const Pt& p : env) c.add(p.y, p.z, p.line);
  const std::size_t n1 = c.size() - 1;
  for (std::size_t k = i1 + 1; k < r.size(); ++k) c.add(r.y[k], r.z[k], r.line[k]);
  r = std::move(c);
  i0 = n0;
  i1 = n1;
  if (dlo > dhi) dlo = dhi = zones.front().lo;
  r.cleanup.folds = nfolds;
  r.cleanup.fold_points = dropped;
  r.cleanup.crossings = crossings;
  r.cleanup.y_from_mm = dlo;
  r.cleanup.y_to_mm = dhi;
  r.cleanup.largest_fold_mm = largest;
  r.warnings.push_back("clean-up: " + std::to_string(nfolds) + (nfolds == 1 ? " fold/loop" : " folds/loops") +
                       " where contact can happen replaced by the outer envelope: dropped " + std::to_string(dropped) +
                       " points at y " + format_number(std::round(dlo * 1e3) / 1e3) + " … " +
                       format_number(std::round(dhi * 1e3) / 1e3) + " mm" +
                       (crossings ? ", added " + std::to_string(crossings) + " crossing points" : std::string()) +
                       " (largest step back " + mm(largest) + "; cleanup \"strict\" rejects instead)");
}

/// Walking from index i0 towards the start of the file, where y should keep decreasing: the
/// first index up to which every backward step (a fold or loop) is local, i.e. is no deeper than
/// kMaxFold_mm and followed, further on, by a point beyond the fold's start. A step back that the
/// profile never recovers from (a face turning away, a flank) ends the walk: the points beyond
/// it are clipped as before.
std::size_t extend_over_local_folds(const RawProfile& r, std::size_t i0) {
  std::size_t a = i0;
  while (a > 0) {
    if (r.y[a - 1] < r.y[a]) { --a; continue; }
    const double ystart = r.y[a];
    double depth = 0;
    std::size_t resume = a;
    for (std::size_t j = a; j-- > 0;) {
      depth = std::max(depth, r.y[j] - ystart);
      if (depth > L::kMaxFold_mm) break;
      if (r.y[j] < ystart) { resume = j; break; }
    }
    if (resume == a) break;
    a = resume;
  }
  // No gain unless the walk passed a fold (a plain monotone run is kept by the clip anyway).
  std::size_t plain = i0;
  while (plain > 0 && r.y[plain - 1] < r.y[plain]) --plain;
  return a < plain ? a : i0;
}

}  // namespace

bool shape_could_be(const RawProfile& r, ProfileKind k) {
  if (r.size() < 3) return false;
  const Shape s = shape_of(r);
  if (k == ProfileKind::Wheel) return flange_on_gauge_side(r, s) || flange_on_field_side(r, s);
  if (k == ProfileKind::Rail) return rail_like(r, s);
  return false;
}

void clean_and_check(RawProfile& r, const std::string& path, const ProfileReadOptions& opt) {
  const std::string kname[] = {"unknown", "wheel", "rail"};
  if (r.size() < L::kMinPoints)
    throw InputError(path, std::to_string(r.size()) + " points",
                     "a profile needs at least " + std::to_string(L::kMinPoints) + " points",
                     "check the file (commented-out points? wrong format?)");
  r.cleanup.mode = to_string(opt.cleanup);
  // Exact duplicates of the previous point (not with clean-up off: the check below rejects them
  // where contact can happen).
  std::size_t dups = 0;
  if (opt.cleanup != ProfileCleanup::Off) {
    RawProfile c = r;
    c.y.clear(); c.z.clear(); c.line.clear();
    for (std::size_t k = 0; k < r.size(); ++k) {
      if (k > 0 && r.y[k] == c.y.back() && r.z[k] == c.z.back()) { ++dups; continue; }
      c.add(r.y[k], r.z[k], r.line[k]);
    }
    r = c;
  }
  r.cleanup.duplicates = dups;
  if (dups) r.warnings.push_back("removed " + std::to_string(dups) + " duplicated points");
  if (r.size() == 1)
    throw InputError(path, "y = " + mm(r.y[0]) + ", z = " + mm(r.z[0]), "all points are equal",
                     "the file holds no profile");
  if (r.size() < L::kMinPoints)
    throw InputError(path, std::to_string(r.size()) + " distinct points",
                     "a profile needs at least " + std::to_string(L::kMinPoints) + " points",
                     "the others repeat the previous point: check the file (a column read twice?)");
  if (r.y.back() < r.y.front()) reverse_raw(r);
  Shape s = shape_of(r);
  if (s.width < L::kMinWidth_mm || s.width > L::kMaxWidth_mm) {
    std::string hint = "check the length unit; use scale";
    if (s.width < L::kMinWidth_mm && s.width * 1000 >= L::kMinWidth_mm) hint = "looks like metres; use scale 1000";
    else if (s.width > L::kMaxWidth_mm && s.width / 1000 <= L::kMaxWidth_mm) hint = "looks like micrometres; use scale 0.001";
    throw InputError(path, "total width " + format_number(s.width) + " mm",
                     "the width of a profile must lie within 5-500 mm", hint);
  }
  // Kind: header/extension, the user's --kind, the shape.
  if (opt.kind != ProfileKind::Unknown && r.kind != ProfileKind::Unknown && opt.kind != r.kind)
    throw InputError(path, std::string("kind ") + to_string(opt.kind),
                     std::string("the file says it is a ") + to_string(r.kind),
                     "drop --kind or use the right file");
  if (r.kind == ProfileKind::Unknown) r.kind = opt.kind;
  if (r.kind == ProfileKind::Unknown) {
    if (flange_on_gauge_side(r, s) || flange_on_field_side(r, s)) r.kind = ProfileKind::Wheel;
    else if (rail_like(r, s)) r.kind = ProfileKind::Rail;
    if (r.kind != ProfileKind::Unknown)
      r.warnings.push_back(std::string("kind '") + to_string(r.kind) + "' guessed from the shape (use --kind to state it)");
  }
  if (opt.check) {
    if (r.kind == ProfileKind::Wheel) {
      if (flange_on_field_side(r, s))
        throw InputError(path, "flange tip at y = " + mm(r.y[s.i_min]),
                         "wheel flange on the field side (positive y); the canonical frame has it at negative y",
                         "use mirror_y (--mirror-y)");
      if (rail_like(r, s) && !flange_on_gauge_side(r, s))
        throw InputError(path, "highest point at y = " + mm(r.y[s.i_max]),
                         "read as a wheel but shaped like a rail head (or a wheel upside down)",
                         "use --kind rail, or mirror_z (--mirror-z) if it is an upside-down wheel");
    } else if (r.kind == ProfileKind::Rail) {
      if (upside_down_rail(r, s))
        throw InputError(path, "lowest point at y = " + mm(r.y[s.i_min]) + " in the middle",
                         "rail upside down: the head top must be the highest point",
                         "use mirror_z (--mirror-z)");
      if (flange_on_gauge_side(r, s) || flange_on_field_side(r, s)) {
        const double f = frac(s, r.y[s.i_min]);
        const bool interior = f > 0.02 && f < 0.98;
        if (interior)
          throw InputError(path, "lowest point at y = " + mm(r.y[s.i_min]),
                           "read as a rail but shaped like a wheel (a flange near one end)",
                           "use --kind wheel or the wheel file");
      }
    }
  }
  // Region that can touch; inside it y must increase strictly; outside, trailing parts that are
  // not monotone in y are clipped off with a warning.
  std::size_t i0 = 0, i1 = r.size() - 1;
  std::string what0 = "start", what1 = "end";
  if (r.kind == ProfileKind::Rail) {
    const double ztop = r.z[s.i_max];
    i0 = i1 = s.i_max;
    while (i0 > 0 && r.z[i0 - 1] > ztop - L::kRailContactDepth_mm) --i0;
    while (i1 + 1 < r.size() && r.z[i1 + 1] > ztop - L::kRailContactDepth_mm) ++i1;
    what0 = "gauge side (flank below the head)";
    what1 = "field side (flank below the head)";
  } else if (r.kind == ProfileKind::Wheel) {
    i0 = s.i_min;
    i1 = static_cast<std::size_t>(std::max_element(r.y.begin() + static_cast<long>(i0), r.y.end()) - r.y.begin());
    what0 = "flange back";
    what1 = "field-side end (rim face)";
  }
  // A wheel's flange back lies outside that region (it never touches the rail) but places the
  // taping line (70 mm from it). A local loop or fold there (a scan that loops at the flange tip)
  // is cleaned where it is, like inside the region, instead of clipping all the points beyond it:
  // the region grows over every fold after which the profile goes on past the fold's start.
  if (r.kind == ProfileKind::Wheel) {
    std::size_t a = i0;
    for (bool grown = true; grown;) {
      grown = false;
      // A fold that starts in the region and reaches back past points before it (a loop around
      // the flange tip): those points belong to the fold.
      double m = *std::min_element(r.y.begin() + static_cast<std::ptrdiff_t>(a), r.y.begin() + static_cast<std::ptrdiff_t>(i1) + 1);
      while (a > 0 && r.y[a - 1] >= m) --a, m = std::min(m, r.y[a]), grown = true;
      const std::size_t b = extend_over_local_folds(r, a);
      if (b < a) a = b, grown = true;
    }
    if (a < i0) {
      r.warnings.push_back("clean-up extended over " + std::to_string(i0 - a) + " points of the flange back (lines " +
                           std::to_string(r.line[a]) + " … " + std::to_string(r.line[i0]) +
                           ") to clean a fold or loop there where it is, instead of clipping the flange back, which places "
                           "the taping line");
      i0 = a;
    }
  }
  if (opt.cleanup == ProfileCleanup::Envelope && r.kind == ProfileKind::Rail) {
    // A flank that turns under the head inside the depth that can touch (a worn gauge face that
    // narrows downwards, avg_low2.ban) is hidden from the wheel under the widest point: the
    // region starts at the widest point on each side, and the points below are clipped like the
    // flank further down (warning below), rather than taken for a fold.
    std::size_t itop = i0;
    for (std::size_t k = i0; k <= i1; ++k)
      if (r.z[k] > r.z[itop]) itop = k;
    std::size_t a = i0, b = i1;
    for (std::size_t k = i0; k <= itop; ++k)
      if (r.y[k] < r.y[a]) a = k;
    for (std::size_t k = itop; k <= i1; ++k)
      if (r.y[k] > r.y[b]) b = k;
    if (a != i0) r.cleanup.gauge_undercut = true;
    i0 = a;
    i1 = b;
  }
  // A vertical gauge face (a 60E1 flank at 1:20, as the writers put it before the first point):
  // points from the gauge-side start of the region upwards with exactly the same y and rising z,
  // at least kMinGaugeFace_mm tall (a measured face, never exactly vertical, may repeat a rounded
  // y over a few points, not over that height). They are kept as the profile's face
  // (Profile::face_y, face_z), from the top down, and the region starts at the face's top, the
  // first point of z(y).
  std::size_t face_from = i0, face_top = i0;
  if (r.kind == ProfileKind::Rail) {
    std::size_t itop = i0;
    for (std::size_t k = i0; k <= i1; ++k)
      if (r.z[k] > r.z[itop]) itop = k;
    std::size_t f = i0;
    for (std::size_t k = i0; k <= itop; ++k)
      if (r.y[k] < r.y[f]) f = k;
    std::size_t j = f;
    while (j < itop && r.y[j + 1] == r.y[f] && r.z[j + 1] > r.z[j]) ++j;
    if (j > f && r.z[j] - r.z[f] >= L::kMinGaugeFace_mm) {
      for (std::size_t k = j; k-- > f;) r.face_y.push_back(r.y[k]), r.face_z.push_back(r.z[k]);
      face_from = f;
      face_top = j;
      i0 = j;
    }
  }
  // Measurement jitter: inside the region, a point that does not advance in y, and lies at most
  // kJitter_mm behind the last kept point, is dropped (with a warning); a larger backward step
  // is a loop or zig-zag and an error below.
  if (opt.cleanup != ProfileCleanup::Off) {
    std::vector<std::size_t> keep;
    keep.reserve(r.size());
    std::size_t dropped = 0;
    double worst = 0;
    for (std::size_t k = 0; k < r.size(); ++k) {
      if (k > i0 && k <= i1 && !keep.empty() && keep.back() >= i0) {
        const double back = r.y[keep.back()] - r.y[k];
        if (back >= 0 && back <= L::kJitter_mm) {
          ++dropped;
          worst = std::max(worst, back);
          continue;
        }
      }
      keep.push_back(k);
    }
    if (dropped) {
      std::size_t n0 = 0, n1 = 0;
      for (std::size_t j = 0; j < keep.size(); ++j) {
        if (keep[j] == i0) n0 = j;
        if (keep[j] <= i1) n1 = j;
      }
      RawProfile c = r;
      c.y.clear(); c.z.clear(); c.line.clear();
      for (std::size_t k : keep) c.add(r.y[k], r.z[k], r.line[k]);
      r = std::move(c);
      i0 = n0;
      i1 = n1;
      r.cleanup.jitter = dropped;
      r.warnings.push_back("dropped " + std::to_string(dropped) + " points that " +
                           (worst > 0 ? "stepped back in y by at most " + mm(worst) : std::string("repeat the previous point's y")) +
                           " (measurement jitter, at most " + mm(L::kJitter_mm) + ") where contact can happen");
    }
  }
  if (opt.cleanup == ProfileCleanup::Envelope && r.kind != ProfileKind::Unknown)
    outer_envelope(r, path, i0, i1);
  for (std::size_t k = i0 + 1; k <= i1; ++k)
    if (!(r.y[k] > r.y[k - 1]))
      throw InputError(at_line(path, r.line[k]), "y = " + mm(r.y[k]) + " after y = " + mm(r.y[k - 1]),
                       std::string("y steps backward (a loop or zig-zag) inside the region that can touch the ") +
                           (r.kind == ProfileKind::Wheel ? "rail" : r.kind == ProfileKind::Rail ? "wheel" : "other body"),
                       opt.cleanup == ProfileCleanup::Envelope
                           ? "fix the points there (remove the loop), or state the kind (--kind) so that the clean-up knows which side can touch; y must increase strictly"
                           : std::string("fix the points there (remove the loop), or let the clean-up remove it (cleanup \"envelope\", the default, instead of \"") +
                                 to_string(opt.cleanup) + "\"); y must increase strictly");
  std::size_t a = i0, b = i1;
  while (a > 0 && r.y[a - 1] < r.y[a]) --a;
  while (b + 1 < r.size() && r.y[b + 1] > r.y[b]) ++b;
  const std::size_t on_face = face_top - face_from;  // the face's points, before a
  if (on_face > 0) {
    if (a > on_face)
      r.warnings.push_back("clipped " + std::to_string(a - on_face) + " points below the gauge face (z < " +
                           mm(r.face_z.back()) + ")");
  } else if (a > 0 && r.cleanup.gauge_undercut)
    r.warnings.push_back("clipped " + std::to_string(a) + " points at the gauge side: the gauge face turns under the head below z = " +
                         mm(r.z[a]) + " (hidden from the wheel; the widest point, y = " + mm(r.y[a]) + ", is the gauge point if the face "
                         "does not reach the gauge height, EN 13848-1)");
  else if (a > 0) r.warnings.push_back("clipped " + std::to_string(a) + " points not monotone in y at the " + what0);
  if (b + 1 < r.size())
    r.warnings.push_back("clipped " + std::to_string(r.size() - 1 - b) + " points not monotone in y at the " + what1);
  keep_range(r, a, b);
  if (r.size() < L::kMinPoints)
    throw InputError(path, std::to_string(r.size()) + " points left", "too few points after clipping",
                     "the profile turns back in y almost everywhere: check the axes (--mirror-y, --kind) and the format");
  // Taping-line rule for wheels whose file origin is not the taping line (MiniProf: measured
  // from the flange back): if the flange tip is not at negative y, put y = 0 at 70 mm
  // (EN 13715 taping line) from the flange back = the innermost point, lowest y.
  // A wheel whose flange tip lies at positive y was measured from its flange back (MiniProf
  // wheels: X from the back face): y = 0 goes 70 mm (EN 13715) from its innermost point, the
  // flange back. (MiniProf's X = 0 is the back face itself; the first points may start a little
  // inside it, on the rounded corner: 1.55 mm in avg_wheel.whl. The innermost point is used
  // whatever the format, so that a file's placement does not depend on its extension.)
  if (r.kind == ProfileKind::Wheel) {
    s = shape_of(r);
    if (flange_on_gauge_side(r, s) && r.y[s.i_min] >= 0) {
      const double shift = s.y0 + L::kTapingLineFromFlangeBack_mm;
      for (auto& y : r.y) y -= shift;
      r.taping_line = "file y = " + mm(shift) + ", " + mm(L::kTapingLineFromFlangeBack_mm) +
                      " from the flange back, the innermost point at file y = " + mm(s.y0) +
                      ": the file is measured from the flange back (its flange tip lies at positive y" +
                      (r.format == "miniprof" ? ", as MiniProf wheels are" : "") + "); EN 13715";
      r.warnings.push_back("y = 0 moved to the taping line, " + mm(L::kTapingLineFromFlangeBack_mm) +
                           " from the flange back at file y = " + mm(s.y0));
    }
  }
}

}  // namespace mh::formats
