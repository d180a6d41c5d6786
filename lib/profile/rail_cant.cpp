#include "profile/rail_cant.hpp"

#include "core/roots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "core/errors.hpp"
#include "core/numfmt.hpp"

namespace mh {

bool RailCantOptions::valid(std::string* why) const {
  auto fail = [&](const std::string& s) { if (why) *why = s; return false; };
  if (!(depth_min >= 0)) return fail("depth_min must be >= 0");
  if (!(depth_max > depth_min)) return fail("depth_max must be > depth_min");
  if (levels < 3) return fail("levels must be >= 3");
  if (min_levels < 3 || min_levels > levels) return fail("min_levels must be in [3, levels]");
  if (max_iterations < 1) return fail("max_iterations must be >= 1");
  if (!(max_angle > 0) || max_angle > 0.5) return fail("max_angle must be in (0, 0.5] rad");
  if (!(scan_step > 0) || scan_step > max_angle) return fail("scan_step must be in (0, max_angle]");
  if (!(max_std_error > 0) || !(max_residual > 0)) return fail("max_std_error and max_residual must be > 0");
  if (!(min_sensitivity > 0)) return fail("min_sensitivity must be > 0");
  return true;
}

namespace {

struct Line {
  int n = 0;
  double b = 0;          // slope dy_mid/dz
  double std_error = 0;  // of atan(b) [rad]
  double rms = 0;        // [m]
};

// Midpoints of the horizontal cuts of the profile turned back (clockwise) by theta, and their line.
Line chord_midpoints(const Profile& p, double theta, const RailCantOptions& opt) {
  const std::size_t n = p.size();
  const double c = std::cos(theta), s = std::sin(theta);
  std::vector<double> y(n), z(n);
  std::size_t top = 0;
  for (std::size_t i = 0; i < n; ++i) {
    y[i] = c * p.y[i] + s * p.z[i];   // inverse of the counter-clockwise turn of profile.hpp
    z[i] = -s * p.y[i] + c * p.z[i];
    if (z[i] > z[top]) top = i;
  }
  std::vector<double> zs, ms;
  for (int l = 0; l < opt.levels; ++l) {
    const double zl = z[top] - (opt.depth_min + (opt.depth_max - opt.depth_min) * l / (opt.levels - 1));
    double yl = 0, yr = 0;
    bool fl = false, fr = false;
    for (std::size_t i = top; i > 0 && !fl; --i)
      if (z[i - 1] <= zl && z[i] > zl) { yl = y[i - 1] + (zl - z[i - 1]) / (z[i] - z[i - 1]) * (y[i] - y[i - 1]); fl = true; }
    for (std::size_t i = top; i + 1 < n && !fr; ++i)
      if (z[i + 1] <= zl && z[i] > zl) { yr = y[i] + (zl - z[i]) / (z[i + 1] - z[i]) * (y[i + 1] - y[i]); fr = true; }
    if (fl && fr) { zs.push_back(zl); ms.push_back(0.5 * (yl + yr)); }
  }
  Line L;
  L.n = static_cast<int>(zs.size());
  if (L.n < 3) return L;
  double mz = 0, mm = 0;
  for (int i = 0; i < L.n; ++i) { mz += zs[i]; mm += ms[i]; }
  mz /= L.n; mm /= L.n;
  double szz = 0, szm = 0;
  for (int i = 0; i < L.n; ++i) { szz += (zs[i] - mz) * (zs[i] - mz); szm += (zs[i] - mz) * (ms[i] - mm); }
  L.b = szm / szz;
  double ss = 0;
  for (int i = 0; i < L.n; ++i) { const double e = ms[i] - mm - L.b * (zs[i] - mz); ss += e * e; }
  L.rms = std::sqrt(ss / L.n);
  // Standard error of the slope of a straight-line fit (n − 2 degrees of freedom), as an angle.
  L.std_error = std::sqrt(ss / (L.n - 2) / szz) / (1 + L.b * L.b);
  return L;
}

}  // namespace

RailCant estimate_rail_cant(const Profile& rail, const RailCantOptions& opt) {
  std::string why;
  if (!opt.valid(&why)) throw InputError("rail cant options", "", why);
  RailCant r;
  if (rail.size() < 3) { r.why = "too few points"; return r; }
  // The cant is the turn-back θ at which the midpoint line is vertical: b(θ) = 0. b falls as θ
  // grows; b(θ) is far from linear (on a tilted crown the horizontal cuts move a lot), so the
  // root is bracketed by a scan over ±max_angle and bisected (core/roots.hpp); of several roots
  // the one whose
  // midpoints lie closest to a line wins.
  auto b_at = [&](double th, Line* out) {
    const Line L = chord_midpoints(rail, th, opt);
    if (out) *out = L;
    return L.n >= opt.min_levels ? L.b : std::numeric_limits<double>::quiet_NaN();
  };
  const int n_scan = static_cast<int>(std::ceil(2 * opt.max_angle / opt.scan_step));
  double best_theta = 0, best_rms = std::numeric_limits<double>::infinity();
  Line L;
  int max_levels = 0;
  double th0 = -opt.max_angle, b0 = b_at(th0, &L);
  max_levels = std::max(max_levels, L.n);
  for (int k = 1; k <= n_scan; ++k) {
    const double th1 = -opt.max_angle + 2 * opt.max_angle * k / n_scan, b1 = b_at(th1, &L);
    max_levels = std::max(max_levels, L.n);
    if (std::isfinite(b0) && std::isfinite(b1) && b0 >= 0 && b1 <= 0) {
      // Inside the bracket b may be undefined (too few levels): the root finder then ends there.
      RootTolerance tol;
      tol.abs = 1e-12;
      tol.rel = 0;
      tol.max_iterations = opt.max_iterations;
      const double th = bisected_root([&](double t) { const double bt = b_at(t, nullptr); return std::isfinite(bt) ? bt : 0.0; },
                                      th0, th1, tol).x;
      Line Lr;
      b_at(th, &Lr);
      if (Lr.n >= opt.min_levels && Lr.rms < best_rms) { best_rms = Lr.rms; best_theta = th; }
    }
    th0 = th1;
    b0 = b1;
  }
  double theta = best_theta;
  b_at(theta, &L);
  if (!std::isfinite(best_rms)) {
    r.levels = max_levels;
    r.why = max_levels < opt.min_levels
                ? "the head is cut on both sides at only " + std::to_string(max_levels) + " of " + std::to_string(opt.levels) +
                      " levels " + format_number(opt.depth_min * 1e3) + " … " + format_number(opt.depth_max * 1e3) +
                      " mm below its top (need " + std::to_string(opt.min_levels) + ")"
                : "no axis of symmetry within ±" + format_number(std::round(opt.max_angle / units::deg * 1e3) / 1e3) + " deg";
    return r;
  }
  r.levels = L.n;
  // Sensitivity db/dθ at the root: the standard error of b becomes one of θ, and a head whose
  // cuts do not move when turned (a circular arc, symmetric about every radius) has no axis.
  const double h = 0.1 * units::deg;
  Line Lp, Lm;
  const double bp = b_at(theta + h, &Lp), bm = b_at(theta - h, &Lm);
  const double dbdth = (bp - bm) / (2 * h);
  if (!std::isfinite(dbdth) || std::fabs(dbdth) < opt.min_sensitivity) {
    r.why = "no unique axis of symmetry: the cuts do not move when the head is turned (a circular arc?)";
    return r;
  }
  r.found = true;
  r.angle = theta;
  r.std_error = L.std_error * (1 + L.b * L.b) / std::fabs(dbdth);  // se(b) / |db/dθ|
  r.residual = L.rms;
  r.confident = r.std_error <= opt.max_std_error && r.residual <= opt.max_residual;
  if (!r.confident)
    r.why = "the head is not symmetric enough (standard error " + format_number(std::round(r.std_error / units::deg * 1e3) / 1e3) +
            " deg, midpoints " + format_number(std::round(r.residual * 1e6) / 1e3) + " mm RMS from the axis)";
  return r;
}

namespace {
std::string deg(double a) { return format_number(std::round(a / units::deg * 1e3) / 1e3 + 0.0) + " deg"; }
}  // namespace

RailCantCheck check_rail_cant(const Profile& rail, const Inclination& incl, const RailCantOptions& opt,
                              const RailCantLimits& lim) {
  RailCantCheck c;
  c.used = estimate_rail_cant(rail, opt);
  c.inclination = inclination_angle(incl);
  c.file_angle = c.used.angle - c.inclination;
  if (!c.used.found) return c;
  // A worn head gives an estimate that is not confident (biased by the wear): the checks still
  // run on it, with a margin of two standard errors, and the warning says so (a
  // worn rail laid at 1:40 canted again gave 7.7 deg silently).
  const double margin = c.used.confident ? 0.0 : 2 * c.used.std_error;
  const std::string note = c.used.confident ? std::string() : " (estimate not confident: " + c.used.why + ")";
  const bool cants = incl.mode == Inclination::Mode::Ratio || (incl.mode == Inclination::Mode::Angle && incl.value != 0);
  const std::size_t before = c.warnings.size();
  if (std::fabs(c.file_angle) >= lim.already_canted + margin) {
    if (cants)
      c.warnings.push_back("cant: the rail file looks canted already (" + deg(c.file_angle) + ", " + cant_ratio(c.file_angle) +
                           ") and the case cants it again by " + to_string(incl) + ": " + deg(c.used.angle) +
                           " as used; use \"inclination\": \"as-is\" if the file is laid as used");
    else if (incl.mode == Inclination::Mode::None)
      c.warnings.push_back("cant: the case says \"none\" (a vertical rail) but the rail file looks canted (" +
                           deg(c.file_angle) + ", " + cant_ratio(c.file_angle) + "); use \"as-is\" for a file laid as used");
  }
  if (c.used.angle < -lim.tolerance - margin)
    c.warnings.push_back("cant: the rail as used leans to the field side (" + deg(c.used.angle) + ", " + cant_ratio(c.used.angle) +
                         "), outside the usual 0 … 1:20: a canted rail mirrored in y (check mirror_y)?");
  else if (c.used.angle > lim.max_cant + lim.tolerance + margin)
    c.warnings.push_back("cant: the rail as used is canted " + deg(c.used.angle) + " (" + cant_ratio(c.used.angle) +
                         "), more than the usual 1:20 (2.862 deg)");
  for (std::size_t k = before; k < c.warnings.size(); ++k) c.warnings[k] += note;
  return c;
}

std::string cant_ratio(double angle) {
  // Upright when the angle prints as 0 deg (below 0.0005 deg, steeper than 1:114,000): a ratio of
  // -1:585778.6 is the cuts' noise, not a cant.
  if (std::fabs(angle) < 0.0005 * units::deg) return "upright";
  const double N = 1.0 / std::tan(std::fabs(angle));
  char buf[40];  // one decimal, fixed notation (not 1e+05), ".0" dropped
  std::snprintf(buf, sizeof buf, "%.1f", std::round(N * 10) / 10);
  std::string n = buf;
  if (n.size() > 2 && n.compare(n.size() - 2, 2, ".0") == 0) n.resize(n.size() - 2);
  return std::string(angle < 0 ? "-" : "") + "1:" + n;
}

}  // namespace mh
