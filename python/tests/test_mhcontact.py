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
    assert mhcontact.fft_backend in ("kissfft", "fftw3")
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
    assert list(cols) == list(mhcontact.CASE_COLUMNS)
    for name in ("dz_virtual_mm", "approach_mm", "residual", "Fz_kN", "Fy_kN", "pmax_MPa", "area_mm2",
                 "gamma_main_deg", "r_roll_main_mm", "iterations"):
        table = np.array([float(r[name]) if r[name] != "" else math.nan for r in rows])
        np.testing.assert_array_equal(cols[name], table, err_msg=name)  # bit for bit
    assert list(cols["status"]) == [r["status"] for r in rows]
    assert list(cols["method"]) == [r["method"] for r in rows]
    assert list(cols["n_contacts"]) == [int(r["n_contacts"]) for r in rows]
    assert list(cols["n_warnings"]) == [int(r["n_warnings"]) for r in rows]
    one = pair.solve(tY[40], Q_N=Q[40])
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
    with pytest.raises(mhcontact.UnsupportedError, match="roll"):
        pair.solve(0.0, Q_N=50e3, roll_rad=0.01)
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
    p1 = mhcontact.Pair(w, r, {"rail_inclination": 40, "tY_min_m": -8e-3, "tY_max_m": 10e-3})
    p2 = mhcontact.Pair(w2, r, {"rail_inclination": 40, "tY_min_m": -8e-3, "tY_max_m": 10e-3})
    assert p1.tY_range_m == pytest.approx((-8e-3, 10e-3))
    a = p1.solve(1e-3, Q_N=60e3)
    b = p2.solve(1e-3, Q_N=60e3)
    assert a["Fy_kN"] == pytest.approx(b["Fy_kN"], rel=1e-6)
    assert a["contacts"] and a["contacts"][0]["N_kN"] > 0
    with pytest.raises(TypeError, match="unknown option"):
        mhcontact.Pair(w, r, {"gage_m": 1.435})
