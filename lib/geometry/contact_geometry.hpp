#pragma once
// Contact geometry of one wheel–rail profile pair (paper section 2.3, method.md §3 and §7):
// strips, the contact angle function (CAF) γ(t_Y), its jumps, the potential ellipses, and for
// every t_Y of a fine grid the candidate of every potential ellipse. Built once per profile pair;
// every case of a sweep only interpolates these tables (it never rescans the profiles).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "profile/profile.hpp"
#include "profile/curve.hpp"
#include "profile/rail_cant.hpp"
#include "core/units.hpp"
#include "geometry/curvature_samples.hpp"

namespace mh {

/// Track and wheelset data that place the wheel against the rail at t_Y = 0 (method.md §7).
/// Defaults: standard gauge values.
struct TrackSetup {
  double gauge = 1.435;                   ///< [m] track gauge (default 1435 mm)
  double gauge_height = 0.014;            ///< [m] measured this far below the top of rail (default 14 mm)
  double flange_back_distance = 1.360;    ///< [m] wheelset flange-back distance (default 1360 mm)
  double flange_back_position = -0.070;   ///< [m] y of the flange back on the wheel profile (default −70 mm)
  double nominal_radius = 0.460;          ///< [m] wheel radius at the taping line y = 0 (default 460 mm)
  /// How the wheel is placed against the rail at t_Y = 0 (docs/case-file.md):
  ///  Gauge (default): from the rail's gauge point (gauge_height below its top), the gauge and the
  ///    wheelset's flange-back distance/position (method.md §7);
  ///  Explicit: the rail y of the wheel profile's origin (taping line) is `lateral_offset`, for
  ///    a test-rig roller, a rail scanned only over its head, a narrow section: no gauge point.
  enum class Positioning { Gauge, Explicit };
  Positioning positioning = Positioning::Gauge;
  double lateral_offset = 0;              ///< [m] Explicit: rail y of the wheel origin at t_Y = 0
  /// [m] A roller rig: the roller's radius at the rail profile's z = 0 (its origin); its
  /// longitudinal curvature enters A = 1/(2 R_wyy) + 1/(2 R_ryy). 0 (default): a straight rail.
  double roller_radius = 0;
};

struct GeometryOptions {
  double tY_min = -10e-3;      ///< [m] first t_Y of the grid (default −10 mm)
  double tY_max = 12e-3;       ///< [m] last t_Y of the grid (default +12 mm: covers flange contact)
  double tY_step = 0.01e-3;    ///< [m] grid step (default 0.01 mm)
  double strip_width = 0.1e-3; ///< [m] width of the rail strips (default 0.1 mm)
  /// A jump of the CAF (method.md §3.5) is a discontinuity of the contact point in t_Y, located
  /// by bisection between grid points down to a 0.01 µm bracket, independently of the grid step:
  /// across that bracket γ must change by more than jump_threshold (default 0.5°) ...
  double jump_threshold = 0.5 * units::pi / 180.0;  ///< [rad]
  /// ... and the contact point move on the rail by more than jump_distance (default 1 mm; the
  /// jumps of the Manchester pair move it 4 to 10 mm). Continuous motion moves it by ~0 there.
  double jump_distance = 1.0e-3;  ///< [m]
  /// An interior potential ellipse narrower than this in t_Y (a sliver between two jumps), or
  /// one that contains no grid point, is merged into the neighbour whose contact point is closer
  /// (the jump between them is dropped). Default 0.05 mm.
  double min_ellipse_width = 0.05e-3;  ///< [m]
  /// Flange climb (method.md §3.7): the steepest flange section is where the wheel's contact
  /// angle is within this of its largest (default 1°: the smoothed S1002 overshoots its straight
  /// 70° section by 0.67° at the junction with the R13 arc; the whole straight section, and a
  /// contact on it, stays inside) ...
  double flange_angle_tolerance = 1.0 * units::pi / 180.0;  ///< [rad]
  /// ... and a wheel has a flange when its lowest point lies on the gauge side (y < 0) at least
  /// this far below its height at the taping line (default 10 mm, profiles.md §5).
  double flange_min_height = 10e-3;  ///< [m]
  CurveOptions curve;          ///< smoothing of both profiles (profile/curve.hpp)
  /// Measured or exact, per profile (case file geometry.noise; profiles.md "Measured or exact");
  /// each overrides curve.noise for its profile. Default auto: decided from the data.
  ProfileNoise wheel_noise = ProfileNoise::Auto, rail_noise = ProfileNoise::Auto;
  /// Smoothing for contact (profiles.md §7 "Smoothing for contact"): the contact gap of the grid
  /// methods (half-space, strips) is built on measured profiles smoothed by a spline of
  /// smoothing length L (profile/smoothing_spline.hpp: a wave of length L along the profile keeps
  /// half its amplitude); exact profiles are never smoothed. Case file geometry.smoothing_mm.
  /// Default (empty, "auto"): each measured profile's L is chosen from its own noise, the spline
  /// moving the points normal to the profile by the noise σ of its curve fit (NoiseDecision::sigma;
  /// smooth_profile_to_noise within `auto_smoothing`'s bounds). A value forces that L for every
  /// measured profile; 0 turns the smoothing off.
  std::optional<double> contact_smoothing;  ///< [m]
  NoiseSmoothingOptions auto_smoothing;    ///< bounds of the automatic L (profile/smoothing_spline.hpp)
  /// The smoothing's uncertainty band (profiles.md §7 "Uncertainty band"): when a profile of the
  /// pair is smoothed for contact and the case's method is a grid method or auto, the pair's
  /// geometry is also built with every smoothing length halved and doubled (both profiles
  /// together; build_band_geometry) and every case is solved on them too, reporting how its
  /// peak pressure and area move. Case file geometry.smoothing_band. Default true: it costs
  /// nothing where nothing is smoothed (exact profiles) and is not computed for the
  /// multi-Hertzian method (whose tables are on the window fit, not on the smoothed surface).
  bool smoothing_band = true;
  bool valid(std::string* why) const;
};

/// One candidate contact (a potential ellipse's strip) at one t_Y. SI, paper signs.
struct CandidateGeom {
  double gap = 0;     ///< [m] z_w − z_r at the strip minus the minimum over all strips (0 at the main strip)
  /// [m] z_w − z_r at the strip itself, the wheel at its datum height (not lowered to contact).
  /// A smooth (C¹) function of t_Y for every candidate, across the jumps too (method.md §3.6), so
  /// it is what candidates_at interpolates; the gaps follow as sep − min over the candidates.
  double sep = 0;
  double y_r = 0;     ///< [m] rail lateral coordinate of the strip
  double y_w = 0;     ///< [m] wheel lateral coordinate facing it (y_r − y_offset − t_Y)
  double gamma = 0;   ///< [rad] contact angle: rail slope angle at the strip
  double k_rxx = 0;   ///< [1/m] 1/R_rxx (positive: convex rail)
  double k_wxx = 0;   ///< [1/m] 1/R_wxx (negative: concave wheel, e.g. the flange root)
  double r_roll = 0;  ///< [m] wheel rolling radius at y_w
  double R_wyy() const;  ///< [m] r_roll / cos γ (method.md §2, Meusnier)
  double r_roller = 0;   ///< [m] roller rigs: the roller's radius at y_r (0: a straight rail)
  /// The point lies off the end of a profile (method.md §3.7): y_w outside the wheel profile (its
  /// height and curvature are the end's, extrapolated) or within one strip width of its ends (an
  /// edge contact: the profile is cut where the contact would be), or y_r within one strip width
  /// of the rail's ends.
  bool off_profile = false;
  /// Flange climb (method.md §3.7): y_w lies between the wheel's flange tip and its steepest
  /// flange point, i.e. the contact has passed the largest contact angle of the wheel.
  bool flange_climb = false;
  /// [1/m] 1/R_ryy = cos γ / r_roller (Meusnier, as for the wheel); 0 for a straight rail.
  double k_ryy() const;
};

struct PotentialEllipse {
  int index = 0;               ///< 1-based, in increasing t_Y
  std::size_t k_first = 0, k_last = 0;  ///< grid indices of its t_Y interval
  double tY_min = 0, tY_max = 0;        ///< [m]
  double y_r_min = 0, y_r_max = 0;      ///< [m] where its main strips lie on the rail
  double y_w_min = 0, y_w_max = 0;      ///< [m] and on the wheel
  /// [m] its contact point on the rail just inside its lower / upper jump: its candidate at any
  /// t_Y below / above its interval (method.md §3.6); 0 for the first / last ellipse.
  double y_r_below = 0, y_r_above = 0;
};

/// Where the wheel rolled by δ is closest to the rail, tabulated for any |δ| up to a limit
/// (method.md §3.8, build_rolled_minima): at each t_Y of the grid the rolled separation of strip j
/// to first order in δ is the line g_j + σ h_j in σ = sin δ (g_j the upright separation, h_j the
/// rotation's lever at the strip), so the strip of the smallest rolled separation is a piece of
/// the lower envelope of these lines; each grid point keeps its pieces over |σ| ≤ sigma_max.
struct RolledMinima {
  double sigma_max = 0;                ///< [-] sin of the largest |δ| covered
  std::vector<std::uint32_t> first;    ///< grid point k's pieces: [first[k], first[k + 1])
  std::vector<double> sigma_from;      ///< [-] per piece: the σ from which its strip is the minimum
  std::vector<std::uint32_t> strip;    ///< per piece: that strip
  /// The strip of the smallest rolled separation at grid point k and σ (|σ| ≤ sigma_max); the
  /// number of strips if the wheel faces none there.
  std::uint32_t at(std::size_t k, double sigma) const;
};

class RolledMinimaOnDemand;  // rolled_candidates.hpp

class ContactGeometry {
 public:
  std::vector<double> tY;                ///< [m] grid
  std::vector<int> main_ellipse;         ///< per grid point: 0-based index of the ellipse of the main strip
  std::vector<PotentialEllipse> ellipses;
  std::vector<double> jumps;             ///< [m] t_Y of the jumps between ellipses (bisected, grid-independent)
  std::vector<CandidateGeom> table;      ///< [k * n_ellipses() + e]
  std::vector<double> strip_y;           ///< [m] centres of the rail strips
  std::vector<std::size_t> main_strip;   ///< per grid point: index of the strip with the smallest gap
  std::vector<double> z_contact;         ///< [m] per grid point: wheel height offset at geometric contact
  double y_offset = 0;                   ///< [m] rail y of the wheel's origin (taping line) at t_Y = 0
  /// The wheel's steepest flange section (method.md §3.7): largest contact angle [rad] on the flange
  /// face (between the flange tip and y_w = 0), and the tip-side end of the part of the face
  /// within `flange_angle_tolerance` of it [m]; has_flange false for a wheel without a flange.
  bool has_flange = false;
  double flange_gamma_max = 0, flange_y_steepest = 0;
  /// [m] The flange tip (the wheel's lowest point): its lateral y_w and its rolling radius, the
  /// largest of the wheel (the judge's derailment test, contact/judge/judge.hpp). 0 without a flange.
  double flange_y_tip = 0, flange_r_tip = 0;
  /// Warnings about the pair's placement (a wheel without a flange placed by the gauge rule).
  std::vector<std::string> warnings;
  double rail_gauge_y = 0;               ///< [m] gauge point of the rail (rail frame); explicit positioning: the gauge point if the rail has one, else 0
  double wheel_window = 0, rail_window = 0;  ///< [m] curvature fit windows used (profile/curve.hpp)
  /// The smooth profiles the tables were built from, kept for the 3-D gap of the grid methods
  /// (geometry/gap.hpp): wheel in its own frame, rail with its inclination.
  std::shared_ptr<const ProfileCurve> wheel_curve, rail_curve;
  /// The profiles of the grid methods' contact gap (geometry/gap.hpp): a measured profile
  /// smoothed for contact (GeometryOptions::contact_smoothing), otherwise the same curve as
  /// wheel_curve / rail_curve.
  std::shared_ptr<const ProfileCurve> wheel_gap_curve, rail_gap_curve;
  /// [m] The rail's vertical gauge face (Profile::face_z, a 60E1 flank at 1:20): the height of
  /// its foot; the face hangs from the first point of the rail curves, at their y_min. NaN for a
  /// rail without one. Only the grid methods see it (their normal gap, gap.hpp, and the patch-end
  /// test off_profile_at); the tables above are built on z(y), which ends at the face's top.
  double rail_face_foot = std::numeric_limits<double>::quiet_NaN();
  bool has_rail_face() const { return rail_face_foot == rail_face_foot; }
  double nominal_radius = 0;             ///< [m] wheel radius at the taping line (y_w = 0)
  double wheel_z0 = 0;                   ///< [m] smoothed wheel height at y_w = 0 (r(y_w) = R0 − (z_w(y_w) − z0))
  /// Curvature samples of both profiles every kappa_dy over each profile's width, in the
  /// solver's signs: rail_k gives 1/R_rxx at y_r, wheel_k 1/R_wxx at y_w, with the gap they give
  /// along the patch (geometry/curvature_samples.hpp). Used by the Hertz validity test over the
  /// patch width (contact/ellipse/hertz_validity.hpp).
  double kappa_dy = 0.05e-3;
  CurvatureSamples rail_k, wheel_k;
  bool has_curvature_samples() const { return !rail_k.empty() && !wheel_k.empty(); }
  /// The same samples of the contact surface, the profiles the grid methods solve on
  /// (wheel_gap_curve, rail_gap_curve), when a profile is smoothed for contact; empty otherwise
  /// (the contact surface is then the curves above). The Hertz validity test measures the gap at
  /// the patch edges on both (contact/ellipse/hertz_validity.hpp).
  CurvatureSamples rail_gap_k, wheel_gap_k;
  bool has_contact_surface_samples() const { return !rail_gap_k.empty() && !wheel_gap_k.empty(); }
  /// 1/R_rxx, 1/R_wxx [1/m] at any y, linear between samples, held constant beyond the ends.
  double k_rxx_at(double y_r) const { return rail_k.at(y_r); }
  double k_wxx_at(double y_w) const { return wheel_k.at(y_w); }

  std::size_t n_ellipses() const { return ellipses.size(); }
  const CandidateGeom& at(std::size_t k, std::size_t e) const { return table[k * ellipses.size() + e]; }
  const CandidateGeom& main_at(std::size_t k) const { return at(k, static_cast<std::size_t>(main_ellipse[k])); }
  bool covers(double t) const { return t >= tY.front() - 1e-12 && t <= tY.back() + 1e-12; }

  /// Candidates of all potential ellipses at an arbitrary t_Y inside the grid (method.md §3.6):
  /// positions, angles, radii and separations `sep` linearly interpolated between the two
  /// neighbouring grid points; the gaps are sep − min(sep), and `main` receives the candidate of
  /// the smallest separation (the ellipse whose t_Y interval between the jumps holds t on ties).
  /// Interpolating the separations, which are smooth in t_Y, instead of the gaps, which have a
  /// kink at every jump, keeps the load sharing near a jump independent of the grid step
  ///. Precondition: covers(t).
  void candidates_at(double t, CandidateGeom* out, int* main) const;

  /// The candidates at t evaluated from the profiles themselves (no interpolation): the main
  /// strip at t for the ellipse whose interval holds t, y_r_below / y_r_above for the others.
  /// Used by candidates_at in grid intervals that hold a jump. False if the profiles do not
  /// overlap at t.
  bool exact_candidates_at(double t, CandidateGeom* out, int* main) const;

  /// The candidates at t with the wheel rolled by δ against the rail (`roll`, [rad], about x in
  /// the pair's frame, positive raising the wheel's field side, y > 0; method.md §3.8, eq. 3.8.1):
  /// the wheel profile rotated by δ about its origin (its taping line point), then placed by t as
  /// upright. The smallest rolled separation over the rail (a strip scan refined between strips)
  /// is the candidate of the ellipse whose part of the rail holds it (strip_ellipse); every other
  /// ellipse keeps its upright candidate's rail point (candidates_at(t)) with the rolled wheel's
  /// separation there, so that δ → 0 gives the upright candidates back. Contact angle γ the
  /// rail's slope at the point (the wheel's own slope there is γ − δ), curvatures and rolling
  /// radius those of the profiles at the points facing each other. δ = 0 is candidates_at(t)
  /// exactly (same bits). False if the profiles do not overlap at t (out then as candidates_at(t)).
  /// Precondition: covers(t).
  bool candidates_at(double t, double roll, CandidateGeom* out, int* main) const;
  /// Per rail strip: the potential ellipse whose rail range [y_r_min, y_r_max] is nearest (its part
  /// of the rail for the rolled candidates); filled by build_geometry.
  std::vector<int> strip_ellipse;
  /// The rolled minima's envelopes (build_rolled_minima; null: candidates_at(t, δ) scans the
  /// strips). Rolls beyond their limit are scanned too.
  std::shared_ptr<const RolledMinima> rolled_minima;
  /// Or the same tables built by the first rolled call that can use them (rolled_candidates.hpp;
  /// used when rolled_minima is null).
  std::shared_ptr<const RolledMinimaOnDemand> rolled_minima_on_demand;
  /// The wheel point facing rail point y_r at t with the wheel rolled by δ: its y_w (wheel frame)
  /// and the rotated wheel surface's height there, z̃_w (rail frame, datum height).
  void rolled_wheel_at(double t, double roll, double y_r, double* y_w, double* z_w) const;

  /// The main strip at t: the strip of smallest z_w − z_r, refined between strips to the local
  /// minimum of the smooth gap; `found` false when the profiles do not overlap laterally.
  struct MainPoint { double y_r = 0, gmin = 0; std::size_t strip = 0; bool found = false; };
  MainPoint locate_main(double t) const;
  /// Candidate data at t for the rail point y_r (method.md §3.6); `gmin` is the smallest
  /// separation at t, `is_main` makes the gap exactly 0.
  void fill_candidate(double t, double y_r, bool is_main, double gmin, CandidateGeom& c) const;
  /// The rail point y_r, and the wheel point facing it at t, lie off the end of a profile or
  /// within one strip width of it (method.md §3.7; CandidateGeom::off_profile).
  bool off_profile(double t, double y_r) const;
  /// The same for a point (y_r, z) near the rail surface (a grid patch's end in its plane): a
  /// point beside the rail's vertical gauge face, above its foot by more than a strip width, lies
  /// on the rail although y_r is at the end of z(y). With the wheel rolled by `roll` [rad] against
  /// the rail, the wheel point is the rolled wheel's facing y_r (rolled_wheel_at).
  bool off_profile_at(double t, double y_r, double z, double roll = 0) const;

  /// Unique per build_geometry call (copies share it: same content); keys the per-thread cache of
  /// exact_candidates_at, so that a geometry built at the address of a destroyed one (the next
  /// pair of a batch) never sees the other's candidates.
  std::uint64_t build_id = 0;
  std::vector<double> strip_zr;          ///< [m] rail height at the strip centres
  double strip_width = 0;                ///< [m]
  double roller_radius = 0;              ///< [m] roller rigs (TrackSetup::roller_radius), else 0
};

/// Build the geometry of a wheel on a rail. The rail must already carry its inclination
/// (the case loader applies it once). Throws InputError when the pair cannot be placed
/// (no gauge point on the rail, profiles that never overlap) or the options are invalid.
ContactGeometry build_geometry(const Profile& wheel, const Profile& rail, const TrackSetup& track,
                               const GeometryOptions& opt);

/// Tabulate G's rolled minima for |δ| ≤ roll_max [rad] (RolledMinima): one upright evaluation of
/// every strip at every t_Y of the grid, about the cost of build_geometry again. candidates_at(t, δ)
/// then evaluates the rolled separation at the strips around the envelopes' minima of the two grid
/// points around t instead of scanning the rail (the same strip at the grid points; between them
/// the wheel moves by a tenth of a strip).
void build_rolled_minima(ContactGeometry& G, double roll_max);
/// The default limit of the wheelset call's tables (rad): 25 mrad, twice the kinematic roll of
/// S1002 on 60E1 in flange contact (11.3 mrad at t_Y 10 mm in CONTACT's cases).
constexpr double kRolledMinimaRollMax = 25e-3;

/// The pair's geometries of the smoothing's uncertainty band (profiles.md §7 "Uncertainty band"),
/// null where not made: every contact smoothing length × 0.5 (`half`) and × 2 (`twice`). For the
/// grid methods' rows the spline of the contact surface; for the multi-Hertzian rows the spline
/// and the wide window fit of their curvature tables together (`window_half`, `window_twice`).
/// The grid rows' band keeps the window: their answer is the surface's, and the window moves only
/// where their placement starts (by up to 1.2 % of the band's values, measured on avg_low2).
struct BandGeometries {
  std::shared_ptr<const ContactGeometry> half, twice, window_half, window_twice;
  bool any() const { return half || window_half; }
};

/// A profile pair as used (rail with its inclination) and its contact geometry.
struct PairGeometry {
  Profile wheel, rail;
  ContactGeometry geo;
  /// The rail's cant as estimated from its head, against the case's inclination (its warnings
  /// are also in rail.warnings).
  RailCantCheck cant;
  /// The uncertainty band's geometries (GeometryOptions::smoothing_band; set_band_geometries).
  BandGeometries band;
};

/// Whether G's contact gap is made on a smoothed profile (wheel or rail; profiles.md §7).
bool smoothed_for_contact(const ContactGeometry& G);

/// The geometry of the pair with every contact smoothing length multiplied by `scale`
/// (NoiseSmoothingOptions::length_scale; a length given is scaled too), and with `window` the
/// wide fit window of measured profiles too (CurveOptions::measured_window_half_width): the
/// uncertainty band's geometry at L/2 (0.5) and 2L (2).
ContactGeometry build_band_geometry(const Profile& wheel, const Profile& rail, const TrackSetup& track,
                                    const GeometryOptions& opt, double scale, bool window = false);

/// pg.band when a profile of pg is smoothed for contact (null otherwise): the spline's for
/// `grid_rows`, the spline's and window's for `ellipse_rows` (a method's rows: strips and
/// half-space grid, multi-Hertzian ellipse, `auto` both). The one place the command, batches
/// and the C interface make them.
void set_band_geometries(PairGeometry& pg, const TrackSetup& track, const GeometryOptions& opt, bool grid_rows,
                         bool ellipse_rows);

}  // namespace mh
