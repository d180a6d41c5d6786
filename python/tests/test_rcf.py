"""The Python module's RCF, damage and wear access (docs/python.md "RCF, damage and wear"):
Pair.rcf against the RCF and damage columns of the command's ellipses.csv for the same case file,
and hertz_subsurface against the command's subsurface columns of the same contact.
Run by ctest (python.pytest) with the module's other tests.
Break seen to fail: Pair.rcf solving at 0.999 Q (the comparison with the command)."""
import csv
import json
import math
import os
import subprocess
import tempfile

import pytest

import mhcontact

SRC = os.environ.get("MHCONTACT_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("MHCONTACT_BINARY", "mhcontact")
RCF = os.path.join(SRC, "cases", "manchester-rcf.json")
# Pair.rcf key -> ellipses.csv column (the same name unless listed).
KEYS = ("traction_actual", "Tgamma_N", "Tgamma_spin_N", "D_burstow_per_axle", "wear_rate_ug_per_m_mm2", "wear_ug_per_m",
        "p0_el_over_k", "elastic_limit_p0_over_k", "shakedown_limit_p0_over_k", "FI_surf_el", "shakedown_regime")


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def run(case, d):
    subprocess.run([BINARY, "run", case, "-o", d, "--digits", "max", "-q", "--format", "csv"], check=True)
    return rows(os.path.join(d, "ellipses.csv"))


def test_rcf_as_the_command():
    pair = mhcontact.Pair.from_case_file(RCF)
    with tempfile.TemporaryDirectory() as d:
        ells = run(RCF, d)
    for tY in ("0", "1", "2", "8"):
        want = [r for r in ells if r["tY_mm"] == tY]
        got = pair.rcf(float(tY) * 1e-3, 100e3, k_Pa=300e6)  # the case's shear_yield_MPa
        assert len(got) == len(want) > 0
        for g, w in zip(got, want):
            for k in KEYS:
                if k == "shakedown_regime":
                    assert g[k] == w[k], (tY, k)
                else:
                    assert g[k] == pytest.approx(float(w[k]), rel=1e-12, abs=1e-300), (tY, k)
    # At t_Y = 1 mm ellipse 2 is on the damage function's rising branch (docs/methods.md example).
    assert pair.rcf(1e-3, 100e3, k_Pa=300e6)[1]["D_burstow_per_axle"] > 0


def test_rcf_without_friction_and_k():
    with open(RCF) as f:
        case = json.load(f)
    del case["friction"], case["kinematics"], case["rcf"]
    for side in ("wheel", "rail"):
        case[side]["profile"] = os.path.join(SRC, "profiles", os.path.basename(case[side]["profile"]))
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "case.json")
        with open(path, "w") as f:
            json.dump(case, f)
        c = mhcontact.Pair.from_case_file(path).rcf(0.0, 100e3)[0]
    assert c["N_kN"] > 0 and c["p0_el_MPa"] > 0
    for k in ("traction_actual", "D_burstow_per_axle", "wear_ug_per_m", "p0_el_over_k"):  # no friction, no yield
        assert math.isnan(c[k]), k
    assert c["shakedown_regime"] is None


def test_hertz_subsurface_as_the_command():
    # Without friction the command's ellipse rows take the closed-form full slip f p along x
    # (sub_source hertz_ellipse); with friction given, FASTSIM's traction (not this closed form).
    with open(RCF) as f:
        case = json.load(f)
    for k in ("friction", "kinematics"):
        del case[k]
    case["rcf"] = {"shear_yield_MPa": 300, "traction_coefficient": 0.3, "subsurface": {"dang_van_c": 0.3}}
    case["sweep"] = {"tY_mm": [1], "Q_kN": 100}
    for side in ("wheel", "rail"):
        case[side]["profile"] = os.path.join(SRC, "profiles", os.path.basename(case[side]["profile"]))
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "case.json")
        with open(path, "w") as f:
            json.dump(case, f)
        ells = run(path, os.path.join(d, "out"))
    r = ells[1]
    assert r["sub_source"] == "hertz_ellipse"
    a, b, N = float(r["a_mm"]) * 1e-3, float(r["b_mm"]) * 1e-3, float(r["N_kN"]) * 1e3
    s = mhcontact.hertz_subsurface(a, b, 1.5 * N / (math.pi * a * b), float(r["traction_coefficient"]), 0.0, nu=0.28)
    for key, col, scale in (("vm_max_Pa", "sub_vm_max_MPa", 1e6), ("vm_depth_m", "sub_vm_depth_mm", 1e-3),
                            ("tau_max_Pa", "sub_tau_max_MPa", 1e6), ("tau_orth_amp_Pa", "sub_tau_orth_amp_MPa", 1e6),
                            ("tau_eq_amp_Pa", "sub_tau_eq_amp_MPa", 1e6), ("sigma_h_Pa", "sub_sigma_h_MPa", 1e6)):
        assert s[key] == pytest.approx(float(r[col]) * scale, rel=1e-6), key
    assert s["tau_eq_amp_Pa"] + 0.3 * s["sigma_h_Pa"] == pytest.approx(float(r["FI_sub_MPa"]) * 1e6, rel=1e-6)
    with pytest.raises(ValueError, match="a_m, b_m, p0_Pa"):
        mhcontact.hertz_subsurface(-1e-3, 1e-3, 1e9)


SUB_KEYS = ("sub_vm_max_MPa", "sub_vm_depth_mm", "sub_tau_max_MPa", "sub_tau_depth_mm", "sub_tau_orth_amp_MPa",
            "sub_tau_orth_depth_mm", "sub_tau_eq_amp_MPa", "sub_sigma_h_MPa", "FI_sub_MPa")


def test_subsurface_of_a_solved_patch_as_the_command():
    """Pair.subsurface (mhc_result_subsurface) against the subsurface columns of the command's
    patches.csv: the Manchester half-space pair with friction, CONTACT's creepages of A-2.2 case 2
    (t_Y 0.5 mm, docs/python.md "Subsurface stresses of a solved case"), the patch's own grid."""
    with open(os.path.join(SRC, "cases", "manchester-halfspace.json")) as f:
        case = json.load(f)
    for side in ("wheel", "rail"):
        case[side]["profile"] = os.path.join(SRC, "profiles", os.path.basename(case[side]["profile"]))
    case["friction"] = {"coefficient": 0.3}
    case["creepages"] = {"xi": -4.948e-4, "eta": -1.202e-3, "phi_per_mm": -1.233e-4}
    case["rcf"] = {"shear_yield_MPa": 300, "subsurface": {"grid": True, "dang_van_c": 0.3}}
    case["sweep"] = {"tY_mm": [0.5], "Q_kN": [10]}
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "case.json")
        with open(path, "w") as f:
            json.dump(case, f)
        out = os.path.join(d, "out")  # a run's directory holds only what the run writes
        subprocess.run([BINARY, "run", path, "-o", out, "--digits", "max", "-q", "--format", "csv"], check=True)
        want = rows(os.path.join(out, "patches.csv"))
        got = mhcontact.Pair.from_case_file(path).subsurface(0.5e-3, 10e3, dang_van_c=0.3)
    assert len(got) == len(want) == 1
    assert got[0]["sub_source"] == want[0]["sub_source"] == "grid_patch_solved_traction"
    assert got[0]["warnings"] == []
    for k in SUB_KEYS:
        assert got[0][k] == pytest.approx(float(want[0][k]), rel=1e-12), k
