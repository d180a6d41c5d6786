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
CubicSpline1 smoothing_spline(const std::vector<double>& s, const std::vector<double>& d,
                              const std::vector<double>& w, double lambda);

/// A profile smoothed as a plane curve (see above), with smoothing length L [m] (L = 0: the
/// interpolating spline). Its y(s) is increasing wherever the profile's y is.
struct SmoothedProfile {
  double L = 0;            ///< [m] smoothing length
  CubicSpline1 y, z;       ///< y(s), z(s), s the chord length of the input points
  double rms_change = 0;   ///< [m] RMS distance between the input points and their smoothed positions
  double max_change = 0;   ///< [m] and the largest
};
SmoothedProfile smooth_profile(const Profile& p, double L);

}  // namespace mh
