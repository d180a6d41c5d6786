#pragma once
// The cant (inclination) of a rail profile estimated from its head (profiles.md "Cant estimate"):
// a rail head is symmetric about an axis; the cant is that axis' tilt from the vertical.
//
// Method (horizontal chords of the head turned back): in a frame turned back (clockwise) by a
// trial cant θ, the profile is cut at `levels` heights between `depth_min` and `depth_max` below
// its highest point; on each cut the first crossing on the gauge side and on the field side of
// the highest point are interpolated and their midpoint taken, and a least-squares line
// y_mid = a + b·z is fitted through the midpoints. The cant is the θ at which that line is
// vertical, b(θ) = 0: bracketed by a scan over ±max_angle and bisected (core/roots.hpp). Turned back by the right
// θ an exactly symmetric head has its horizontal chords' midpoints on its (vertical) axis, so
// the estimate is exact there and biased only by the asymmetry of the head (wear, a worn gauge
// corner) and by noise. (At a wrong θ the midpoints do not follow the tilted axis: the tilt of
// a crown moves its cuts by far more than the axis moves, hence the root search.)
//
// Sign: positive when the top of the head leans towards the gauge side (negative y), i.e. the
// rail is canted towards the track centre as `rotate_towards_track_centre` (profile.hpp) does:
// an upright 60E1 turned by that function through atan(1/40) gives +atan(1/40). A rail mirrored
// in y after being canted gives a negative cant.
//
// Accuracy: on the generated 60E1 and 54E1 (upright, 1:40, 1:20) within 1e-4° (tested); on
// the measured rails of tests/data/profiles the standard error is printed with the estimate.
#include <string>
#include <vector>

#include "core/units.hpp"
#include "profile/profile.hpp"

namespace mh {

struct RailCantOptions {
  double depth_min = 1.0e-3;   ///< [m] first cut below the highest point (default 1 mm: the crown is too flat above)
  double depth_max = 12.0e-3;  ///< [m] last cut (default 12 mm: above the 60E1/54E1 flank, 14.3 mm, and the gauge point)
  int levels = 45;             ///< cuts between them, equally spaced (default 45: every 0.25 mm)
  int min_levels = 10;         ///< fewer cuts with both sides found: no estimate (default 10)
  double max_angle = 10 * units::deg;  ///< [rad] cants searched: ±max_angle (default ±10°)
  double scan_step = 0.25 * units::deg;  ///< [rad] scan that brackets the root (default 0.25°)
  /// Smallest |db/dθ| [1/rad] at the root for an axis to count as found (default 0.5; the 60E1
  /// crown gives about 8: a circular arc gives 0, symmetric about every radius).
  double min_sensitivity = 0.5;
  int max_iterations = 60;     ///< bisection steps after the scan (default 60: far below 1e-9 rad)
  /// The estimate counts as confident when the standard error of the tilt and the RMS distance
  /// of the midpoints from the fitted axis are below these (defaults 0.05° and 0.05 mm).
  double max_std_error = 0.05 * units::deg;  ///< [rad]
  double max_residual = 0.05e-3;                                 ///< [m]
  bool valid(std::string* why) const;
};

struct RailCant {
  bool found = false;      ///< false: too few cuts crossed both sides (why says it)
  std::string why;
  double angle = 0;        ///< [rad] cant, sign as above
  double std_error = 0;    ///< [rad] standard error of the cant: that of the midpoint line's slope b over |db/dθ|
  double residual = 0;     ///< [m] RMS distance of the midpoints from the fitted axis
  int levels = 0;          ///< cuts used
  bool confident = false;  ///< found, std_error ≤ max_std_error and residual ≤ max_residual
};

/// Estimate the cant of a rail profile (canonical frame, y increasing). Never throws on a
/// profile; invalid options are an InputError.
RailCant estimate_rail_cant(const Profile& rail, const RailCantOptions& opt = {});

/// The checks of a rail's cant against the case's inclination (profiles.md "Cant checks").
struct RailCantLimits {
  double max_cant = 0.049958395721942765;     ///< [rad] usual range 0 … 1:20 (atan(1/20), 2.862°)
  double tolerance = 0.25 * units::deg;  ///< [rad] beyond the range before a warning (default 0.25°)
  /// A file whose own cant is at least this counts as canted already (default half of 1:40, 0.716°).
  double already_canted = 0.5 * 0.024994793618920598;   ///< [rad]
};

struct RailCantCheck {
  RailCant used;           ///< estimated on the rail as used (after the case's inclination)
  double inclination = 0;  ///< [rad] the cant the case applied
  double file_angle = 0;   ///< [rad] used.angle − inclination: the cant the file had
  /// "cant: ..." messages; empty when nothing is wrong or no estimate was found. An estimate that
  /// is not confident (a worn head) is checked too, with a margin of two standard errors on
  /// every limit, and its warnings say "estimate not confident".
  std::vector<std::string> warnings;
};

/// Estimate the cant of `rail_as_used` (the profile after `incl` was applied) and check it:
///  - the case cants the rail ("1:N" or an angle) and the file's own cant is ≥ already_canted
///    (or the case says "none" and the file is canted): the cant is applied twice (or misstated);
///  - the cant as used lies outside −tolerance … max_cant + tolerance, in particular negative
///    (leaning to the field side: a canted rail mirrored in y).
RailCantCheck check_rail_cant(const Profile& rail_as_used, const Inclination& incl, const RailCantOptions& opt = {},
                              const RailCantLimits& lim = {});

/// "1:40.0" style ratio of an angle [rad] (1:N with N = 1/tan|angle|, one decimal; "upright" below
/// 0.0005 deg, where the angle prints as 0 deg;
/// a leading '-' for a negative angle).
std::string cant_ratio(double angle);

}  // namespace mh
