#include "contact/grid/grid_checks.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/grid/pressure_spike.hpp"
#include "core/numfmt.hpp"

namespace mh {

namespace {

double rail_y(const PatchCheckInput& in, int j) { return in.y_ref + (in.s0 + j * in.ds) * std::cos(in.gamma); }

}  // namespace

int elements_across(const std::vector<double>& p, int nx, int ns) {
  auto loaded = [&](int i, int j) { return p[static_cast<std::size_t>(i + nx * j)] > 0; };
  int run_s = 0, run_x = 0;
  for (int i = 0; i < nx; ++i)
    for (int j = 0, run = 0; j < ns; ++j) { run = loaded(i, j) ? run + 1 : 0; run_s = std::max(run_s, run); }
  if (nx == 1) return run_s;
  for (int j = 0; j < ns; ++j)
    for (int i = 0, run = 0; i < nx; ++i) { run = loaded(i, j) ? run + 1 : 0; run_x = std::max(run_x, run); }
  return std::min(run_s, run_x);
}

ContactHole find_contact_hole(const PatchCheckInput& in) {
  ContactHole h;
  const double tol = kGapRtol * in.approach;
  auto P = [&](int i, int j) { return in.p[static_cast<std::size_t>(i + in.nx * j)]; };
  // For each element, whether a loaded element lies before / after it along its row and column:
  // prefix and suffix scans, O(nx ns).
  const std::size_t n = in.p.size();
  // Per-thread scratch, zeroed as fresh vectors (no allocation once grown to the largest grid).
  thread_local std::vector<char> left, right, below, above;
  for (auto* v : {&left, &right, &below, &above}) v->assign(n, 0);
  for (int j = 0; j < in.ns; ++j) {
    char seen = 0;
    for (int i = 0; i < in.nx; ++i) { left[i + in.nx * j] = seen; seen = seen || P(i, j) > 0; }
    seen = 0;
    for (int i = in.nx - 1; i >= 0; --i) { right[i + in.nx * j] = seen; seen = seen || P(i, j) > 0; }
  }
  for (int i = 0; i < in.nx; ++i) {
    char seen = 0;
    for (int j = 0; j < in.ns; ++j) { below[i + in.nx * j] = seen; seen = seen || P(i, j) > 0; }
    seen = 0;
    for (int j = in.ns - 1; j >= 0; --j) { above[i + in.nx * j] = seen; seen = seen || P(i, j) > 0; }
  }
  for (int j = 0; j < in.ns; ++j)
    for (int i = 0; i < in.nx; ++i) {
      const std::size_t e = static_cast<std::size_t>(i + in.nx * j);
      if (P(i, j) > 0 || !(in.overlap[e] > tol)) continue;
      if (!below[e] || !above[e] || !left[e] || !right[e]) continue;
      ++h.elements;
      if (in.overlap[e] > h.overlap) { h.overlap = in.overlap[e]; h.i = i; h.j = j; }
    }
  return h;
}

void close_grid_case(const std::vector<PatchCheckInput>& in, double Q, double residual_tol, CaseResult& r) {
  close_grid_case(in.data(), in.size(), Q, residual_tol, r);
}

void close_grid_case(const PatchCheckInput* in, std::size_t n, double Q, double residual_tol, CaseResult& r) {
  int index = 0;
  for (PatchResult& P : r.patches) P.patch = ++index;
  r.n_contacts = static_cast<int>(r.patches.size());
  r.residual = (r.Fz - Q) / Q;
  if (r.status == CaseStatus::Ok && std::fabs(r.residual) > residual_tol) {
    r.status = CaseStatus::NotConverged;
    r.message = "force balance residual " + format_number(r.residual);
    r.warnings.push_back(Warning(WarningClass::NotConvergedLoad).add(Quantity::Residual, r.residual, '>', residual_tol));
  }
  check_grid_result(in, n, Q, r);
}

void check_grid_result(const std::vector<PatchCheckInput>& in, double Q, CaseResult& r) {
  check_grid_result(in.data(), in.size(), Q, r);
}

void check_grid_result(const PatchCheckInput* in, std::size_t n_in, double Q, CaseResult& r) {
  if (r.status != CaseStatus::Ok) return;
  // Force balance (eq. 10), from the patches as reported.
  double Fz = 0;
  for (const PatchResult& P : r.patches) Fz += P.N * std::cos(P.gamma);
  const double res = (Fz - Q) / Q;
  if (!(std::fabs(res) <= kForceBalanceRtol))
    r.warnings.push_back(Warning(WarningClass::ForceBalance).add(Quantity::Residual, res, '>', kForceBalanceRtol));
  for (std::size_t k = 0; k < n_in && k < r.patches.size(); ++k) {
    const PatchCheckInput& c = in[k];
    const int patch = static_cast<int>(k) + 1;
    if (!c.p.empty()) {  // the peak's row j along s; a capped plateau's middle row
      const double p_top = *std::max_element(c.p.begin(), c.p.end());
      int j_lo = -1, j_hi = -1;
      const int nx = std::max(c.nx, 1);
      for (std::size_t e = 0; e < c.p.size(); ++e)
        if (c.p[e] >= p_top * (1 - 1e-9)) {
          const int j = static_cast<int>(e) / nx;
          if (j_lo < 0) j_lo = j;
          j_hi = j;
        }
      if (p_top > 0) r.patches[k].y_peak = rail_y(c, (j_lo + j_hi) / 2);
    }
    auto warn = [&](WarningClass cls) -> Warning& {
      r.warnings.emplace_back(cls, ContactKind::Patch, patch);
      return r.warnings.back();
    };
    // Complementarity: 0 ≤ p ≤ p_lim (a cap reached to round-off), the deformed gap's conditions.
    double p_lo = 0, p_hi = 0;
    for (double v : c.p) { p_lo = std::min(p_lo, v); p_hi = std::max(p_hi, v); }
    if (p_lo < 0) warn(WarningClass::Complementarity).add(Quantity::PMin, p_lo, '<', 0);
    if (std::isfinite(c.p_lim) && p_hi > c.p_lim * (1 + 1e-9))
      warn(WarningClass::Complementarity).add(Quantity::PMax, p_hi, '>', c.p_lim);
    const double gap_tol = kGapRtol * c.approach;
    if (std::isfinite(c.gap_violation) && c.gap_violation > gap_tol)
      warn(WarningClass::Complementarity).add(Quantity::GapViolation, c.gap_violation, '>', gap_tol);
    if (std::isfinite(c.end_gap_error) && !c.refined && c.end_gap_error > c.end_gap_tol)
      warn(WarningClass::Complementarity).add(Quantity::EndGapError, c.end_gap_error, '>', c.end_gap_tol);
    // An isolated peak (half-space).
    if (c.spike_check) {
      const PressureSpike spike = find_pressure_spike(c.p, c.nx, c.ns);
      if (spike.found)
        warn(WarningClass::PressureSpike)
            .add(Quantity::YRail, rail_y(c, spike.j))
            .add(Quantity::PSpike, spike.p)
            .add(Quantity::PNeighbours, spike.neighbours);
    }
    // Too few elements across the patch for the method's peak accuracy.
    if (c.min_across > 0) {
      const int n = elements_across(c.p, c.nx, c.ns);
      if (n < c.min_across)
        warn(WarningClass::UnderResolved)
            .add(Quantity::ElementsAcross, n, '<', c.min_across)
            .add(Quantity::Element, c.element);
      else if (c.peak_change > c.peak_rtol)  // refined, but the peak still moved on the last halving
        warn(WarningClass::UnderResolved)
            .add(Quantity::PeakChange, c.peak_change, '>', c.peak_rtol)
            .add(Quantity::Element, c.element);
    }
    // A hole where the bodies overlap.
    const ContactHole hole = c.hole_check ? find_contact_hole(c) : ContactHole();
    if (hole.elements > 0)
      warn(WarningClass::ContactHole)
          .add(Quantity::Elements, hole.elements)
          .add(Quantity::YRail, rail_y(c, hole.j))
          .add(Quantity::Overlap, hole.overlap, '>', gap_tol);
  }
}

void withhold_unconverged_pressures(CaseResult& r) {
  if (r.status != CaseStatus::NotConverged) return;
  r.pmax = NAN;
  r.area = NAN;
  r.patches.clear();
}

}  // namespace mh
