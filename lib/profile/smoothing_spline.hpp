#pragma once
// Smoothing of a measured profile for the contact gap of the grid methods (profiles.md §7
// "Smoothing for contact"; the field's practice, as CONTACT's smoothing spline with parameter
// lambda).
//
// The profile is written as a plane curve (y(s), z(s)) in its chord length s, and each coordinate
// is replaced by the cubic smoothing spline f that minimises (Reinsch 1967; Green & Silverman,
// Nonparametric Regression and Generalized Linear Models, 1994, §2.3)
//     Σ_i w_i (d_i − f(s_i))² + lambda ∫ f''(s)² ds,     w_i = the chord length each point stands for,
// so the data term approximates ∫ (d − f)² ds whatever the point spacing. On a uniform
// spacing this is a low-pass filter with transfer 1 / (1 + (L / ℓ)⁴) for a wave of length ℓ along
// the profile, with
//     L = 2π lambda^(1/4),       i.e. lambda = (L / 2π)⁴     [m⁴ → m]
// the *smoothing length*: a wave of length L keeps half its amplitude, one of L/2 1/17, one of
// 2L 94 %. Cubics are reproduced exactly (the Euler–Lagrange equation f − d + lambda f'''' = 0),
// so a circle of radius R is biased by about lambda × 3/R³ (60E1's R13 at L = 2.5 mm: 0.01 µm).
// Parametric smoothing keeps steep flanks as well resolved as the tread (a length scale along
// the profile, not in y).
#include <vector>

#include "profile/profile.hpp"

namespace mh {

/// A natural cubic spline in one parameter s: values f_i and second derivatives f''_i at knots
/// s_i (f'' = 0 at both ends).
class CubicSpline1 {
 public:
  CubicSpline1() = default;
  CubicSpline1(std::vector<double> s, std::vector<double> f, std::vector<double> f2)
      : s_(std::move(s)), f_(std::move(f)), f2_(std::move(f2)) {}
  /// Value, first and second derivative at s (clamped to the knot range: linear beyond).
  double eval(double s, double* d1 = nullptr, double* d2 = nullptr) const;
  const std::vector<double>& knots() const { return s_; }
  const std::vector<double>& values() const { return f_; }

 private:
  std::vector<double> s_, f_, f2_;
};

/// The cubic smoothing spline of data d at knots s (strictly increasing, n ≥ 3) with weights w
/// (> 0) and smoothing parameter lambda ≥ 0 [units of s⁴ / s] (0: the interpolating natural
/// spline). Reinsch's algorithm: (R + lambda Qᵀ W⁻¹ Q) γ = Qᵀ d, f = d − lambda W⁻¹ Q γ, a
/// pentadiagonal solve.
/// `trace`, if given, receives tr A, the trace of the hat matrix d → f (the spline's equivalent
/// degrees of freedom: n at lambda = 0, 2 as lambda → ∞).
CubicSpline1 smoothing_spline(const std::vector<double>& s, const std::vector<double>& d,
                              const std::vector<double>& w, double lambda, double* trace = nullptr);

/// A profile smoothed as a plane curve (see above), with smoothing length L [m] (L = 0: the
/// interpolating spline). Its y(s) is increasing wherever the profile's y is.
struct SmoothedProfile {
  double L = 0;            ///< [m] smoothing length
  CubicSpline1 y, z;       ///< y(s), z(s), s the chord length of the input points
  double rms_change = 0;   ///< [m] RMS distance between the input points and their smoothed positions
  double max_change = 0;   ///< [m] and the largest
  double rms_normal_change = 0;  ///< [m] RMS of that distance's component normal to the smoothed curve
  double dof = 0;                ///< tr A of the spline (the same for y and z): its degrees of freedom
  /// [m] smooth_profile_to_noise: the noise σ the length was chosen from (0: L was given),
  /// whether L hit a bound of NoiseSmoothingOptions, and the shortest local length where the
  /// spline was made to keep geometry above the noise (L itself where it was not).
  double sigma = 0;
  bool at_bound = false;
  double L_local_min = 0;
  double local_from = 0, local_to = 0;  ///< [m] y range of the shortened regions (both 0: none)
};
SmoothedProfile smooth_profile(const Profile& p, double L);

/// Points a smoothing keeps where they are (a mixed profile's exact regions, curve.hpp
/// NoiseDecision::regions): their weights are raised so that the spline's local length there is
/// kKeepLength, far below any geometry of a profile: it passes through them.
constexpr double kKeepLength = 1e-5;  ///< [m] (10 µm, the curve's grid step)
/// The same as smooth_profile with the points where keep[i] is non-zero kept (keep empty: none).
SmoothedProfile smooth_profile(const Profile& p, double L, const std::vector<char>& keep);

/// The smoothing length chosen from the noise (smooth_profile_to_noise; documented defaults).
struct NoiseSmoothingOptions {
  /// The reference point of the length rule: L_ref at noise sigma_ref and point spacing
  /// spacing_ref (profiles.md §7: 5 mm is the shortest length that keeps S1002's peak pressure
  /// within 1 % at 3.5 µm RMS scatter every 0.4 mm).
  double L_ref = 5e-3;          ///< [m] (default 5 mm)
  double sigma_ref = 3.5e-6;    ///< [m] (default 3.5 µm)
  double spacing_ref = 0.4e-3;  ///< [m] (default 0.4 mm)
  double L_min = 0.5e-3;        ///< [m] shortest length, also locally (default 0.5 mm)
  double L_max = 20e-3;         ///< [m] longest (default 20 mm, the largest a case file may force)
  /// Local guard: where the spline moves the points by more than local_factor × the noise
  /// (RMS over ±L/2 along the profile), it removes geometry, not noise, and its
  /// length is halved there, up to `local_steps` times (defaults 2 and 5).
  double local_factor = 2.0;
  int local_steps = 5;
  /// Every length of the result multiplied by this once chosen: the global L and, with the same
  /// local weights, the shortened regions' lengths (default 1). The uncertainty band of a case
  /// (profiles.md §7 "Uncertainty band") solves again at 0.5 and 2. smooth_for_contact applies
  /// it to a length given too.
  double length_scale = 1.0;
};

/// A profile smoothed by as much as its noise needs (profiles.md §7 "Smoothing for contact"):
///  1. the length from the noise: L = L_ref (sigma / sigma_ref)^(2/3) (Δ / spacing_ref)^(1/3),
///     Δ the median point spacing along the profile, within [L_min, L_max]: the pressure error
///     left by a filtered white scatter falls like sigma √Δ L^(−3/2) (profiles.md §7), so this
///     keeps it at the level measured at the reference point;
///  2. and no more: the discrepancy principle applied locally (Reinsch 1967): where the normal
///     residual's RMS over ±L/2 exceeds local_factor × sigma, geometry above the noise is being
///     removed and the length is halved there (the weights w_i multiplied by 16: the penalty's
///     lambda / w_i sets the local length), up to local_steps times, not below L_min;
///  3. with opt.length_scale != 1, the spline of steps 1–2 is made again with L × length_scale
///     and the same local weights (every length scaled, the shortened regions kept).
///  Points where keep[i] is non-zero (keep empty: none) are kept (kKeepLength), and the point
///  spacing of step 1 is the median over the other points.
SmoothedProfile smooth_profile_to_noise(const Profile& p, double sigma, const NoiseSmoothingOptions& opt = {},
                                        const std::vector<char>& keep = {});

}  // namespace mh
