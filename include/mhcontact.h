/* mhcontact.h — the C interface of mhcontact: wheel–rail normal contact by the multi-Hertzian
 * method (Sebès et al., Wear 314 (2014) 118–124), the elastic half-space and the strip method,
 * callable from a vehicle-dynamics simulation at every time step. C99; usable from C++.
 *
 * Units: SI everywhere (m, N, Pa, rad); every field names its unit in its suffix (_m, _N, _Pa,
 * _rad, _m2, _per_m, _N_per_m). Frames and signs are those of the command (docs/method.md §1):
 * y lateral towards the field side, z up; t_Y the lateral displacement of the wheel on the rail.
 *
 * Objects (docs/c-api.md):
 *   mhc_profile    a wheel or rail profile (file, points or standard name); immutable.
 *   mhc_pair       a wheel–rail pair: profiles placed by the track data, geometry tables and
 *                  potential ellipses built once, material, model and method; immutable.
 *   mhc_workspace  the scratch memory of one thread's calls on one pair.
 * Immutable objects may be shared by any number of threads; a workspace belongs to one thread
 * at a time. There is no global state: the only per-thread state is the last message
 * (mhc_last_message).
 *
 * Errors: every function returning mhc_error returns MHC_OK or an error code and never lets an
 * exception or a signal cross the interface; the message of the thread's last error (same wording
 * as the command's) is mhc_last_message(). A case that was solved but did not end `ok` (no
 * contact, t_Y outside the tables, not converged) is not an error: the result's status says it.
 */
#ifndef MHCONTACT_H
#define MHCONTACT_H

#include <stddef.h>
#include <stdint.h>

#if defined(_WIN32)
#define MHC_API __declspec(dllimport)
#elif defined(__GNUC__)
#define MHC_API __attribute__((visibility("default")))
#else
#define MHC_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/** The ABI this header describes: incremented on any incompatible change of a struct or a
 *  function. Compare with mhc_abi_version() at run time. */
#define MHC_ABI_VERSION 1

/** Contact slots of a result: the loaded ellipses (multi-Hertzian) or patches (grid methods) of
 *  one case, in increasing rail y. More contacts than this set MHC_WARN_TRUNCATED. */
#define MHC_MAX_CONTACTS 6

typedef enum mhc_error {
  MHC_OK = 0,
  MHC_ERR_ARGUMENT = 1,    /**< a null pointer, a wrong struct_size, a value out of its range
                                (the plausible ranges of the case file: E, nu, p_lim, yield
                                stress, nominal radius, load; the message names the field, the
                                value, the rule and the unit: docs/c-api.md "Errors") */
  MHC_ERR_INPUT = 2,       /**< unreadable or invalid input data (profile file, points, case file,
                                a pair that cannot be placed): the command's exit code 2 */
  MHC_ERR_UNSUPPORTED = 3, /**< a valid request this pair cannot honour: a relative roll, an
                                approach-prescribed solve with a grid method */
  MHC_ERR_MEMORY = 4,      /**< out of memory */
  MHC_ERR_INTERNAL = 5     /**< a bug: please report with the message */
} mhc_error;

/** The outcome of one case: the `status` column of cases.csv. */
typedef enum mhc_status {
  MHC_STATUS_OK = 0,
  MHC_STATUS_NO_CONTACT = 1,    /**< no force: Q = 0, or the wheel lifted (approach below first
                                     contact) */
  MHC_STATUS_OUT_OF_RANGE = 2,  /**< t_Y outside the pair's geometry table */
  MHC_STATUS_NOT_CONVERGED = 3, /**< the equilibrium was not reached; the fields hold the last iterate.
                                     Also a conformal contact the multi-Hertzian method cannot solve
                                     (every candidate with B <= 0): no force computed, the message
                                     says so (solve it with MHC_METHOD_AUTO, _STRIPS or _HALF_SPACE) */
  MHC_STATUS_OUTSIDE_VALIDITY = 4, /**< solved, but outside the method's validity (a warning says
                                       why: MHC_WARN_* bits); an answer, not to be trusted */
  MHC_STATUS_DERAILED = 5 /**< solved, but the wheel rides on its flange tip, off the rail (the
                               `derailed` warning, docs/status.md); an answer, never `ok` */
} mhc_status;

typedef enum mhc_kind { MHC_WHEEL = 1, MHC_RAIL = 2 } mhc_kind;

typedef enum mhc_method {
  MHC_METHOD_MULTI_HERTZIAN = 0, /**< the paper's method: microseconds per case */
  MHC_METHOD_HALF_SPACE = 1,     /**< exact elastic half-space on a grid (milliseconds) */
  MHC_METHOD_STRIPS = 2,         /**< strip method (sub-millisecond to milliseconds) */
  MHC_METHOD_AUTO = 3            /**< multi-Hertzian where its Hertz checks pass, strips elsewhere */
} mhc_method;

/** Case warnings (bits of mhc_result.warnings): the `warnings` column of cases.csv by kind. */
#define MHC_WARN_FLANGE_CLIMB 0x1u          /**< the contact has passed the steepest flange point */
#define MHC_WARN_NON_HERTZIAN 0x2u          /**< a loaded ellipse fails a Hertz assumption */
#define MHC_WARN_NON_HERTZIAN_EXCLUDED 0x4u /**< a conformal candidate (B <= 0) would have touched */
#define MHC_WARN_OFF_PROFILE 0x8u           /**< a loaded contact lies off the end of a profile */
#define MHC_WARN_TRUNCATED 0x10u            /**< more than MHC_MAX_CONTACTS contacts: the rest omitted */
#define MHC_WARN_OTHER 0x20u                /**< any other warning (the text: mhc_last_message) */
#define MHC_WARN_INTERACTING 0x40u          /**< two loaded ellipses closer than d_comb: they interact */
#define MHC_WARN_PRESSURE_SPIKE 0x80u       /**< a grid patch's peak stands on a single element */
#define MHC_WARN_STRIP_OUTLIER 0x100u       /**< a strip's peak stands far above its neighbours' */

/** Per-contact flags (mhc_contact.flags). */
#define MHC_CONTACT_PLASTIC 0x1u      /**< beyond the elastic range of its plastic law: the Hertz
                                           peak above p_lim (capped law), above first yield
                                           1.6 sigma_y (yield law), or capped elements (grid) */
#define MHC_CONTACT_NON_HERTZIAN 0x2u /**< fails a Hertz assumption (docs/method.md §4) */
#define MHC_CONTACT_OFF_PROFILE 0x4u  /**< lies off the end of a profile (docs/method.md §3.7) */

/** One contact of a case: a loaded ellipse (multi-Hertzian) or a contact patch (grid methods). */
typedef struct mhc_contact {
  int32_t index;          /**< 1-based: the potential ellipse, or the patch in increasing rail y */
  uint32_t flags;         /**< MHC_CONTACT_* bits */
  double y_rail_m;        /**< contact point on the rail profile, lateral (rail frame, with the cant) */
  double z_rail_m;        /**< ... its height on the rail profile */
  double y_wheel_m;       /**< facing point on the wheel profile (wheel frame, 0 at the taping line) */
  double z_wheel_m;       /**< ... its height on the wheel profile (NaN for grid patches) */
  double gamma_rad;       /**< contact angle */
  double r_roll_m;        /**< wheel rolling radius at y_wheel */
  double N_N;             /**< normal force */
  double Fz_N;            /**< its vertical component N cos(gamma) */
  double Fy_N;            /**< its lateral component N sin(gamma), towards the field side */
  double a_m;             /**< semi-axis along x, rolling direction (grid: half the contact length) */
  double b_m;             /**< semi-axis across, in the contact plane (grid: half the width) */
  double A_per_m;         /**< curvature sum along x (eq. 1); NaN for grid patches */
  double B_per_m;         /**< curvature sum across (eq. 1); NaN for grid patches */
  double p_max_Pa;        /**< largest pressure carried (capped at p_lim in the plastic model) */
  double area_m2;         /**< contact area (pi a b for an ellipse) */
  double h0_m;            /**< virtual penetration of eq. 6 (h0 = b^2 B); NaN for grid patches */
  double approach_m;      /**< true normal approach of the contact (delta of Hertz) */
  double dN_ddz_N_per_m;  /**< dN/d(dz): this contact's normal-force derivative in the wheel's
                               vertical approach dz at fixed t_Y; NaN for grid patches */
} mhc_contact;

/** The result of one case. Caller-owned: set struct_size = sizeof(mhc_result) before a call. */
typedef struct mhc_result {
  size_t struct_size;        /**< set by the caller: sizeof(mhc_result) */
  int32_t status;            /**< mhc_status */
  int32_t method;            /**< mhc_method that solved it (never AUTO) */
  int32_t n_contacts;        /**< contacts (may exceed MHC_MAX_CONTACTS: see MHC_WARN_TRUNCATED) */
  int32_t iterations;        /**< solver iterations */
  uint32_t warnings;         /**< MHC_WARN_* bits */
  int32_t n_warnings;        /**< number of warnings (the n_warnings column of cases.csv) */
  double tY_m;               /**< the lateral displacement solved for */
  double Q_N;                /**< the vertical load prescribed, or the one carried (approach given) */
  double dz_m;               /**< vertical virtual penetration of eq. 11 (0 at first contact);
                                  the approach given, for approach-prescribed solves */
  double approach_m;         /**< rigid vertical approach of the wheel from first contact */
  double residual;           /**< (sum N cos(gamma) - Q) / Q at the end (0 when approach given) */
  double Fz_N;               /**< total vertical force, sum N cos(gamma) */
  double Fy_N;               /**< total lateral force, sum N sin(gamma) */
  double p_max_Pa;           /**< largest contact pressure of the case */
  double area_m2;            /**< total contact area */
  double gamma_main_rad;     /**< contact angle of the contact carrying the largest N (NaN: none) */
  double r_roll_main_m;      /**< rolling radius there (NaN: none) */
  double dFz_ddz_N_per_m;    /**< vertical contact stiffness dFz/d(dz) at fixed t_Y, for implicit
                                  integrators (multi-Hertzian; NaN for the grid methods) */
  int32_t plastic;           /**< 1 when a contact has MHC_CONTACT_PLASTIC (the plastic column of
                                  cases.csv) */
  int32_t reserved;
  mhc_contact contact[MHC_MAX_CONTACTS];  /**< the first min(n_contacts, MHC_MAX_CONTACTS) */
} mhc_result;

/** What a pair is built from besides its two profiles. mhc_pair_options_init fills the defaults
 *  of the command's case file (README "Case file") and struct_size. Fields are only ever
 *  appended; mhc_pair_create accepts the struct_size of every earlier version of this struct. */
typedef struct mhc_pair_options {
  size_t struct_size;             /**< sizeof(mhc_pair_options), set by mhc_pair_options_init */
  /* track and wheelset (docs/method.md §7) */
  double gauge_m;                 /**< track gauge (default 1.435) */
  double gauge_height_m;          /**< gauge measured this far below the top of rail (default 0.014) */
  double flange_back_distance_m;  /**< wheelset flange-back distance (default 1.360) */
  double flange_back_position_m;  /**< y of the flange back on the wheel profile (default -0.070) */
  double nominal_radius_m;        /**< wheel radius at the taping line (default 0.460) */
  double rail_inclination;        /**< cant 1:N applied to the rail profile, N (e.g. 40); 0: the
                                       profile is used as given (default 0) */
  /* material: wheel, and rail (NaN: the wheel's) */
  double E_wheel_Pa;              /**< Young's modulus (default 210e9) */
  double nu_wheel;                /**< Poisson's ratio (default 0.28) */
  double E_rail_Pa;               /**< default NaN: as the wheel */
  double nu_rail;                 /**< default NaN: as the wheel */
  double p_lim_Pa;                /**< limit pressure of the plastic model, the law capped at it;
                                       INFINITY (default): elastic, or the yield law when
                                       yield_wheel_Pa is given */
  int32_t method;                 /**< mhc_method (default MHC_METHOD_MULTI_HERTZIAN) */
  int32_t reserved;
  /* the geometry table: t_Y range and step */
  double tY_min_m;                /**< default -0.010 */
  double tY_max_m;                /**< default +0.012 */
  double tY_step_m;               /**< default 1e-5 */
  /* the grid methods' element size */
  double grid_dx_m;               /**< default 0.2e-3 */
  double grid_ds_m;               /**< default 0.2e-3 */
  /* Appended after the first release: a caller compiled against a header without them passes
     struct_size = offsetof(mhc_pair_options, yield_wheel_Pa) and gets them as not given.
     The yield stress, as the case file's material.yield_MPa (docs/method.md §5.1): with p_lim_Pa
     INFINITY, a yield stress makes the pair plastic with the yield law of the multi-Hertzian
     ellipse (Hertz up to first yield 1.6 sigma_y, slope 0.3 above), and the grid methods cap the
     pressure at p_lim = 2.1 sigma_y, sigma_y of the softer body; with p_lim_Pa finite the law is
     capped at p_lim_Pa and the yield stress only kept. NaN, or > 0 and finite. */
  double yield_wheel_Pa;          /**< the wheel's yield stress sigma_y (default NaN: not given) */
  double yield_rail_Pa;           /**< the rail's (default NaN: as the wheel's; given alone: an error) */
  /* Appended with explicit positioning: a caller compiled against a header without them passes
     struct_size = offsetof(mhc_pair_options, positioning) and gets gauge positioning. As the case
     file's track.positioning and track.lateral_offset_mm (docs/case-file.md): */
  int32_t positioning;            /**< MHC_POSITIONING_GAUGE (default): the wheel placed from the
                                       rail's gauge point and the wheelset data above, and the
                                       placement checked (docs/profiles.md "Placement check");
                                       MHC_POSITIONING_EXPLICIT: at lateral_offset_m, not checked */
  int32_t reserved2;
  double lateral_offset_m;        /**< explicit: the rail y of the wheel profile's origin (its taping
                                       line) at t_Y = 0, within +-0.2 m (default 0; must stay 0 with
                                       gauge positioning). A refused gauge placement names the value
                                       that reproduces it (the message's lateral_offset_mm / 1000). */
} mhc_pair_options;

/** mhc_pair_options.positioning */
#define MHC_POSITIONING_GAUGE 0
#define MHC_POSITIONING_EXPLICIT 1

typedef struct mhc_profile mhc_profile;
typedef struct mhc_pair mhc_pair;
typedef struct mhc_workspace mhc_workspace;

/* ---- version ---------------------------------------------------------------------------- */

/** "0.2.0" */
MHC_API const char* mhc_version(void);
/** MHC_ABI_VERSION of the library (compare with the header's). */
MHC_API int32_t mhc_abi_version(void);
/** "pocketfft" or "fftw3": the FFT the half-space method uses in this build (docs/embedding.md). */
MHC_API const char* mhc_fft_backend(void);

/* ---- errors ----------------------------------------------------------------------------- */

/** The thread's last message: the error of its last failed call, or the message of its last case
 *  whose status is not ok; "" if none. Valid until the thread's next call. */
MHC_API const char* mhc_last_message(void);
/** "ok", "argument", "input", "unsupported", "memory", "internal". */
MHC_API const char* mhc_error_name(mhc_error e);
/** "ok", "no_contact", "out_of_range", "not_converged" (the cases.csv words). */
MHC_API const char* mhc_status_name(int32_t status);

/* ---- profiles ------------------------------------------------------------------------------ */

/** Read a profile file in any format the command reads (SIMPACK .prr/.prw, MiniProf .ban/.whl,
 *  VAMPIRE .whe/.rai, tables .csv/.txt/.dat; by extension, else by content), with the command's
 *  clean-up and plausibility checks. kind: MHC_WHEEL or MHC_RAIL. */
MHC_API mhc_error mhc_profile_read(const char* path, int32_t kind, mhc_profile** out);
/** A profile from n points (y_m[i], z_m[i]) in the canonical frame (y to the field side, z up;
 *  a wheel's flange at negative y, its taping line at y = 0), with the same checks as a file. */
MHC_API mhc_error mhc_profile_from_points(const double* y_m, const double* z_m, size_t n, int32_t kind,
                                          mhc_profile** out);
/** A standard profile: "S1002" (wheel), "60E1", "54E1" (rails), generated with 0.1 mm nodes. */
MHC_API mhc_error mhc_profile_standard(const char* name, mhc_profile** out);
/** Points of a profile as used (after clean-up): n, and if y_m / z_m are non-null, up to
 *  capacity values each. */
MHC_API mhc_error mhc_profile_points(const mhc_profile* p, size_t* n, double* y_m, double* z_m, size_t capacity);
MHC_API void mhc_profile_free(mhc_profile* p);

/* ---- pairs ------------------------------------------------------------------------------- */

MHC_API void mhc_pair_options_init(mhc_pair_options* opt);
/** Build a pair (tens of milliseconds: the geometry tables). The profiles are copied: they may be
 *  freed afterwards. */
MHC_API mhc_error mhc_pair_create(const mhc_profile* wheel, const mhc_profile* rail, const mhc_pair_options* opt,
                                  mhc_pair** out);
/** Build the pair of a case file exactly as `mhcontact run` does (profiles, track, geometry,
 *  material, model, method and every option; its sweep is ignored). */
MHC_API mhc_error mhc_pair_from_case_file(const char* path, mhc_pair** out);
/** The t_Y range of the pair's geometry table [m]. */
MHC_API mhc_error mhc_pair_tY_range(const mhc_pair* pair, double* tY_min_m, double* tY_max_m);
/** The pair's warnings, as the command prints them after "mhcontact: warning: " (each starts with
 *  the profile it concerns): the profiles' clean-up and kind, the rail's cant (applied twice,
 *  mirrored: docs/profiles.md "Cant checks"), the placement (a wheel without a flange placed by the
 *  gauge rule). A pair with warnings is built; they are the caller's to show. */
MHC_API int32_t mhc_pair_n_warnings(const mhc_pair* pair);
/** Warning i (0-based) of the pair; NULL when i is out of range. Valid while the pair lives. */
MHC_API const char* mhc_pair_warning(const mhc_pair* pair, int32_t i);
/** Potential ellipses of the pair (docs/method.md §3.5). */
MHC_API int32_t mhc_pair_n_ellipses(const mhc_pair* pair);
MHC_API void mhc_pair_free(mhc_pair* pair);

/* ---- solving ------------------------------------------------------------------------------- */

/** Scratch memory for one thread's calls on `pair` (which must outlive it). */
MHC_API mhc_error mhc_workspace_create(const mhc_pair* pair, mhc_workspace** out);
MHC_API void mhc_workspace_free(mhc_workspace* ws);

/** One case with the vertical load prescribed (eq. 10): the wheel at lateral displacement tY_m
 *  and relative roll roll_rad (only 0 is supported: MHC_ERR_UNSUPPORTED otherwise), carrying
 *  Q_N. Fills *out (out->struct_size must be set). Any method. Q_N = 0: no_contact (a wheel
 *  lifted); Q_N negative, not finite, or above the plausible range (2000 kN: docs/case-file.md
 *  "Plausible ranges"): MHC_ERR_ARGUMENT, the message naming the value and the rule. */
MHC_API mhc_error mhc_solve_load(const mhc_pair* pair, mhc_workspace* ws, double tY_m, double roll_rad, double Q_N,
                                 mhc_result* out);
/** One case with the vertical approach prescribed: the penetration-driven force element. dz_m is
 *  the vertical virtual penetration of eq. 11 (0 at first contact; mhc_result.dz_m of a
 *  load-prescribed solve gives back its load). Multi-Hertzian pairs only (MHC_ERR_UNSUPPORTED
 *  otherwise). dz_m <= 0: status no_contact, zero forces. */
MHC_API mhc_error mhc_solve_approach(const mhc_pair* pair, mhc_workspace* ws, double tY_m, double roll_rad,
                                     double dz_m, mhc_result* out);

typedef enum mhc_prescribe { MHC_PRESCRIBE_LOAD = 0, MHC_PRESCRIBE_APPROACH = 1 } mhc_prescribe;

/** n cases at once: tY_m[i], roll_rad[i] (roll_rad may be NULL: 0) and value[i] (Q_N or dz_m
 *  by `prescribe`), into out[i] — an array of n results of result_size bytes each
 *  (sizeof(mhc_result)). n_threads: 0 = all cores. Results do not depend on the thread count.
 *  Returns the first argument error; a case that is not ok is not an error. */
MHC_API mhc_error mhc_solve_many(const mhc_pair* pair, int32_t prescribe, size_t n, const double* tY_m,
                                 const double* roll_rad, const double* value, mhc_result* out, size_t result_size,
                                 int32_t n_threads);


/* ---- warnings of the last case --------------------------------------------------------------- */

/** One warning of a case as data (docs/status.md, docs/c-api.md): the same as the `warnings`
 *  column of cases.csv, whose text mhc_warning_text gives. Measures are in SI (`unit`: "1", "m",
 *  "Pa" or "count"); `name` is the quantity's name in the text, which carries the text's unit
 *  ("edge_gap_mm": the text is in mm, value_si in m). */
#define MHC_WARNING_MAX_MEASURES 6
typedef struct mhc_warning_measure {
  const char* name;    /**< "b_over_R", "gap_kink", "edge_gap_mm", ... (static storage) */
  const char* unit;    /**< SI unit of value_si and limit_si: "1", "m", "Pa", "count" */
  double value_si;     /**< the measured value */
  double limit_si;     /**< the limit it crossed (meaningless when relation is 0) */
  int32_t relation;    /**< '>' value above the limit, '<' below, 0 no limit */
  int32_t reserved;
} mhc_warning_measure;
typedef struct mhc_warning {
  size_t struct_size;       /**< set by the caller: sizeof(mhc_warning) */
  const char* class_name;   /**< "non_hertzian", "interacting", "auto", ... (static storage) */
  int32_t outside_validity; /**< 1 when this class puts a row outside validity, 0 informational */
  int32_t contact_kind;     /**< 0 the case, 1 a loaded ellipse, 2 a grid patch, 3 a pair of ellipses */
  int32_t contact;          /**< 1-based ellipse or patch index (0: the case) */
  int32_t contact2;         /**< the second ellipse of a pair (contact_kind 3) */
  int32_t n_measures;
  int32_t reserved;
  mhc_warning_measure measure[MHC_WARNING_MAX_MEASURES];
} mhc_warning;

/** Number of warnings of the last case solved with `ws` (mhc_solve_load, mhc_solve_approach;
 *  mhc_result.n_warnings of that case), 0 before any. */
MHC_API int32_t mhc_result_n_warnings(const mhc_workspace* ws);
/** Warning i (0-based) of the last case solved with `ws`, as data into *out (out->struct_size
 *  must be set). MHC_ERR_ARGUMENT when i is out of range. */
MHC_API mhc_error mhc_result_warning(const mhc_workspace* ws, int32_t i, mhc_warning* out);
/** Warning i of the last case solved with `ws` as written in cases.csv
 *  ("non_hertzian:ellipse=3:gap_kink=2.4>0.1"); "" when i is out of range. Valid until the
 *  thread's next call of this function. */
MHC_API const char* mhc_warning_text(const mhc_workspace* ws, int32_t i);

/* ---- RCF, damage and wear of the last case's contacts (lib/capi/rcf.cpp) ---------------------- */

/** The RCF indicators, damage and wear of one contact of the last case solved with a workspace
 *  (docs/methods.md "RCF indicators", "Damage and wear functions", "Subsurface stresses"): the
 *  same values as the RCF, damage and wear columns of ellipses.csv and patches.csv with the
 *  functions' published default constants. NaN where not defined (no friction: no creep forces). */
typedef struct mhc_rcf_contact {
  size_t struct_size;         /**< set by the caller: sizeof(mhc_rcf_contact) */
  double N_N;                 /**< normal force of the contact */
  double traction;            /**< |F|/N from its creep forces (NaN without friction) */
  double Tgamma_N;            /**< Tγ = Fx ξ + Fy η [N = J/m], forces on the rail */
  double Tgamma_spin_N;       /**< the spin term Mz φ [N] */
  double damage_per_axle;     /**< Burstow's Whole Life Rail Model damage per axle passage */
  double wear_rate_kg_per_m3; /**< USFD wear rate: mass per metre rolled per unit contact area */
  double wear_kg_per_m;       /**< mass worn per metre rolled */
  double p0_el_Pa;            /**< elastic Hertz peak pressure of N on the contact's elastic ellipse */
  double p0_el_over_k;        /**< p0_el / k (NaN without k) */
  double elastic_limit;       /**< first-yield limit of p0/k at this traction and aspect ratio */
  double shakedown_limit;     /**< elastic shakedown limit of p0/k */
  double FI_surf_el;          /**< surface fatigue index f − k/p0_el */
  int32_t shakedown_regime;   /**< 0 elastic, 1 elastic shakedown, 2 plastic shakedown, 3 ratchetting, -1 unknown */
  int32_t reserved;
} mhc_rcf_contact;

/** Contact i (0-based: the loaded ellipses, or the grid patches, in increasing rail y) of the last
 *  case solved with `ws`, with shear yield k_Pa (NaN: σ_y/√3 of the pair's material, NaN if it has
 *  none), into *out (out->struct_size must be set). MHC_ERR_ARGUMENT when i is out of range. */
MHC_API mhc_error mhc_result_rcf(const mhc_workspace* ws, int32_t i, double k_Pa, mhc_rcf_contact* out);

/** The peaks of the elastic stress field below a Hertzian ellipse (semi-axes a_m along x, the
 *  rolling direction, and b_m; peak pressure p0_Pa) with full-slip traction (fx, fy) p, Poisson's
 *  ratio nu (docs/methods.md "Subsurface stresses"; about 0.5 s). */
typedef struct mhc_subsurface {
  size_t struct_size;          /**< set by the caller: sizeof(mhc_subsurface) */
  double vm_max_Pa, vm_depth_m;            /**< largest von Mises stress, its depth */
  double tau_max_Pa, tau_depth_m;          /**< largest principal shear stress, its depth */
  double tau_orth_amp_Pa, tau_orth_depth_m; /**< orthogonal shear amplitude over a pass, its depth */
  double tau_eq_amp_Pa, sigma_h_Pa;        /**< equivalent shear amplitude and hydrostatic stress (FI_sub) */
} mhc_subsurface;
MHC_API mhc_error mhc_hertz_subsurface(double a_m, double b_m, double p0_Pa, double fx, double fy, double nu,
                                       mhc_subsurface* out);

#ifdef __cplusplus
}
#endif

#endif /* MHCONTACT_H */
