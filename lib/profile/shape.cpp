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

}  // namespace

void clean_and_check(RawProfile& r, const std::string& path, const ProfileReadOptions& opt) {
  const std::string kname[] = {"unknown", "wheel", "rail"};
  if (r.size() < L::kMinPoints)
    throw InputError(path, std::to_string(r.size()) + " points",
                     "a profile needs at least " + std::to_string(L::kMinPoints) + " points",
                     "check the file (commented-out points? wrong format?)");
  // Exact duplicates of the previous point.
  std::size_t dups = 0;
  {
    RawProfile c = r;
    c.y.clear(); c.z.clear(); c.line.clear();
    for (std::size_t k = 0; k < r.size(); ++k) {
      if (k > 0 && r.y[k] == c.y.back() && r.z[k] == c.z.back()) { ++dups; continue; }
      c.add(r.y[k], r.z[k], r.line[k]);
    }
    r = c;
  }
  if (dups) r.warnings.push_back("removed " + std::to_string(dups) + " duplicated points");
  if (r.size() == 1)
    throw InputError(path, "y = " + mm(r.y[0]) + ", z = " + mm(r.z[0]), "all points are equal",
                     "the file holds no profile");
  if (r.size() < L::kMinPoints)
    throw InputError(path, std::to_string(r.size()) + " distinct points",
                     "a profile needs at least " + std::to_string(L::kMinPoints) + " points");
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
  // Measurement jitter: inside the region, a point that does not advance in y, and lies at most
  // kJitter_mm behind the last kept point, is dropped (with a warning); a larger backward step
  // is a loop or zig-zag and an error below.
  {
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
      RawProfile c;
      c.kind = r.kind;
      c.format = r.format;
      c.warnings = r.warnings;
      for (std::size_t k : keep) c.add(r.y[k], r.z[k], r.line[k]);
      r = std::move(c);
      i0 = n0;
      i1 = n1;
      r.warnings.push_back("dropped " + std::to_string(dropped) + " points that stepped back in y by at most " +
                           mm(worst) + " (measurement jitter, at most " + mm(L::kJitter_mm) + ") where contact can happen");
    }
  }
  for (std::size_t k = i0 + 1; k <= i1; ++k)
    if (!(r.y[k] > r.y[k - 1]))
      throw InputError(at_line(path, r.line[k]), "y = " + mm(r.y[k]) + " after y = " + mm(r.y[k - 1]),
                       std::string("y steps backward (a loop or zig-zag) inside the region that can touch the ") +
                           (r.kind == ProfileKind::Wheel ? "rail" : r.kind == ProfileKind::Rail ? "wheel" : "other body"),
                       "fix the points there (remove the loop); y must increase strictly");
  std::size_t a = i0, b = i1;
  while (a > 0 && r.y[a - 1] < r.y[a]) --a;
  while (b + 1 < r.size() && r.y[b + 1] > r.y[b]) ++b;
  if (a > 0) r.warnings.push_back("clipped " + std::to_string(a) + " points not monotone in y at the " + what0);
  if (b + 1 < r.size())
    r.warnings.push_back("clipped " + std::to_string(r.size() - 1 - b) + " points not monotone in y at the " + what1);
  keep_range(r, a, b);
  if (r.size() < L::kMinPoints)
    throw InputError(path, std::to_string(r.size()) + " points left", "too few points after clipping");
  // Taping-line rule for wheels whose file origin is not the taping line (MiniProf: measured
  // from the flange back): if the flange tip is not at negative y, put y = 0 at 70 mm
  // (EN 13715 taping line) from the flange back = the innermost point, lowest y.
  if (r.kind == ProfileKind::Wheel) {
    s = shape_of(r);
    if (flange_on_gauge_side(r, s) && r.y[s.i_min] >= 0) {
      const double shift = s.y0 + L::kTapingLineFromFlangeBack_mm;
      for (auto& y : r.y) y -= shift;
      r.warnings.push_back("y = 0 moved to the taping line, " + mm(L::kTapingLineFromFlangeBack_mm) +
                           " from the flange back at file y = " + mm(s.y0));
    }
  }
}

}  // namespace mh::formats
