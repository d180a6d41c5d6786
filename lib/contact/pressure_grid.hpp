#pragma once
// The points of a case's pressure grid, with the traction where it was kept: the rows of
// pressure.csv (docs/outputs.md "pressure.csv", written by output/case_tables.cpp) and the arrays
// of the C interface's mhc_result_grid (lib/capi/grids.cpp, docs/c-api.md "Pressure and traction
// grids"). One home, so that the command and the library give the same numbers.
//
// Multi-Hertzian: each loaded ellipse on an N × N grid over its patch (method.md §5, §5.1): the
// ellipse law's pressure of the Hertz pressure p0 √(1 − x²/a² − y²/b²) (capped at p_lim, or
// flattened above first yield by the yield law) and, in plastic mode, the elastic Hertz pressure
// at the same load on the elastic patch (a_el, b_el). Grid methods: the elements in contact of
// each patch, on the grid the tractions were solved on where they were kept (traction_grid.hpp).
// Tractions ON THE RAIL (the files' convention, docs/tangential.md): minus those on the wheel.
#include <cmath>
#include <cstddef>
#include <vector>

#include "contact/case_result.hpp"
#include "contact/tangential/traction_grid.hpp"
#include "core/units.hpp"

namespace mh {

/// One point of a pressure grid, SI, in the contact frame of its ellipse or patch.
struct GridPoint {
  int contact = 0;        ///< 1-based ellipse (multi-Hertzian) or patch index
  double x = 0;           ///< [m] along the rolling direction, from the ellipse centre / patch reference point
  double s = 0;           ///< [m] across, in the contact plane (pressure.csv: y_mm of an ellipse, s_mm of a patch)
  double y_rail = NAN;    ///< [m] rail y of a patch point, y_r + s cos γ (NaN for an ellipse)
  double p = 0;           ///< [Pa] normal pressure
  double p_elastic = NAN; ///< [Pa] plastic multi-Hertzian: the elastic Hertz pressure at the same load (else NaN)
  bool traction = false;  ///< px, py, slip are set (the tractions were kept and solved)
  double px = NAN, py = NAN;  ///< [Pa] traction on the rail along x and s
  bool slip = false;      ///< 1 in slip (|p_t| = μ p), 0 in adhesion
};

/// Visit every point of the multi-Hertzian grid of `r`, N × N per loaded ellipse (x outer, y
/// inner, pressure.csv's row order). `plastic`: the ellipse law's pressure and p_elastic.
/// `tangential`: the traction from r.ellipse_traction where it was kept and solved.
template <class F>
void for_each_ellipse_grid_point(const CaseResult& r, bool plastic, int N, bool tangential, F&& f) {
  GridPoint g;
  for (std::size_t e = 0; e < r.loaded.size(); ++e) {
    const LoadedEllipse& L = r.loaded[e];
    const double a = L.s.a, b = L.s.b;
    // FASTSIM's cells of this ellipse, resampled at the grid points (traction_grid.hpp).
    const EllipseTraction* T = tangential && e < r.ellipse_traction.size() && L.t.solved &&
                                       !r.ellipse_traction[e].empty() ? &r.ellipse_traction[e] : nullptr;
    const double p0_el = 1.5 * L.s.N / (units::pi * L.s.a_el * L.s.b_el);
    g.contact = L.ellipse;
    g.traction = T != nullptr;
    for (int i = 0; i < N; ++i) {
      const double x = -a + 2 * a * i / (N - 1);
      for (int j = 0; j < N; ++j) {
        const double y = -b + 2 * b * j / (N - 1);
        const double q = 1 - (x * x) / (a * a) - (y * y) / (b * b);
        double p = q > 0 ? L.s.p0 * std::sqrt(q) : 0.0;
        if (plastic) p = L.s.pressure_at(p);  // the ellipse law's pressure (method.md §5, §5.1)
        g.x = x;
        g.s = y;
        g.p = p;
        if (plastic) {
          const double qe = 1 - (x * x) / (L.s.a_el * L.s.a_el) - (y * y) / (L.s.b_el * L.s.b_el);
          g.p_elastic = qe > 0 ? p0_el * std::sqrt(qe) : 0.0;
        }
        if (T) {
          const TractionSample t = fastsim_traction_at(*T, a, b, L.t.mu, x, y);
          g.px = 0.0 - t.px;  // on the rail; 0 − p: no "-0"
          g.py = 0.0 - t.py;
          g.slip = t.slip;
        }
        f(static_cast<const GridPoint&>(g));
      }
    }
  }
}

/// Visit the elements in contact (p > 0) of every patch of a grid method's case `r` (s outer, x
/// inner, pressure.csv's row order): on the grid the tractions were solved on where they were
/// kept (`tangential`, PatchResult::traction), else on the normal solve's (PatchResult::p, kept
/// with HalfSpaceOptions::keep_pressure; the strip method has no such grid).
template <class F>
void for_each_patch_grid_point(const CaseResult& r, bool tangential, F&& f) {
  GridPoint g;
  for (const PatchResult& P : r.patches) {
    const double c = std::cos(P.gamma);
    const PatchTraction* T = tangential && !P.traction.empty() && P.t.solved ? &P.traction : nullptr;
    const int nx = T ? T->nx : P.nx, ns = T ? T->ns : P.ns;
    const double dx = T ? T->dx : P.dx, ds = T ? T->ds : P.ds, x0 = T ? T->x0 : P.x0, s0 = T ? T->s0 : P.s0;
    const std::vector<double>& pn = T ? T->pn : P.p;
    g.contact = P.patch;
    g.traction = T != nullptr;
    for (int j = 0; j < ns; ++j)
      for (int i = 0; i < nx; ++i) {
        const std::size_t k = static_cast<std::size_t>(i) + static_cast<std::size_t>(nx) * static_cast<std::size_t>(j);
        const double p = pn[k];
        if (!(p > 0)) continue;
        g.x = x0 + i * dx;
        g.s = s0 + j * ds;
        g.y_rail = P.y_r + g.s * c;
        g.p = p;
        if (T) {  // on the rail: minus the traction on the wheel
          g.px = 0.0 - T->px[k];
          g.py = 0.0 - T->py[k];
          g.slip = T->slip[k] != 0;
        }
        f(static_cast<const GridPoint&>(g));
      }
  }
}

}  // namespace mh
