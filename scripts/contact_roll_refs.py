#!/usr/bin/env python3
"""CONTACT references for the wheelset's roll: tests/data/contact_tangential/mbench_roll_right.csv.

The deck is CONTACT's shipped Manchester A-2.2 right-wheel deck (examples/mbench_a22_right.inp of
github.com/eve70a/CONTACT: S1002 on UIC60 1:40, FZ 10 kN, mu 0.3, 0.2 mm elements, V 2 m/s) with
its first case's settings kept and the cases replaced: the wheelset at Y 0, 2, 4 mm, no yaw, the
pitch rate of A-2.2's first case, and the roll ROLL departing from A-2.2's own roll at that Y (the
wheelset's kinematic roll: 0, -0.1128, -0.2557 mrad) by -1 ... 1 mrad. CONTACT rotates the
wheel profile by ROLL about the wheelset axis; mhcontact's wheelset call keeps each wheel upright
on its rail (the roll only moves the wheels' heights, docs/c-api.md "The wheelset call"), so the
rows measure what that neglect costs.

    python3 scripts/contact_roll_refs.py deck CONTACT_EXAMPLES_DIR RUNDIR     # writes RUNDIR/mbench_roll_right.inp
    (cd RUNDIR && cp CONTACT_EXAMPLES_DIR/MBench_* . && OMP_NUM_THREADS=1 contact_linux64 2 mbench_roll_right)
    python3 scripts/contact_roll_refs.py parse RUNDIR OUT.csv
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from contact_a22_refs import deck_inputs, parse_output  # noqa: E402

Y_MM = [0.0, 2.0, 4.0]
# A-2.2's own roll at these Y (its deck: the wheelset's kinematic roll, both wheels touching).
ROLL_KIN_MRAD = {0.0: 0.0, 2.0: -0.11280, 4.0: -0.25570}
# The departures from it.
DROLL_MRAD = [-1.0, -0.5, -0.2, -0.1, 0.0, 0.1, 0.2, 0.5, 1.0]
NAME = "mbench_roll_right"


def make_deck(examples, rundir):
    src = open(f"{examples}/mbench_a22_right.inp").read().splitlines()
    # The first case whole (its settings), the later cases in the deck's short form (case 2's flags).
    first_end = next(i for i, l in enumerate(src) if "VS,VY,VZ, VROLL,VYAW,VPITCH" in l)
    first = src[:first_end + 1]
    i2 = next(i for i in range(first_end + 1, len(src)) if src[i].strip().endswith("MODULE"))
    short = src[i2:i2 + 4]
    vel = src[first_end]
    out, n = [], 0
    for y in Y_MM:
        for d in DROLL_MRAD:
            roll = ROLL_KIN_MRAD[y] + d
            n += 1
            pose = f"  0.0  {y:.1f}  10000. {roll * 1e-3:.8f} 0.0000  0.0      S, Y, FZ, ROLL, YAW, PITCH"
            out.append(f"\n%  {n}: Lateral displacement {y:.1f} mm, roll {roll:+.4f} mrad, no yaw\n")
            if n == 1:
                body = [l for l in first if not l.startswith("%")]
                body = [pose if "S, Y, FZ, ROLL, YAW, PITCH" in l else l for l in body]
                out.extend(l for l in body if l.strip())
            else:
                out.extend(short)
                out.append(pose)
                out.append(vel)
    hdr = [l for l in src[:first_end] if l.startswith("%")][:4]
    hdr = ["% mhcontact: scripts/contact_roll_refs.py, from CONTACT's examples/mbench_a22_right.inp:",
           "% the wheelset at Y 0, 2, 4 mm, roll the kinematic one -1 ... +1 mrad, no yaw."] + hdr
    os.makedirs(rundir, exist_ok=True)
    with open(f"{rundir}/{NAME}.inp", "w") as f:
        f.write("\n".join(hdr + out + ["", " 0 MODULE"]) + "\n")


def parse(rundir, out):
    pose, vel = deck_inputs(open(f"{rundir}/{NAME}.inp").read().splitlines())
    rows = parse_output(open(f"{rundir}/{NAME}.out").read().splitlines())
    assert len(rows) == len(pose) == len(vel) == len(Y_MM) * len(DROLL_MRAD), (len(rows), len(pose), len(vel))
    cols = ["case", "tY_mm", "roll_rad", "droll_rad", "npatch", "deltcp_rad", "cksi", "ceta", "cphi_per_mm",
            "FN_N", "FX_N", "FS_N", "MN_Nmm", "FY_TR_N", "FZ_TR_N", "ncon", "nadh", "vs_mm_s", "vpitch_rad_s"]
    full = {"roll_rad", "droll_rad", "vs_mm_s", "vpitch_rad_s"}
    with open(out, "w") as f:
        f.write(",".join(cols) + "\n")
        for r, p, v in zip(rows, pose, vel):
            r["tY_mm"], r["roll_rad"], r["vs_mm_s"], r["vpitch_rad_s"] = p[1], p[3], v[0], v[5]
            r["droll_rad"] = p[3] - ROLL_KIN_MRAD[p[1]] * 1e-3
            f.write(",".join((f"{r[c]:.10g}" if c in full else f"{r[c]:g}") if isinstance(r[c], float) else str(r[c])
                             for c in cols) + "\n")


if __name__ == "__main__":
    if sys.argv[1] == "deck":
        make_deck(sys.argv[2], sys.argv[3])
    else:
        parse(sys.argv[2], sys.argv[3])
