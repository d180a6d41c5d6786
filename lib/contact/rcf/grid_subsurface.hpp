#pragma once
// Stresses below a grid patch (docs/methods.md "Subsurface stresses below a grid patch"): the
// pressure, and optionally the traction, of a grid method's patch (half-space elements, or the
// strips' pressure sampled on a grid), each element a uniform load on its rectangle, on the
// surface z = 0 of an elastic half-space. The stress at a point is the sum over the elements of the
// point-force solutions of Boussinesq and Cerruti (subsurface.hpp) integrated over each rectangle
// by an n × n Gauss–Legendre product rule, n growing as the point comes closer to the rectangle
// than its size (GridQuadrature); the peaks are searched as below a Hertz ellipse (field_peaks).
//
// Elastic only, as the Hertz field: for an elastic patch these are its stresses; for a plastic
// patch (elements at the pressure cap) the elastic stresses of the capped pressure are not the
// stresses of the yielded material, and the callers do not compute them there (docs/outputs.md).
//
// Sign convention and frame as subsurface.hpp: tension positive, z the depth, the loads act on the
// body, x rolling, y lateral (a patch's s). SI throughout.
#include <vector>

#include "contact/rcf/subsurface.hpp"

namespace mh {

/// A surface load on nx × ny uniform rectangles dx × dy, element (i, j) centred at
/// (x0 + i dx, y0 + j dy), x fastest (PatchResult's grid: y is its s).
struct GridLoad {
  int nx = 0, ny = 0;
  double dx = 0, dy = 0, x0 = 0, y0 = 0;  ///< [m]
  std::vector<double> p;       ///< [Pa] pressure on the body, nx·ny values
  std::vector<double> qx, qy;  ///< [Pa] traction on the body along x and y, nx·ny values; empty: none
  double nu = 0.3;             ///< [-] Poisson's ratio of the body
};

/// The quadrature of one rectangle seen from a field point at depth z, d the distance from the
/// point to the rectangle (its lateral distance and z) and h the rectangle's larger side. Far
/// (d ≥ near_distance h): n × n Gauss points, n = ⌈points_per_distance · h / d⌉ clamped to
/// [1, max_points]. Near: the rectangle as the signed sum of the four regions from the point's
/// projection to its corners, each integrated in polar coordinates about the projection with
/// r = z sinh u (the kernels' scale z resolved at any depth), near_theta × near_radial Gauss points
/// per triangle. Defaults: 1e-4 of the load below one rectangle against the closed form, the
/// peaks to 1e-3 p0 with the quadrature doubled (tests/unit/contact/test_grid_subsurface.cpp).
struct GridQuadrature {
  double near_distance = 1;
  int near_theta = 8, near_radial = 12;
  double points_per_distance = 12;
  int max_points = 16;
};

/// [Pa] The stress at (x, y, z), z > 0.
Stress grid_stress(const GridLoad& G, double x, double y, double z, const GridQuadrature& q = {});

/// The peaks of the field below the loaded elements (p > 0): the pass of the load along x over
/// the loaded chord of each of SubsurfaceOptions::ny·2 − 1 rows (at least 1) over 0.8 of the loaded
/// width about its middle, the depths scaled by the smaller loaded half-extent and starting one
/// element deep (shallower, the field resolves the elements' steps of pressure, not the pressure
/// they sample: SubsurfacePeaks::surface then means "within one element of the surface"). NaN
/// peaks without a loaded element.
SubsurfacePeaks grid_subsurface_peaks(const GridLoad& G, const SubsurfaceOptions& o = {}, const GridQuadrature& q = {});

}  // namespace mh
