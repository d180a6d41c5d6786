"""The Python module's pressure and traction grids (docs/python.md "Pressure and traction grids"):
Pair.pressure_grid against pressure.csv of `mhcontact run --pressure-grid` for the same case file,
every column of every row at the file's full digits (the command's file against the library call):
FASTSIM ellipses with friction, and the plastic pair's elastic column; and its argument errors.
Run by ctest (python.pytest) with the module's other tests.
Break seen to fail: the traction columns multiplied by 1e6 instead of divided (python/grids_module.cpp)."""
import csv
import os
import subprocess
import sys
import tempfile

import numpy as np
import pytest

import mhcontact

SRC = os.environ.get("MHCONTACT_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("MHCONTACT_BINARY", "mhcontact")


def command_grid(case, n):
    with tempfile.TemporaryDirectory() as d:
        subprocess.run([BINARY, "run", case, "-o", d, "--digits", "max", "-q", "--format", "csv", "--pressure-grid",
                        str(n), "--force"], check=True)
        with open(os.path.join(d, "cases.csv")) as f:
            cases = list(csv.DictReader(f))
        with open(os.path.join(d, "pressure.csv")) as f:
            points = list(csv.DictReader(f))
    return cases, points


@pytest.mark.parametrize("name", ["manchester-tangential", "manchester-plastic"])
def test_pressure_grid_as_the_command(name):
    case = os.path.join(SRC, "cases", name + ".json")
    n = 7
    cases, points = command_grid(case, n)
    pair = mhcontact.Pair.from_case_file(case)
    columns = [c for c in points[0].keys() if c != "case"]
    compared = 0
    for c in (cases if len(cases) <= 6 else cases[::7]):  # manchester-tangential: all five
        got = pair.pressure_grid(float(c["tY_mm"]) * 1e-3, Q_N=float(c["Q_kN"]) * 1e3, n=n)
        want = [p for p in points if p["case"] == c["case"]]
        assert got["method"] == "multi-hertzian"
        assert sorted(k for k in got if k not in ("method", "status")) == sorted(columns)
        assert len(got["p_MPa"]) == len(want) == n * n * int(c["n_contacts"])
        for col in columns:
            w = np.array([float(p[col]) for p in want])
            assert np.array_equal(np.asarray(got[col], dtype=float), w), (c["case"], col)
        compared += len(want)
    assert compared > 0
    if name == "manchester-tangential":
        assert "px_MPa" in columns and "slip" in columns
    else:
        assert "p_elastic_MPa" in columns and "px_MPa" not in columns


def test_pressure_grid_errors():
    pair = mhcontact.Pair.from_case_file(os.path.join(SRC, "cases", "manchester-tangential.json"))
    with pytest.raises(ValueError, match="n = 1: must be between 2 and 1000"):
        pair.pressure_grid(0.0, Q_N=10e3, n=1)
    with pytest.raises(TypeError, match="expected an integer"):
        pair.pressure_grid(0.0, Q_N=10e3, n=2.5)
    with pytest.raises(ValueError, match="exactly one of Q_N"):
        pair.pressure_grid(0.0, n=5)
    empty = pair.pressure_grid(0.0, Q_N=0.0, n=5)  # a lifted wheel: no points
    assert empty["status"] == "no_contact" and len(empty["p_MPa"]) == 0


def test_docs_example_prints_what_the_page_shows():
    """docs/python.md "Pressure and traction grids": the first indented block after the heading is
    the example, the second what it prints; run from the repository's top directory."""
    with open(os.path.join(SRC, "docs", "python.md")) as f:
        text = f.read()
    section = text.split("### Pressure and traction grids", 1)[1].split("\n## ", 1)[0]
    blocks, cur = [], []
    for line in section.split("\n"):
        if line.startswith("    "):
            cur.append(line[4:])
        elif cur:
            blocks.append(cur)
            cur = []
    assert len(blocks) >= 2, "the example and its output"
    code, shown = "\n".join(blocks[0]), blocks[1]
    out = subprocess.run([sys.executable, "-c", code], cwd=SRC, check=True, capture_output=True,
                         text=True, env=dict(os.environ)).stdout.splitlines()
    assert out == shown
