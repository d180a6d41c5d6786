// Strip extents from a virtual interpenetration (docs/method.md §9, "Hertz helper" and
// "Algorithm" items 2–3): at approach delta the interpenetrated strips are grouped into lateral
// bands, split at the saddles (interior local maxima) of the minimum-gap curve g(s); each strip's
// half-length is the union of a KPEC-type estimate (equivalent ellipse per band; Kik & Piotrowski
// 1996, Piotrowski & Kik 2008) and an ANALYN-type estimate (local Hertz solution per strip;
// Sichani et al. 2014), both from the Hertz ellipse shape of h = A x^2 + B y^2 (Johnson §3.6 /
// §4.2). The interpretation of the band approach is in contact/strips/strip_patch.hpp.
//
// Internal to the strip solver (contact/strips/strip_patch.hpp): namespace strips_detail.
#pragma once

#include <vector>

#include "contact/strips/strip_types.hpp"

namespace mh {
namespace strips_detail {

/// The extent estimates of one strip geometry: what depends on the geometry only (local lateral
/// curvature and ANALYN Hertz shape per strip, deepest row) is computed once; bands and extents
/// per approach.
struct StripExtents {
  const StripGeometry& geo;
  int n;
  std::vector<double> Bloc;       // [1/m] local lateral curvature (g''/2), <= 0: none
  std::vector<double> ka, kb;     // ANALYN Hertz shape per strip (valid where Bloc > 0)
  double gmin = 0.0;
  int imin = 0;

  explicit StripExtents(const StripGeometry& g);
  /// The geometry's contents changed: everything above computed again (the vectors kept).
  void init();

  /// Bands at approach delta: runs of g < delta split at interior local maxima.
  /// Band id per strip into `band` (-1 outside), sets nb.
  void bands(double delta, int* nb, std::vector<int>& band) const;

  /// Strip half-lengths at approach delta into `a`: union of KPEC and ANALYN estimates.
  /// Within a band the approach is measured from the band's deepest gap g0:
  /// delta_b = delta - g0 and g - g0 (identical to the spec for g0 = 0 and
  /// exact for an elliptic patch whose minimum gap is g0).
  void extents(double delta, const std::vector<int>& band, int nb, std::vector<double>& a) const;
};

/// Hertz contact ellipse for h = A x^2 + B y^2 at approach delta (Johnson §4.2):
/// semi-axes a (along x), b (along y). Independent of elastic constants.
/// Returns false for non-positive input.
bool hertz_axes(double A, double B, double delta, double* a, double* b);

}  // namespace strips_detail
}  // namespace mh
