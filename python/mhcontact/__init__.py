"""mhcontact: wheel-rail normal contact by the multi-Hertzian method (Sebes et al. 2014), the
elastic half-space and the strip method, for scripts and vehicle-dynamics loops (docs/python.md).

    import mhcontact
    pair = mhcontact.Pair(mhcontact.Profile.standard("S1002"), mhcontact.Profile.standard("60E1"),
                          {"rail_inclination": "1:40"})
    pair.solve(2e-3, Q_N=50e3)["Fy_kN"]
    steel = mhcontact.Pair(mhcontact.Profile.standard("S1002"), mhcontact.Profile.standard("60E1"),
                           {"rail_inclination": "1:40", "yield_wheel_Pa": 350e6})   # plastic: yield law
    cols = pair.solve_many(np.linspace(-6e-3, 10e-3, 1000), Q_N=50e3)   # columns of cases.csv

Inputs are SI (m, N, rad); results carry the names and units of the command's tables (cases.csv:
tY_mm, Fz_kN, pmax_MPa, ...), with NaN where the table has an empty cell.
"""
import numpy as _np

from ._core import (INTERFACE_VERSION, InputError, MAX_CONTACTS, METHOD_NAMES, STATUS_NAMES, UnsupportedError, Pair,
                    Profile, Table, TableResult, Wheelset, WheelsetTable, WheelsetTableResult, __version__, abi_version,
                    fft_backend, hertz_subsurface)
from ._core import _pair_rcf as _core_pair_rcf
from ._core import _pair_subsurface as _core_pair_subsurface
from ._core import _pair_pressure_grid as _core_pair_pressure_grid

from .fleet import fleet, make_table, read_tables

__all__ = ["fleet", "make_table", "read_tables", "Pair", "Profile", "Table", "TableResult", "MAX_CONTACTS", "Wheelset",
           "WheelsetTable", "WheelsetTableResult", "InputError", "UnsupportedError", "STATUS_NAMES", "METHOD_NAMES",
           "CASE_COLUMNS", "TANGENTIAL_COLUMNS", "INTERFACE_VERSION", "__version__", "abi_version", "fft_backend", "hertz_subsurface"]

#: The columns of solve_many, in the order of cases.csv (lib/output/case_tables.cpp; its
#: `warnings` and `message` text aside), then the vertical contact stiffness dFz/d(dz) (not in
#: cases.csv).
CASE_COLUMNS = ("case", "tY_mm", "Q_kN", "status", "method", "dz_virtual_mm", "approach_mm", "iterations",
                "residual", "n_contacts", "Fz_kN", "Fy_kN", "Y_over_Q", "pmax_MPa", "area_mm2", "gamma_main_deg",
                "r_roll_main_mm", "plastic", "n_warnings", "pmax_half_L_MPa", "pmax_double_L_MPa",
                "area_half_L_mm2", "area_double_L_mm2", "dFz_ddz_kN_per_mm")

#: With friction (a case file's `friction`, or Pair.set_tangential), solve_many adds the
#: tangential columns of cases.csv after these (docs/tangential.md; docs/python.md "Creep forces").
TANGENTIAL_COLUMNS = ("Fx_kN", "Fy_creep_kN", "Mz_Nm", "F_over_muN", "Y_kN", "Fz_creep_kN")


def _prescribed(Q_N, dz_m):
    if (Q_N is None) == (dz_m is None):
        raise ValueError("give exactly one of Q_N (load prescribed) and dz_m (approach prescribed)")
    return (dz_m, "dz_m", True) if Q_N is None else (Q_N, "Q_N", False)


def _number(name, v, unit):
    """float(v), or a TypeError naming the argument and the type expected."""
    try:
        return float(v)
    except (TypeError, ValueError):
        raise TypeError("%s = %r: expected a number [%s], got %s" % (name, v, unit, type(v).__name__)) from None


def _numbers(name, v, unit):
    """v as an array of floats, or a TypeError naming the argument and the type expected."""
    try:
        return _np.asarray(v, dtype=float)
    except (TypeError, ValueError):
        raise TypeError("%s = %r: expected numbers (a float or an array of floats) [%s]" % (name, v, unit)) from None


# Pair (the extension's class): Pair(wheel, rail, options) with options the fields of
# mhc_pair_options (SI: gauge_m, rail_inclination, E_wheel_Pa, p_lim_Pa, yield_wheel_Pa,
# yield_rail_Pa, method, tY_min_m, ...), or Pair.from_case_file(path). A yield stress alone gives
# the plastic model with the yield law, as material.yield_MPa in a case file (docs/method.md §5.1).
# positioning "explicit" with lateral_offset_m places the wheel yourself (a refused gauge placement
# names the offset that reproduces it). smoothing_band False (or pair.set_smoothing_band(False))
# leaves out the smoothing's uncertainty band that a grid method computes on a measured profile
# (pmax_half_L_MPa ..., as the case file's geometry.smoothing_band). Options are checked as a case file's values are (plausible
# ranges: ValueError naming the option, the value, the rule and the unit; a wrong type: TypeError
# naming the option and the type expected). pair.warnings lists the pair's warnings (profiles, rail
# cant, placement) in the command's words. Immutable; share it between threads. Its solve methods
# are these:


def _pair_solve(self, tY_m, Q_N=None, dz_m=None, roll_rad=0.0):
    """One case: the load Q_N [N] or the vertical approach dz_m [m] prescribed, at lateral
    position tY_m [m]. A dict of the cases.csv fields, 'contacts', one dict per contact, and
    'warnings', one dict per warning (class, outside_validity, contact_kind, contact, contact2,
    measures: name, value_si, limit_si, relation, unit; text: as in cases.csv).
    Q_N = 0 is no_contact (a wheel lifted); a negative load, or one above 2000 kN, raises
    ValueError, as the command refuses it."""
    value, name, approach = _prescribed(Q_N, dz_m)
    return self._solve(_number("tY_m", tY_m, "m"), _number(name, value, "m" if approach else "N"), approach,
                       _number("roll_rad", roll_rad, "rad"))


def _pair_solve_many(self, tY_m, Q_N=None, dz_m=None, threads=0):
    """Many cases: tY_m [m] and Q_N [N] (or dz_m [m]) broadcast against each other, solved on
    `threads` threads (0: all cores) without the GIL. A dict of 1-D numpy arrays named as
    the columns of cases.csv (CASE_COLUMNS); status and method as strings."""
    value, name, approach = _prescribed(Q_N, dz_m)
    t, v = _np.broadcast_arrays(_numbers("tY_m", tY_m, "m"), _numbers(name, value, "m" if approach else "N"))
    t = _np.ascontiguousarray(t.ravel())
    v = _np.ascontiguousarray(v.ravel())
    raw = self._solve_many(t, v, approach, int(threads))
    out = {"case": _np.arange(1, t.size + 1)}
    status = _np.asarray(STATUS_NAMES)[raw.pop("status_code")]
    method = _np.asarray(METHOD_NAMES)[raw.pop("method_code")]
    for name in CASE_COLUMNS[1:]:
        if name == "status":
            out[name] = status
        elif name == "method":
            out[name] = method
        else:
            out[name] = raw[name]
    for name in TANGENTIAL_COLUMNS:
        if name in raw:
            out[name] = raw[name]
    # Per case, a list of warning dicts (class, outside_validity, contact_kind, contact,
    # contact2, measures, text), the `warnings` column of cases.csv as data.
    out["warnings"] = raw["warnings"]
    return out


Pair.solve = _pair_solve
Pair.solve_many = _pair_solve_many


def _pair_rcf(self, tY_m, Q_N, k_Pa=float("nan")):
    """The RCF indicators, damage and wear of each contact of one case (load Q_N [N] at tY_m [m]),
    as the RCF and damage columns of ellipses.csv / patches.csv with the published default
    constants (docs/python.md "RCF, damage and wear"): a list of dicts, one per contact in the
    order of solve()'s 'contacts'. k_Pa: the shear yield k [Pa] (NaN: sigma_y/sqrt(3) of the
    pair's material; NaN values where neither is known). Needs friction for the damage and wear
    and the actual traction (a case file's `friction` or set_tangential); NaN without."""
    return _core_pair_rcf(self, _number("tY_m", tY_m, "m"), _number("Q_N", Q_N, "N"), _number("k_Pa", k_Pa, "Pa"))


Pair.rcf = _pair_rcf


def _pair_subsurface(self, tY_m, Q_N, grid=True, traction=float("nan"), dang_van_c=float("nan")):
    """The stresses below each contact of one case (load Q_N [N] at tY_m [m]), as the subsurface
    columns of ellipses.csv / patches.csv (docs/python.md "Subsurface stresses of a solved case"):
    a list of dicts, one per contact in the order of solve()'s 'contacts', with sub_source,
    sub_vm_max_MPa, sub_vm_depth_mm, sub_tau_max_MPa, sub_tau_depth_mm, sub_tau_orth_amp_MPa,
    sub_tau_orth_depth_mm, sub_tau_eq_amp_MPa, sub_sigma_h_MPa, FI_sub_MPa and 'warnings' (names:
    "plastic", "grid_not_kept", "at_surface"). grid: a grid patch from its own pressure (the case
    file's "subsurface": {"grid": true}); traction: the full-slip f of a pair without friction
    (with friction each contact's own, leave it NaN); dang_van_c: c of FI_sub (NaN: none).
    Through mhc_result_subsurface; seconds per grid patch."""
    return _core_pair_subsurface(self, _number("tY_m", tY_m, "m"), _number("Q_N", Q_N, "N"), 1 if grid else 0,
                                 _number("traction", traction, "-"), _number("dang_van_c", dang_van_c, "-"))


Pair.subsurface = _pair_subsurface


def _pair_pressure_grid(self, tY_m, Q_N=None, dz_m=None, n=20, roll_rad=0.0):
    """The pressure grid of one case (load Q_N [N] or approach dz_m [m] at tY_m [m]), as the rows
    of pressure.csv of `mhcontact run --pressure-grid n` (docs/python.md "Pressure and traction
    grids"): a dict of 1-D numpy arrays named as its columns, one entry per point, and 'method',
    'status'. Multi-Hertzian: ellipse, x_mm, y_mm, p_MPa (p_elastic_MPa when plastic), n x n
    points per loaded ellipse; half-space and strips: patch, x_mm, s_mm, y_rail_mm, p_MPa, the
    elements in contact (n not used). With friction px_MPa, py_MPa (traction on the rail) and
    slip (1 slip, 0 adhesion, -1 not solved). Through mhc_result_grid."""
    value, name, approach = _prescribed(Q_N, dz_m)
    if isinstance(n, bool) or not isinstance(n, (int, _np.integer)):
        raise TypeError("n = %r: expected an integer (points per axis, 2 to 1000)" % (n,))
    return _core_pair_pressure_grid(self, _number("tY_m", tY_m, "m"), _number(name, value, "m" if approach else "N"),
                                    approach, _number("roll_rad", roll_rad, "rad"), int(n))


Pair.pressure_grid = _pair_pressure_grid


# Wheelset (the extension's class): Wheelset(left_pair, right_pair, mu=nan, fastsim_nx=16,
# fastsim_ny=16, roll_in_geometry=True), both pairs built from profiles in their canonical frames (the right pair is
# mirrored, as the field gives its profiles); mu finite: the creep forces (FASTSIM). Track frame:
# x forward, y towards the LEFT rail, z up (docs/python.md "The wheelset call").

def _wheelset_step(self, y_m, Q_left_N=None, Q_right_N=None, Z_m=None, roll_rad=None, yaw_rad=0.0,
                   V_m_per_s=1.0, lateral_velocity_m_per_s=0.0, yaw_rate_rad_per_s=0.0,
                   pitch_rate_rad_per_s=float("nan"), derivatives=False, threads=1):
    """Steps of the wheelset, every input broadcast against the others (numpy arrays or floats):
    the loads Q_left_N, Q_right_N [N] (the roll and height are then outputs), or the axle height
    Z_m [m] with roll_rad given (None: solved so that both wheels touch). A dict of 1-D arrays
    (F_N, M_N_m and the derivatives: n x 3, track frame), status strings, the main contact of each
    wheel (left_N_N, left_gamma_rad, ...); the steps run on `threads` threads (0: all cores)
    without the GIL."""
    loads = Q_left_N is not None or Q_right_N is not None
    if loads == (Z_m is not None):
        raise ValueError("give either the loads Q_left_N and Q_right_N, or the axle height Z_m")
    if loads and (Q_left_N is None or Q_right_N is None):
        raise ValueError("give both loads, Q_left_N and Q_right_N")
    solve_roll = not loads and roll_rad is None
    args = {"y_m": y_m, "yaw_rad": yaw_rad, "Q_left_N": Q_left_N if loads else 0.0,
            "Q_right_N": Q_right_N if loads else 0.0, "Z_m": 0.0 if loads else Z_m,
            "roll_rad": 0.0 if roll_rad is None else roll_rad, "V_m_per_s": V_m_per_s,
            "lateral_velocity_m_per_s": lateral_velocity_m_per_s, "yaw_rate_rad_per_s": yaw_rate_rad_per_s,
            "pitch_rate_rad_per_s": pitch_rate_rad_per_s}
    units = {"y_m": "m", "yaw_rad": "rad", "Q_left_N": "N", "Q_right_N": "N", "Z_m": "m", "roll_rad": "rad",
             "V_m_per_s": "m/s", "lateral_velocity_m_per_s": "m/s", "yaw_rate_rad_per_s": "rad/s",
             "pitch_rate_rad_per_s": "rad/s"}
    arrays = _np.broadcast_arrays(*[_numbers(k, v, units[k]) for k, v in args.items()])
    cols = {k: _np.ascontiguousarray(a.ravel()) for k, a in zip(args, arrays)}
    out = self._step_many(cols, 0 if loads else 1, solve_roll, bool(derivatives), int(threads))
    names = _np.asarray(STATUS_NAMES)
    for k in ("status", "left_status", "right_status"):
        out[k] = names[out.pop(k + "_code")]
    return out


Wheelset.step = _wheelset_step

