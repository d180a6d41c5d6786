"""The Python module's creep forces (docs/python.md "Creep forces"): the tangential columns of
the command's tables, through solve and solve_many, from a case file with friction or from
set_tangential. Run by ctest (python.pytest) as test_mhcontact.py.
Break seen to fail: Y_over_Q left without the creep forces in solve_many (the table check)."""
import csv
import math
import os
import subprocess
import tempfile

import numpy as np
import pytest

import mhcontact

SRC = os.environ.get("MHCONTACT_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("MHCONTACT_BINARY", "mhcontact")
TANGENTIAL = os.path.join(SRC, "cases", "manchester-tangential.json")
COLS = ("Fx_kN", "Fy_creep_kN", "Mz_Nm", "F_over_muN", "Y_kN", "Fz_creep_kN")


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def test_tangential_columns_as_the_command():
    pair = mhcontact.Pair.from_case_file(TANGENTIAL)
    with tempfile.TemporaryDirectory() as d:
        subprocess.run([BINARY, "run", TANGENTIAL, "-o", d, "--digits", "max", "-q", "--format", "csv"], check=True)
        cases, ells = rows(os.path.join(d, "cases.csv")), rows(os.path.join(d, "ellipses.csv"))
    tY = np.array([float(r["tY_mm"]) for r in cases]) * 1e-3
    many = pair.solve_many(tY, Q_N=10e3, threads=1)
    for c in COLS + ("Y_over_Q", "Fz_kN"):
        np.testing.assert_array_equal(many[c], [float(r[c]) for r in cases], err_msg=c)
    one = pair.solve(8e-3, Q_N=10e3)
    row = [r for r in cases if r["tY_mm"] == "8"][0]
    for c in COLS + ("Y_over_Q",):
        assert one[c] == float(row[c]), c
    e = [r for r in ells if r["tY_mm"] == "8"]
    assert len(one["contacts"]) == len(e)
    for got, want in zip(one["contacts"], e):
        for c, w in (("xi", "xi"), ("eta", "eta"), ("Fx_kN", "Fx_kN"), ("Fs_kN", "Fy_kN"), ("Mz_Nm", "Mz_Nm"),
                     ("adhesion_fraction", "adhesion_fraction"), ("Tgamma_N", "Tgamma_N")):
            assert got[c] == float(want[w]), c
    # Eq. 10.1 of docs/method.md: the vertical load balanced with the creep forces.
    assert sum(c["Fz_kN"] for c in one["contacts"]) + one["Fz_creep_kN"] == pytest.approx(10.0, rel=1e-6)


def test_set_tangential_and_errors():
    pair = mhcontact.Pair(mhcontact.Profile.read(os.path.join(SRC, "profiles", "MBench_S1002_v3.prw"), "wheel"),
                          mhcontact.Profile.read(os.path.join(SRC, "profiles", "MBench_UIC60_v3.prr"), "rail"),
                          {"rail_inclination": "as-is"})
    assert "Fx_kN" not in pair.solve(2e-3, Q_N=10e3)
    assert "Fx_kN" not in pair.solve_many([2e-3], Q_N=10e3)
    pair.set_tangential({"mu": 0.3, "speed_m_s": 30, "yaw_rad_per_m": 2.4})
    ref = mhcontact.Pair.from_case_file(TANGENTIAL).solve(2e-3, Q_N=10e3)
    got = pair.solve(2e-3, Q_N=10e3)
    for c in COLS:
        assert got[c] == ref[c], c
    pair.set_tangential({"mu": 0.3, "eta": 0.05})  # full lateral slip: |F| = mu N
    r = pair.solve(-3e-3, Q_N=10e3)
    assert r["F_over_muN"] == pytest.approx(1, rel=1e-6)
    with pytest.raises(ValueError, match="tangential options.mu = -1"):
        pair.set_tangential({"mu": -1})
    with pytest.raises(TypeError, match="unknown option"):
        pair.set_tangential({"friction": 0.3})
