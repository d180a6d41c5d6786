#pragma once
// Rolling-contact-fatigue indicators of one contact (docs/methods.md "RCF
// indicators"): the point on Johnson's shakedown map and the surface fatigue index of Ekberg,
// Kabo and Andersson (2002). Both are defined with the ELASTIC Hertzian peak pressure p0 of the
// contact's normal load (Johnson 1985 §9.3; Ekberg et al. 2002 eq. 2), never with a plastic
// patch's pressure or area: the callers pass the elastic Hertz semi-axes at the load N (the
// ellipse law's a_el, b_el; for a grid patch, docs/outputs.md "RCF columns"). SI throughout.
// Header-only, no state.
#include <algorithm>
#include <cmath>
#include <string>

#include "contact/options.hpp"

namespace mh {

/// RCF input (case file "rcf"): traction coefficient f = T/N [-] and shear yield k [Pa]
/// (NaN: from the material's yield stress, k = σ_y/√3).
struct RcfOptions {
  double f = NAN;
  double k = NAN;
  bool enabled() const { return std::isfinite(f); }
};

/// [Pa] The tensile yield stress σ_y the indicators use: the softer body's (Material::yield_min),
/// NaN when the case gives none.
inline double material_yield(const Material& mat) { return mat.yield_min(); }

/// [Pa] k: the user's shear yield if given, else σ_y/√3 (von Mises) from material_yield();
/// NaN when neither is known.
inline double rcf_shear_yield(const Material& mat, const RcfOptions& o) {
  if (std::isfinite(o.k)) return o.k;
  return material_yield(mat) / std::sqrt(3.0);
}

/// Region of Johnson's shakedown map (docs/methods.md "RCF indicators").
enum class ShakedownRegime { Elastic, ElasticShakedown, PlasticShakedown, Ratchetting };
inline const char* to_string(ShakedownRegime r) {
  switch (r) {
    case ShakedownRegime::Elastic: return "elastic";
    case ShakedownRegime::ElasticShakedown: return "elastic_shakedown";
    case ShakedownRegime::PlasticShakedown: return "plastic_shakedown";
    case ShakedownRegime::Ratchetting: return "ratchetting";
  }
  return "?";
}

/// The RCF indicators of one contact.
struct RcfPoint {
  double p0_el = NAN;           ///< [Pa] elastic Hertz peak pressure of the load, 3N/(2π a_el b_el)
  double p0_el_over_k = NAN;    ///< [-] p0_el/k
  double elastic_limit = NAN;   ///< [-] p0/k of first yield at this f and aspect ratio
  double shakedown_limit = NAN; ///< [-] p0/k of the elastic shakedown limit at this f and aspect ratio
  double fi_surf_el = NAN;      ///< [-] FI_surf = f − 2π a_el b_el k / (3N) = f − k/p0_el
  ShakedownRegime regime = ShakedownRegime::Elastic;
};

/// Frictionless limits of p0/k for the aspect ratio e = min(a,b)/max(a,b), linear in e between
/// line contact (e = 0) and circular contact (e = 1) [project interpolation]:
///   first yield (von Mises, ν = 0.3; Johnson 1985 §4.3 and §3.4): 3.10 (line), 2.77 (circle, p0 = 1.60 σ_y);
///   elastic shakedown (Johnson 1985 §9.3; Ponter, Hearle & Johnson 1985): 4.0 (line), 4.7 (circle).
inline double frictionless_elastic_limit(double e) { return 3.10 + (2.77 - 3.10) * e; }
inline double frictionless_shakedown_limit(double e) { return 4.0 + (4.7 - 4.0) * e; }

/// The point of a contact carrying N [N] whose ELASTIC Hertz patch at that load has semi-axes
/// a_el, b_el [m] (its aspect ratio sets the limits), with traction coefficient f and shear
/// yield k [Pa]. Each limit is the frictionless
/// (subsurface) value capped by the surface limit p0/k = 1/f (f p0 = k). Regime: below the first
/// yield limit, elastic; below the shakedown limit, elastic shakedown; above it, ratchetting
/// when the surface limit is exceeded (f p0/k > 1, FI_surf > 0), else plastic shakedown
/// (subsurface cyclic plasticity). NaN inputs give NaN values.
inline RcfPoint rcf_point(double f, double k, double N, double a_el, double b_el) {
  constexpr double pi = 3.14159265358979323846;
  RcfPoint r;
  if (!(N > 0 && a_el > 0 && b_el > 0 && k > 0 && f >= 0)) return r;
  r.p0_el = 1.5 * N / (pi * a_el * b_el);
  const double e = std::min(a_el, b_el) / std::max(a_el, b_el);
  const double surface = f > 0 ? 1.0 / f : INFINITY;
  r.p0_el_over_k = r.p0_el / k;
  r.elastic_limit = std::min(frictionless_elastic_limit(e), surface);
  r.shakedown_limit = std::min(frictionless_shakedown_limit(e), surface);
  r.fi_surf_el = f - 2.0 * pi * a_el * b_el * k / (3.0 * N);
  if (r.p0_el_over_k <= r.elastic_limit) r.regime = ShakedownRegime::Elastic;
  else if (r.p0_el_over_k <= r.shakedown_limit) r.regime = ShakedownRegime::ElasticShakedown;
  else if (r.fi_surf_el > 0) r.regime = ShakedownRegime::Ratchetting;
  else r.regime = ShakedownRegime::PlasticShakedown;
  return r;
}

}  // namespace mh
