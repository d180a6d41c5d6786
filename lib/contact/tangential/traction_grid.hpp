#pragma once
// The tangential traction of one contact element by element, kept on request only
// (TangentialOptions::keep_traction, set by `run --pressure-grid` for the cases whose grid it
// writes; docs/outputs.md "pressure.csv"), and FASTSIM's traction at any point of its ellipse
// from its cells (the pressure grid's points). Frame and signs: tangential_types.hpp (tractions on
// the wheel; the files write those on the rail).
#include <vector>

#include "contact/tangential/fastsim.hpp"

namespace mh {

/// FASTSIM's cells of one loaded ellipse (fastsim.hpp, FastsimGrid) and the shape of the traction
/// bound they were solved with.
struct EllipseTraction {
  FastsimGrid cells;
  TractionBound bound = TractionBound::Elliptical;
  bool empty() const { return cells.nx == 0; }
};

/// The tractions of a grid patch (half-space, strips) on the element grid its tangential problem
/// was solved on: nx × ns elements of dx × ds, x fastest, centres at x0 + i dx, s0 + j ds (the
/// patch plane, relative to its reference point). Half-space: the normal solve's grid (pn is
/// PatchResult::p); strips: the grid the strips' pressure is laid on (contact/solve.cpp,
/// solve_tangential_strips).
struct PatchTraction {
  int nx = 0, ns = 0;
  double dx = 0, ds = 0, x0 = 0, s0 = 0;
  std::vector<double> pn;           ///< [Pa] normal pressure (≤ 0: exterior)
  std::vector<double> px, py;       ///< [Pa] traction on the wheel along x and s
  std::vector<unsigned char> slip;  ///< 1 in slip (|p| = μ pn), 0 in adhesion or exterior
  bool empty() const { return nx == 0; }
  void clear() { nx = ns = 0; pn.clear(); px.clear(); py.clear(); slip.clear(); }
};

/// One point's traction [Pa] on the wheel (x, y of the contact frame) and its state.
struct TractionSample {
  double px = 0, py = 0;
  bool slip = false;
};

/// FASTSIM's traction at (x, y) [m] (ellipse frame, origin at its centre) of the ellipse a × b [m]
/// solved into `t` with friction μ. The cells of the strip that holds y give the used friction
/// u = p/(μ pn) at their centres; along x it is interpolated linearly between the two centres
/// around x (held beyond the first and last), the state taken from the nearer one; a point in slip
/// keeps the direction of u at full length. The traction is μ pn(x, y) u with pn the bound's
/// pressure at the point itself (the cells' normalisation; elliptical: P √(1 − x²/a² − y²/b²)).
/// So in slip |p| = μ pn exactly and in adhesion |p| ≤ μ pn. Outside the ellipse: zero, adhesion.
TractionSample fastsim_traction_at(const EllipseTraction& t, double a, double b, double mu, double x, double y);

}  // namespace mh
