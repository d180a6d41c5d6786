#pragma once
// Rigid contact geometry of a wheelset on a track (docs/wheelset.md): both wheels, both rails,
// for a lateral displacement y of the wheelset, the contact point of each wheel on its rail, the
// rolling radii r_left, r_right, their difference Δr = r_right − r_left, the contact angles and,
// with the roll solved, the roll angle. The input of the equivalent conicity (conicity.hpp).
//
// Frames (docs/wheelset.md "Placement"). Track: Y lateral, positive towards the RIGHT rail, Z up;
// a positive y moves the wheelset towards the right rail. Each profile stays in its own canonical
// frame (profile.hpp: η or y_r towards its FIELD side, z up), so one profile serves both sides:
// on the right, local u = +Y; on the left, u = −Y (the mirror image).
//  - wheel s ∈ {left, right}: its taping line (profile y = 0) lies a_s = flange_back_distance/2
//    − flange_back_position from the wheelset centre (1360/2 + 70 = 750 mm), its axle
//    R0_s (the nominal radius at the taping line) above the taping-line point;
//  - rail s: its origin at |Y| = c_s: by gauge, c_s = gauge/2 − y_gauge,s (the rail's gauge
//    point, gauge_height below its top, lies gauge/2 from the track centre), or absolute.
// Roll φ (positive: the right end of the axle up, counter-clockwise in (Y, Z)) rotates each wheel's
// profile section about the axle centre; without yaw the contact of a body of revolution with a
// straight rail lies in the vertical plane of the axle, so the rotated profile is the section that
// touches. Roll None: each wheel lowered onto its own rail, φ = 0 (the EN 15302 reference
// convention; the axle heights of the two sides differ). Roll Solved: φ such that both wheels
// touch at one axle height (TOMS 748 on h_right(φ) − h_left(φ)).
//
// Contact search (one wheel): the vertical gap G(η) = Z_wheel(η) − z_rail(y_r(η)) along the wheel
// profile coordinate η; the contact is its minimum. The gap is sampled every `scan_step` (the
// scan) to find its local minima, each is refined by solving G'(η) = 0 (TOMS 748, core/roots.hpp)
// on the smooth profiles (profile/curve.hpp); local minima within `two_point_gap` of the lowest,
// farther than `jump_distance` along the rail, make a two-point contact. The scan skips blocks
// of samples that provably hold no sample within two_point_gap (plus a margin) of the lowest:
// a block's lowest possible gap is bounded by its lowest wheel sample and the highest rail value
// it can face (docs/wheelset.md "Contact search"), so the samples it evaluates, and with them the
// contact points and flags, are those of the full scan.
#include <memory>
#include <string>
#include <vector>

#include "profile/curve.hpp"
#include "profile/profile.hpp"

namespace mh {

/// Where the wheels and rails are (docs/wheelset.md "Placement"). Lengths [m]. Defaults:
/// standard gauge and the EN 13715 wheelset (flange back 70 mm from the taping line).
struct WheelsetPlacement {
  enum class Rails { Gauge, Absolute };
  Rails rails = Rails::Gauge;             ///< how the rails are placed (default by gauge)
  double gauge = 1.435;                   ///< [m] Gauge: track gauge (default 1435 mm) ...
  double gauge_height = 0.014;            ///< [m] ... measured this far below the top of rail (default 14 mm)
  /// [m] Absolute: |Y| of the rail profiles' origins (EN 15302 reference: 750 mm each).
  double rail_origin_left = 0.750, rail_origin_right = 0.750;
  double flange_back_distance = 1.360;    ///< [m] (default 1360 mm)
  double flange_back_position = -0.070;   ///< [m] y of the flange back on the wheel profiles (default −70 mm)
  /// [m] wheel radius at the taping line, per wheel (default 460 mm; EN 15302's asymmetric cases
  /// use 920 and 918 mm diameters).
  double nominal_radius_left = 0.460, nominal_radius_right = 0.460;
};

enum class WheelsetRoll { None, Solved };
/// "none", "solved"; std::invalid_argument otherwise.
WheelsetRoll parse_wheelset_roll(const std::string& s);
const char* to_string(WheelsetRoll r);

/// Options of the contact search, with their documented defaults.
struct WheelsetOptions {
  WheelsetRoll roll = WheelsetRoll::None;  ///< (default none: the EN 15302 reference convention)
  /// [m] spacing of the scan of the gap along the wheel that finds its local minima (default
  /// 0.1 mm: two local minima closer than this are seen as one; each is then refined to machine
  /// precision, so the step does not enter the results otherwise).
  double scan_step = 0.1e-3;
  /// [m] a second local minimum of the gap within this of the lowest makes a two-point contact
  /// (default 1 µm) ...
  double two_point_gap = 1e-6;
  /// [m] ... if it lies farther than this from the contact point along the rail; the same distance
  /// between neighbouring rows of a sweep marks a jump of the contact point (default 1 mm, as
  /// GeometryOptions::jump_distance).
  double jump_distance = 1e-3;
  /// Evaluate every scan sample instead of skipping the blocks that the bound excludes (default
  /// false). Same results, slower: the plain scan that the tests compare the pruned one with.
  bool full_scan = false;
  /// [rad] largest |roll| searched (default 0.05 rad = 2.9°: a Δr of 75 mm) ...
  double max_roll = 0.05;
  /// ... and the roll's convergence: the bracket of TOMS 748 (default 1e-12 rad: 1 nm at 750 mm).
  double roll_tolerance = 1e-12;
  /// Smoothing of the profiles (profile/curve.hpp): its defaults but a 0.02 mm grid, half the
  /// cost of the 0.01 mm default (which the contact runs need for their curvatures). Cubic
  /// Hermite between the fitted nodes; its slope error across a jump of curvature, ∝ the grid
  /// step, is what moves a near-conformal contact point: EN 15302 wheel A on rail A gives Δr
  /// within 0.0005 mm of the table (its rounding) at 0.01 mm, 0.0016 mm at 0.02 (at y = ±3.0 mm),
  /// 0.0021 mm at 0.03, 0.0037 mm at 0.05.
  CurveOptions curve = wheelset_curve_defaults();
  /// [m] the largest |y| the wheelset is asked for (default 20 mm). The wheel profiles are
  /// smoothed only over the part that can face a rail for |y| up to this (the rail's width
  /// shifted by ±y, the roll's reach when solved, and twice the widest fit window on each side):
  /// a third of the smoothing of a 135 mm wheel is saved on EN 15302 rail A. A y beyond it is
  /// still answered, on that part only (a contact at its end is off_profile: never a silent
  /// figure). The jobs set it from the sweep.
  double max_displacement = 0.020;
  static CurveOptions wheelset_curve_defaults() {
    CurveOptions c;
    c.grid_step = 0.02e-3;
    return c;
  }
  /// False with the field, the value and the broken rule in `why`.
  bool valid(std::string* why) const;
};

/// One wheel's contact (SI; local frames of the wheel and the rail profiles).
struct WheelContact {
  double y_w = 0;      ///< [m] wheel profile coordinate of the contact point (η)
  double z_w = 0;      ///< [m] wheel profile height there
  double y_r = 0;      ///< [m] rail profile coordinate of the contact point
  double z_r = 0;      ///< [m] rail profile height there
  double r = 0;        ///< [m] rolling radius: R0 − (z_w(y_w) − z_w(0))
  double gamma = 0;    ///< [rad] contact angle: the rail's slope angle at y_r (positive towards the gauge corner)
  double h = 0;        ///< [m] axle-centre height above the rail frame's z = 0 at which this wheel touches
  bool two_point = false;      ///< a second contact point within two_point_gap, farther than jump_distance
  double y_r_second = 0;       ///< [m] its rail coordinate (when two_point)
  bool off_profile = false;    ///< the contact lies at an end of the wheel or rail profile (not a real contact)
};

/// The wheelset at one lateral displacement.
struct WheelsetState {
  double y = 0;        ///< [m] lateral displacement of the wheelset (towards the right rail)
  double roll = 0;     ///< [rad] roll angle (0 without roll)
  WheelContact left, right;
  bool found = false;  ///< both wheels overlap their rails
  bool converged = true;  ///< the roll was solved (Solved only)
  double delta_r() const { return right.r - left.r; }                      ///< [m] Δr
  double delta_tan_gamma() const;                                          ///< tan γ_right − tan γ_left
};

/// A wheelset on a track: built once (smooth profiles, placement), then queried for any y.
class Wheelset {
 public:
  /// Profiles in their canonical frames (rails with their inclination applied); the left ones may
  /// be the same objects as the right ones (one profile mirrored). Throws InputError when the
  /// options are invalid, a profile cannot be smoothed, a rail has no gauge point (Gauge
  /// placement) or a wheel does not reach its taping line (y = 0).
  Wheelset(const Profile& wheel_left, const Profile& wheel_right, const Profile& rail_left, const Profile& rail_right,
           const WheelsetPlacement& placement, const WheelsetOptions& opt = {});

  /// Other wheels on the same rails, placement and options as `track` (a fleet: the rails are
  /// smoothed and placed once). Throws InputError as above for the wheels.
  Wheelset(const Wheelset& track, const Profile& wheel_left, const Profile& wheel_right);

  /// The contact state at lateral displacement y [m].
  WheelsetState at(double y) const;
  /// States at every y of `ys` [m], increasing; marks the jumps of the contact point between
  /// neighbours (WheelContact::two_point also set where the point moves by more than
  /// jump_distance from the previous row).
  /// `threads` > 1 shares the rows between threads; the results are the same whatever the count.
  std::vector<WheelsetState> sweep(const std::vector<double>& ys, unsigned threads = 1) const;

  /// [m] |Y| of the rail origins and of the wheels' taping lines (after placement).
  double rail_origin(int side) const { return side < 0 ? c_[0] : c_[1]; }
  double taping_line(int side) const { return side < 0 ? a_[0] : a_[1]; }
  /// [m] gauge measured on the placed rails (their gauge points, gauge_height below their tops):
  /// the 1435.164 mm of the EN 15302 reference placement.
  double measured_gauge() const { return measured_gauge_; }
  /// [m] |Y| of a placed rail's gauge point (gauge_height below its top, gauge side); NaN when
  /// the rail has none (absolute placement of a rail that does not reach that low).
  double gauge_point(int side) const { return gauge_point_[side < 0 ? 0 : 1]; }
  const WheelsetOptions& options() const { return opt_; }
  /// The smooth profiles the contact search works on (side < 0: left, else right).
  const ProfileCurve& wheel_curve(int side) const { return *side_[side < 0 ? 0 : 1].W; }
  const ProfileCurve& rail_curve(int side) const { return *side_[side < 0 ? 0 : 1].R; }

 private:
  /// Samples per block of the pruned scan: 1.6 mm at the default scan step.
  static constexpr std::size_t kScanBlock = 16;
  /// A rail's scan data, built once per track and shared by every wheel of a fleet: heights
  /// every `step` from y_min (linear between them: zr_fast), and their running maxima over
  /// 2^k entries (a sparse table: the highest rail value over any range in two lookups).
  struct RailScan {
    double y_min = 0, step = 0;
    std::vector<double> z;
    std::vector<double> max;   // level k at [k·n, (k+1)·n): max of z[i .. i + 2^k)
    std::size_t levels = 0;
    double z_at(double yr) const;
    /// [m] An upper bound of z_at over [lo, hi] (every table value that its interpolation uses).
    double max_over(double lo, double hi) const;
  };
  struct Side {
    std::shared_ptr<const ProfileCurve> W, R;
    std::shared_ptr<const RailScan> rail;
    double R0 = 0, zw0 = 0;       // nominal radius, wheel height at its taping line
    double a = 0, c = 0;          // taping line and rail origin |Y|
    double s = 1;                 // +1 right, −1 left
    double yw_min = 0, yw_max = 0, yr_min = 0, yr_max = 0;
    // Scan tables: wheel heights every scan_step on the grid anchored at the wheel profile's first
    // point (ys0; sample i of the table is grid point is0 + i, so a wheel smoothed only in part
    // is scanned at the same η as in full), and their lowest and highest per block of
    // kScanBlock samples (the bounds of the pruned scan).
    double ys0 = 0;
    std::size_t is0 = 0;
    double eta(std::size_t i, double h) const { return ys0 + h * static_cast<double>(is0 + i); }
    std::vector<double> zw_scan, zw_block_min, zw_block_max;
  };
  Side side_[2];  // 0 left, 1 right
  double a_[2] = {0, 0}, c_[2] = {0, 0};
  double measured_gauge_ = 0;
  double gauge_point_[2] = {0, 0};
  WheelsetOptions opt_;

  void set_wheel(Side& S, std::shared_ptr<const ProfileCurve> W, const Profile& wheel);
  /// The smoothing options of the wheels: opt_.curve limited to the part that can face the
  /// rails (max_displacement), once the rails are placed.
  CurveOptions wheel_curve_options() const;
  /// Both sides hold the same wheel, rail and placement, and there is no roll: the left wheel's
  /// contact at y is the right wheel's at −y (sweep() computes it once).
  bool mirrored() const;
  /// Contact of one wheel with the wheelset at displacement y and roll phi.
  WheelContact contact(const Side& S, double y, double phi, bool* found) const;
};

}  // namespace mh
