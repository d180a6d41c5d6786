#!/usr/bin/env python3
"""CONTACT references for the grid methods with a roll: tests/data/contact/contact_mbench_roll_right_q50.csv.

The deck is CONTACT's shipped Manchester A-2.2 right-wheel deck (examples/mbench_a22_right.inp of
github.com/eve70a/CONTACT: S1002 on UIC60 1:40, 0.2 mm elements, D_SEP 8 mm, D_COMB 4 mm) with its
first case's settings kept, frictionless (TANG 0: the normal problem alone; with equal materials
CONTACT's normal solution does not depend on the tangential one) and the cases replaced: the
wheelset at Y (this project's t_Y of the right wheel upright) with the roll ROLL, FZ 50 kN on the
right wheel, no yaw, no pitch. CONTACT rotates the wheel profile by ROLL about the wheelset axis.

    python3 scripts/contact_roll_grid_refs.py deck CONTACT_EXAMPLES_DIR RUNDIR   # RUNDIR/mbench_roll_grid.inp
    (cd RUNDIR && cp CONTACT_EXAMPLES_DIR/MBench_* . && OMP_NUM_THREADS=1 contact_linux64 2 mbench_roll_grid)
    python3 scripts/contact_roll_grid_refs.py parse RUNDIR OUT.csv

One row per case and contact patch: the patch's reference point on the rail (YCP(R), ZCP(R) [mm],
rail profile coordinates, y towards the field side), its contact angle DELTCP [rad] (CONTACT's
sign: negative on the gauge side of the right rail), its normal force FN [N], peak pressure PMAX
[MPa], elements in contact NCON (area = NCON DX DS) and the case's FZ(TR) [N].
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from contact_a22_refs import numbers  # noqa: E402

Y_MM = [0.0, 4.0, 5.0, 6.5, 8.0]
ROLL_MRAD = [-10.0, -5.0, 0.0, 5.0, 10.0]
FZ_N = 50000.0
NAME = "mbench_roll_grid"


def make_deck(examples, rundir):
    src = open(f"{examples}/mbench_a22_right.inp").read().splitlines()
    first_end = next(i for i, l in enumerate(src) if "VS,VY,VZ, VROLL,VYAW,VPITCH" in l)
    first = src[:first_end + 1]
    i2 = next(i for i in range(first_end + 1, len(src)) if src[i].strip().endswith("MODULE"))
    short = src[i2:i2 + 4]
    # Frictionless: TANG (4th digit of C-P-B-T-N-F-S) 0.
    untang = lambda l: re.sub(r"^(\s*)(\d{3})3(\d{3})", r"\g<1>\g<2>0\g<3>", l) if "C-P-B-T-N-F-S" in l else l
    vel = " 2000. 0.0    0.0   0.0        0.0   0.0        VS,VY,VZ, VROLL,VYAW,VPITCH"
    out, n = [], 0
    for y in Y_MM:
        for roll in ROLL_MRAD:
            n += 1
            pose = f"  0.0  {y:.1f}  {FZ_N:.0f}. {roll * 1e-3:.8f} 0.0000  0.0      S, Y, FZ, ROLL, YAW, PITCH"
            out.append(f"\n%  {n}: Lateral displacement {y:.1f} mm, roll {roll:+.4f} mrad, no yaw\n")
            if n == 1:
                body = [untang(l) for l in first if not l.startswith("%")]
                body = [pose if "S, Y, FZ, ROLL, YAW, PITCH" in l else vel if "VS,VY" in l else l for l in body]
                out.extend(l for l in body if l.strip())
            else:
                out.extend(untang(l) for l in short)
                out.append(pose)
                out.append(vel)
    hdr = ["% mhcontact: scripts/contact_roll_grid_refs.py, from CONTACT's examples/mbench_a22_right.inp:",
           f"% the wheelset at Y {Y_MM} mm, roll {ROLL_MRAD} mrad, FZ {FZ_N:.0f} N, frictionless, no yaw."]
    os.makedirs(rundir, exist_ok=True)
    with open(f"{rundir}/{NAME}.inp", "w") as f:
        f.write("\n".join(hdr + out + ["", " 0 MODULE"]) + "\n")


def parse_patches(lines):
    """Per case: FZ(TR) and per patch YCP(R), ZCP(R), DELTCP, FN, PMAX, NCON, as CONTACT prints them."""
    cases, cur, patch = [], None, None
    for i, l in enumerate(lines):
        if re.match(r"^ Case +\d+", l):
            cur = {"case": int(l.split()[1]), "patches": []}
            cases.append(cur)
        elif l.split()[:3] == ["FX(TR)", "FY(TR)", "FZ(TR)"]:
            cur["FZ_TR_N"] = numbers(lines[i + 1])[2]
        elif "DATA FOR CONTACT PATCH" in l:
            patch = {}
            cur["patches"].append(patch)
        elif "DELTCP(TR)" in l and "YCP(R)" in l:
            v = numbers(lines[i + 1])
            patch["deltcp_rad"], patch["ycp_r_mm"], patch["zcp_r_mm"] = v[3], v[4], v[5]
        elif l.split()[:2] == ["FN", "FX"]:
            patch["FN_N"] = numbers(lines[i + 1])[0]
        elif l.split()[:2] == ["FN/G", "FX/FSTAT/FN"]:
            patch["pmax_MPa"] = numbers(lines[i + 1])[4]
        elif l.split()[:3] == ["NPOT", "NCON", "NADH"]:
            patch["ncon"] = int(numbers(lines[i + 1])[1])
    return cases


def parse(rundir, out):
    inp = open(f"{rundir}/{NAME}.inp").read().splitlines()
    pose = [numbers(l.split("S, Y")[0]) for l in inp if "S, Y, FZ, ROLL, YAW, PITCH" in l]
    cases = parse_patches(open(f"{rundir}/{NAME}.out").read().splitlines())
    assert len(cases) == len(pose) == len(Y_MM) * len(ROLL_MRAD), (len(cases), len(pose))
    cols = ["case", "Y_mm", "roll_rad", "FZ_N", "npatch", "patch", "ycp_r_mm", "zcp_r_mm", "deltcp_rad", "FN_N",
            "pmax_MPa", "ncon", "area_mm2", "FZ_TR_N"]
    with open(out, "w") as f:
        f.write(",".join(cols) + "\n")
        for c, p in zip(cases, pose):
            for k, P in enumerate(c["patches"]):
                row = [c["case"], f"{p[1]:g}", f"{p[3]:.10g}", f"{p[2]:g}", len(c["patches"]), k + 1,
                       f"{P['ycp_r_mm']:g}", f"{P['zcp_r_mm']:g}", f"{P['deltcp_rad']:g}", f"{P['FN_N']:g}",
                       f"{P['pmax_MPa']:g}", P["ncon"], f"{P['ncon'] * 0.04:.4g}", f"{c['FZ_TR_N']:g}"]
                f.write(",".join(str(x) for x in row) + "\n")


if __name__ == "__main__":
    if sys.argv[1] == "deck":
        make_deck(sys.argv[2], sys.argv[3])
    else:
        parse(sys.argv[2], sys.argv[3])
