#!/usr/bin/env python3
"""The Manchester A-2.2 references of tests/data/contact_tangential/mbench_a22_right.csv.

Reads CONTACT's shipped input deck and expected output of the benchmark's case A-2.2, right wheel
(examples/mbench_a22_right.inp and .ref_out of CONTACT, github.com/eve70a/CONTACT) and writes one
row per case: the wheelset's lateral position, yaw, roll and pitch rate from the deck (the pitch
rate is the deck's VPITCH of each case, not V over the nominal radius), and from the output the
contact patch's angle, creepages and total forces as CONTACT prints them (its signs and units;
tests/data/contact_tangential/README.md says how they map onto mhcontact's).

    python3 scripts/contact_a22_refs.py CONTACT_EXAMPLES_DIR OUT.csv
"""
import re
import sys


def numbers(line):
    return [float(x) for x in line.split()]


def parse_output(ref):
    """One dict per case of a CONTACT module-1 output (its lines): the patch's angle, creepages,
    total forces, the track-frame forces and the element counts, as CONTACT prints them."""
    rows, cur = [], None
    for i, l in enumerate(ref):
        if re.match(r"^ Case +\d+", l):
            cur = {"case": int(l.split()[1])}
            rows.append(cur)
            cur["npatch"] = 0
        elif "DELTCP(TR)" in l:
            cur["npatch"] += 1
            cur["deltcp_rad"] = numbers(ref[i + 1])[3]
        elif l.split()[:3] == ["CHI", "DQ", "VELOC"]:
            v = numbers(ref[i + 1])
            cur["cksi"], cur["ceta"], cur["cphi_per_mm"] = v[3], v[4], v[5]
        elif l.split()[:3] == ["FN", "FX", "FS"]:
            v = numbers(ref[i + 1])
            cur["FN_N"], cur["FX_N"], cur["FS_N"], cur["MN_Nmm"] = v[:4]
        elif l.split()[:3] == ["FX(TR)", "FY(TR)", "FZ(TR)"]:
            v = numbers(ref[i + 1])
            cur["FY_TR_N"], cur["FZ_TR_N"] = v[1], v[2]
        elif l.split()[:3] == ["NPOT", "NCON", "NADH"]:
            v = numbers(ref[i + 1])
            cur["ncon"], cur["nadh"] = int(v[1]), int(v[2])
    return rows


def deck_inputs(inp):
    """Per case of a module-1 deck (its lines): the S, Y, FZ, ROLL, YAW, PITCH and the VS, VY, VZ,
    VROLL, VYAW, VPITCH lines' numbers."""
    pose = [numbers(l.split("S, Y")[0]) for l in inp if "S, Y, FZ, ROLL, YAW, PITCH" in l]
    vel = [numbers(l.split("VS,VY")[0]) for l in inp if "VS,VY,VZ, VROLL,VYAW,VPITCH" in l]
    return pose, vel


def main(examples, out):
    pose, vel = deck_inputs(open(f"{examples}/mbench_a22_right.inp").read().splitlines())
    rows = parse_output(open(f"{examples}/mbench_a22_right.ref_out").read().splitlines())
    assert len(rows) == len(pose) == len(vel) == 21, (len(rows), len(pose), len(vel))
    cols = ["case", "tY_mm", "yaw_mrad", "npatch", "deltcp_rad", "cksi", "ceta", "cphi_per_mm",
            "FN_N", "FX_N", "FS_N", "MN_Nmm", "FY_TR_N", "FZ_TR_N", "ncon", "nadh",
            "roll_rad", "vs_mm_s", "vpitch_rad_s"]
    with open(out, "w") as f:
        f.write(",".join(cols) + "\n")
        for r, p, v in zip(rows, pose, vel):
            r["tY_mm"], r["yaw_mrad"] = p[1], p[4] * 1e3
            r["roll_rad"], r["vs_mm_s"], r["vpitch_rad_s"] = p[3], v[0], v[5]
            # CONTACT's printed numbers to their 4 digits; the deck's inputs as written there.
            full = {"roll_rad", "vs_mm_s", "vpitch_rad_s"}
            f.write(",".join((f"{r[c]:.10g}" if c in full else f"{r[c]:g}") if isinstance(r[c], float) else str(r[c])
                             for c in cols) + "\n")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
