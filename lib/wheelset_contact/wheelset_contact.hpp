#pragma once
// The wheelset call (docs/c-api.md "The wheelset call"): both wheels of a rigid wheelset on their rails,
// one call per time step of a vehicle-dynamics code. Pose and velocities in, per contact and per
// wheelset the forces in track coordinates out, with the statuses and warnings of the judge and
// the derivatives an implicit integrator needs.
//
// Each wheel on its rail is one pair of the single-contact solve (contact/solve.hpp): its
// geometry tables are built once (geometry/contact_geometry.hpp: the same gauge placement as
// geometry/wheelset.hpp), each step solves both pairs by the chosen method (multi-Hertzian
// first; the grid methods through the same solve_contact) and, with friction, the tangential
// problem from the kinematics (contact/tangential: creepages, FASTSIM).
//
// Track frame (docs/tangential.md, the frame of a left wheel's pair): x forward, y towards the
// LEFT rail, z up (right-handed). Note: geometry/wheelset.hpp's y points to the right rail.
// Mirroring (as the field does): every profile stays in its canonical frame, y towards its field
// side; the left pair's frame is the track frame, the right pair's its mirror image (σ = +1 left,
// −1 right: Y_track = σ y_pair). A lateral displacement y of the wheelset is t_Y = σ y of each
// pair (t_Y > 0: towards that wheel's flange contact).
//
// What is modelled, and the limits (each reported as a WheelsetWarning when it applies):
//  - roll φ (about x, positive raising the left wheel): with WheelsetSetup::roll_in_geometry (the
//    default), whatever the method, each wheel
//    is rolled against its rail by δ = σ φ about the axle centre (pair_pose(), method.md §3.8):
//    its candidates are those of the rolled profile (contact point, angle, curvatures, gaps), the
//    grid methods' gap that of the rolled wheel (WheelRailGap with a roll), its height that of the
//    rolled wheel's first contact, the spin that of the rolled axle. Without it the roll enters
//    each wheel's height only, to first order (δz_s = h_s − Z − σ φ L_s, roll_lever()), with the
//    warnings roll_in_geometry_neglected above WheelsetStepOptions::roll_limit and
//    roll_near_flange (roll_flange_gamma);
//  - yaw ψ enters the creepages (η = (ẏ − Ω r ψ)/(V cos γ), docs/method.md §10), not the
//    contact point: the lead of the contact point ahead of the axle, x ≈ −r tan γ tan ψ for a
//    cone, is not modelled; warning yaw_lead_not_modelled when |x| exceeds a tenth of the
//    contact's semi-axis a along x (the measured lead and that limit are the warning's values).
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "contact/case_result.hpp"
#include "contact/multi_hertz/approach_given.hpp"
#include "contact/options.hpp"
#include "contact/solve.hpp"
#include "geometry/contact_geometry.hpp"
#include "profile/profile.hpp"

namespace mh {

/// The wheelset call's defaults for the creep forces, apart from the single-pair call's
/// (docs/performance.md "The wheelset call"):
///  - FASTSIM on 16 × 16 cells (the single pair: 32 × 32): it meets every accuracy target of
///    issue 33 against the independent references (docs/tangential.md "Grid of FASTSIM": Kalker's
///    linear theory within 0.24 %, CONTACT's exact solution at medians 0–1.9 % and p95 ≤ 5.9 %,
///    the same as 32 × 32 since FASTSIM's own model error dominates its grid error of ≤ 1.7 % μN)
///    at a third of the cost;
///  - the vertical equilibrium to 1e-5 Q (the single pair: 1e-7 Q): 0.5 N at 50 kN, a tenth
///    of what the 16 × 16 grid itself moves the creep forces' vertical share; one FASTSIM solve
///    less per wheel on most steps.
constexpr int kWheelsetFastsimCells = 16;
constexpr double kWheelsetEquilibriumTolerance = 1e-5;

/// m with the wheelset call's defaults above in its tangential options.
inline MethodOptions wheelset_method_options(MethodOptions m = {}) {
  m.tangential.fastsim.nx = m.tangential.fastsim.ny = kWheelsetFastsimCells;
  m.tangential.equilibrium_tolerance = kWheelsetEquilibriumTolerance;
  return m;
}

/// What a wheelset is built from. Profiles in their canonical frames (y towards the field side,
/// z up; rails with their inclination applied); the left ones may be copies of the right ones.
struct WheelsetSetup {
  Profile wheel_left, wheel_right, rail_left, rail_right;
  /// Gauge, gauge height, flange-back distance and position (defaults: standard gauge, EN 13715);
  /// its nominal_radius is replaced by the two below.
  TrackSetup track;
  double nominal_radius_left = 0.460, nominal_radius_right = 0.460;  ///< [m] R0 at each taping line
  Material material;
  /// Method and its options; tangential.mu finite: the creep forces are solved (FASTSIM on each
  /// multi-Hertzian ellipse), tangential.kin is replaced by each step's velocities. Default: the
  /// wheelset call's (wheelset_method_options).
  MethodOptions method = wheelset_method_options();
  /// The pairs' tables. Their t_Y range must cover |y| plus the roll's shift R0 |φ| (pair_pose:
  /// 4.6 mm at 10 mrad): default −16 … +18 mm (the single pair's −10 … +12 mm widened).
  GeometryOptions geometry = [] {
    GeometryOptions g;
    g.tY_min = -16e-3;
    g.tY_max = 18e-3;
    return g;
  }();
  /// Each wheel rolled against its rail in the contact geometry, every method (default true:
  /// method.md §3.8, the answer CONTACT gives with the wheelset rolled). False: the upright wheels'
  /// tables and the roll to first order in the heights, about a tenth of the cost of a
  /// multi-Hertzian step in loads mode, with the errors against CONTACT of docs/wheelset.md "Roll in the
  /// geometry, or not" and the warnings roll_in_geometry_neglected and roll_near_flange.
  bool roll_in_geometry = true;
};

/// How the vertical state of a step is given.
enum class WheelsetVertical {
  Loads,     ///< Q_left, Q_right [N] (eq. 10 on each wheel); the roll is an output
  Position,  ///< the axle-centre height Z [m] and the roll (given or solved)
};

/// One step's input (SI, track frame).
struct WheelsetPose {
  double y = 0;         ///< [m] lateral displacement of the wheelset (towards the left rail)
  double yaw = 0;       ///< [rad] ψ about z (positive turning x towards the left)
  WheelsetVertical vertical = WheelsetVertical::Loads;
  double Q_left = 0, Q_right = 0;  ///< [N] vertical loads (Loads)
  /// [m] Position: the axle centre's height in the virtual-penetration sense of eq. 11: each wheel's
  /// δz_s = h_s(t_Y) − Z − σ φ L_s, h_s the axle height at which that wheel first touches its rail
  /// upright (rail frames' z = 0 at track z = 0), L_s its roll lever (roll_lever()). As
  /// mhc_solve_approach, multi-Hertzian only.
  double Z = 0;
  /// Position: φ such that both wheels touch at one height; Loads: φ such that the two wheels'
  /// approaches agree on one rigid axle. False: `roll` given (Loads: each wheel then carries its load
  /// at that roll, and Z is the mean of the two wheels' axle heights).
  bool solve_roll = true;
  double roll = 0;      ///< [rad] with solve_roll false: the roll φ
  // Velocities for the creepages (used when the setup has friction):
  double V = 0;               ///< [m/s] forward speed (> 0 with friction)
  double lateral_velocity = 0;  ///< [m/s] ẏ
  double yaw_rate = 0;        ///< [rad/s] ψ̇
  double pitch_rate = NAN;    ///< [rad/s] Ω of the axle; NaN: V / r0 of each wheel
};

/// A wheelset-level limit that applies to a step (the per-contact statuses and warnings are the
/// judge's, in each WheelResult::r).
struct WheelsetWarning {
  enum class Kind { RollInGeometryNeglected, YawLeadNotModelled, RollNearFlange };
  Kind kind = Kind::RollInGeometryNeglected;
  int side = 0;        ///< +1 left, −1 right, 0 the wheelset
  double value = 0;    ///< [rad] |φ| / [m] |lead| estimated / [rad] γ of the contact
  double limit = 0;    ///< [rad] roll_limit / [m] a tenth of the semi-axis a / [rad] roll_flange_gamma
};
/// "roll_in_geometry_neglected:roll_mrad=1.2>1", "yaw_lead_not_modelled:wheel=left:lead_mm=3.1>0.6",
/// "roll_near_flange:wheel=left:gamma_deg=29>25"
std::string to_string(const WheelsetWarning& w);

/// Forces and moments [N], [N m] on the wheelset, track frame, moments about the axle centre.
struct Wrench {
  std::array<double, 3> F{0, 0, 0}, M{0, 0, 0};
};

/// One loaded contact (ellipse or patch) in track and wheelset coordinates.
struct ContactPoint {
  int index = 0;                  ///< ellipse or patch index of the pair (1-based)
  double Y = 0, Z = 0;            ///< [m] contact point on the rail, track frame
  double Y_ws = 0, Z_ws = 0;      ///< [m] on the wheel, wheelset frame (from the axle centre, unrolled)
  double gamma = 0;               ///< [rad] contact angle in the pair's sign (positive towards the gauge corner)
  double r_roll = 0;              ///< [m] rolling radius
  double N = 0;                   ///< [N] normal force
  double a = 0, b = 0;            ///< [m] semi-axes (grid patches: half length and width)
  double Fx = 0, Fs = 0, Mn = 0;  ///< [N], [N m] creep forces ON THE WHEEL, contact frame (pair's signs)
  Wrench on_wheelset;             ///< this contact's normal and creep forces on the wheelset
};

/// One wheel's answer.
struct WheelResult {
  int side = 0;        ///< +1 left, −1 right
  double tY = 0;       ///< [m] the pair's t_Y: σ y, plus the roll's shift when it enters the geometry (pair_pose)
  double delta = 0;    ///< [rad] the wheel's roll against its rail in its pair's frame, σ φ (0 when not modelled)
  double h = 0;        ///< [m] axle height at which this wheel first touches its rail, at t_Y
  CaseResult r;        ///< the single-pair result (pair frame): status, warnings, ellipses, tangential
  bool judged = false; ///< r has its judge's status and warnings (always, once step() returns)
  std::vector<ContactPoint> contacts;  ///< the loaded contacts in track coordinates
  Wrench on_wheelset;  ///< the wheel's contacts summed
  /// Partial derivatives of on_wheelset.F [N/m, N/rad, N/m or N/N] in y, φ and the vertical input,
  /// the other inputs held (the roll too when it is solved): Position: Z; Loads: that wheel's own
  /// load Q_s, and dF_droll NaN (the roll is an output). In y and φ central differences with the
  /// steps of WheelsetStepOptions (fd_*); in the vertical input analytic where the method gives it
  /// (multi-Hertzian ellipses: dN/dh0 and FASTSIM's load slope; dF_dvertical_analytic), central
  /// differences otherwise. NaN unless asked.
  std::array<double, 3> dF_dy{NAN, NAN, NAN}, dF_droll{NAN, NAN, NAN}, dF_dvertical{NAN, NAN, NAN};
  /// dF_dvertical analytic (true) or by central differences (false, also when not asked).
  bool dF_dvertical_analytic = false;
};

struct WheelsetResult {
  WheelResult left, right;
  double roll = 0;     ///< [rad] the roll: given, solved, or (Loads) from the wheels' approaches
  double Z = NAN;      ///< [m] the axle-centre height (Position: given; Loads: from the approaches)
  Wrench total;        ///< both wheels
  /// The same derivatives of total.F (Loads: dF_dvertical is in Q_left and Q_right together, both
  /// loads moved by the step).
  std::array<double, 3> dF_dy{NAN, NAN, NAN}, dF_droll{NAN, NAN, NAN}, dF_dvertical{NAN, NAN, NAN};
  std::vector<WheelsetWarning> warnings;
  /// Worst of the two wheels' statuses (by is_failure first, then not Ok).
  CaseStatus status = CaseStatus::Ok;
};

/// Options of a step, with their documented defaults.
struct WheelsetStepOptions {
  bool derivatives = false;  ///< compute the dF_d* (2 or 4 more solves of each wheel, 2 more where the vertical one is not analytic)
  /// dF_dvertical analytic where the method gives it (multi-Hertzian ellipses, elastic where
  /// there is friction; WheelResult::dF_dvertical_analytic says which); false: central
  /// differences always (default true).
  bool analytic_vertical = true;
  double fd_y = 1e-5;        ///< [m] central-difference step in y (default 0.01 mm: the tables' step)
  double fd_roll = 1e-5;     ///< [rad] in φ (default 0.01 mrad: 7.5 µm at the taping line)
  double fd_Z = 1e-6;        ///< [m] in Z (default 1 µm)
  double fd_Q = 1e-4;        ///< [-] Loads: in each Q, relative (default 1e-4)
  /// |lead| above this fraction of the contact's semi-axis a: yaw_lead_not_modelled (default 0.1).
  double lead_fraction = 0.1;
  /// [rad] The roll not in the geometry only (roll_in_geometry false): |φ|
  /// above this, roll_in_geometry_neglected (default 1 mrad; against CONTACT a roll 0.1 mrad off
  /// the kinematic one already moves a centred tread contact's Fx by 7.8 % of μN, docs/c-api.md).
  double roll_limit = 1e-3;
  /// [rad] The roll not in the geometry only: a loaded contact steeper than this under a roll |φ| > 0.1 mrad: roll_near_flange
  /// (default 25°). The first-order roll (roll_lever) assumes the contact point stays where the
  /// upright wheel has it; near the flange the roll moves it (S1002 on 60E1 1:40, the roll solved
  /// against geometry/wheelset's exact rotation: within 3 % up to y = 6 mm, γ 21°; at 6.5 mm
  /// (γ 29°) 0.84 against 4.17 mrad: the rolled wheel touches on its flange, γ 68°).
  double roll_flange_gamma = 25 * 3.14159265358979323846 / 180;
};

/// One thread's memory for the steps of one wheelset (the grid methods' and the
/// approach-prescribed solve's buffers): no allocation once it has seen a step as large.
struct WheelsetWorkspace {
  GridWorkspace grid;
  ApproachWorkspace approach;
  WheelResult plus, minus;  ///< the derivatives' perturbed solves
  std::vector<CandidateGeom> cand;  ///< the rolled candidates of first_contact_height
};

/// A wheelset on its track: the two pairs' tables built once (tens of milliseconds), then
/// step() any number of times. Immutable after construction: share it between threads, each with
/// its own WheelsetWorkspace.
class WheelsetContact {
 public:
  /// Throws InputError as build_geometry (a pair that cannot be placed).
  explicit WheelsetContact(const WheelsetSetup& setup);
  /// From the two pairs' geometry already built (the C interface's pairs; the profiles of
  /// setup() are then empty): each geometry's nominal radius and placement, `track`'s flange-back
  /// data, the material and method of both. `warnings`: the pairs' (kept as given).
  /// `roll_in_geometry`: WheelsetSetup::roll_in_geometry.
  WheelsetContact(const ContactGeometry& left, const ContactGeometry& right, const TrackSetup& track,
                  const Material& material, const MethodOptions& method, std::vector<std::string> warnings,
                  bool roll_in_geometry = true);

  const ContactGeometry& geometry(int side) const { return side > 0 ? left_.geo : right_.geo; }
  const WheelsetSetup& setup() const { return setup_; }
  /// [m] |Y| of each rail profile's origin and of each wheel's taping line from the track centre.
  double rail_origin(int side) const { return side > 0 ? left_.c : right_.c; }
  double taping_line(int side) const { return side > 0 ? left_.a : right_.a; }
  /// [m] The axle height at which wheel `side` first touches its rail at its t_Y (linear in the
  /// table); NaN outside the table.
  double first_contact_height(int side, double tY) const;
  /// Whether the roll enters each pair's contact geometry (WheelsetSetup::roll_in_geometry, every
  /// method: the rolled candidates of ContactGeometry::candidates_at(t, δ), the grid methods'
  /// rolled gap); otherwise only the heights, to first order (roll_lever), and the warnings say so.
  bool roll_in_geometry() const { return setup_.roll_in_geometry; }
  /// The pair's pose of wheel `side` for the wheelset at lateral y rolled by φ (method.md §3.8,
  /// eq. 3.8.2): the wheel's roll against its rail δ = σ φ and the t_Y that puts its rolled
  /// profile where the wheelset's rotation about the axle centre puts it,
  /// t_Y = σ y + a (cos δ − 1) + (z0 + R0) sin δ (a: taping line from the centre, z0 + R0: the
  /// axle above the wheel profile's origin). φ = 0: (σ y, 0).
  void pair_pose(int side, double y, double roll, double* tY, double* delta) const;
  /// [m] The axle-centre height at which wheel `side` first touches its rail with the wheelset at
  /// y rolled by φ, from the rolled candidates (roll_in_geometry()); φ = 0 or not modelled:
  /// first_contact_height(side, σ y) − σ φ roll_lever(side, σ y), the first-order rule.
  double first_contact_height(int side, double y, double roll, WheelsetWorkspace& ws) const;
  /// [m] The lever L_s of the roll on wheel `side`'s first-contact height at its t_Y: rolling the
  /// wheelset by φ lowers that height by σ φ L_s to first order, L_s = a + y_w − r tan γ of the
  /// main contact (y_w, r, γ from the table; the rotated profile's contact point moves, hence the
  /// r tan γ: at a 60° flange it exceeds a). a outside the table.
  double roll_lever(int side, double tY) const;
  /// [m] The same lever of the rolled wheel (roll_in_geometry()): −σ dh_s/dφ of eq. 3.8.2 at the
  /// wheelset's y and roll φ, from the rolled main candidate (method.md §3.8); the slope of the
  /// roll's root search. roll_lever(side, σ y) where the roll does not enter the geometry.
  double roll_lever(int side, double y, double roll, WheelsetWorkspace& ws) const;
  /// The pairs' warnings (placement), "<profile>: <warning>".
  const std::vector<std::string>& warnings() const { return warnings_; }

  /// One step into `out` (its vectors keep their capacity: no allocation once they have grown,
  /// multi-Hertzian). Never throws for a numerical reason (the statuses say it); std::invalid_argument
  /// for an input out of its range (a negative load, V <= 0 with friction, a non-finite value).
  void step(const WheelsetPose& pose, const WheelsetStepOptions& opt, WheelsetResult& out,
            WheelsetWorkspace& ws) const;

 private:
  struct Side {
    int sigma = 1;
    ContactGeometry geo;
    double a = 0, c = 0, R0 = 0;
  };
  WheelsetSetup setup_;
  Side left_, right_;
  std::vector<std::string> warnings_;

  void place(Side& S, int sigma);
  /// Both geometries' rolled minima, built by the first rolled step (RolledMinimaOnDemand), when
  /// the roll enters the geometry.
  void tabulate_rolled_minima();

  /// One wheel at t_Y = σ y with its load (Loads) or its δz (Position), into w (no derivatives),
  /// not judged where the method leaves the judge to its caller (w.judged false): the roll's search
  /// and the derivatives solve whole wheels many times and keep one, judged by judge_wheel.
  void solve_wheel(const Side& S, const WheelsetPose& pose, double roll, WheelResult& w, WheelsetWorkspace& ws) const;
  /// The options of w's solve (the setup's, with w's roll and the pose's kinematics in S's frame).
  MethodOptions wheel_options(const Side& S, const WheelsetPose& pose, const WheelResult& w) const;
  /// The judge (judge_case) on w's answer, once, if solve_wheel left it.
  void judge_wheel(const Side& S, const WheelsetPose& pose, WheelResult& w) const;
  /// Both wheels and the totals (no derivatives); the roll of Position as given or solved.
  void solve_both(const WheelsetPose& pose, const WheelsetStepOptions& opt, WheelsetResult& out,
                  WheelsetWorkspace& ws) const;
  /// out's derivatives after solve_both (NaN and the analytic flags false unless opt.derivatives;
  /// wheelset_derivatives.cpp).
  void add_derivatives(const WheelsetPose& pose, const WheelsetStepOptions& opt, WheelsetResult& out,
                       WheelsetWorkspace& ws) const;
};

}  // namespace mh
