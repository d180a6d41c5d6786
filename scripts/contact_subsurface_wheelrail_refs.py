#!/usr/bin/env python3
"""CONTACT references for the stresses below a wheel-rail patch under its own solved traction
(tests/data/contact_subsurface_wheelrail/).

CONTACT solves the Manchester benchmark's case A-2.2 for the right wheel (its own shipped deck
examples/mbench_a22_right.inp: S1002 on UIC60 canted 1:40, Fz = 10 kN, mu = 0.3, 0.2 x 0.2 mm
elements, module 1, exact steady rolling) at the pose and velocities of chosen cases (the yaw of
A-2.2: 2.4 mrad per mm of t_Y), and computes, in the same run, the stresses in the rail (its body 1)
below its own normal and tangential solution (subsurface option S = 3, A_s = 2: the full tensor,
ISUBS = 6) at the centre of every element along x on every second row, at a list of depths. The
test solves the same case with mhcontact's half-space method (its own patch from its own geometry,
its own exact tangential solve with CONTACT's creepages) and compares the stresses below ITS
pressure and traction: the whole chain against an independent program.

Cases (the row of CONTACT's A-2.2 deck):
  tread_yaw     case 2: t_Y 0.5 mm, yaw 1.2 mrad, contact angle 3.3 deg, nearly full slip
  gauge_spin    case 12: t_Y 5.5 mm, yaw 13.2 mrad, the gauge corner at 19.3 deg, large spin
  gauge_noyaw   case 12 with the yaw and the roll set to zero: the wheel's pose of mhcontact's
                two-dimensional geometry (no contact point lead), so that the patches compare

Outputs per case: CASE_pressure.csv (x, s [mm] element centres in CONTACT's contact frame, pn [MPa],
px, ps [MPa] on the rail, every element in contact), CASE_stresses.csv (x, y, z [mm], the six
components [MPa], tension positive, the rail); cases.csv (creepages, totals, contact angle).

Usage: /usr/bin/python3 scripts/contact_subsurface_wheelrail_refs.py CONTACT_BINARY CONTACT_EXAMPLES_DIR [OUT_DIR]
"""
import os
import re
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from contact_subsurface_refs import run  # noqa: E402  (one home for CONTACT's files)

DEPTHS = [0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0, 2.5, 3.0]
CASES = [("tread_yaw", 2, False), ("gauge_spin", 12, False), ("gauge_noyaw", 12, True)]


def deck(examples, case, upright):
    """CONTACT's A-2.2 right-wheel deck: its first case's settings with case `case`'s pose and
    velocities (`upright`: its roll and yaw set to 0), the .mat file (A = 1) and the subsurface
    points."""
    lines = open(os.path.join(examples, "mbench_a22_right.inp")).read().splitlines()
    start = [i for i, l in enumerate(lines) if l.strip().endswith("MODULE")]
    first = lines[start[0]:start[1]]
    this = lines[start[case - 1]:start[case]]
    pose = [l for l in this if "S, Y, FZ" in l][0]
    if upright:  # S, Y, FZ, ROLL, YAW, PITCH: roll and yaw 0
        f = pose.split()
        pose = "  " + "  ".join(f[:3] + ["0.0", "0.0"] + f[5:])
    vel = [l for l in this if "VS,VY,VZ" in l][0]
    out = []
    for l in first:
        if "C-P-B-T-N-F-S" in l:
            l = " 1203103    C-P-B-T-N-F-S   CONFIG, PVTIME, BOUND,  TANG,   NORM,   FORCE,  STRESS"
        elif "H-G-I-A-O-W-R" in l:
            l = " 0001321    H-G-I-A-O-W-R"
        elif "S, Y, FZ" in l:
            l = pose
        elif "VS,VY,VZ" in l:
            l = vel
        out.append(l)
    out += ["   2   1        MATFIL, OUTPUT", "   6            ISUBS",
            "   1  1  999   IXL, IXINC, IXH", "   1  2  999   IYL, IYINC, IYH",
            "   {0}          NZ".format(len(DEPTHS)), "   " + " ".join(str(z) for z in DEPTHS),
            "   0            ISUBS", " 0  MODULE", ""]
    return "\n".join(out), pose


def totals(outfile):
    """CONTACT's creepages, forces and the patch's contact angle from its .out file: each a row of
    names followed by a row of values."""
    lines = open(outfile).read().splitlines()
    v = {}
    for a, b in zip(lines, lines[1:]):
        names, vals = a.split(), b.split()
        for want in ("CKSI", "FN", "DELTCP(TR)"):
            if want in names and len(vals) == len(names) and want not in v:
                v.update((n, float(x)) for n, x in zip(names, vals))
    return [v["CKSI"], v["CETA"], v["CPHI"]], [v["FN"], v["FX"], v["FS"], v["MN"]], v["DELTCP(TR)"]


def main(binary, examples, out):
    os.makedirs(out, exist_ok=True)
    work = tempfile.mkdtemp(prefix="contact_subs_wr_")
    for f in ("MBench_S1002_v3.prw", "MBench_UIC60_v3.prr"):
        shutil.copy(os.path.join(examples, f), work)
    rows = ["case,a22_case,tY_mm,yaw_mrad,cksi,ceta,cphi_per_mm,deltcp_rad,FN_N,FX_N,FS_N,MN_Nmm,dx_mm,ds_mm,n_contact,n_points,"
            "length_mm,width_mm,pmax_MPa\n"]
    for name, case, upright in CASES:
        d, pose = deck(examples, case, upright)
        (hdr, elems), subs = run(binary, work, name, d)
        ck, f, delta = totals(os.path.join(work, name + ".out"))
        mx = int(hdr["MX"])
        xl, yl, dx, dy = hdr["XL"], hdr["YL"], hdr["DX"], hdr["DY"]
        n = 0
        with open(os.path.join(out, name + "_pressure.csv"), "w") as fo:
            fo.write("x_mm,s_mm,pn_MPa,px_MPa,ps_MPa\n")
            for e in elems:
                if e["PN"] <= 0:
                    continue
                k = int(e["I"]) - 1
                x, y = xl + (k % mx + 0.5) * dx, yl + (k // mx + 0.5) * dy
                fo.write(f"{x:.10g},{y:.10g},{e['PN']:.6g},{e['PX']:.6g},{e['PY']:.6g}\n")
                n += 1
        # Per depth, over CONTACT's points: the largest von Mises stress and where (x, s from the
        # pressure centroid), and the orthogonal shear amplitude: per row (s, z) half the range of
        # sigma_xz along x with the unloaded 0 included (the pass of the load), the largest row and its s.
        pc = [e for e in elems if e["PN"] > 0]
        w = sum(e["PN"] for e in pc)
        xs = [xl + ((int(e["I"]) - 1) % mx + 0.5) * dx for e in pc]
        ss = [yl + ((int(e["I"]) - 1) // mx + 0.5) * dy for e in pc]
        xc = sum(e["PN"] * x for e, x in zip(pc, xs)) / w
        sc = sum(e["PN"] * y for e, y in zip(pc, ss)) / w
        vm, rng = {}, {}
        kept = 0
        for r in subs:
            z = r["Z"]
            if z <= 0:
                continue
            kept += 1
            sx, sy, sz, txy, txz, tyz = (r[c] for c in ("SIGXX", "SIGYY", "SIGZZ", "SIGXY", "SIGXZ", "SIGYZ"))
            v = (0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2) + 3 * (txy ** 2 + txz ** 2 + tyz ** 2)) ** 0.5
            if z not in vm or v > vm[z][0]:
                vm[z] = (v, r["X"] - xc, r["Y"] - sc)
            lo, hi = rng.get((z, r["Y"]), (0.0, 0.0))
            rng[(z, r["Y"])] = (min(lo, txz), max(hi, txz))
        with open(os.path.join(out, name + "_depths.csv"), "w") as fo:
            fo.write("z_mm,vm_max_MPa,vm_x_mm,vm_s_mm,orth_amp_MPa,orth_s_mm\n")
            for z in sorted(vm):
                amp, at = max((0.5 * (hi - lo), yy - sc) for (zz, yy), (lo, hi) in rng.items() if zz == z)
                v, vx, vs = vm[z]
                fo.write(f"{z:g},{v:.6g},{vx:.4g},{vs:.4g},{amp:.6g},{at:.4g}\n")
        x_lo, x_hi, s_lo, s_hi = min(xs) - dx / 2, max(xs) + dx / 2, min(ss) - dy / 2, max(ss) + dy / 2
        p = pose.split()
        rows.append(f"{name},{case},{p[1]},{float(p[4]) * 1e3:.6g},{ck[0]:.6g},{ck[1]:.6g},{ck[2]:.6g},{delta:.6g},"
                    f"{f[0]:.6g},{f[1]:.6g},{f[2]:.6g},{f[3]:.6g},{dx:.10g},{dy:.10g},{n},{kept},"
                    f"{x_hi - x_lo:.4g},{s_hi - s_lo:.4g},{max(e['PN'] for e in pc):.6g}\n")
    open(os.path.join(out, "cases.csv"), "w").write("".join(rows))
    shutil.rmtree(work)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], sys.argv[3] if len(sys.argv) > 3 else "tests/data/contact_subsurface_wheelrail")
