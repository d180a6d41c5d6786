#!/usr/bin/env python3
"""CONTACT references for the stresses below a grid patch (tests/data/contact_subsurface/).

For each case, CONTACT solves a contact problem on a grid of piecewise-constant elements (its
influence coefficients C3 = 2) and then computes the stresses in the half-space below it from
that same piecewise-constant load (its subsurface option S = 3, at the centres of a regular
selection of elements, ISUBS = 6, at listed depths). This script keeps both: the loaded elements
(pressure and traction on body 1, as CONTACT writes them to its .mat file) and the stresses at the
points (its .subs file). A test then loads the same elements into mhcontact's grid_subsurface and
compares the stresses at the same points: the comparison tests the stress computation alone.

Cases (CONTACT's units: N, mm, N/mm² = MPa; E = 210 GPa, ν = 0.28 for both bodies):
  hertz_frictionless  module 3, Hertzian gap of an ellipse a = 6 mm, b = 4 mm (IPOTCN = -3),
                      Fn = 80 kN, 40 × 40 elements over 1.1 × the ellipse, no tangential problem
  hertz_rolling       the same, steady rolling (T = 3) with ξ = 0.5 ‰, η = −0.4 ‰, μ = 0.3:
                      partial slip, traction along x and y, not proportional to the pressure
  mbench_frictionless module 1, the Manchester benchmark's right wheel (CONTACT's own
                      examples/mbench_a22_right.inp: S1002 on UIC60 1:40, Fz = 10 kN), t_Y = 4 mm,
                      yaw 9.6 mrad (its case 9), dx = ds = 0.2 mm, frictionless (T = 0)
  mbench_rolling      the same case with friction 0.3 and the deck's steady rolling (T = 3)

Outputs per case: CASE_elements.csv (element centres x, y [mm] in CONTACT's contact frame, pn,
px, py [MPa] on body 1, the elements in contact) and
CASE_stresses.csv (x, y, z [mm], z the depth into body 1, and the six stress components [MPa],
tension positive); cases.csv (the grid: dx, dy [mm], ν, and CONTACT's totals for a check).

Usage: /usr/bin/python3 scripts/contact_subsurface_refs.py CONTACT_BINARY CONTACT_EXAMPLES_DIR [OUT_DIR]
CONTACT_BINARY: CONTACT 25.2 (build: tests/data/contact_subsurface/README.md);
CONTACT_EXAMPLES_DIR: its examples/ folder (for the Manchester profiles).
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

NU = 0.28
G = 82000.0

# Subsurface points: every STEP-th element of the potential contact area, at these depths [mm].
HERTZ_DEPTHS = [0.15, 0.4, 0.8, 1.5, 2.5, 4.0, 6.0]
MBENCH_DEPTHS = [0.1, 0.25, 0.5, 1.0, 1.8, 3.0]
STEP = 3

HERTZ_DECK = """ 3  MODULE
  20{T}103     P-B-T-N-F-S   PVTIME, BOUND , TANG  , NORM  , FORCE , STRESS
  022020     L-D-C-M-Z-E   FRCLAW, DISCNS, INFLCF, MATER , RZNORM, EXRHS
 0001341   H-G-I-A-O-W-R   HEAT, GAUSEI, IESTIM, MATFIL, OUTPUT, FLOW, RETURN
   80   200    5    1      1e-8    MAXGS , MAXIN , MAXNR , MAXOUT, EPS
   80000.0   {cksi}   {ceta}   0.0              FN, CKSI, CETA, CPHI
   0.3  0.3                                     FSTAT, FKIN
{kin}   {nu}  {nu}  {g}  {g}                         POISS 1,2,  GG 1,2
   -3                                           IPOTCN
   40  40  6.0  4.0  1.1                        MX,MY,AA,BB,SCALE
   2   1        MATFIL, OUTPUT
   6            ISUBS
   2  {step}  40        IXL, IXINC, IXH
   2  {step}  40        IYL, IYINC, IYH
   {nz}          NZ
   {zs}
   0            ISUBS
 0  MODULE
"""


def mbench_deck(examples, T):
    """CONTACT's own Manchester A-2.2 deck, right wheel: its first case's settings with case 9's
    pose and velocities, the tangential problem T (0 frictionless, 3 steady rolling), the .mat
    file (A = 1: the elements in contact) and the subsurface points."""
    lines = open(os.path.join(examples, "mbench_a22_right.inp")).read().splitlines()
    start = [i for i, l in enumerate(lines) if l.strip().endswith("MODULE")]
    first = lines[start[0]:start[1]]
    case9 = lines[start[8]:start[9]]
    pose = [l for l in case9 if "S, Y, FZ" in l][0]
    vel = [l for l in case9 if "VS,VY,VZ" in l][0]
    out = []
    for l in first:
        if "C-P-B-T-N-F-S" in l:
            l = " 120{}103    C-P-B-T-N-F-S   CONFIG, PVTIME, BOUND,  TANG,   NORM,   FORCE,  STRESS".format(T)
        elif "H-G-I-A-O-W-R" in l:
            l = " 0001321    H-G-I-A-O-W-R"
        elif "S, Y, FZ" in l:
            l = pose
        elif "VS,VY,VZ" in l:
            l = vel
        out.append(l)
    zs = " ".join(str(z) for z in MBENCH_DEPTHS)
    out += ["   2   1        MATFIL, OUTPUT", "   6            ISUBS",
            "   1  {0}  999   IXL, IXINC, IXH".format(STEP), "   1  {0}  999   IYL, IYINC, IYH".format(STEP),
            "   {0}          NZ".format(len(MBENCH_DEPTHS)), "   " + zs, "   0            ISUBS", " 0  MODULE", ""]
    return "\n".join(out)


def ffloat(s):
    """A Fortran number, also without the 'E' of a 3-digit exponent (0.182980-309)."""
    try:
        return float(s)
    except ValueError:
        m = re.match(r"^([-+]?[0-9.]+)([-+][0-9]+)$", s)
        return float(m.group(1) + "e" + m.group(2))


def read_mat(path):
    """The grid (MX, MY, XL, YL, DX, DY) and the element table of a CONTACT .mat file."""
    hdr, elems, lines = {}, [], open(path).read().splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("%"):
            names = lines[i][1:].split()
            if names and names[0] == "I":
                for l in lines[i + 1:]:
                    if l.strip():
                        elems.append(dict(zip(names, map(ffloat, l.split()))))
                break
            for n, v in zip(names, lines[i + 1].split()):
                if n != "-" and n not in hdr:
                    hdr[n] = ffloat(v)
            i += 2
        else:
            i += 1
    return hdr, elems


def read_subs(path):
    """Rows (X, Y, Z, SIGXX, SIGXY, SIGXZ, SIGYY, SIGYZ, SIGZZ) of a CONTACT .subs file (A_s = 2)."""
    rows, names = [], None
    for l in open(path):
        if l.startswith("%"):
            names = l[1:].split()
            continue
        v = l.split()
        if names and names[0] == "X" and len(v) == len(names):
            rows.append(dict(zip(names, map(ffloat, v))))
    return rows


def run(binary, workdir, name, deck):
    open(os.path.join(workdir, name + ".inp"), "w").write(deck)
    env = dict(os.environ, OMP_NUM_THREADS="1")
    subprocess.run([binary, "2", name], cwd=workdir, env=env, check=True, stdout=subprocess.DEVNULL)
    text = open(os.path.join(workdir, name + ".out")).read()
    if "ERROR" in text:
        sys.exit(f"CONTACT refused {name}.inp:\n" + text[text.index("ERROR"):][:400])
    mats = sorted(f for f in os.listdir(workdir) if f.startswith(name + ".0001") and f.endswith(".mat"))
    subs = sorted(f for f in os.listdir(workdir) if f.startswith(name + ".0001") and f.endswith(".subs"))
    assert len(mats) == 1 and len(subs) == 1, (name, mats, subs)  # one contact patch
    return read_mat(os.path.join(workdir, mats[0])), read_subs(os.path.join(workdir, subs[0]))


def write_case(out, name, hdr, elems, subs):
    mx = int(hdr["MX"])
    xl, yl, dx, dy = hdr["XL"], hdr["YL"], hdr["DX"], hdr["DY"]
    fn = fx = fy = 0.0
    with open(os.path.join(out, name + "_elements.csv"), "w") as f:
        f.write("x_mm,y_mm,pn_MPa,px_MPa,py_MPa\n")
        for e in elems:
            if e["PN"] == 0 and e["PX"] == 0 and e["PY"] == 0:
                continue
            k = int(e["I"]) - 1
            x, y = xl + (k % mx + 0.5) * dx, yl + (k // mx + 0.5) * dy
            f.write(f"{x:.10g},{y:.10g},{e['PN']:.6g},{e['PX']:.6g},{e['PY']:.6g}\n")
            fn, fx, fy = fn + e["PN"] * dx * dy, fx + e["PX"] * dx * dy, fy + e["PY"] * dx * dy
    comps = ["SIGXX", "SIGYY", "SIGZZ", "SIGXY", "SIGXZ", "SIGYZ"]
    with open(os.path.join(out, name + "_stresses.csv"), "w") as f:
        f.write("x_mm,y_mm,z_mm,sxx_MPa,syy_MPa,szz_MPa,sxy_MPa,sxz_MPa,syz_MPa\n")
        for r in subs:
            if r["Z"] <= 0:
                continue
            f.write(",".join(f"{r[c]:.10g}" for c in ["X", "Y", "Z"]) + "," +
                    ",".join(f"{r[c]:.6g}" for c in comps) + "\n")
    return f"{name},{dx:.10g},{dy:.10g},{NU},{fn:.6g},{fx:.6g},{fy:.6g},{len(subs)}\n"


def main(binary, examples, out):
    os.makedirs(out, exist_ok=True)
    work = tempfile.mkdtemp(prefix="contact_subs_")
    for f in ("MBench_S1002_v3.prw", "MBench_UIC60_v3.prr"):
        shutil.copy(os.path.join(examples, f), work)
    rows = ["case,dx_mm,dy_mm,nu,Fn_N,Fx_N,Fy_N,n_points\n"]
    zs = " ".join(str(z) for z in HERTZ_DEPTHS)
    for name, T, cksi, ceta in [("hertz_frictionless", 0, 0.0, 0.0), ("hertz_rolling", 3, 5e-4, -4e-4)]:
        # the rolling direction and step (CHI, DQ, VELOC) only with a tangential problem
        kin = f"   0.000   {2 * 6.0 * 1.1 / 40:.10f}   30000.                   CHI, DQ, VELOC\n" if T else ""
        deck = HERTZ_DECK.format(T=T, cksi=cksi, ceta=ceta, kin=kin, nu=NU, g=G, step=STEP, nz=len(HERTZ_DEPTHS), zs=zs)
        (hdr, elems), subs = run(binary, work, name, deck)
        rows.append(write_case(out, name, hdr, elems, subs))
    for name, T in [("mbench_frictionless", 0), ("mbench_rolling", 3)]:
        (hdr, elems), subs = run(binary, work, name, mbench_deck(examples, T))
        rows.append(write_case(out, name, hdr, elems, subs))
    open(os.path.join(out, "cases.csv"), "w").write("".join(rows))
    shutil.rmtree(work)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], sys.argv[3] if len(sys.argv) > 3 else "tests/data/contact_subsurface")
