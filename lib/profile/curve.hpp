#pragma once
// Smooth representation of a profile z(y): height, slope and curvature everywhere, from a moving
// local circle fit (a local regression, "LOESS with circles").
//
// At every node of a fine uniform grid the points of the profile within a window (measured along
// the profile, so steep flanks get windows as short as the tread's) are fitted by a
// circle-or-line in a frame rotated to the local chord direction,
//     v = alpha (u² + v²) + beta u + delta            (linear least squares in alpha, beta, delta)
// which is exact on exact circles and straight lines at any slope, and averages measurement noise
// over the window. The fit gives z, dz/dy and the curvature kappa at the node; between nodes z is
// cubic Hermite in (z, dz/dy) and kappa is linear.
//
// Breakpoint rule (curvature jumps such as the arcs of S1002 or 60E1): three windows are fitted at
// each node — centred [s−w, s+w] and one-sided [s−2w, s], [s, s+2w] (s: length along the profile) (each one-sided window reaching
// one data point past y). The centred fit is used
// unless its RMS residual exceeds `one_sided_factor` times the better one-sided residual (and
// `residual_floor`); then the better one-sided fit is used. A window straddling a jump in curvature
// cannot be fitted by one circle, so near a jump each side takes the radius of its own arc instead
// of a blend of both (this is the documented rule for radii at breakpoints; tested on S1002 and
// 60E1).
//
// Signs: kappa = z''/(1+z'²)^(3/2) in the canonical frame (z up), positive where the profile bends
// upwards. Radii with the paper's sign (positive when the centre of curvature is inside the
// material, method.md §1): rail 1/R_rxx = −kappa (material below), wheel 1/R_wxx = +kappa
// (material above).
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "profile/profile.hpp"
#include "profile/smoothing_spline.hpp"

namespace mh {

/// Whether a profile is an exact construction or a measurement (profiles.md "Measured or exact"):
/// Auto decides from the data, Exact and Measured force the narrow or the wide window.
enum class ProfileNoise { Auto, Exact, Measured };
/// "auto", "exact", "measured"; std::invalid_argument otherwise.
ProfileNoise parse_profile_noise(const std::string& s);
const char* to_string(ProfileNoise n);

struct CurveOptions {
  double window_half_width = 1.0e-3;  ///< [m] w: half-width of the centred fit window (default 1 mm)
  double grid_step = 0.01e-3;         ///< [m] resampling step of the smooth representation (default 0.01 mm)
  double one_sided_factor = 3.0;      ///< switch to a one-sided window when the centred residual exceeds this × the better one (default 3)
  double residual_floor = 1e-9;       ///< [m] residuals below this count as exact: no switch (default 1 nm)
  int min_points = 5;                 ///< a window is widened until it holds at least this many points (default 5)
  /// Measured profiles: a profile is "measured" (not an exact construction but carrying
  /// measurement noise) when the median RMS residual r of the centred fits exceeds
  /// `noise_threshold` and its noise σ (NoiseDecision::sigma) exceeds `quantisation_factor` ×
  /// q/√12, the RMS error that rounding the printed coordinates to their step q
  /// (Profile::print_step) alone gives (uniform rounding error; the fit's residual normal to the
  /// profile is q/√12 whatever the slope, as both y and z are rounded to q). The default √2 says:
  /// measured when the scatter beyond the rounding is at least as large as the rounding itself
  /// (σ² ≥ 2 q²/12); an exact profile printed to q has σ ≈ q/√12. A measured profile is refitted with the wider window
  /// `measured_window_half_width`, which keeps the curvature sign stable on a rail crown (R 300
  /// mm) under ±2 µm noise. Set it ≤ window_half_width to disable. `noise` forces the choice.
  double noise_threshold = 0.2e-6;            ///< [m] (default 0.2 µm)
  double quantisation_factor = 1.41421356237309505;  ///< [-] (default √2)
  /// ... but rounding is noise to the narrow window too: when the rounding RMS q/√12 exceeds
  /// this (2 decimals: 2.9 µm), the quantisation allowance is not granted and a residual above
  /// `noise_threshold` makes the profile measured (default 0.5 µm: 3 decimals, 0.29 µm, can still
  /// be exact).
  double max_exact_rounding = 0.5e-6;         ///< [m]
  double measured_window_half_width = 3.0e-3; ///< [m] (default 3 mm)
  ProfileNoise noise = ProfileNoise::Auto;    ///< (default auto: decided from the data as above)
  /// [m] Build the smooth representation only over [y_from, y_to] ∩ the profile (default: all of
  /// it). The grid stays anchored at the profile's first point and every node is fitted from the
  /// raw points as without the limits, so a node keeps its value as long as the measured/exact
  /// decision, which looks at the built nodes only, is the same. The wheelset smooths only the
  /// part of a wheel that can face the rail (wheelset.hpp).
  double y_from = -std::numeric_limits<double>::infinity();
  double y_to = std::numeric_limits<double>::infinity();
};

/// One region of a file printed to one precision (print_regions.hpp), classed on its own.
struct NoiseRegion {
  double y_from = 0, y_to = 0;  ///< [m] its points' y range (boundaries halfway to the next region's)
  double print_step = 0;        ///< [m] its printed step
  double median_residual = 0;   ///< [m] of the narrow centred fits at its nodes
  double threshold = 0;         ///< [m] as NoiseDecision::threshold, from its own step
  double sigma = 0;             ///< [m] its noise σ (as NoiseDecision::sigma, over its nodes)
  bool measured = false;
};

/// How a profile was classified by the curve fit (ProfileCurve::noise()).
struct NoiseDecision {
  bool measured = false;        ///< true: the wide window was used
  bool forced = false;          ///< decided by CurveOptions::noise, not from the data
  double median_residual = 0;   ///< [m] r: median RMS residual of the narrow-window centred fits
  double print_step = 0;        ///< [m] q: step of the printed coordinates (0: not printed/unknown)
  double rounding_rms = 0;      ///< [m] q/√12
  double threshold = 0;         ///< [m] the median residual above which measured: max(noise_threshold, the r of σ = quantisation_factor × q/√12)
  /// [m] σ: the standard deviation of the measurement noise normal to the profile (scatter and
  /// rounding together), from the same narrow centred fits. A window of k points fitted by the
  /// three parameters of a circle-or-line leaves k − 3 degrees of freedom, so each node's
  /// RSS / (k − 3) = r_j² k / (k − 3) estimates σ²; σ² is their median divided by the median of
  /// χ²_ν / ν, ν = k − 3 (Wilson & Hilferty 1931: (1 − 2/(9ν))³), the median keeping the
  /// windows that straddle a breakpoint out. What the smoothing for contact removes is matched
  /// to it (profile/smoothing_spline.hpp, smooth_profile_to_noise).
  double sigma = 0;
  /// "exact: median residual 0.2 µm <= 0.28 µm (the residual of a noise sigma of 1.41 x 0.29 µm, rounding to the printed 0.001 mm: …)".
  std::string reason;
  /// A file printed to different precision along the profile whose regions class differently
  /// (profiles.md §7 "Region by region"): each region, in y order. Then `measured` is true, the
  /// wide window is used in the measured regions and the narrow one in the exact ones, `sigma`
  /// is the largest measured region's, and the smoothing for contact keeps the exact regions'
  /// points. Empty otherwise (one class for the whole profile, decided as above).
  std::vector<NoiseRegion> regions;
  bool mixed() const { return !regions.empty(); }
  /// "exact", "measured" or "mixed" (the outputs' spelling).
  const char* class_name() const { return mixed() ? "mixed" : measured ? "measured" : "exact"; }
  /// Whether rail/wheel y lies in an exact region of a mixed profile.
  bool exact_at(double y) const;
};

namespace curve_detail {
/// One node's local fit (curve.cpp): z, dz/dy, kappa and the RMS residual of the window.
struct LocalFit {
  bool ok = false;
  int points = 0;  ///< points in the window
  double z = 0, slope = 0, kappa = 0, rms = std::numeric_limits<double>::infinity();
};
}  // namespace curve_detail

/// The smoothing for contact of one profile (profiles.md §7 "Smoothing for contact"; the one
/// rule, used by the contact geometry and by `profile info`): none for an exact profile; L given
/// (> 0): that length (× opt.length_scale, the uncertainty band's factor); L given as 0: none; L not given ("auto"): the length that removes the
/// profile's own noise, smooth_profile_to_noise(p, noise.sigma, opt).
std::optional<SmoothedProfile> smooth_for_contact(const Profile& p, const NoiseDecision& noise,
                                                  const std::optional<double>& L, const NoiseSmoothingOptions& opt = {});

class ProfileCurve {
 public:
  ProfileCurve() = default;
  /// Throws InputError if the profile has fewer than `min_points` points or y is not increasing.
  ProfileCurve(const Profile& p, const CurveOptions& opt = {});
  /// The curve of a smoothed profile (profile/smoothing_spline.hpp) for the contact gap of the
  /// grid methods: z, dz/dy and kappa at every node of a `grid_step` grid from the splines
  /// y(s), z(s) themselves (no window fit). `noise` is carried over from the fitted curve.
  ProfileCurve(const SmoothedProfile& sp, double grid_step, const NoiseDecision& noise);
  /// A curve from its nodes: y_first + h i [m], z, dz/dy and kappa at each (the same size, ≥ 2);
  /// `noise` and the smoothing figures carried over from `like` (a curve derived from another,
  /// such as the rolled wheel's, geometry/rolled_gap.hpp).
  static ProfileCurve from_nodes(double y_first, double h, std::vector<double> z, std::vector<double> dz,
                                 std::vector<double> kappa, const ProfileCurve& like);
  /// The same into this curve, its vectors keeping their capacity (no allocation once grown) and
  /// growing to at least `reserve` nodes when they grow (room for later, longer node sets).
  void assign_nodes(double y_first, double h, const std::vector<double>& z, const std::vector<double>& dz,
                    const std::vector<double>& kappa, const ProfileCurve& like, std::size_t reserve = 0);

  double y_min() const { return y0_; }
  double y_max() const { return y_first_ + h_ * static_cast<double>(j0_ + z_.size() - 1); }
  bool contains(double y) const { return y >= y_min() && y <= y_max(); }

  /// Smoothed height z(y) [m] and slope dz/dy at y (clamped to the range).
  inline double z(double y, double* dz = nullptr) const;
  /// Signed curvature kappa(y) [1/m] (see above).
  double kappa(double y) const;
  /// Which fit was used at the node nearest y: 0 centred, −1 left-sided, +1 right-sided.
  int window_side(double y) const;
  /// Half-width of the fit window actually used [m], and the median RMS residual of its centred fits.
  double window_used() const { return window_; }
  double median_residual() const { return median_rms_; }
  /// Exact or measured, and why.
  const NoiseDecision& noise() const { return noise_; }
  /// [m] The smoothing length L of the spline this curve was made from (0: a window fit of the
  /// points as given), and the RMS / largest distance [m] it moved the points.
  double smoothing_length() const { return smoothing_L_; }
  double smoothing_rms_change() const { return smoothing_rms_; }
  double smoothing_max_change() const { return smoothing_max_; }
  /// [m] The noise σ the length was chosen to remove (0: the length was given), and whether that
  /// choice hit a bound of NoiseSmoothingOptions.
  double smoothing_sigma() const { return smoothing_sigma_; }
  bool smoothing_at_bound() const { return smoothing_at_bound_; }
  /// [m] The shortest local length where the spline keeps geometry above the noise, and the y
  /// range of the shortened regions (SmoothedProfile; equal to smoothing_length() where none).
  double smoothing_local_min() const { return smoothing_local_min_; }
  double smoothing_local_from() const { return smoothing_local_from_; }
  double smoothing_local_to() const { return smoothing_local_to_; }

  const std::vector<double>& node_kappa() const { return k_; }
  double node_y(std::size_t i) const { return y_first_ + h_ * static_cast<double>(j0_ + i); }
  std::size_t nodes() const { return z_.size(); }
  /// [m] max − min of z over the nodes.
  double node_z_span() const;

 private:
  double y0_ = 0, h_ = 1;
  // The full grid's origin (the profile's first point) and the index of the first node built
  // (CurveOptions::y_from): positions are computed on the full grid, the same bits either way.
  double y_first_ = 0;
  std::size_t j0_ = 0;
  /// (y − y_first)/h − j0: the position in nodes (exact subtraction of the integer j0).
  double grid_pos(double y) const { return (y - y_first_) / h_ - static_cast<double>(j0_); }
  std::vector<double> z_, dz_, k_;
  std::vector<signed char> side_;
  double window_ = 0, median_rms_ = 0;
  NoiseDecision noise_;
  double smoothing_L_ = 0, smoothing_rms_ = 0, smoothing_max_ = 0, smoothing_sigma_ = 0;
  bool smoothing_at_bound_ = false;
  double smoothing_local_min_ = 0, smoothing_local_from_ = 0, smoothing_local_to_ = 0;
  /// Fit every node with window half-width w. `centred_only`: only the centred fits, into
  /// `*centred` (enough for the median residual that decides measured or exact); else the whole
  /// curve, taking the centred fits from `*centred` when given (the same window, fitted before).
  void build(const Profile& p, const CurveOptions& opt, double w, bool centred_only = false,
             std::vector<curve_detail::LocalFit>* centred = nullptr);
  /// Measured or exact from the narrow centred fits of nodes [j0, j1) and their median RMS
  /// residual, against the rounding of `print_step` (profiles.md "Measured or exact"); `rule_out`
  /// receives the comparison's text without the class.
  static NoiseDecision classify_noise(const std::vector<curve_detail::LocalFit>& centred, std::size_t j0, std::size_t j1,
                                      double median_residual, double print_step, const CurveOptions& opt,
                                      std::string* rule_out = nullptr);
  /// A file printed to different precision along the profile (print_regions.hpp): each region
  /// classed by its own nodes' fits; noise_.regions set when the classes differ.
  void classify_regions(const Profile& p, const std::vector<curve_detail::LocalFit>& centred, const CurveOptions& opt);
};


// Inline: the gap's searches evaluate it at every sample (a call cost more than its arithmetic).
inline double ProfileCurve::z(double y, double* dz) const {
  const std::size_t m = z_.size();
  double s = grid_pos(y);
  if (s <= 0) { if (dz) *dz = dz_[0]; return z_[0] + dz_[0] * (y - y0_); }
  if (s >= static_cast<double>(m - 1)) {
    if (dz) *dz = dz_[m - 1];
    return z_[m - 1] + dz_[m - 1] * (y - y_max());
  }
  const std::size_t i = static_cast<std::size_t>(s);
  const double t = s - static_cast<double>(i);
  const double z0 = z_[i], z1 = z_[i + 1], d0 = dz_[i] * h_, d1 = dz_[i + 1] * h_;
  // Cubic Hermite.
  const double t2 = t * t, t3 = t2 * t;
  const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t, h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
  if (dz) {
    const double g00 = 6 * t2 - 6 * t, g10 = 3 * t2 - 4 * t + 1, g01 = -6 * t2 + 6 * t, g11 = 3 * t2 - 2 * t;
    *dz = (g00 * z0 + g10 * d0 + g01 * z1 + g11 * d1) / h_;
  }
  return h00 * z0 + h10 * d0 + h01 * z1 + h11 * d1;
}

}  // namespace mh
