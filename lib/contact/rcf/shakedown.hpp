#pragma once
// Rolling-contact-fatigue indicators of one contact (docs/methods.md "RCF
// indicators"): the point on Johnson's shakedown map and the surface fatigue index of Ekberg,
// Kabo and Andersson (2002). Both are defined with the ELASTIC Hertzian peak pressure p0 of the
// contact's normal load (Johnson 1985 §9.3; Ekberg et al. 2002 eq. 2), never with a plastic
// patch's pressure or area: the callers pass the elastic Hertz semi-axes at the load N (the
// ellipse law's a_el, b_el; for a grid patch, docs/outputs.md "RCF columns"). SI throughout.
// The line contact's first yield with traction is searched in shakedown.cpp (a table per ν
// and thread); the rest is header-only.
#include <algorithm>
#include <cmath>
#include <string>

#include "contact/options.hpp"
#include "contact/rcf/damage.hpp"

namespace mh {

/// RCF input (case file "rcf"): traction coefficient f = T/N [-] and shear yield k [Pa]
/// (NaN: from the material's yield stress, k = σ_y/√3). With friction given (the tangential
/// problem solved) f is not an input: each contact's actual traction coefficient |F|/N is used
/// (`actual`). The damage and wear functions' constants (damage.hpp) apply to the Tγ columns
/// written with friction, with or without the shakedown columns.
struct RcfOptions {
  double f = NAN;
  double k = NAN;
  bool actual = false;      ///< f per contact from its creep forces, |F|/N (friction given)
  BurstowOptions burstow;   ///< "rcf": {"burstow": {...}}
  UsfdWearOptions usfd;     ///< "rcf": {"usfd_wear": {...}}
  /// [m] "rcf": {"tY_distribution": {"mean_mm", "sd_mm"}}: a normal distribution of the lateral
  /// displacement t_Y weighting the damage over a sweep (scripts/plot_rcf.py); NaN: not given.
  double tY_mean = NAN, tY_sd = NAN;
  /// "rcf": {"subsurface": {...}}: the stresses below each contact's elastic Hertz ellipse with
  /// full-slip traction f (subsurface.hpp; about 0.5 s per contact), in the rail (Poisson's ratio
  /// nu, the rail's); dang_van_c [-] the Dang Van parameter of FI_sub (NaN: no FI_sub column value).
  bool subsurface = false;
  /// "rcf": {"subsurface": {"grid": true}}: a grid patch's stresses from its own element
  /// pressure (grid_subsurface.hpp; seconds per patch) instead of its elastic Hertz ellipse; never
  /// for a patch with elements at the plastic cap (docs/outputs.md "Subsurface columns").
  bool subsurface_grid = false;
  double nu = 0.28;
  double dang_van_c = NAN;
  bool enabled() const { return std::isfinite(f) || actual; }
  /// [-] The traction coefficient of a contact carrying N [N] with tangential force (Fx, Fy) [N]:
  /// the user's f, or with `actual` |F|/N (NaN when the contact's tangential problem is unsolved).
  double traction(double N, double Fx, double Fy, bool solved) const {
    if (!actual) return f;
    return solved && N > 0 ? std::hypot(Fx, Fy) / N : NAN;
  }
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

/// [-] The largest von Mises stress below a frictionless Hertz contact, over p0, at Poisson's
/// ratio ν, from the closed forms: the circular contact on its axis (Johnson, Contact Mechanics,
/// 1985, §3.4, eq. 3.45: σ_z = −p0/(1 + t²), σ_r = σ_θ = p0[−(1 + ν)(1 − t atan(1/t)) + ½/(1 + t²)],
/// t = z/a; von Mises |σ_r − σ_z|) and the line contact on its plane of symmetry (Johnson §7.1,
/// McEwen 1949: σ_x = −p0[(1 + 2t²)/√(1 + t²) − 2t], σ_z = −p0/√(1 + t²), σ_y = ν(σ_x + σ_z),
/// plane strain). Maximised in t by golden-section search (the functions are unimodal). At ν = 0.3:
/// 0.6200 at 0.481 a (circle) and 0.5575 at 0.704 b (line). The last ν's two values are kept per
/// thread (the RCF columns ask for them at every contact, always at the material's ν).
inline double frictionless_vm_peak(bool line, double nu) {
  thread_local double memo_nu[2] = {NAN, NAN}, memo[2] = {NAN, NAN};
  if (memo_nu[line] == nu) return memo[line];
  auto vm = [&](double t) {
    if (line) {
      const double r = std::sqrt(1 + t * t);
      const double sx = -((1 + 2 * t * t) / r - 2 * t), sz = -1 / r, sy = nu * (sx + sz);
      return std::sqrt(0.5 * ((sx - sy) * (sx - sy) + (sy - sz) * (sy - sz) + (sz - sx) * (sz - sx)));
    }
    const double s = 1 / (1 + t * t), sr = -(1 + nu) * (1 - t * std::atan(1 / t)) + 0.5 * s;
    return std::fabs(sr + s);
  };
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double a = 0.05, b = 2.0, c = b - g * (b - a), d = a + g * (b - a), fc = vm(c), fd = vm(d);
  while (b - a > 1e-9) {
    if (fc >= fd) b = d, d = c, fd = fc, c = b - g * (b - a), fc = vm(c);
    else a = c, c = d, fc = fd, d = a + g * (b - a), fd = vm(d);
  }
  memo_nu[line] = nu;
  return memo[line] = std::max(fc, fd);
}

/// Frictionless limits of p0/k for the aspect ratio e = min(a,b)/max(a,b), linear in e between
/// line contact (e = 0) and circular contact (e = 1) [project interpolation]:
///   first yield (von Mises, k = σ_y/√3): √3 / frictionless_vm_peak at the material's ν: 3.107
///   (line) and 2.793 (circle) at ν = 0.3 (Johnson's rounded "p0 = 1.60 Y" for the circle is 2.77);
///   elastic shakedown (Johnson 1985 §9.3, line contact, elastic–perfectly plastic; Ponter, Hearle &
///   Johnson 1985, point contact): 4.0 (line), 4.7 (circle), not re-derived here.
inline double frictionless_elastic_limit(double e, double nu = 0.3) {
  const double line = std::sqrt(3.0) / frictionless_vm_peak(true, nu);
  const double circle = std::sqrt(3.0) / frictionless_vm_peak(false, nu);
  return line + (circle - line) * e;
}
inline double frictionless_shakedown_limit(double e) { return 4.0 + (4.7 - 4.0) * e; }

/// [-] The elastic shakedown limit of p0/k of the line contact with full-slip traction f,
/// below the surface: Melan's static theorem as Johnson applies it (1985, §9.3; steady rolling,
/// plane strain, the residual stress ρ_x(z) the only one a line contact permits, the in-plane
/// yield condition ((σ_x + ρ_x − σ_z)/2)² + τ_xz² ≤ k²): at each depth the least k over ρ_x of the
/// largest ((σ_x − σ_z)/2 + ρ_x/2)² + τ_xz² along x, the limit 1/(its largest over z). On
/// McEwen's field (1949) this derivation gives 4.000 at f = 0 (τ_xz = ±0.25 p0 at z = 0.5 a, the
/// value Johnson quotes) and falls with f: 3.564 at 0.1, 3.202 at 0.2, 3.044 at 0.25, 2.900 at
/// 0.3; it meets the surface limit 1/f at f ≈ 0.368. Tabulated every 0.025 in f from that
/// derivation (x over ±10 a at 0.00125 a, z golden-searched; tests/unit/contact/test_rcf.cpp
/// derives the table again on a coarser grid and holds it within 2e-4), linear between.
/// Above 0.375 the surface limit governs (its last value is kept, min(·, 1/f) takes over).
inline double line_shakedown_limit(double f) {
  static constexpr double kTable[] = {4.00000, 3.88320, 3.77182, 3.66558, 3.56421, 3.46745, 3.37504, 3.28676,
                                      3.20236, 3.12165, 3.04440, 2.97044, 2.89958, 2.83164, 2.76647, 2.70391};
  constexpr double df = 0.025;
  constexpr int n = static_cast<int>(sizeof(kTable) / sizeof(kTable[0]));
  if (!(f > 0)) return kTable[0];
  const double u = f / df;
  if (u >= n - 1) return kTable[n - 1];
  const int i = static_cast<int>(u);
  return kTable[i] + (kTable[i + 1] - kTable[i]) * (u - i);
}

/// [-] The first-yield limit of p0/k (von Mises, k = σ_y/√3) of the line contact with full-slip
/// traction f at Poisson's ratio ν: √3 over the largest von Mises stress of McEwen's field
/// (subsurface.hpp, mcewen_stress) below and on the surface (shakedown.cpp). At ν = 0.3: 3.107 at
/// f = 0 (0.5575 p0 at 0.70 a), 2.936 at 0.2, 2.843 at 0.25 (still below the surface, 0.49 a),
/// 2.598 at 0.3 and 1.777 at 0.5 (on the surface; it moves there at f ≈ 0.27). Tabulated every
/// 0.0125 in f up to 1 per ν on first use (per thread, about 8 ms), linear between (measured
/// against a scan of the field, tests/unit/contact/test_rcf.cpp: within 3e-4, and 1.7e-3 (0.06 %)
/// where the peak changes branch between two nodes);
/// above f = 1 searched at each call.
double line_first_yield_limit(double f, double nu);

/// [-] The circular contact's first-yield limit with full-slip traction f over its frictionless
/// value: √3 over the largest von Mises stress of the library's field below a circle with traction
/// (subsurface.hpp, subsurface_peaks with z from 0.002 a and 40 depths; 1 Dec 2026, ν = 0.3), every
/// 0.025 in f up to 0.6, linear between. The peak stays below the surface up to f ≈ 0.33 (0.48 a
/// at f = 0, 0.42 a at 0.325), then lies at the trailing edge of the surface. ν moves the ratio by
/// less than 0.2 % up to f = 0.3 (ν 0.25–0.3) and by about 1 % where the peak changes branch (the
/// table is ν = 0.3's for every ν). Above f = 0.6 the line contact's fall continues it.
/// tests/unit/contact/test_rcf.cpp computes two points again.
inline double circle_first_yield_ratio(double f, double nu) {
  static constexpr double kE[] = {2.79345, 2.79221, 2.78850, 2.78233, 2.77375, 2.76279, 2.74950, 2.73397, 2.71625,
                                  2.69642, 2.67460, 2.65087, 2.62529, 2.59801, 2.52063, 2.39151, 2.27463, 2.16836,
                                  2.07134, 1.98242, 1.89434, 1.81275, 1.73769, 1.66842, 1.60431};
  constexpr double df = 0.025;
  constexpr int n = static_cast<int>(sizeof(kE) / sizeof(kE[0]));
  if (!(f > 0)) return 1;
  const double u = f / df;
  if (u >= n - 1) return kE[n - 1] / kE[0] * line_first_yield_limit(f, nu) / line_first_yield_limit(df * (n - 1), nu);
  const int i = static_cast<int>(u);
  return (kE[i] + (kE[i + 1] - kE[i]) * (u - i)) / kE[0];
}

/// [-] The first-yield limit of p0/k at aspect ratio e, traction f and ν, before the surface cap:
/// linear in e between the line contact (frictionless closed form × its fall with traction,
/// line_first_yield_limit) and the circle (frictionless closed form × circle_first_yield_ratio)
/// **[project interpolation in e, as frictionless_elastic_limit]**.
inline double first_yield_limit(double e, double f, double nu) {
  const double line = frictionless_elastic_limit(0, nu) * line_first_yield_limit(f, nu) / line_first_yield_limit(0, nu);
  const double circle = frictionless_elastic_limit(1, nu) * circle_first_yield_ratio(f, nu);
  return line + (circle - line) * e;
}

/// [-] The elastic shakedown limit of p0/k at aspect ratio e and traction f, before the surface
/// cap: the frictionless limit (4.0 line, 4.7 circle, linear in e) times the line contact's
/// derived fall with traction, line_shakedown_limit(f)/4 **[project assumption for e > 0:
/// Ponter, Hearle & Johnson's point-contact limits with traction were not available to this
/// project; exact for the line contact]**.
inline double shakedown_limit(double e, double f) {
  return frictionless_shakedown_limit(e) * line_shakedown_limit(f) / line_shakedown_limit(0);
}

/// The point of a contact carrying N [N] whose ELASTIC Hertz patch at that load has semi-axes
/// a_el, b_el [m] (its aspect ratio sets the limits), with traction coefficient f, shear
/// yield k [Pa] and Poisson's ratio ν (of the first-yield limit). Each limit is capped by the
/// surface limit p0/k = 1/f (f p0 = k): first yield first_yield_limit(e, f, ν), the elastic
/// shakedown limit shakedown_limit(e, f). Regime: below the first
/// yield limit, elastic; below the shakedown limit, elastic shakedown; above it, ratchetting
/// when the surface limit is exceeded (f p0/k > 1, FI_surf > 0), else plastic shakedown
/// (subsurface cyclic plasticity). NaN inputs give NaN values.
inline RcfPoint rcf_point(double f, double k, double N, double a_el, double b_el, double nu = 0.3) {
  constexpr double pi = 3.14159265358979323846;
  RcfPoint r;
  if (!(N > 0 && a_el > 0 && b_el > 0 && k > 0 && f >= 0)) return r;
  r.p0_el = 1.5 * N / (pi * a_el * b_el);
  const double e = std::min(a_el, b_el) / std::max(a_el, b_el);
  const double surface = f > 0 ? 1.0 / f : INFINITY;
  r.p0_el_over_k = r.p0_el / k;
  r.elastic_limit = std::min(first_yield_limit(e, f, nu), surface);
  r.shakedown_limit = std::min(shakedown_limit(e, f), surface);
  r.fi_surf_el = f - 2.0 * pi * a_el * b_el * k / (3.0 * N);
  if (r.p0_el_over_k <= r.elastic_limit) r.regime = ShakedownRegime::Elastic;
  else if (r.p0_el_over_k <= r.shakedown_limit) r.regime = ShakedownRegime::ElasticShakedown;
  else if (r.fi_surf_el > 0) r.regime = ShakedownRegime::Ratchetting;
  else r.regime = ShakedownRegime::PlasticShakedown;
  return r;
}

}  // namespace mh
