"""The Python module (docs/python.md): the command's numbers, errors as exceptions, broadcasting,
threads. Run by ctest (python.pytest) with PYTHONPATH at the build tree's python/ directory."""
import csv
import math
import os
import subprocess
import tempfile
import threading

import numpy as np
import pytest

import mhcontact

SRC = os.environ.get("MHCONTACT_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("MHCONTACT_BINARY", "mhcontact")
MANCHESTER = os.path.join(SRC, "cases", "manchester.json")


@pytest.fixture(scope="module")
def pair():
    return mhcontact.Pair.from_case_file(MANCHESTER)


def test_version():
    assert mhcontact.abi_version == 1
    assert mhcontact.fft_backend in ("pocketfft", "fftw3")
    assert mhcontact.__version__


def test_same_numbers_as_the_command(pair):
    with tempfile.TemporaryDirectory() as d:
        subprocess.run([BINARY, "run", MANCHESTER, "-o", d, "--digits", "max", "-q", "--format", "csv"], check=True)
        with open(os.path.join(d, "cases.csv")) as f:
            rows = list(csv.DictReader(f))
    assert len(rows) == 99
    tY = np.array([float(r["tY_mm"]) for r in rows]) * 1e-3  # as the case reader: mm * 1e-3
    Q = np.array([float(r["Q_kN"]) for r in rows]) * 1e3
    cols = pair.solve_many(tY, Q_N=Q, threads=2)
    assert list(cols) == list(mhcontact.CASE_COLUMNS) + ["warnings"]
    for name in ("dz_virtual_mm", "approach_mm", "residual", "Fz_kN", "Fy_kN", "pmax_MPa", "area_mm2",
                 "gamma_main_deg", "r_roll_main_mm", "iterations"):
        table = np.array([float(r[name]) if r[name] != "" else math.nan for r in rows])
        np.testing.assert_array_equal(cols[name], table, err_msg=name)  # bit for bit
    assert list(cols["status"]) == [r["status"] for r in rows]
    assert list(cols["method"]) == [r["method"] for r in rows]
    assert list(cols["n_contacts"]) == [int(r["n_contacts"]) for r in rows]
    assert list(cols["n_warnings"]) == [int(r["n_warnings"]) for r in rows]
    # The same warnings, as data and as the command writes them (the one judge, docs/status.md).
    assert [";".join(w["text"] for w in ws) for ws in cols["warnings"]] == [r["warnings"] for r in rows]
    for ws, r in zip(cols["warnings"], rows):
        assert [w["class"] for w in ws] == [t.split(":")[0] for t in r["warnings"].split(";") if t]
        if r["status"] == "outside_validity":
            assert any(w["outside_validity"] for w in ws)
    one = pair.solve(tY[40], Q_N=Q[40])
    assert [w["text"] for w in one["warnings"]] == [t for t in rows[40]["warnings"].split(";") if t]
    assert one["Fy_kN"] == float(rows[40]["Fy_kN"])
    assert one["status"] == rows[40]["status"]


def test_broadcast_and_threads(pair):
    tY = np.linspace(-6e-3, 10e-3, 301)
    a = pair.solve_many(tY, Q_N=50e3, threads=1)
    b = pair.solve_many(tY[:, None], Q_N=np.array([50e3]), threads=3)
    for name in mhcontact.CASE_COLUMNS:
        np.testing.assert_array_equal(a[name], b[name], err_msg=name)
    assert np.all(np.isin(a["status"], ["ok", "outside_validity"]))  # every case solved
    np.testing.assert_allclose(a["Fz_kN"], 50.0, rtol=1e-12)


def test_two_python_threads_on_one_pair(pair):
    tY = np.linspace(-6e-3, 10e-3, 2000)
    ref = pair.solve_many(tY, Q_N=70e3, threads=1)
    out = [None, None]

    def work(k):
        out[k] = pair.solve_many(tY[::-1] if k else tY, Q_N=70e3, threads=1)

    ts = [threading.Thread(target=work, args=(k,)) for k in (0, 1)]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    np.testing.assert_array_equal(out[0]["Fy_kN"], ref["Fy_kN"])
    np.testing.assert_array_equal(out[1]["Fy_kN"][::-1], ref["Fy_kN"])


def test_approach_prescribed_gives_back_the_load(pair):
    r = pair.solve(3e-3, Q_N=80e3)
    a = pair.solve(3e-3, dz_m=r["dz_virtual_mm"] * 1e-3)
    assert a["Fz_kN"] == pytest.approx(80.0, rel=1e-11)
    assert a["dFz_ddz_kN_per_mm"] == pytest.approx(r["dFz_ddz_kN_per_mm"], rel=1e-10)
    cols = pair.solve_many([3e-3, 3e-3], dz_m=[r["dz_virtual_mm"] * 1e-3, -1e-5])
    assert list(cols["status"]) == ["ok", "no_contact"]
    assert math.isnan(cols["Fz_kN"][1])


def test_errors_cross_as_exceptions(pair):
    with pytest.raises(mhcontact.InputError, match="does_not_exist.prr"):
        mhcontact.Profile.read(os.path.join(SRC, "does_not_exist.prr"), "rail")
    with pytest.raises(ValueError):
        mhcontact.Profile.read(os.path.join(SRC, "profiles", "MBench_UIC60_v3.prr"), "bogie")
    with pytest.raises(ValueError, match="roll"):
        pair.solve(0.0, Q_N=50e3, roll_rad=0.1)  # beyond 50 mrad (a roll within is solved)
    with pytest.raises(ValueError, match="exactly one"):
        pair.solve(0.0)
    r = pair.solve(0.05, Q_N=50e3)
    assert r["status"] == "out_of_range"
    assert r["message"] == "t_Y = 50 mm outside the geometry table [-10, 12] mm"
    assert pair.solve(0.0, Q_N=0.0)["status"] == "no_contact"


def test_profiles_from_standard_and_points():
    w = mhcontact.Profile.standard("S1002")
    r = mhcontact.Profile.standard("60E1")
    y, z = w.points()
    w2 = mhcontact.Profile.from_points(y, z, "wheel")
    p1 = mhcontact.Pair(w, r, {"rail_inclination": "1:40", "tY_min_m": -8e-3, "tY_max_m": 10e-3})
    p2 = mhcontact.Pair(w2, r, {"rail_inclination": "1:40", "tY_min_m": -8e-3, "tY_max_m": 10e-3})
    assert p1.tY_range_m == pytest.approx((-8e-3, 10e-3))
    a = p1.solve(1e-3, Q_N=60e3)
    b = p2.solve(1e-3, Q_N=60e3)
    assert a["Fy_kN"] == pytest.approx(b["Fy_kN"], rel=1e-6)
    assert a["contacts"] and a["contacts"][0]["N_kN"] > 0
    with pytest.raises(TypeError, match="unknown option"):
        mhcontact.Pair(w, r, {"rail_inclination": "as-is", "gage_m": 1.435})


def _manchester_profiles():
    return (mhcontact.Profile.read(os.path.join(SRC, "profiles", "MBench_S1002_v3.prw"), "wheel"),
            mhcontact.Profile.read(os.path.join(SRC, "profiles", "MBench_UIC60_v3.prr"), "rail"))


def _case_file(d, material):
    """cases/manchester.json, plastic, with `material`, profiles by absolute path."""
    path = os.path.join(d, "case.json")
    with open(path, "w") as f:
        f.write('{"wheel": {"profile": "%s", "nominal_radius_mm": 460},'
                ' "rail": {"profile": "%s", "inclination": "as-is"},'
                ' "material": %s, "model": "plastic", "sweep": {"tY_mm": [0], "Q_kN": [100]}}'
                % (os.path.join(SRC, "profiles", "MBench_S1002_v3.prw"),
                   os.path.join(SRC, "profiles", "MBench_UIC60_v3.prr"), material))
    return path


def test_yield_stress_as_the_case_file():
    # Interface equivalence: yield_wheel_Pa / yield_rail_Pa give the pair of a case file's yield_MPa.
    w, r = _manchester_profiles()
    tY = np.linspace(-6e-3, 10e-3, 33)
    with tempfile.TemporaryDirectory() as d:
        for options, material in (({"rail_inclination": "as-is", "yield_wheel_Pa": 350e6}, '{"yield_MPa": 350}'),
                                  ({"rail_inclination": "as-is", "yield_wheel_Pa": 350e6, "yield_rail_Pa": 500e6},
                                   '{"wheel": {"yield_MPa": 350}, "rail": {"yield_MPa": 500}}')):
            ours = mhcontact.Pair(w, r, options).solve_many(tY, Q_N=100e3, threads=1)
            ref = mhcontact.Pair.from_case_file(_case_file(d, material)).solve_many(tY, Q_N=100e3, threads=1)
            for name in mhcontact.CASE_COLUMNS:
                np.testing.assert_array_equal(ours[name], ref[name], err_msg=f"{options}: {name}")
            assert ours["plastic"].sum() > 0


def _ellip_KE(k):
    """Complete elliptic integrals K(k), E(k) by the arithmetic-geometric mean (Abramowitz &
    Stegun 17.6.3-4): E/K = 1 - sum 2^(n-1) c_n^2."""
    a, b, c, s, w = 1.0, math.sqrt(1 - k * k), k, 0.5 * k * k, 0.5
    for _ in range(40):  # quadratic convergence: c is at round-off after about 6 steps
        a, b, c = 0.5 * (a + b), math.sqrt(a * b), 0.5 * (a - b)
        w *= 2
        s += w * c * c
    K = math.pi / (2 * a)
    return K, K * (1 - s)


def _hertz(A, B, N, E_J):
    """Hertz's ellipse of the gap A x^2 + B y^2 under N (Johnson, Contact Mechanics, eqs. 3.69-3.71):
    (a along x, b along y, p0). For A <= B, g = b/a from B/A = (K - D)/(g^2 D), D = (K - E)/e^2,
    e^2 = 1 - g^2; a^3 = 3 N D / (2 pi E* A), p0 = 3 N / (2 pi a b)."""
    if A > B:
        b, a, p0 = _hertz(B, A, N, E_J)
        return a, b, p0

    def ratio(g):
        e2 = 1 - g * g
        K, E = _ellip_KE(math.sqrt(e2))
        D = (K - E) / e2
        return (K - D) / (g * g * D), D

    lo, hi = 1e-6, 1 - 1e-9  # ratio falls from large to 1 as g rises to 1
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if ratio(mid)[0] > B / A:
            lo = mid
        else:
            hi = mid
    g = 0.5 * (lo + hi)
    D = ratio(g)[1]
    a = (3 * N * D / (2 * math.pi * E_J * A)) ** (1.0 / 3.0)
    return a, g * a, 3 * N / (2 * math.pi * a * g * a)


def test_yield_law_against_its_closed_form():
    # method.md §5.1 written out, independent of the library: the patch of penetration h0 is the
    # Hertz patch of some load N_H (_hertz), its pressure flattened above p_y = 1.6 sigma_y with
    # slope 0.3, so N = 0.3 N_H + 0.7 pi a b p_y (1 - s^2/3), s = p_y/p0 (N = N_H for p0 <= p_y),
    # and p_max = p_y + 0.3 (p0 - p_y). N_H is bisected from the contact's N. Tolerance 1e-7
    # relative (the bisection of g above is good to about 1e-9).
    sigma_y, beta = 350e6, 0.3
    p_y = 1.6 * sigma_y
    w, r = _manchester_profiles()
    pair = mhcontact.Pair(w, r, {"rail_inclination": "as-is", "yield_wheel_Pa": sigma_y})
    E_J = 1.0 / (2 * (1 - 0.28 ** 2) / 210e9)  # Johnson's E* of two steels, E 210 GPa, nu 0.28
    beyond = 0
    for tY in (0.0, 3e-3, 6.5e-3):
        for c in pair.solve(tY, Q_N=100e3)["contacts"]:
            A, B, N = c["A_per_mm"] * 1e3, c["B_per_mm"] * 1e3, c["N_kN"] * 1e3

            def law(N_H):
                a, b, p0 = _hertz(A, B, N_H, E_J)
                if p0 <= p_y:
                    return N_H
                s = p_y / p0
                return beta * N_H + (1 - beta) * math.pi * a * b * p_y * (1 - s * s / 3)

            lo, hi = N, N / beta  # 0.3 N_H <= N <= N_H
            for _ in range(100):
                mid = 0.5 * (lo + hi)
                if law(mid) < N:
                    lo = mid
                else:
                    hi = mid
            a, b, p0 = _hertz(A, B, 0.5 * (lo + hi), E_J)
            assert c["plastic"] == (p0 > p_y)
            beyond += p0 > p_y
            assert c["a_mm"] * 1e-3 == pytest.approx(a, rel=1e-7)
            assert c["b_mm"] * 1e-3 == pytest.approx(b, rel=1e-7)
            assert c["pmax_MPa"] * 1e6 == pytest.approx(p_y + beta * (p0 - p_y) if p0 > p_y else p0, rel=1e-7)
    assert beyond >= 3


def test_yield_stress_errors_and_defaults():
    w, r = _manchester_profiles()
    with pytest.raises(ValueError, match=r"options.yield_wheel_Pa = -1 Pa: a yield stress must be > 0 and finite"):
        mhcontact.Pair(w, r, {"rail_inclination": "as-is", "yield_wheel_Pa": -1.0})
    with pytest.raises(ValueError, match="without yield_wheel_Pa"):
        mhcontact.Pair(w, r, {"rail_inclination": "as-is", "yield_rail_Pa": 500e6})
    # p_lim_Pa given takes precedence: the capped law, as p_lim_MPa in a case file.
    with tempfile.TemporaryDirectory() as d:
        ours = mhcontact.Pair(w, r, {"rail_inclination": "as-is", "yield_wheel_Pa": 350e6, "p_lim_Pa": 900e6}).solve(0.0, Q_N=100e3)
        ref = mhcontact.Pair.from_case_file(_case_file(d, '{"yield_MPa": 350, "p_lim_MPa": 900}')).solve(0.0, Q_N=100e3)
    assert ours["pmax_MPa"] == ref["pmax_MPa"]
    assert ours["contacts"] == ref["contacts"]
    assert mhcontact.Pair(w, r, {"rail_inclination": "as-is"}).solve(0.0, Q_N=100e3)["plastic"] == 0  # no yield stress: elastic


def test_plausible_ranges_as_the_case_file():
    """E_wheel_Pa = 210e3 (MPa typed as Pa) solved to a 0.23 MPa peak, Q_N = 5e9 solved: now refused,
    naming the field, the value, the rule and the unit."""
    w, r = _manchester_profiles()
    with pytest.raises(ValueError, match=r"options\.E_wheel_Pa: value 210000 Pa \(0\.00021 GPa\): must be between "
                                         r"50 and 400 GPa.*E_wheel_Pa is in Pa"):
        mhcontact.Pair(w, r, {"rail_inclination": "as-is", "E_wheel_Pa": 210e3})
    with pytest.raises(ValueError, match=r"options\.nominal_radius_m: value 920 m"):
        mhcontact.Pair(w, r, {"rail_inclination": "as-is", "nominal_radius_m": 920})
    pair = mhcontact.Pair(w, r, {"rail_inclination": "as-is"})
    with pytest.raises(ValueError, match=r"Q_N: value 5e\+09 N \(5e\+06 kN\): must be at most 2000 kN"):
        pair.solve(0.0, Q_N=5e9)
    with pytest.raises(ValueError, match=r"Q_N: value 5e\+09 N"):
        pair.solve_many([0.0, 1e-3], Q_N=[50e3, 5e9])
    assert pair.solve(0.0, Q_N=0.0)["status"] == "no_contact"  # a wheel lifted: a status


def test_negative_load_is_the_same_input_error_as_the_command():
    w, r = _manchester_profiles()
    pair = mhcontact.Pair(w, r, {"rail_inclination": "as-is"})
    with pytest.raises(ValueError, match=r"Q_N: value -5000 N \(-5 kN\): a wheel load must not be negative"):
        pair.solve(0.0, Q_N=-5e3)
    with tempfile.TemporaryDirectory() as d:
        path = _case_file(d, '{"yield_MPa": 350}').replace("case.json", "neg.json")
        with open(path, "w") as f:
            f.write(open(_case_file(d, '{"yield_MPa": 350}')).read().replace('"Q_kN": [100]', '"Q_kN": [-5]'))
        run = subprocess.run([BINARY, "run", path, "-o", os.path.join(d, "out"), "-q"], capture_output=True, text=True)
    assert run.returncode == 2  # an input error
    assert "Q_kN" in run.stderr and "-5" in run.stderr


def test_errors_name_the_key_and_the_type():
    w, r = _manchester_profiles()
    with pytest.raises(TypeError, match=r"Pair option E_wheel_Pa = '210e9': expected a number .*got str"):
        mhcontact.Pair(w, r, {"rail_inclination": "as-is", "E_wheel_Pa": "210e9"})
    with pytest.raises(TypeError, match=r"Pair option method = 3: expected a str .*got int"):
        mhcontact.Pair(w, r, {"rail_inclination": "as-is", "method": 3})
    with pytest.raises(TypeError, match=r"Pair option positioning = None: expected a str"):
        mhcontact.Pair(w, r, {"rail_inclination": "as-is", "positioning": None})
    pair = mhcontact.Pair(w, r, {"E_wheel_Pa": np.float64(210e9), "rail_inclination": "as-is"})  # numpy scalars, ints
    with pytest.raises(TypeError, match=r"tY_m = 'a': expected a number \[m\], got str"):
        pair.solve("a", Q_N=50e3)
    with pytest.raises(TypeError, match=r"Q_N = \['x'\]: expected numbers"):
        pair.solve_many([0.0], Q_N=["x"])


def test_pair_warnings_are_the_command_s():
    """The Manchester rail file is canted 1:40 already: canted again it lies at 2.86 deg. The command
    warns; pair.warnings has the same words."""
    w, r = _manchester_profiles()
    twice = mhcontact.Pair(w, r, {"rail_inclination": "1:40"})
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "twice.json")
        with open(path, "w") as f:
            f.write('{"wheel": {"profile": "%s"}, "rail": {"profile": "%s", "inclination": "1:40"},'
                    ' "sweep": {"tY_mm": [0], "Q_kN": [50]}}'
                    % (os.path.join(SRC, "profiles", "MBench_S1002_v3.prw"),
                       os.path.join(SRC, "profiles", "MBench_UIC60_v3.prr")))
        run = subprocess.run([BINARY, "geometry", path, "-o", os.path.join(d, "geo")], capture_output=True, text=True)
        assert run.returncode == 0, run.stderr
        from_file = mhcontact.Pair.from_case_file(path)
    prefix = "mhcontact: warning: "
    command = [line[len(prefix):] for line in run.stderr.splitlines() if line.startswith(prefix)]
    assert any("and the case cants it again" in x for x in command)
    assert twice.warnings == command
    assert from_file.warnings == command
    assert mhcontact.Pair(w, r, {"rail_inclination": "as-is"}).warnings == []


def test_explicit_positioning():
    s1002, rail = mhcontact.Profile.standard("S1002"), mhcontact.Profile.standard("60E1")
    # A misplaced wheel (flange-back distance 50 mm short) is refused; the message names the
    # explicit placement that reproduces it, and that placement builds.
    with pytest.raises(mhcontact.InputError, match="gauge positioning misplaces the wheel") as e:
        mhcontact.Pair(s1002, rail, {"rail_inclination": "1:40", "flange_back_distance_m": 1.260})
    off_mm = float(str(e.value).split('"lateral_offset_mm": ')[1].split("}")[0])
    mhcontact.Pair(s1002, rail, {"rail_inclination": "1:40", "flange_back_distance_m": 1.260,
                                 "positioning": "explicit", "lateral_offset_m": off_mm * 1e-3})
    # Explicit at the gauge rule's offset for the standard track: the same numbers.
    with pytest.raises(mhcontact.InputError) as e:
        mhcontact.Pair(s1002, rail, {"rail_inclination": "1:40", "flange_back_distance_m": 1.430})
    wide_mm = float(str(e.value).split('"lateral_offset_mm": ')[1].split("}")[0])
    gauge = mhcontact.Pair(s1002, rail, {"rail_inclination": "1:40"})
    explicit = mhcontact.Pair(s1002, rail, {"rail_inclination": "1:40", "positioning": "explicit",
                                            "lateral_offset_m": (wide_mm - 35.0) * 1e-3})  # 70 mm / 2 back
    a, b = gauge.solve(2e-3, Q_N=80e3), explicit.solve(2e-3, Q_N=80e3)
    assert a["Fy_kN"] == pytest.approx(b["Fy_kN"], rel=1e-6)
    assert a["pmax_MPa"] == pytest.approx(b["pmax_MPa"], rel=1e-6)
    with pytest.raises(ValueError, match="positioning = \"sideways\""):
        mhcontact.Pair(s1002, rail, {"rail_inclination": "as-is", "positioning": "sideways"})
    with pytest.raises(ValueError, match="only used with positioning MHC_POSITIONING_EXPLICIT"):
        mhcontact.Pair(s1002, rail, {"rail_inclination": "as-is", "lateral_offset_m": 1e-3})


def test_one_judge_through_every_entry_point():
    """The same status and warnings from the command, a batch manifest and Python (over the C
    interface) on a worn measured pair, unsmoothed, 120 kN: t_Y 4 and 5.5 mm carry a corner of the
    gap inside the patch (gap_kink 0.161, 0.149 > 0.1), `outside_validity` by the multi-Hertzian
    method, handed to the strips by auto (docs/status.md, the judge)."""
    data = os.path.join(SRC, "tests", "data", "profiles")
    common = {"material": {"E_GPa": 210, "nu": 0.28}, "geometry": {"smoothing_mm": 0},
              "sweep": {"tY_mm": [3, 4, 5.5], "Q_kN": [120]}}
    import json
    with tempfile.TemporaryDirectory() as d:
        for method in ("multi-hertzian", "auto"):
            case = dict(common, method=method,
                        wheel={"profile": os.path.join(data, "avg_wheel.whl"), "nominal_radius_mm": 460},
                        rail={"profile": os.path.join(data, "avg_HR.BAN"), "inclination": "1:40"})
            manifest = dict(common, method=method, nominal_radius_mm=460, inclination="1:40",
                            pairs=[{"name": "worn", "wheel": os.path.join(data, "avg_wheel.whl"),
                                    "rail": os.path.join(data, "avg_HR.BAN")}])
            paths = {}
            for name, doc in (("case", case), ("batch", manifest)):
                paths[name] = os.path.join(d, f"{method}-{name}.json")
                with open(paths[name], "w") as f:
                    json.dump(doc, f)
                subprocess.run([BINARY, "run", paths[name], "-o", os.path.join(d, f"{method}-{name}"), "-q",
                                "--format", "csv"], check=True)
            rows = {}
            for name in ("case", "batch"):
                with open(os.path.join(d, f"{method}-{name}", "cases.csv")) as f:
                    rows[name] = [(r["status"], r["method"], r["warnings"]) for r in csv.DictReader(f)]
            assert rows["case"] == rows["batch"]
            p = mhcontact.Pair.from_case_file(paths["case"])
            cols = p.solve_many(np.array([3e-3, 4e-3, 5.5e-3]), Q_N=120e3)
            py = [(s, m, ";".join(w["text"] for w in ws))
                  for s, m, ws in zip(cols["status"], cols["method"], cols["warnings"])]
            assert py == rows["case"], (py, rows["case"])
            one = [p.solve(t, Q_N=120e3) for t in (3e-3, 4e-3, 5.5e-3)]
            assert [(o["status"], o["method"], ";".join(w["text"] for w in o["warnings"])) for o in one] == rows["case"]
            if method == "multi-hertzian":
                for r in rows["case"][1:]:
                    assert r[0] == "outside_validity" and "gap_kink=" in r[2], r
                kink = [w for w in cols["warnings"][1] if w["class"] == "non_hertzian"][0]
                assert kink["measures"][0]["name"] == "gap_kink" and kink["measures"][0]["value_si"] > 0.1
                assert kink["contact_kind"] == "ellipse" and kink["outside_validity"]
            else:
                for r in rows["case"][1:]:
                    assert r[1] == "strips" and "gap_kink=" in r[2], r


def _command_rows_and_pair(case):
    """The case (a dict) run by the command: its cases.csv rows, and the Pair of the same case file."""
    import json
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "case.json")
        with open(path, "w") as f:
            json.dump(case, f)
        subprocess.run([BINARY, "run", path, "-o", os.path.join(d, "out"), "-q", "--format", "csv"], check=True)
        with open(os.path.join(d, "out", "cases.csv")) as f:
            rows = list(csv.DictReader(f))
        return rows, mhcontact.Pair.from_case_file(path)


def test_planar_extent_judged_alike_by_the_command_and_python():
    """A 10 mm circle in a 10.02 mm groove, strips: the patch wraps 37.5 and 52 deg round the rail
    at 5 and 20 kN, beyond the planar approach's extent (edge_tilt_deg > 35: outside_validity),
    24 deg at 1 kN (ok). The command and Python say the same (docs/trust.md "Evidence domains")."""
    data = os.path.join(SRC, "tests", "data", "profiles")
    case = {"wheel": {"profile": os.path.join(data, "circ_r10.prw"), "nominal_radius_mm": 300},
            "rail": {"profile": os.path.join(data, "groove_r1002.prr"), "inclination": "as-is"},
            "track": {"positioning": "explicit", "lateral_offset_mm": 0},
            "material": {"E_GPa": 210, "nu": 0.3}, "method": "strips",
            "sweep": {"tY_mm": [0], "Q_kN": [1, 5, 20]}}
    rows, p = _command_rows_and_pair(case)
    rows = [(r["status"], r["warnings"]) for r in rows]
    py = []
    for Q in (1e3, 5e3, 20e3):
        o = p.solve(0.0, Q_N=Q)
        py.append((o["status"], ";".join(w["text"] for w in o["warnings"])))
    assert py == rows, (py, rows)
    assert rows[0] == ("ok", "")
    for status, warnings in rows[1:]:
        assert status == "outside_validity" and "edge_tilt_deg=" in warnings, (status, warnings)


def test_smoothing_band_reported_alike_by_the_command_and_python():
    """A measured MiniProf rail (avg_low2.ban, smoothed for contact) under S1002, strips and auto:
    the smoothing's uncertainty band (pmax_half_L_MPa ...) and its smoothing_sensitive warning
    were the command's only; solve and solve_many give the same numbers and warning texts as
    cases.csv (docs/profiles.md "Uncertainty band"), auto's multi-Hertzian rows too (their window
    fit's band), and smoothing_band False none."""
    band = ("pmax_half_L_MPa", "pmax_double_L_MPa", "area_half_L_mm2", "area_double_L_mm2")
    data = os.path.join(SRC, "tests", "data", "profiles")
    tY, Q = [0, 2, 2.5, 10], [20, 60]
    for method in ("strips", "auto"):
        case = {"wheel": {"profile": {"standard": "S1002"}, "nominal_radius_mm": 460},
                "rail": {"profile": os.path.join(data, "avg_low2.ban"), "inclination": "as-is"},
                "material": {"E_GPa": 210, "nu": 0.28}, "method": method,
                "sweep": {"tY_mm": tY, "Q_kN": Q}}
        rows, p = _command_rows_and_pair(case)
        many = p.solve_many([t * 1e-3 for t in tY for _ in Q], Q_N=[q * 1e3 for _ in tY for q in Q])
        assert len(rows) == len(tY) * len(Q)
        for i, r in enumerate(rows):
            one = p.solve(float(r["tY_mm"]) * 1e-3, Q_N=float(r["Q_kN"]) * 1e3)
            for o, k in [(one, None), (many, i)]:
                for c in band:
                    got = o[c] if k is None else o[c][k]
                    if r[c] == "":
                        assert math.isnan(got), (method, r["tY_mm"], r["Q_kN"], c, got)
                    else:
                        assert got == pytest.approx(float(r[c]), rel=1e-9), (method, r["tY_mm"], r["Q_kN"], c)
                texts = [w["text"] for w in (o["warnings"] if k is None else o["warnings"][k])]
                assert ";".join(texts) == r["warnings"], (method, r["tY_mm"], r["Q_kN"], texts, r["warnings"])
        if method == "strips":  # the band on every row, smoothing_sensitive on some (measured 2 Dec 2026)
            assert all(r["pmax_half_L_MPa"] != "" for r in rows)
            assert any("smoothing_sensitive" in r["warnings"] for r in rows)
        else:  # auto: the rows kept multi-Hertzian carry their window fit's band
            kept = [r for r in rows if r["method"] == "multi-hertzian"]
            assert kept and all(r["pmax_half_L_MPa"] != "" for r in kept)
        p.set_smoothing_band(False)
        off = p.solve(2e-3, Q_N=20e3)
        assert math.isnan(off["pmax_half_L_MPa"]) and not [w for w in off["warnings"] if w["class"] == "smoothing_sensitive"]
    with pytest.raises(TypeError, match="smoothing_band = 1: expected a bool"):
        mhcontact.Pair(mhcontact.Profile.standard("S1002"), mhcontact.Profile.standard("60E1"),
                       {"rail_inclination": "1:40", "smoothing_band": 1})


def test_rail_inclination_spelt_and_required_as_in_the_case_file():
    # Issue 38: the inclination was a number defaulting to 0 (as-is) while the case file requires
    # an explicit "as-is" or "1:N". The same words, the same choice required.
    w, r = mhcontact.Profile.standard("S1002"), mhcontact.Profile.standard("60E1")
    with pytest.raises(ValueError, match=r'rail_inclination: required: "as-is" .* or "1:N"'):
        mhcontact.Pair(w, r, {})
    with pytest.raises(ValueError, match=r'rail_inclination = 40: give "as-is"'):
        mhcontact.Pair(w, r, {"rail_inclination": 40})
    with pytest.raises(ValueError, match=r'rail_inclination = "1:4": must be'):
        mhcontact.Pair(w, r, {"rail_inclination": "1:4"})
    with pytest.raises(ValueError, match=r'rail_inclination = "1/40": must be'):
        mhcontact.Pair(w, r, {"rail_inclination": "1/40"})
    canted = mhcontact.Pair(w, r, {"rail_inclination": "1:40"}).solve(0.0, Q_N=80e3)
    upright = mhcontact.Pair(w, r, {"rail_inclination": "as-is"}).solve(0.0, Q_N=80e3)
    assert canted["gamma_main_deg"] != upright["gamma_main_deg"]  # the cant was applied, or not
