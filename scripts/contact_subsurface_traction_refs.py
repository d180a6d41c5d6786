#!/usr/bin/env python3
"""CONTACT references for the stresses below a grid patch under its own solved traction
(tests/data/contact_subsurface_traction/).

CONTACT solves a steady-rolling contact problem on a Hertzian gap (module 3, its exact solver on a
grid of piecewise-constant elements, influence coefficients C3 = 2) and computes, in the same run,
the stresses below it from its own normal and tangential solution (subsurface option S = 3). This
script keeps CONTACT's pressure (the normal solution, which mhcontact's tangential solver then
takes as its input, as on the half-space method's grid) and the stresses on rows of points through
the patch, every element along the rolling direction x, at a list of depths. The test solves the
tangential problem itself with mhcontact's exact solver on CONTACT's pressure and compares the
stresses of ITS traction with CONTACT's: the chain solved traction -> stresses against an
independent solver, not the stress integration alone (tests/data/contact_subsurface/ does that).

Cases (CONTACT's units: N, mm, MPa; E = 210 GPa, nu = 0.28 for both bodies, mu = 0.3): the
Hertzian gap of an ellipse a = 6 mm (rolling direction), b = 4 mm, Fn = 80 kN, 40 x 40 elements over
1.1 x the ellipse (0.33 x 0.22 mm),
  partial_slip  xi = 1e-3, eta = -8e-4: a stick zone at the leading edge, slip behind it
  full_slip     xi = 1e-2, eta = 0: the whole patch slides, traction mu p along x

Outputs per case: CASE_pressure.csv (x, y [mm] element centres, pn [MPa], CONTACT's px, py [MPa] on
body 1, every element in contact), CASE_stresses.csv (x, y, z [mm], the six components [MPa],
tension positive, body 1); cases.csv (creepages, grid, totals).

Usage: /usr/bin/python3 scripts/contact_subsurface_traction_refs.py CONTACT_BINARY [OUT_DIR]
"""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from contact_subsurface_refs import G, NU, read_mat, read_subs, run  # noqa: E402  (one home for CONTACT's files)

DEPTHS = [0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0, 2.5, 3.0, 4.0]
ROWS = (8, 6, 32)  # IYL, IYINC, IYH: five rows y = -2.75 ... 2.53 mm, the middle one at y = -0.11 mm
CASES = [("partial_slip", 1e-3, -8e-4), ("full_slip", 1e-2, 0.0)]

DECK = """ 3  MODULE
  203103     P-B-T-N-F-S   PVTIME, BOUND , TANG  , NORM  , FORCE , STRESS
  022020     L-D-C-M-Z-E   FRCLAW, DISCNS, INFLCF, MATER , RZNORM, EXRHS
 0001341   H-G-I-A-O-W-R   HEAT, GAUSEI, IESTIM, MATFIL, OUTPUT, FLOW, RETURN
   80   200    5    1      1e-8    MAXGS , MAXIN , MAXNR , MAXOUT, EPS
   80000.0   {cksi}   {ceta}   0.0              FN, CKSI, CETA, CPHI
   0.3  0.3                                     FSTAT, FKIN
   0.000   {dq:.10f}   30000.                   CHI, DQ, VELOC
   {nu}  {nu}  {g}  {g}                         POISS 1,2,  GG 1,2
   -3                                           IPOTCN
   40  40  6.0  4.0  1.1                        MX,MY,AA,BB,SCALE
   2   1        MATFIL, OUTPUT
   6            ISUBS
   1  1  40        IXL, IXINC, IXH
   {iyl}  {iyinc}  {iyh}        IYL, IYINC, IYH
   {nz}          NZ
   {zs}
   0            ISUBS
 0  MODULE
"""


def main(binary, out):
    os.makedirs(out, exist_ok=True)
    work = tempfile.mkdtemp(prefix="contact_subs_traction_")
    rows = ["case,xi,eta,mu,dx_mm,dy_mm,nu,G_MPa,Fn_N,Fx_N,Fy_N,n_contact,n_points\n"]
    for name, cksi, ceta in CASES:
        deck = DECK.format(cksi=cksi, ceta=ceta, dq=2 * 6.0 * 1.1 / 40, nu=NU, g=G, iyl=ROWS[0], iyinc=ROWS[1],
                           iyh=ROWS[2], nz=len(DEPTHS), zs=" ".join(str(z) for z in DEPTHS))
        (hdr, elems), subs = run(binary, work, name, deck)
        mx = int(hdr["MX"])
        xl, yl, dx, dy = hdr["XL"], hdr["YL"], hdr["DX"], hdr["DY"]
        fn = fx = fy = 0.0
        n = 0
        with open(os.path.join(out, name + "_pressure.csv"), "w") as f:
            f.write("x_mm,y_mm,pn_MPa,px_MPa,py_MPa\n")
            for e in elems:
                if e["PN"] <= 0:
                    continue
                k = int(e["I"]) - 1
                x, y = xl + (k % mx + 0.5) * dx, yl + (k // mx + 0.5) * dy
                f.write(f"{x:.10g},{y:.10g},{e['PN']:.6g},{e['PX']:.6g},{e['PY']:.6g}\n")
                fn, fx, fy, n = fn + e["PN"] * dx * dy, fx + e["PX"] * dx * dy, fy + e["PY"] * dx * dy, n + 1
        comps = ["SIGXX", "SIGYY", "SIGZZ", "SIGXY", "SIGXZ", "SIGYZ"]
        kept = 0
        with open(os.path.join(out, name + "_stresses.csv"), "w") as f:
            f.write("x_mm,y_mm,z_mm,sxx_MPa,syy_MPa,szz_MPa,sxy_MPa,sxz_MPa,syz_MPa\n")
            for r in subs:
                if r["Z"] <= 0:
                    continue
                kept += 1
                f.write(",".join(f"{r[c]:.10g}" for c in ["X", "Y", "Z"]) + "," +
                        ",".join(f"{r[c]:.6g}" for c in comps) + "\n")
        rows.append(f"{name},{cksi},{ceta},0.3,{dx:.10g},{dy:.10g},{NU},{G},{fn:.6g},{fx:.6g},{fy:.6g},{n},{kept}\n")
    open(os.path.join(out, "cases.csv"), "w").write("".join(rows))
    shutil.rmtree(work)


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else "tests/data/contact_subsurface_traction")
