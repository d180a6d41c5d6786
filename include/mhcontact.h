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

/* The export macro: on Windows dllexport while building the DLL (MHC_BUILDING, set by the build),
 * dllimport when using it, nothing for a static library (MHC_STATIC); elsewhere the default
 * visibility (the library hides everything else). */
#if defined(_WIN32)
#if defined(MHC_STATIC)
#define MHC_API
#elif defined(MHC_BUILDING)
#define MHC_API __declspec(dllexport)
#else
#define MHC_API __declspec(dllimport)
#endif
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
  MHC_ERR_UNSUPPORTED = 3, /**< a valid request this pair cannot honour: an approach-prescribed
                                solve with a grid method */
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
 *  and relative roll roll_rad (the wheel rolled against the rail about x, pair frame, positive
 *  raising its field side; docs/method.md section 3 item 8: every method, the grid methods' gap
 *  that of the rolled wheel; |roll_rad| <= 0.05, else MHC_ERR_ARGUMENT), carrying
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
 *  "Pa", "rad" or "count"); `name` is the quantity's name in the text, which carries the text's unit
 *  ("edge_gap_mm": the text is in mm, value_si in m). */
#define MHC_WARNING_MAX_MEASURES 6
typedef struct mhc_warning_measure {
  const char* name;    /**< "b_over_R", "gap_kink", "edge_gap_mm", ... (static storage) */
  const char* unit;    /**< SI unit of value_si and limit_si: "1", "m", "Pa", "rad", "count" */
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
/** mhc_solve_many with each case's warnings as data: the first min(out[i].n_warnings, per_case)
 *  warnings of case i into warnings[i * per_case + k] (k = 0 ...), each of warning_size bytes
 *  (sizeof(mhc_warning); the struct_size of each is set by the call). A case with more than
 *  per_case warnings keeps its count in out[i].n_warnings; the rest are not written (a case has
 *  at most one warning per class and contact: 8 per case is ample for one or two contacts).
 *  per_case = 0 or warnings = NULL: as mhc_solve_many. */
MHC_API mhc_error mhc_solve_many_warnings(const mhc_pair* pair, int32_t prescribe, size_t n, const double* tY_m,
                                          const double* roll_rad, const double* value, mhc_result* out,
                                          size_t result_size, mhc_warning* warnings, size_t warning_size,
                                          size_t per_case, int32_t n_threads);
/** Warning i of the last case solved with `ws` as written in cases.csv
 *  ("non_hertzian:ellipse=3:gap_kink=2.4>0.1"); "" when i is out of range. Valid until the
 *  thread's next call of this function. */
MHC_API const char* mhc_warning_text(const mhc_workspace* ws, int32_t i);

/* ---- the smoothing's uncertainty band (interface version 4) ------------------------------------ */

/** The smoothing's uncertainty band of the last case solved with a workspace (docs/profiles.md
 *  "Smoothing for contact", "Uncertainty band"; the columns pmax_half_L_MPa, pmax_double_L_MPa,
 *  area_half_L_mm2, area_double_L_mm2 of cases.csv): the case solved again, by the method that
 *  solved it, with every contact smoothing length of the pair halved and doubled (for a
 *  multi-Hertzian row the wide window fit of its curvature tables). NaN where not computed: no
 *  profile of the pair smoothed for contact (exact profiles), the band turned off
 *  (mhc_pair_set_smoothing_band), an approach-prescribed solve, a case without an answer. A row whose
 *  peak pressure moves by more than 10 % or whose area by more than 15 % carries the
 *  informational warning smoothing_sensitive (mhc_result_warning). */
typedef struct mhc_smoothing_band {
  size_t struct_size;        /**< set by the caller: sizeof(mhc_smoothing_band) */
  double p_max_half_L_Pa;    /**< largest pressure with every smoothing length halved */
  double p_max_double_L_Pa;  /**< ... doubled */
  double area_half_L_m2;     /**< contact area, lengths halved */
  double area_double_L_m2;   /**< ... doubled */
} mhc_smoothing_band;

/** The band of the last case solved with `ws` into *out (out->struct_size must be set). */
MHC_API mhc_error mhc_result_smoothing_band(const mhc_workspace* ws, mhc_smoothing_band* out);

/** Whether the pair's load-prescribed solves compute the band: on = 1 (the default of a pair with
 *  a profile smoothed for contact, as the case file's geometry.smoothing_band), 0 off. Each case
 *  costs three solves with it: a caller that solves at every time step and does not read it turns
 *  it off. Building it costs two more geometry tables (four for MHC_METHOD_AUTO, whose ellipse and
 *  grid rows each have theirs), each about as long as the pair's own. Nothing happens for a pair
 *  without a smoothed profile. Not while another thread solves with the pair. */
MHC_API mhc_error mhc_pair_set_smoothing_band(mhc_pair* pair, int32_t on);

/* ---- contact tables (docs/tables.md) ------------------------------------------------------------
 * A table made by `mhcontact table` (a grid method at every node of a t_Y x Q grid, and of the
 * wheel's roll when its case gives roll nodes; contacts matched across nodes into tracks) read
 * once and interpolated: bicubic (tricubic with a roll axis) Hermite with continuous values and
 * first derivatives in t_Y, Q and the roll; a contact appearing or disappearing between nodes
 * fades in from N = 0 (no step). Lookups allocate nothing; a table may be shared by any number
 * of threads. */
typedef struct mhc_table mhc_table;

/** One contact of a lookup (and, in d_dtY / d_dQ / d_droll, its derivatives, same fields). */
typedef struct mhc_table_contact {
  int32_t track;          /**< 1-based contact track of the table (the CSV's `contact`) */
  int32_t reserved;
  double N_N;             /**< normal force */
  double y_rail_m;        /**< contact reference point on the rail, lateral */
  double z_rail_m;        /**< its height on the rail profile */
  double y_wheel_m;       /**< facing wheel-profile point */
  double gamma_rad;       /**< contact angle */
  double r_roll_m;        /**< wheel rolling radius */
  double p_max_Pa;        /**< peak pressure */
  double area_m2;         /**< contact area */
  double a_m;             /**< half the contact length along x */
  double b_m;             /**< half the contact width across */
  double a_el_m;          /**< equivalent ellipse semi-axis along x (for the tangential method) */
  double b_el_m;          /**< ... across */
  double C11;             /**< Kalker's creepage coefficients at a_el/b_el */
  double C22;
  double C23;
} mhc_table_contact;

/** The answer at one (t_Y, Q, roll). Caller-owned: set struct_size = sizeof(mhc_table_result)
 *  (a caller built with the layout before the roll fields, ending at d_dQ, gets those filled). */
typedef struct mhc_table_result {
  size_t struct_size;
  int32_t status;       /**< mhc_status: the worst of the cell's nodes (out_of_range outside the
                             table); outside_validity in a cell that missed its tolerance (coarse),
                             and for a table without a roll axis asked at another roll (off_roll) */
  int32_t n_contacts;   /**< contacts with N > 0 (the first MHC_MAX_CONTACTS are filled) */
  int32_t coarse;       /**< 1: the cell missed the table's interpolation tolerance */
  int32_t reserved;
  double tY_m;
  double Q_N;
  double Fz_N;          /**< sum N cos(gamma) */
  double Fy_N;          /**< sum N sin(gamma), towards the field side */
  double dFy_dtY_N_per_m;
  double dFy_dQ;        /**< [-] */
  mhc_table_contact contact[MHC_MAX_CONTACTS];
  mhc_table_contact d_dtY[MHC_MAX_CONTACTS];  /**< d/dt_Y of each field of contact[k], per metre */
  mhc_table_contact d_dQ[MHC_MAX_CONTACTS];   /**< d/dQ of each field of contact[k], per newton */
  /* The roll (tables of schema mhcontact.table/2): */
  double roll_rad;             /**< the wheel's roll against the rail asked (method.md section 3.8) */
  double dFy_droll_N_per_rad;  /**< 0 for a table without a roll axis */
  int32_t off_roll;            /**< 1: a table without a roll axis asked at another roll than its own */
  int32_t reserved2;
  mhc_table_contact d_droll[MHC_MAX_CONTACTS];  /**< d/droll of each field of contact[k], per radian */
} mhc_table_result;

/** Read a table file (MHC_ERR_INPUT with the file, line and rule when it is not one). */
MHC_API mhc_error mhc_table_read(const char* path, mhc_table** out);
/** Node ranges of the table [m], [N]; any pointer may be NULL. */
MHC_API mhc_error mhc_table_range(const mhc_table* t, double* tY_min_m, double* tY_max_m, double* Q_min_N,
                                  double* Q_max_N);
/** Roll nodes of the table [rad]: the range and their count (1: no roll axis, the table made at
 *  roll_min = roll_max); any pointer may be NULL. */
MHC_API mhc_error mhc_table_roll_range(const mhc_table* t, double* roll_min_rad, double* roll_max_rad,
                                       int32_t* roll_nodes);
/** The table's JSON header (profiles with checksums, method, ranges, units, measured error);
 *  valid while the table lives. NULL for a null table. */
MHC_API const char* mhc_table_header(const mhc_table* t);
/** The answer at (tY_m, Q_N) with the wheel upright (roll 0) into *out (out->struct_size must be
 *  set). Outside the ranges: status out_of_range, no contacts (not an error). */
MHC_API mhc_error mhc_table_lookup(const mhc_table* t, double tY_m, double Q_N, mhc_table_result* out);
/** The same at the wheel's roll roll_rad against the rail (method.md section 3.8; in a wheelset
 *  the left pair's is the wheelset's roll, the right pair's its negative). A table with a roll
 *  axis answers inside its roll range (out_of_range outside it, or for a roll that is not
 *  finite); a table without one answers with its one layer, the status at best outside_validity
 *  away from its roll (off_roll = 1). */
MHC_API mhc_error mhc_table_lookup_rolled(const mhc_table* t, double tY_m, double Q_N, double roll_rad,
                                          mhc_table_result* out);
MHC_API void mhc_table_free(mhc_table* t);

/* ---- wheelset tables (docs/tables.md "A wheelset table") ----------------------------------------
 * The tables of a wheelset's two pairs in one file (`mhcontact table-wheelset LEFT.csv RIGHT.csv`)
 * with where each pair sits in the wheelset; the lookup places both wheels from the wheelset's
 * lateral displacement y and roll as the wheelset call does (wheel s, sigma +1 left and -1 right:
 * its roll against the rail delta = sigma roll, t_Y = sigma y + a (cos delta - 1) + (z0 + R0) sin
 * delta), looks each pair up at its own load, and sums the normal forces on the wheelset in the
 * track frame (x forward, y towards the left rail, z up; moments about the axle centre as the
 * wheelset call's). Normal contact only: no creep forces. Lookups allocate nothing; a table may
 * be shared by any number of threads. Interface version 3. */
typedef struct mhc_wheelset_table mhc_wheelset_table;

/** The answer at one wheelset pose. Caller-owned: set struct_size = sizeof(mhc_wheelset_table_result). */
typedef struct mhc_wheelset_table_result {
  size_t struct_size;
  int32_t status;               /**< mhc_status: the worse of the two wheels' */
  int32_t reserved;
  double y_m;                   /**< the pose asked */
  double roll_rad;
  double Fy_N;                  /**< both wheels' normal forces on the wheelset, track y */
  double Fz_N;                  /**< ... track z */
  double Mx_Nm;                 /**< their moment about x about the axle centre */
  double dFy_dy_N_per_m;        /**< dFy/dy through both placements (chain rule, table slopes) */
  double dFy_droll_N_per_rad;   /**< dFy/droll: through t_Y and the tables' roll axes */
  double wheel_Fy_N[2];         /**< per wheel (0 left, 1 right), track frame */
  double wheel_Fz_N[2];
  double wheel_Mx_Nm[2];
  double wheel_dFy_dy_N_per_m[2];
  double wheel_dFy_droll_N_per_rad[2];
  double wheel_dFy_dQ[2];       /**< [-] dFy/dQ_left (wheel 0), dFy/dQ_right (wheel 1) */
  mhc_table_result wheel[2];    /**< each pair's answer at its placed t_Y (tY_m) and roll (roll_rad), pair frame */
} mhc_wheelset_table_result;

/** Read a wheelset table file (MHC_ERR_INPUT with the file, line and rule when it is not one). */
MHC_API mhc_error mhc_wheelset_table_read(const char* path, mhc_wheelset_table** out);
/** The wheelset table's own JSON header (sources with checksums, placements, ranges); valid while
 *  the table lives. NULL for a null table. */
MHC_API const char* mhc_wheelset_table_header(const mhc_wheelset_table* t);
/** Node ranges of side s's pair table (0 left, 1 right) [m], [N], [rad]; any pointer may be NULL.
 *  The wheel's t_Y at the wheelset's y is sigma y (plus the roll's shift). */
MHC_API mhc_error mhc_wheelset_table_pair_range(const mhc_wheelset_table* t, int32_t side, double* tY_min_m,
                                                double* tY_max_m, double* Q_min_N, double* Q_max_N,
                                                double* roll_min_rad, double* roll_max_rad);
/** The answer at the wheelset's y_m, roll_rad (positive raising the left wheel) and the wheels'
 *  vertical loads into *out (out->struct_size must be set). A wheel outside its table: status
 *  out_of_range for the wheelset (that wheel's answer has no contacts; not an error). */
MHC_API mhc_error mhc_wheelset_table_lookup(const mhc_wheelset_table* t, double y_m, double roll_rad,
                                            double Q_left_N, double Q_right_N, mhc_wheelset_table_result* out);
MHC_API void mhc_wheelset_table_free(mhc_wheelset_table* t);

/* ---- the wheelset call (docs/c-api.md "The wheelset call") ------------------------------------
 * Both wheels of a rigid wheelset on their rails, one call per time step: the pose and the
 * velocities in, per wheel and per wheelset the forces in track coordinates, the statuses, the
 * warnings and the derivatives out. Built from two pairs (mhc_pair_create): the left wheel on the
 * left rail and the right wheel on the right rail, every profile in its canonical frame (y to its
 * field side): the right pair is the mirror image, as the field gives its profiles.
 * Track frame: x forward, y towards the LEFT rail, z up (right-handed); roll about x (positive
 * raising the left wheel), yaw about z (positive turning x to the left). A wheelset displacement
 * y is t_Y = +y on the left pair and -y on the right one.
 * The roll: with the multi-Hertzian method each wheel is rolled against its rail about the axle
 * centre (contact point, angle, curvatures, heights and spin of the rolled wheel; docs/method.md
 * section 3.8); the pairs' tables must cover |y| + 0.46 m |roll| in t_Y (a pair's default -10 ... 12
 * mm: a flange contact beyond about 7 mm with its roll leaves it: out_of_range). The grid methods
 * take the roll too (their gap that of the rolled wheel). With roll_in_geometry 0 each wheel
 * stays upright, the roll entering its height only (MHC_WHEELSET_WARN_ROLL_* bits).
 * Limits (reported as MHC_WHEELSET_WARN_* bits): the yaw enters the creepages, not the contact
 * point (its lead ahead of the axle is not modelled). */

/** The interface version of this header: 1 = up to the warnings accessors; 2 = the wheelset
 *  call, mhc_interface_version, mhc_solve_many_warnings, the creep forces (mhc_pair_set_tangential,
 *  mhc_result_tangential), the contact tables (mhc_table_*), the RCF accessors (mhc_result_rcf,
 *  mhc_hertz_subsurface) and the grids (mhc_workspace_keep_grids, mhc_result_grid); 3 = the
 *  wheelset tables (mhc_wheelset_table_*); 4 = the smoothing's uncertainty band
 *  (mhc_result_smoothing_band, mhc_pair_set_smoothing_band). Negotiate at run time with
 *  mhc_interface_version(). */
#define MHC_INTERFACE_VERSION 4

/** The newest interface version the library implements (its return) and, in *oldest when not
 *  NULL, the oldest it still serves. A caller built against MHC_INTERFACE_VERSION v may use the
 *  library when oldest <= v; when the return is below v, only the functions and fields of the
 *  returned version exist (structs versioned by size: the library fills the fields it knows). */
MHC_API int32_t mhc_interface_version(int32_t* oldest);

typedef struct mhc_wheelset mhc_wheelset;
typedef struct mhc_wheelset_workspace mhc_wheelset_workspace;

/** What a wheelset adds to its two pairs. mhc_wheelset_options_init fills the defaults.
 *  struct_size: every earlier size of this struct is accepted (later fields: their defaults). */
typedef struct mhc_wheelset_options {
  size_t struct_size;        /**< sizeof(mhc_wheelset_options), set by mhc_wheelset_options_init */
  double mu;                 /**< Coulomb friction for the creep forces (FASTSIM on each ellipse);
                                  NaN (default): normal contact only */
  int32_t fastsim_nx;        /**< FASTSIM cells along x per strip (default 16: the wheelset call's, docs/performance.md) */
  int32_t fastsim_ny;        /**< FASTSIM strips across (default 16) */
  int32_t roll_in_geometry;  /**< 1 (default): each wheel rolled against its rail in the
                                  contact geometry (every method); 0: the upright wheels, the roll to first
                                  order in the heights (faster; its error against CONTACT:
                                  docs/wheelset.md) */
} mhc_wheelset_options;

typedef enum mhc_vertical {
  MHC_VERTICAL_LOADS = 0,    /**< the two wheel loads given; the roll and height are outputs */
  MHC_VERTICAL_POSITION = 1  /**< the axle height given (virtual penetration of eq. 11, as
                                  mhc_solve_approach: multi-Hertzian pairs only) and the roll
                                  given or solved */
} mhc_vertical;

/** One step's input (SI, track frame). Set struct_size = sizeof(mhc_wheelset_pose). */
typedef struct mhc_wheelset_pose {
  size_t struct_size;
  int32_t vertical;              /**< mhc_vertical */
  int32_t solve_roll;            /**< POSITION: 1 the roll such that both wheels touch at one
                                      height, 0 roll_rad given */
  double y_m;                    /**< lateral displacement of the wheelset (towards the left rail) */
  double yaw_rad;                /**< yaw psi */
  double Q_left_N, Q_right_N;    /**< LOADS: vertical wheel loads (>= 0) */
  double Z_m;                    /**< POSITION: axle-centre height; each wheel's penetration is
                                      h_s(roll) - Z, h_s(roll) the axle height at which that wheel,
                                      rolled, first touches (roll_in_geometry 0: h_s - s roll L_s, h_s
                                      upright, L_s = a + y_w - r tan(gamma), s: +1 left) */
  double roll_rad;               /**< POSITION with solve_roll 0: the roll */
  double V_m_per_s;              /**< forward speed (> 0 with friction) */
  double lateral_velocity_m_per_s;
  double yaw_rate_rad_per_s;
  double pitch_rate_rad_per_s;   /**< NaN: V / r0 of each wheel */
  int32_t derivatives;           /**< 1: fill the dF_* fields (in y and roll central differences;
                                      in the vertical input analytic where the method gives it,
                                      mhc_wheelset_wheel.dF_dvertical_analytic, else central
                                      differences: 2 to 6 more solves per wheel); 0: NaN */
  int32_t reserved;
} mhc_wheelset_pose;

/** One loaded contact of a wheel in track and wheelset coordinates. */
typedef struct mhc_wheelset_contact {
  int32_t index;          /**< ellipse or patch index of the pair (1-based) */
  uint32_t flags;         /**< MHC_CONTACT_* bits */
  double y_track_m;       /**< contact point on the rail, track frame */
  double z_track_m;
  double y_wheelset_m;    /**< on the wheel, from the axle centre (wheelset frame, unrolled) */
  double z_wheelset_m;    /**< ... (minus the rolling radius) */
  double gamma_rad;       /**< contact angle (positive towards the gauge corner, each rail's sense) */
  double r_roll_m;        /**< rolling radius */
  double N_N;             /**< normal force */
  double a_m, b_m;        /**< semi-axes along x and across (grid: half length and width) */
  double Fx_N, Fs_N;      /**< creep forces ON THE WHEEL in the contact plane, along x and s (the
                               pair's frame: s towards the field side); 0 without friction */
  double Mn_N_m;          /**< spin moment on the wheel about the normal (the pair's frame) */
  double F_N[3];          /**< this contact's normal and creep force on the wheelset, track frame */
  double M_N_m[3];        /**< its moment about the axle centre, track frame */
} mhc_wheelset_contact;

/** One wheel's answer. */
typedef struct mhc_wheelset_wheel {
  int32_t status;         /**< mhc_status of this wheel's pair */
  uint32_t warnings;      /**< MHC_WARN_* bits (the text and data: mhc_wheelset_warning) */
  int32_t n_warnings;
  int32_t n_contacts;     /**< loaded contacts (at most MHC_MAX_CONTACTS filled) */
  int32_t plastic;        /**< 1 when a contact is plastic */
  int32_t dF_dvertical_analytic; /**< 1: dF_dvertical analytic (multi-Hertzian ellipses: dN/dh0 and
                                      FASTSIM's load slope); 0: central differences, or not asked
                                      (a reserved 0 in libraries before 2 Dec 2026) */
  double tY_m;            /**< the pair's t_Y */
  double h_m;             /**< axle height at which this wheel first touches (NaN off the table) */
  double dz_m;            /**< its vertical virtual penetration (eq. 11) */
  double Fz_pair_N;       /**< the pair's vertical force: sum N cos(gamma), plus with friction the creep
                                forces' vertical share (docs/method.md §10 eq. 10.1): the wheel's load */
  double F_N[3];          /**< the wheel's forces on the wheelset, track frame */
  double M_N_m[3];        /**< their moment about the axle centre */
  double dF_dy_N_per_m[3];      /**< d F_N / d y (the other inputs held) */
  double dF_droll_N_per_rad[3]; /**< d F_N / d roll (POSITION; NaN with LOADS) */
  double dF_dvertical[3];       /**< d F_N / d Z [N/m] (POSITION) or / d Q of this wheel [N/N] (LOADS) */
  mhc_wheelset_contact contact[MHC_MAX_CONTACTS];
} mhc_wheelset_wheel;

/** Wheelset warnings (mhc_wheelset_result.wheelset_warnings). */
#define MHC_WHEELSET_WARN_ROLL_IN_GEOMETRY 0x1u /**< grid methods: |roll| above 1 mrad, the relative
                                                     roll of wheel and rail is not in their contact
                                                     geometry (the multi-Hertzian method models it) */
#define MHC_WHEELSET_WARN_YAW_LEAD_LEFT 0x2u    /**< the left contact's lead under yaw (r tan(gamma)
                                                     tan(psi)) exceeds a tenth of its semi-axis a */
#define MHC_WHEELSET_WARN_YAW_LEAD_RIGHT 0x4u   /**< the same on the right wheel */
#define MHC_WHEELSET_WARN_ROLL_NEAR_FLANGE 0x8u /**< grid methods: a roll above 0.1 mrad with a contact
                                                     steeper than 25 degrees: the roll moves the
                                                     contact point there, which their first-order
                                                     rule misses */

/** One step's answer. Caller-owned: set struct_size. Any size from
 *  offsetof(mhc_wheelset_result, wheel) up is accepted: the library fills the fields that fit
 *  (a caller built against an older, smaller struct gets its fields; a newer, larger one gets
 *  the library's and struct_size set to the bytes filled). */
typedef struct mhc_wheelset_result {
  size_t struct_size;
  int32_t status;              /**< the worse of the two wheels' (a failure before an answer) */
  uint32_t wheelset_warnings;  /**< MHC_WHEELSET_WARN_* bits (the text: mhc_wheelset_warning_text) */
  double roll_rad;             /**< given, solved, or (LOADS) from the wheels' penetrations */
  double Z_m;                  /**< axle-centre height: given, or (LOADS) from the penetrations */
  double F_N[3];               /**< both wheels' forces on the wheelset, track frame */
  double M_N_m[3];             /**< their moment about the axle centre */
  double dF_dy_N_per_m[3];
  double dF_droll_N_per_rad[3];
  double dF_dvertical[3];      /**< d/dZ (POSITION), or with both loads moved by one newton (LOADS) */
  mhc_wheelset_wheel wheel[2]; /**< 0 left, 1 right */
} mhc_wheelset_result;

MHC_API void mhc_wheelset_options_init(mhc_wheelset_options* opt);
/** A wheelset from its left and right pairs (copied: they may be freed afterwards). They must
 *  have the same material, method and flange-back data; opt may be NULL (the defaults). */
MHC_API mhc_error mhc_wheelset_create(const mhc_pair* left, const mhc_pair* right, const mhc_wheelset_options* opt,
                                      mhc_wheelset** out);
MHC_API void mhc_wheelset_free(mhc_wheelset* w);
/** Scratch memory for one thread's steps (no allocation per step once it has seen one as large). */
MHC_API mhc_error mhc_wheelset_workspace_create(const mhc_wheelset* w, mhc_wheelset_workspace** out);
MHC_API void mhc_wheelset_workspace_free(mhc_wheelset_workspace* ws);
/** One step. A wheel that is not ok is not an error (its status says it; mhc_last_message the
 *  first such wheel's message). MHC_ERR_ARGUMENT for a bad pose (the field, value and rule),
 *  MHC_ERR_UNSUPPORTED for POSITION with a grid method. */
MHC_API mhc_error mhc_wheelset_step(const mhc_wheelset* w, mhc_wheelset_workspace* ws, const mhc_wheelset_pose* pose,
                                    mhc_wheelset_result* out);
/** n steps at once: pose[i] into out[i] (arrays of n structs of their struct_size), on n_threads
 *  threads (0: all cores), each with its own workspace. Results do not depend on the thread count. */
MHC_API mhc_error mhc_wheelset_step_many(const mhc_wheelset* w, size_t n, const mhc_wheelset_pose* pose,
                                         mhc_wheelset_result* out, int32_t n_threads);
/** The warnings of wheel `side` (0 left, 1 right) in the last step of ws, as mhc_result_warning. */
MHC_API int32_t mhc_wheelset_n_warnings(const mhc_wheelset_workspace* ws, int32_t side);
MHC_API mhc_error mhc_wheelset_warning(const mhc_wheelset_workspace* ws, int32_t side, int32_t i, mhc_warning* out);
/** Wheel warning i as in cases.csv, or with side = -1 the wheelset's warning i
 *  ("yaw_lead_not_modelled:wheel=left:lead_mm=3.1>0.6"); "" out of range. Valid until the
 *  thread's next call of this function. */
MHC_API const char* mhc_wheelset_warning_text(const mhc_wheelset_workspace* ws, int32_t side, int32_t i);
/** Number of wheelset warnings of the last step (side = -1 of mhc_wheelset_warning_text). */
MHC_API int32_t mhc_wheelset_n_wheelset_warnings(const mhc_wheelset_workspace* ws);
/* ---- tangential contact: friction, kinematics, creep forces ----------------------------------
   docs/tangential.md and docs/c-api.md "Creep forces". A pair solves the tangential problem when
   a friction coefficient is set (mhc_pair_set_tangential, or `friction` in the case file of
   mhc_pair_from_case_file); mhc_result_tangential then gives the creep forces of the last case a
   workspace solved with mhc_solve_load. Forces act ON THE RAIL, per contact in its contact frame
   (x rolling, s in the contact plane towards the field side, Mz about the normal x cross s). */

/** The tangential inputs of a pair (the case file's `friction`, `kinematics` | `creepages`).
 *  mhc_tangential_options_init fills the defaults and struct_size. Fields are only ever appended:
 *  a caller compiled against an earlier header passes its own struct_size and the fields it does
 *  not have keep their defaults. */
typedef struct mhc_tangential_options {
  size_t struct_size;          /**< sizeof(mhc_tangential_options), set by mhc_tangential_options_init */
  double mu;                   /**< Coulomb friction coefficient; NaN (default): no tangential problem */
  int32_t creepages_given;     /**< 0 (default): creepages from the kinematics below; 1: xi, eta, phi */
  int32_t reserved;
  /* kinematics, in the pair's frame (y towards the field side: docs/tangential.md "left and right") */
  double speed_m_s;            /**< forward speed V > 0 (default 30) */
  double yaw_rad;              /**< yaw angle at t_Y = 0 (default 0) */
  double yaw_rad_per_m;        /**< yaw added per metre of t_Y (default 0; A-2.2: 2.4 rad/m) */
  double lateral_velocity_m_s; /**< default 0 */
  double yaw_rate_rad_s;       /**< default 0 */
  double pitch_rate_rad_s;     /**< wheel rotation rate; NaN (default): rolling at the nominal radius */
  /* creepages given (creepages_given = 1), the same for every contact */
  double xi;                   /**< longitudinal creepage (default 0) */
  double eta;                  /**< lateral creepage, in the contact plane (default 0) */
  double phi_per_m;            /**< spin creepage [rad/m] (default 0) */
  int32_t vertical_equilibrium; /**< 1 (default): Q balanced with the creep forces' vertical
                                     components (docs/method.md §10); 0: sum N cos(gamma) = Q */
  int32_t reserved2;
} mhc_tangential_options;

/** Fill *opt with the defaults (no friction) and its struct_size. */
MHC_API void mhc_tangential_options_init(mhc_tangential_options* opt);
/** Set the pair's tangential inputs (replacing those of its case file). Call it before solving:
 *  not while another thread solves with the pair. opt->struct_size: sizeof of this or an earlier
 *  version of the struct (at least up to phi_per_m). MHC_ERR_ARGUMENT names a field out of range
 *  (mu < 0 or > 2, V <= 0, a value not finite). */
MHC_API mhc_error mhc_pair_set_tangential(mhc_pair* pair, const mhc_tangential_options* opt);

/** The creep forces of one contact (the tangential columns of ellipses.csv / patches.csv). */
typedef struct mhc_contact_tangential {
  int32_t solved;              /**< 1 when this contact's tangential problem was solved */
  int32_t reserved;
  double xi, eta, phi_per_m;   /**< its creepages (phi in rad/m) */
  double Fx_N;                 /**< creep force on the rail along x */
  double Fy_N;                 /**< ... along s (in the contact plane, towards the field side) */
  double Mz_Nm;                /**< spin moment on the rail about the contact normal */
  double adhesion_fraction;    /**< adhesion area / contact area */
  double Tgamma_N;             /**< Fx xi + Fy eta [N = J/m] */
  double Tgamma_spin_N;        /**< Mz phi [N] */
} mhc_contact_tangential;

/** The creep forces of a case: its sums (the tangential columns of cases.csv) and per contact in
 *  the order of mhc_result.contact. Caller-owned: set struct_size = sizeof(mhc_tangential). */
typedef struct mhc_tangential {
  size_t struct_size;          /**< set by the caller: sizeof(mhc_tangential) */
  int32_t asked;               /**< 1 when the pair has a friction coefficient */
  int32_t solved;              /**< 1 when every loaded contact's problem was solved */
  int32_t n_contacts;          /**< contacts filled below (min(n_contacts, MHC_MAX_CONTACTS)) */
  int32_t reserved;
  double mu;                   /**< the friction coefficient */
  double Fx_N;                 /**< sum of Fx on the rail */
  double Fy_creep_N;           /**< sum of Fy cos(gamma): the creep forces' lateral part, towards the field side */
  double Mz_Nm;                /**< sum of Mz */
  double F_over_muN;           /**< sum |F| / (mu sum N) */
  double Y_N;                  /**< lateral force on the rail with the creep forces, sum N sin(gamma) + Fy_creep_N */
  double Fz_creep_N;           /**< the creep forces' share of the vertical load, downwards (docs/method.md §10) */
  mhc_contact_tangential contact[MHC_MAX_CONTACTS];
} mhc_tangential;

/** The creep forces of the last case solved with `ws` into *out (out->struct_size must be
 *  sizeof(mhc_tangential)). Without friction: asked = 0, every value NaN. */
MHC_API mhc_error mhc_result_tangential(const mhc_workspace* ws, mhc_tangential* out);
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

/* ---- subsurface stresses of the last case's contacts (lib/capi/subsurface.cpp) ----------------
 * The subsurface columns of ellipses.csv / patches.csv (docs/outputs.md "Subsurface columns") for
 * one contact of the last case a workspace solved, in SI: the same computation as the command's
 * for the same case (docs/c-api.md "Subsurface stresses"). The load is chosen as the command
 * chooses it (`source`): a grid patch's own element pressure with its solved traction (friction)
 * or full slip f p; an ellipse row's Hertz pressure with FASTSIM's traction (friction); else the
 * elastic Hertz ellipse with full slip. The grid and FASTSIM loads need what the solve kept: call
 * mhc_workspace_keep_grids(ws, 1) before solving (without it: the Hertz ellipse, and the warning
 * MHC_SUBSURFACE_WARN_GRID_NOT_KEPT). Seconds per grid patch; about 0.5 s per ellipse. */

/** Options of mhc_result_subsurface: mhc_subsurface_options_init fills the defaults and
 *  struct_size. Fields are only ever appended (earlier sizes accepted). */
typedef struct mhc_subsurface_options {
  size_t struct_size;  /**< sizeof(mhc_subsurface_options), set by mhc_subsurface_options_init */
  int32_t grid;        /**< 1 (default): a grid patch from its own element pressure (the case
                            file's "subsurface": {"grid": true}); 0: its elastic Hertz ellipse */
  int32_t reserved;
  double traction;     /**< full-slip traction coefficient f (the case file's rcf.traction_coefficient)
                            for a pair without friction, 0 to 1; NaN (default) with friction: each
                            contact's own traction (a value is refused then, as by the case file) */
  double dang_van_c;   /**< Dang Van parameter c of FI_sub, 0 to 1; NaN (default): FI_sub NaN */
} mhc_subsurface_options;

/** Which load the stresses are of (the sub_source column). */
typedef enum mhc_subsurface_source {
  MHC_SUBSURFACE_NONE = 0,                       /**< not computed (the values NaN) */
  MHC_SUBSURFACE_HERTZ_ELLIPSE = 1,              /**< hertz_ellipse */
  MHC_SUBSURFACE_GRID_PATCH = 2,                 /**< grid_patch */
  MHC_SUBSURFACE_GRID_PATCH_SOLVED_TRACTION = 3, /**< grid_patch_solved_traction */
  MHC_SUBSURFACE_HERTZ_ELLIPSE_FASTSIM = 4       /**< hertz_ellipse_fastsim_traction */
} mhc_subsurface_source;

/** Warnings of one contact's stresses (mhc_contact_subsurface.warnings). */
#define MHC_SUBSURFACE_WARN_PLASTIC 0x1u       /**< a plastic contact: the ELASTIC stresses of its
                                                    elastic Hertz ellipse at its load, not an
                                                    elastic-plastic field (docs/methods.md) */
#define MHC_SUBSURFACE_WARN_GRID_NOT_KEPT 0x2u /**< a grid or FASTSIM load was possible but the
                                                    last solve kept no grid: the Hertz ellipse used */
#define MHC_SUBSURFACE_WARN_AT_SURFACE 0x4u    /**< the von Mises peak lies on the shallowest depth
                                                    searched (one element deep for a grid) */

/** The subsurface stresses of one contact (SI; the columns sub_* and FI_sub_MPa in MPa and mm).
 *  Caller-owned: set struct_size = sizeof(mhc_contact_subsurface). */
typedef struct mhc_contact_subsurface {
  size_t struct_size;        /**< set by the caller: sizeof(mhc_contact_subsurface) */
  int32_t source;            /**< mhc_subsurface_source; MHC_SUBSURFACE_NONE: not computed (no
                                  traction known: the contact's tangential problem unsolved) */
  uint32_t warnings;         /**< MHC_SUBSURFACE_WARN_* bits */
  double vm_max_Pa, vm_depth_m;             /**< largest von Mises stress, its depth */
  double tau_max_Pa, tau_depth_m;           /**< largest principal shear stress, its depth */
  double tau_orth_amp_Pa, tau_orth_depth_m; /**< orthogonal shear amplitude over a pass, its depth */
  double tau_eq_amp_Pa;                     /**< equivalent shear stress amplitude */
  double sigma_h_Pa;                        /**< hydrostatic stress at the von Mises peak of that pass */
  double FI_sub_Pa;                         /**< tau_eq_amp + c sigma_h (NaN without dang_van_c) */
} mhc_contact_subsurface;

/** Fill *opt with the defaults (grid 1, traction NaN, dang_van_c NaN) and its struct_size. */
MHC_API void mhc_subsurface_options_init(mhc_subsurface_options* opt);
/** The stresses below contact i (0-based, as mhc_result_rcf) of the last case solved with `ws`
 *  into *out (out->struct_size must be set); opt NULL: the defaults. MHC_ERR_ARGUMENT when i is
 *  out of range, an option is out of its range, or a pair without friction is given no traction. */
MHC_API mhc_error mhc_result_subsurface(const mhc_workspace* ws, int32_t i, const mhc_subsurface_options* opt,
                                        mhc_contact_subsurface* out);

/* ---- pressure and traction grids of the last case (lib/capi/grids.cpp) -----------------------
 * The points of pressure.csv (`mhcontact run --pressure-grid N`, docs/outputs.md) for the last
 * case a workspace solved, SI, with the traction columns when the pair has friction: the same
 * numbers as the command's file for the same case. Nothing is kept for them unless asked: call
 * mhc_workspace_keep_grids(ws, 1) before the solve (docs/c-api.md "Pressure and traction grids"). */

/** keep = 1: the following solves with ws keep what a grid needs (the grid methods' element
 *  pressures, FASTSIM's cells and the patches' tractions per element); 0 (the default): nothing
 *  kept, no allocation for it. MHC_ERR_ARGUMENT for another value. */
MHC_API mhc_error mhc_workspace_keep_grids(mhc_workspace* ws, int32_t keep);

/** The grid of a case as arrays of n_points entries each, one entry per point, in pressure.csv's
 *  row order. Caller-owned: set struct_size = sizeof(mhc_grid), capacity and the arrays wanted
 *  (any may be NULL: not filled). */
typedef struct mhc_grid {
  size_t struct_size;     /**< set by the caller: sizeof(mhc_grid) */
  size_t capacity;        /**< in: the entries each non-NULL array holds */
  size_t n_points;        /**< out: the points of the case (also set when capacity is too small) */
  int32_t method;         /**< out: mhc_method that solved the case: multi-Hertzian, n x n points per
                               loaded ellipse; half-space and strips, the elements in contact */
  int32_t traction;       /**< out: 1 when px_Pa, py_Pa and slip are filled (friction: the pair's
                               tangential problem); 0: they are NaN and -1 */
  int32_t* contact;       /**< 1-based ellipse or patch index (mhc_contact.index) */
  double* x_m;            /**< along the rolling direction, from the ellipse centre / the patch's
                               reference point (pressure.csv x_mm) */
  double* s_m;            /**< across, in the contact plane, towards the field side (pressure.csv
                               y_mm of an ellipse, s_mm of a patch) */
  double* y_rail_m;       /**< rail y of a patch point (pressure.csv y_rail_mm); NaN for an ellipse */
  double* p_Pa;           /**< normal pressure (the ellipse law's: capped or flattened when plastic) */
  double* p_elastic_Pa;   /**< plastic multi-Hertzian pairs: the elastic Hertz pressure at the same
                               load (pressure.csv p_elastic_MPa); NaN otherwise */
  double* px_Pa;          /**< traction ON THE RAIL along x (NaN where not solved) */
  double* py_Pa;          /**< traction on the rail along s (NaN where not solved) */
  int32_t* slip;          /**< 1 in slip (|(px, py)| = mu p), 0 in adhesion, -1 not solved */
} mhc_grid;

/** The grid of the last case solved with ws (mhc_solve_load / mhc_solve_approach after
 *  mhc_workspace_keep_grids(ws, 1)) into *out: n points per axis of each ellipse (2 to 1000, as
 *  --pressure-grid; the grid methods' points are their elements and n is not used). Every array
 *  NULL: only n_points (the size query). An array given with capacity < n_points:
 *  MHC_ERR_ARGUMENT naming out->capacity and the size needed, n_points set. MHC_ERR_ARGUMENT when
 *  the last solve did not keep the grid; MHC_ERR_UNSUPPORTED for a strip-method case without
 *  friction (no element grid: the command writes none either). A case without contact: 0 points. */
MHC_API mhc_error mhc_result_grid(const mhc_workspace* ws, int32_t n, mhc_grid* out);

#ifdef __cplusplus
}
#endif

#endif /* MHCONTACT_H */
