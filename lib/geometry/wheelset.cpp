// Rigid contact geometry of a wheelset on a track; see wheelset.hpp and docs/wheelset.md.
#include "geometry/wheelset.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>

#include <boost/math/tools/minima.hpp>

#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "core/parallel.hpp"
#include "core/roots.hpp"

namespace mh {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// Iteration cap of TOMS 748 (contact point: a bracket of one scan step to machine precision in
/// ~10 iterations; roll: ~15). Reaching it is reported, not hidden (WheelsetState::converged).
constexpr int kMaxIterations = 100;
/// The contact point's G'(η) = 0 is solved to a bracket of 2^-49 relative (Boost's
/// eps_tolerance(50): 1e-16 m on a 70 mm coordinate).
constexpr double kContactRelTolerance = 0x1p-49;
/// Local minima of the scanned gap refined: those within two_point_gap plus this of the lowest
/// sample (the scan's own error at 0.05 mm spacing is below 1e-7 m on an R8 arc: h²/(8R)).
constexpr double kCandidateMargin = 10e-6;  // [m]
/// [m] Allowance for rounding in the pruned scan's bounds (the gap and the rail coordinates are
/// sums of terms below 1 m, each rounded to 1.1e-16 m): a block is skipped only when its bound
/// exceeds the threshold by this much more.
constexpr double kBoundSlack = 1e-12;

std::string mm_text(double v) { return format_number(v * 1e3); }

}  // namespace

WheelsetRoll parse_wheelset_roll(const std::string& s) {
  if (s == "none") return WheelsetRoll::None;
  if (s == "solved") return WheelsetRoll::Solved;
  throw std::invalid_argument("roll must be \"none\" or \"solved\"");
}

const char* to_string(WheelsetRoll r) { return r == WheelsetRoll::None ? "none" : "solved"; }

bool WheelsetOptions::valid(std::string* why) const {
  auto bad = [&](const std::string& field, double v, const std::string& rule) {
    if (why) *why = field + " = " + format_number(v) + ": " + rule;
    return false;
  };
  if (!(scan_step > 0 && scan_step <= 1e-3)) return bad("scan_step", scan_step, "must lie in (0, 1 mm]");
  if (!(two_point_gap >= 0 && two_point_gap < 1e-3)) return bad("two_point_gap", two_point_gap, "must lie in [0, 1 mm)");
  if (!(jump_distance > 0)) return bad("jump_distance", jump_distance, "must be > 0");
  if (!(max_roll > 0 && max_roll < 0.5)) return bad("max_roll", max_roll, "must lie in (0, 0.5 rad)");
  if (!(roll_tolerance > 0 && roll_tolerance < 1e-3)) return bad("roll_tolerance", roll_tolerance, "must lie in (0, 1e-3 rad)");
  if (!(max_displacement >= 0 && max_displacement <= 0.2)) return bad("max_displacement", max_displacement, "must lie in [0, 200 mm]");
  return true;
}

double WheelsetState::delta_tan_gamma() const { return std::tan(right.gamma) - std::tan(left.gamma); }

double Wheelset::RailScan::z_at(double yr) const {
  const double t = (yr - y_min) / step;
  const std::size_t n = z.size();
  if (t <= 0) return z[0];
  const std::size_t i = std::min(static_cast<std::size_t>(t), n - 2);
  const double f = t - static_cast<double>(i);
  return z[i] + f * (z[i + 1] - z[i]);
}

double Wheelset::RailScan::max_over(double lo, double hi) const {
  // z_at(y) interpolates between entries i and i + 1, i = floor((y − y_min)/step) clamped to
  // [0, n − 2]: every entry from floor(t_lo) to floor(t_hi) + 1, widened by one on each side for
  // the rounding of t.
  const std::size_t n = z.size();
  const double t_lo = std::floor((lo - y_min) / step) - 1, t_hi = std::floor((hi - y_min) / step) + 2;
  const std::size_t k_lo = t_lo <= 0 ? 0 : std::min(n - 1, static_cast<std::size_t>(t_lo));
  const std::size_t k_hi = t_hi <= 0 ? 0 : std::min(n - 1, static_cast<std::size_t>(t_hi));
  const std::size_t lev = static_cast<std::size_t>(63 - __builtin_clzll(static_cast<unsigned long long>(k_hi - k_lo + 1)));
  const double* m = max.data() + lev * n;
  return std::max(m[k_lo], m[k_hi + 1 - (std::size_t{1} << lev)]);
}

Wheelset::Wheelset(const Profile& wheel_left, const Profile& wheel_right, const Profile& rail_left,
                   const Profile& rail_right, const WheelsetPlacement& P, const WheelsetOptions& opt)
    : opt_(opt) {
  std::string why;
  if (!opt.valid(&why)) throw InputError("wheelset options", "", why);
  const Profile* wheels[2] = {&wheel_left, &wheel_right};
  const Profile* rails[2] = {&rail_left, &rail_right};
  std::shared_ptr<const ProfileCurve> wc[2], rc[2];
  for (int k = 0; k < 2; ++k)  // one profile for both sides (mirrored) is smoothed once
    rc[k] = k == 1 && rails[1] == rails[0] ? rc[0] : std::make_shared<const ProfileCurve>(*rails[k], opt.curve);
  double gauge_y[2] = {kNaN, kNaN};
  for (int k = 0; k < 2; ++k) {
    Side& S = side_[k];
    S.W = wc[k];
    S.R = rc[k];
    S.s = k == 0 ? -1.0 : 1.0;
    S.R0 = k == 0 ? P.nominal_radius_left : P.nominal_radius_right;
    S.a = P.flange_back_distance / 2 - P.flange_back_position;
    const RailLandmarks L = rail_landmarks(*rails[k], P.gauge_height);
    if (L.has_gauge) gauge_y[k] = L.y_gauge;
    if (P.rails == WheelsetPlacement::Rails::Gauge) {
      if (!L.has_gauge)
        throw InputError(rails[k]->source, "", "no gauge point found " + mm_text(P.gauge_height) +
                                                   " mm below the top of the rail on its gauge side (negative y)",
                         "the rail profile must reach that low on the gauge side (check mirror_y); or place the rails "
                         "absolutely: rails.placement \"absolute\" with rails.origin_mm");
      S.c = P.gauge / 2 - L.y_gauge;
    } else {
      S.c = k == 0 ? P.rail_origin_left : P.rail_origin_right;
    }
    a_[k] = S.a;
    c_[k] = S.c;
    S.yr_min = S.R->y_min(), S.yr_max = S.R->y_max();
    if (k == 1 && rc[1] == rc[0]) {
      S.rail = side_[0].rail;
    } else {
      auto T = std::make_shared<RailScan>();
      T->y_min = S.yr_min;
      T->step = std::min(opt.curve.grid_step, opt.scan_step);
      const std::size_t nr = static_cast<std::size_t>(std::ceil((S.yr_max - S.yr_min) / T->step)) + 1;
      T->z.resize(std::max<std::size_t>(nr, 2));
      for (std::size_t i = 0; i < T->z.size(); ++i)
        T->z[i] = S.R->z(std::min(S.yr_min + T->step * static_cast<double>(i), S.yr_max));
      const std::size_t n = T->z.size();
      T->levels = 1;
      while ((std::size_t{1} << T->levels) <= n) ++T->levels;
      T->max.resize(T->levels * n);
      std::copy(T->z.begin(), T->z.end(), T->max.begin());
      for (std::size_t l = 1; l < T->levels; ++l) {
        const double* prev = T->max.data() + (l - 1) * n;
        double* cur = T->max.data() + l * n;
        const std::size_t half = std::size_t{1} << (l - 1);
        for (std::size_t i = 0; i < n; ++i) cur[i] = i + half < n ? std::max(prev[i], prev[i + half]) : prev[i];
      }
      S.rail = std::move(T);
    }
  }
  for (int k = 0; k < 2; ++k) gauge_point_[k] = c_[k] + gauge_y[k];
  measured_gauge_ = gauge_point_[0] + gauge_point_[1];
  const CurveOptions wopt = wheel_curve_options();
  for (int k = 0; k < 2; ++k) {
    wc[k] = k == 1 && wheels[1] == wheels[0] ? wc[0] : std::make_shared<const ProfileCurve>(*wheels[k], wopt);
    set_wheel(side_[k], wc[k], *wheels[k]);
  }
}

CurveOptions Wheelset::wheel_curve_options() const {
  // Wheel coordinate facing rail coordinate y_r without roll: η = y_r − (s y − c) − a, for |y| up
  // to max_displacement and y_r over the rail (contact(): y_r = U0 + cos·(a + η) − sin·q). The
  // roll (Solved) moves it by up to sin(max_roll)·(R0 + 0.1 m), as contact()'s scan allows; the
  // fits of the nodes at the ends reach two window half-widths (the one-sided windows) beyond.
  const CurveOptions& c = opt_.curve;
  const double reach = 2 * std::max(c.window_half_width, c.measured_window_half_width) + 1e-3;
  double lo = 0, hi = 0;  // the taping line (y = 0) is always kept: z_w(0) is the radius's reference
  for (const Side& S : side_) {
    const double roll = opt_.roll == WheelsetRoll::Solved ? std::sin(opt_.max_roll) * (S.R0 + 0.1) : 0.0;
    lo = std::min(lo, S.yr_min - opt_.max_displacement + S.c - S.a - roll - reach);
    hi = std::max(hi, S.yr_max + opt_.max_displacement + S.c - S.a + roll + reach);
  }
  CurveOptions w = c;
  w.y_from = std::max(w.y_from, lo);
  w.y_to = std::min(w.y_to, hi);
  return w;
}

void Wheelset::set_wheel(Side& S, std::shared_ptr<const ProfileCurve> W, const Profile& wheel) {
  S.W = std::move(W);
  if (!S.W->contains(0.0))
    throw InputError(wheel.source, "y = " + mm_text(S.W->y_min()) + " … " + mm_text(S.W->y_max()) + " mm",
                     "the wheel profile does not reach its taping line (y = 0), where the nominal radius is given",
                     "check the profile's origin (taping line 70 mm from the flange back) and mirror options");
  S.zw0 = S.W->z(0.0);
  S.yw_min = S.W->y_min(), S.yw_max = S.W->y_max();
  const double h = opt_.scan_step;
  S.ys0 = wheel.y.front();
  S.is0 = static_cast<std::size_t>(std::max(0.0, std::ceil((S.yw_min - S.ys0) / h)));
  while (S.is0 > 0 && S.eta(0, h) - h >= S.yw_min) --S.is0;  // the first grid point inside
  while (S.eta(0, h) < S.yw_min) ++S.is0;
  std::size_t nw = 0;
  while (S.eta(nw, h) <= S.yw_max) ++nw;
  S.zw_scan.resize(nw);
  for (std::size_t i = 0; i < nw; ++i) S.zw_scan[i] = S.W->z(S.eta(i, h));
  const std::size_t nb = (nw + kScanBlock - 1) / kScanBlock;
  S.zw_block_min.assign(nb, std::numeric_limits<double>::infinity());
  S.zw_block_max.assign(nb, -std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < nw; ++i) {
    double& lo = S.zw_block_min[i / kScanBlock];
    double& hi = S.zw_block_max[i / kScanBlock];
    lo = std::min(lo, S.zw_scan[i]);
    hi = std::max(hi, S.zw_scan[i]);
  }
}

Wheelset::Wheelset(const Wheelset& track, const Profile& wheel_left, const Profile& wheel_right) : Wheelset(track) {
  const CurveOptions wopt = wheel_curve_options();
  auto wl = std::make_shared<const ProfileCurve>(wheel_left, wopt);
  auto wr = &wheel_right == &wheel_left ? wl : std::make_shared<const ProfileCurve>(wheel_right, wopt);
  set_wheel(side_[0], wl, wheel_left);
  set_wheel(side_[1], wr, wheel_right);
}

WheelContact Wheelset::contact(const Side& S, double y, double phi, bool* found) const {
  const double ps = S.s * phi, cs = std::cos(ps), sn = std::sin(ps);
  const double U0 = S.s * y - S.c;  // rail coordinate of the axle centre's vertical
  // Gap at wheel coordinate eta, and its derivative, on the smooth profiles.
  auto gap = [&](double eta, double* dG, double* yr_out) {
    double dzw = 0;
    const double zw = S.W->z(eta, &dzw);
    const double p = S.a + eta, q = -S.R0 + (zw - S.zw0);
    const double yr = U0 + cs * p - sn * q;
    double dzr = 0;
    const double zr = S.R->z(yr, &dzr);
    if (dG) *dG = (sn + cs * dzw) - dzr * (cs - sn * dzw);
    if (yr_out) *yr_out = yr;
    return sn * p + cs * q - zr;
  };
  // Scan, over the wheel coordinates that face the rail: y_r = U0 + cos·(a + η) − sin·q with
  // |q − (−R0)| below 0.1 m (any wheel profile's radius change), bounded by |sin|·0.1 m.
  const double h = opt_.scan_step;
  const std::size_t n = S.zw_scan.size();
  const double slack = std::fabs(sn) * (S.R0 + 0.1) + h;
  const double e_lo = (S.yr_min - U0 - slack) / cs - S.a, e_hi = (S.yr_max - U0 + slack) / cs - S.a;
  const double e0 = S.eta(0, h);
  const double i_lo = std::floor((e_lo - e0) / h), i_hi = std::ceil((e_hi - e0) / h);
  const std::size_t i0 = i_lo <= 0 ? 0 : std::min(n, static_cast<std::size_t>(i_lo));
  const std::size_t i1 = i_hi < 0 ? 0 : std::min(n, static_cast<std::size_t>(i_hi) + 1);
  // The gap at scan sample i (NaN outside [i0, i1) and where the wheel does not face the rail).
  const RailScan& Rs = *S.rail;
  auto sample = [&](std::size_t i) {
    if (i < i0 || i >= i1) return kNaN;
    const double eta = S.eta(i, h);
    const double p = S.a + eta, q = -S.R0 + (S.zw_scan[i] - S.zw0);
    const double yr = U0 + cs * p - sn * q;
    if (yr < S.yr_min || yr > S.yr_max) return kNaN;
    return sn * p + cs * q - Rs.z_at(yr);
  };
  // Pruned scan. Block b holds samples [b·B, (b+1)·B) ∩ [i0, i1). Over it p = a + η lies in
  // [p_lo, p_hi] and q = −R0 + (z_w − z_w0) in [q_lo, q_hi] (the block's lowest and highest wheel
  // samples), so y_r = U0 + cos·p − sin·q stays in a known range and
  //     G = sin·p + cos·q − z_r(y_r) ≥ min(sin·p) + cos·q_lo − max z_r over that range = lb_b.
  // The lowest sample G_min ≤ U (the lowest of the blocks evaluated first); a block with
  // lb_b > U + two_point_gap + kCandidateMargin holds neither G_min nor any sample within the
  // candidates' limit, so skipping it leaves gmin, the candidates and their neighbours' tests as
  // in the full scan. A block whose y_r range misses the rail holds only NaN samples.
  constexpr std::size_t B = kScanBlock;
  const double inf = std::numeric_limits<double>::infinity();
  thread_local std::vector<double> G, lb;
  thread_local std::vector<char> done;
  if (G.size() < n) G.resize(n);
  const std::size_t b0 = i0 / B, nb = i1 > i0 ? (i1 - 1) / B + 1 - b0 : 0;
  lb.assign(nb, inf);
  done.assign(nb, 0);
  for (std::size_t k = 0; k < nb; ++k) {
    const std::size_t b = b0 + k, j0 = std::max(i0, b * B), j1 = std::min(i1, (b + 1) * B);
    const double p_lo = S.a + S.eta(j0, h), p_hi = S.a + S.eta(j1 - 1, h);
    const double q_lo = -S.R0 + (S.zw_block_min[b] - S.zw0), q_hi = -S.R0 + (S.zw_block_max[b] - S.zw0);
    const double sq_lo = std::min(sn * q_lo, sn * q_hi), sq_hi = std::max(sn * q_lo, sn * q_hi);
    const double y_lo = std::max(U0 + cs * p_lo - sq_hi - kBoundSlack, S.yr_min);
    const double y_hi = std::min(U0 + cs * p_hi - sq_lo + kBoundSlack, S.yr_max);
    if (opt_.full_scan) {  // every block evaluated
      lb[k] = -inf;
      continue;
    }
    if (!(y_lo <= y_hi)) continue;
    lb[k] = std::min(sn * p_lo, sn * p_hi) + cs * q_lo - Rs.max_over(y_lo, y_hi) - kBoundSlack;
  }
  double gmin = inf;
  auto evaluate = [&](std::size_t k) {
    const std::size_t b = b0 + k, j1 = std::min(i1, (b + 1) * B);
    for (std::size_t i = std::max(i0, b * B); i < j1; ++i) {
      G[i] = sample(i);
      gmin = std::min(gmin, G[i]);
    }
    done[k] = 1;
  };
  // U: the blocks of lowest bound first, until one sample faces the rail.
  while (!std::isfinite(gmin)) {
    std::size_t best = nb;
    for (std::size_t k = 0; k < nb; ++k)
      if (!done[k] && lb[k] < inf && (best == nb || lb[k] < lb[best])) best = k;
    if (best == nb) break;
    evaluate(best);
  }
  *found = std::isfinite(gmin);
  WheelContact best;
  if (!*found) return best;
  const double threshold = gmin + opt_.two_point_gap + kCandidateMargin;
  for (std::size_t k = 0; k < nb; ++k)
    if (!done[k] && lb[k] <= threshold) evaluate(k);
  // A sample's value: from the evaluated blocks, else computed (a neighbour in a skipped block).
  auto at = [&](std::size_t i) { return i >= i0 && i < i1 && done[i / B - b0] ? G[i] : sample(i); };

  struct Cand { double eta, G, yr; bool edge; };
  thread_local std::vector<Cand> cands;
  cands.clear();
  const double limit = gmin + opt_.two_point_gap + kCandidateMargin;
  for (std::size_t k = 0; k < nb; ++k) {
    if (!done[k]) continue;
    const std::size_t b = b0 + k, j1 = std::min(i1, (b + 1) * B);
    for (std::size_t i = std::max(i0, b * B); i < j1; ++i) {
      if (!(G[i] <= limit)) continue;
      const double gl = i > 0 ? at(i - 1) : kNaN, gr = i + 1 < n ? at(i + 1) : kNaN;
      const bool has_l = !std::isnan(gl), has_r = !std::isnan(gr);
      if ((has_l && gl < G[i]) || (has_r && gr < G[i])) continue;  // not a local minimum
      if (has_l && gl == G[i]) continue;                           // a plateau: its first sample only
      const double eta_i = S.eta(i, h);
      Cand c{eta_i, 0, 0, !(has_l && has_r)};
      if (!c.edge) {
        // Refine: G'(η) = 0 between the neighbours (TOMS 748), else the minimum of G (Brent).
        const double lo = eta_i - h, hi = eta_i + h;
        double dlo = 0, dhi = 0;
        gap(lo, &dlo, nullptr);
        gap(hi, &dhi, nullptr);
        if (dlo < 0 && dhi > 0) {
          RootTolerance tol;
          tol.rel = kContactRelTolerance;
          tol.max_iterations = kMaxIterations;
          auto f = [&](double e) { double d = 0; gap(e, &d, nullptr); return d; };
          const RootResult r = bracketed_root(f, lo, hi, dlo, dhi, tol);
          c.eta = 0.5 * (r.lo + r.hi);
        } else {
          const auto r = boost::math::tools::brent_find_minima([&](double e) { return gap(e, nullptr, nullptr); }, lo, hi, 40);
          c.eta = r.first;
        }
      }
      c.G = gap(c.eta, nullptr, &c.yr);
      cands.push_back(c);
    }
  }
  std::size_t m = 0;
  for (std::size_t k = 1; k < cands.size(); ++k)
    if (cands[k].G < cands[m].G) m = k;
  const Cand& C = cands[m];
  double dzw = 0, dzr = 0;
  best.y_w = C.eta;
  best.z_w = S.W->z(C.eta, &dzw);
  best.y_r = C.yr;
  best.z_r = S.R->z(C.yr, &dzr);
  best.r = S.R0 - (best.z_w - S.zw0);
  best.gamma = std::atan(dzr);
  best.h = -C.G;
  best.off_profile = C.edge;
  for (std::size_t k = 0; k < cands.size(); ++k) {
    if (k == m) continue;
    if (cands[k].G - C.G <= opt_.two_point_gap && std::fabs(cands[k].yr - C.yr) > opt_.jump_distance) {
      best.two_point = true;
      best.y_r_second = cands[k].yr;
    }
  }
  return best;
}

WheelsetState Wheelset::at(double y) const {
  WheelsetState st;
  st.y = y;
  bool fl = false, fr = false;
  if (opt_.roll == WheelsetRoll::None) {
    st.left = contact(side_[0], y, 0.0, &fl);
    st.right = contact(side_[1], y, 0.0, &fr);
    st.found = fl && fr;
    return st;
  }
  // Solved: the axle heights at which each wheel touches agree. h_right falls and h_left rises
  // with φ (raising the right end lifts the right wheel off its rail).
  bool ok = true;
  auto f = [&](double phi) {
    bool a = false, b = false;
    const double v = contact(side_[1], y, phi, &b).h - contact(side_[0], y, phi, &a).h;
    ok = ok && a && b;
    return v;
  };
  const double lo = -opt_.max_roll, hi = opt_.max_roll;
  const double flo = f(lo), fhi = f(hi);
  if (!ok || !(flo > 0 && fhi < 0)) {
    st.found = ok;
    st.converged = false;
    st.roll = kNaN;
    st.left = contact(side_[0], y, 0.0, &fl);
    st.right = contact(side_[1], y, 0.0, &fr);
    return st;
  }
  RootTolerance tol;
  tol.abs = opt_.roll_tolerance;
  tol.rel = 0;
  tol.max_iterations = kMaxIterations;
  const RootResult r = bracketed_root(f, lo, hi, flo, fhi, tol);
  st.converged = r.converged;
  st.roll = 0.5 * (r.lo + r.hi);
  st.left = contact(side_[0], y, st.roll, &fl);
  st.right = contact(side_[1], y, st.roll, &fr);
  st.found = ok && fl && fr;
  return st;
}

bool Wheelset::mirrored() const {
  // Same profiles, rail scan table and placement on both sides: without roll, the left wheel at
  // y is the right wheel at −y (contact() sees U0 = −y − c either way, and nothing else of y).
  const Side &L = side_[0], &R = side_[1];
  return opt_.roll == WheelsetRoll::None && L.W == R.W && L.R == R.R && L.rail == R.rail && L.R0 == R.R0 &&
         L.a == R.a && L.c == R.c && L.ys0 == R.ys0 && L.is0 == R.is0;
}

std::vector<WheelsetState> Wheelset::sweep(const std::vector<double>& ys, unsigned threads) const {
  std::vector<WheelsetState> out(ys.size());
  const std::size_t n = ys.size();
  // The library's one parallel loop (core/parallel.hpp), blocks of 64 rows; each row is written
  // to its own slot, so the results do not depend on the thread count.
  auto parallel = [&](auto&& row) {
    parallel_for(n, std::max(1u, threads), 64, [] { return 0; }, [&](std::size_t k, int&) { row(k); });
  };
  if (!mirrored()) {
    parallel([&](std::size_t k) { out[k] = at(ys[k]); });
  } else {
    // The right wheel at every row, then the left wheel from the row at −y where there is one.
    std::vector<char> found_right(n), found_left(n);
    parallel([&](std::size_t k) {
      bool f = false;
      out[k].y = ys[k];
      out[k].right = contact(side_[1], ys[k], 0.0, &f);
      found_right[k] = f;
    });
    parallel([&](std::size_t k) {
      const auto it = std::lower_bound(ys.begin(), ys.end(), -ys[k]);
      bool f = false;
      if (it != ys.end() && *it == -ys[k]) {
        const std::size_t m = static_cast<std::size_t>(it - ys.begin());
        out[k].left = out[m].right;
        f = found_right[m];
      } else {
        out[k].left = contact(side_[0], ys[k], 0.0, &f);
      }
      found_left[k] = f;
    });
    for (std::size_t k = 0; k < n; ++k) out[k].found = found_left[k] && found_right[k];
  }
  for (std::size_t k = 1; k < n; ++k) {
    WheelsetState& a = out[k];
    const WheelsetState& b = out[k - 1];
    if (!a.found || !b.found) continue;
    if (std::fabs(a.left.y_r - b.left.y_r) > opt_.jump_distance) a.left.two_point = true;
    if (std::fabs(a.right.y_r - b.right.y_r) > opt_.jump_distance) a.right.two_point = true;
  }
  return out;
}

}  // namespace mh
