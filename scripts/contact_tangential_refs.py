#!/usr/bin/env python3
"""CONTACT module-3 references for the tangential problem on Hertzian ellipses.

Writes tests/data/contact_tangential/module3_hertz.csv: for each case (aspect a/b, creepages), the
solution of CONTACT's EXACT steady-rolling solver (M = 0, B = 0) and of its FASTSIM (M = 3,
elliptical bound B = 2) on the same potential contact area and grid (MXY elements each way), and
its FASTSIM again on a fine grid (MXY_FINE). CONTACT 25.2 blends the FASTSIM flexibilities when the
creepages are given (Vollebregt & Voltr 2023; m_hertz.f90, simpflex).

Usage: python3 scripts/contact_tangential_refs.py CONTACT_BINARY [OUT_CSV]
CONTACT_BINARY: a CONTACT 25.2 executable (tests/data/contact_tangential/README.md).

Units of CONTACT's module 3 as used here: N, mm, N/mm² (so G = 82000); φ in rad/mm. Its sign
convention is Kalker's (forces on body 1, the creepages those of body 1 relative to body 2),
the project's (lib/contact/tangential/tangential_types.hpp).
"""
import math, os, re, subprocess, sys, tempfile

G = 82000.0      # N/mm²
NU = 0.28
MU = 0.3
FN = 80000.0     # N
C = 6.0          # mm: √(ab) of every ellipse
MXY = 60         # elements each way over the potential area (1.1 × the ellipse)
MXY_FINE = 300   # FASTSIM again on a fine grid: CONTACT's FASTSIM converges to first order in the
                 # element size, so the two grids bracket its grid-independent answer
SCALE = 1.1

# Kalker's C11, C22, C23 at ν = 0.28 only to choose creepages of a useful size (any values would do).
def sat(aob):
    c11 = {0.2: 3.4, 0.5: 3.73, 1.0: 4.23, 2.0: 5.2, 5.0: 8.0}[aob]
    c22 = {0.2: 2.7, 0.5: 3.03, 1.0: 3.71, 2.0: 4.97, 5.0: 8.4}[aob]
    c23 = {0.2: 0.65, 0.5: 0.94, 1.0: 1.49, 2.0: 2.66, 5.0: 6.9}[aob]
    s = MU * FN / (G * C * C)
    return s / c11, s / c22, s / (c23 * C)

# Creepages as fractions of the saturating ones: (ξ, η, φ).
MIXES = [(0.2, 0, 0), (0, 0.5, 0), (0, 0, 0.5), (0.3, -0.3, 0.3), (2.0, 1.0, 0), (0, -0.2, 1.0)]
ASPECTS = [0.2, 0.5, 1.0, 2.0, 5.0]

def block(method, first, cksi, ceta, cphi, aa, bb, mxy=MXY):
    dq = 2 * aa * SCALE / mxy
    if method == "exact":
        return f""" 3 MODULE
  203100     P-B-T-N-F-S
  022020     L-D-C-M-Z-E
 0001341   H-G-I-A-O-W-R
    80   200    5    1      1e-6    MAXGS , MAXIN , MAXNR , MAXOUT, EPS
   {FN:.1f}   {cksi:.10e}   {ceta:.10e}   {cphi:.10e}   FN, CKSI, CETA, CPHI
   {MU}  {MU}                                 FSTAT, FKIN
   0.000   {dq:.10f}   30000.                  CHI, DQ, VELOC
   {NU}  {NU}  {G}  {G}                       POISS 1,2,  GG 1,2
   -3                                           IPOTCN
   {mxy}  {mxy}  {aa:.10f}  {bb:.10f}  {SCALE}   MX,MY,AA,BB,SCALE
"""
    return f""" 3 MODULE
  223100     P-B-T-N-F-S
  022320     L-D-C-M-Z-E
 0101341   H-G-I-A-O-W-R
   {FN:.1f}   {cksi:.10e}   {ceta:.10e}   {cphi:.10e}   FN, CKSI, CETA, CPHI
   {MU}  {MU}                                 FSTAT, FKIN
   0.000   {dq:.10f}   30000.                  CHI, DQ, VELOC
   {NU}  {NU}  {G}  {G}                       POISS 1,2,  GG 1,2
   1.000      1.000      1.000                  K0_MF,ALFAMF,BETAMF
   -3                                           IPOTCN
   {mxy}  {mxy}  {aa:.10f}  {bb:.10f}  {SCALE}   MX,MY,AA,BB,SCALE
"""

def parse(text):
    out = []
    lines = text.splitlines()
    for i, l in enumerate(lines):
        if re.match(r"\s+FN\s+FX\s+FY\s+MZ", l):
            v = [float(x) for x in lines[i + 1].split()[:4]]
            out.append({"FN": v[0], "FX": v[1], "FY": v[2], "MZ": v[3]})
        if re.match(r"\s+NPOT\s+NCON\s+NADH\s+NSLIP", l):
            v = [int(x) for x in lines[i + 1].split()[:4]]
            out[-1]["NCON"], out[-1]["NADH"] = v[1], v[2]
    return out

def main():
    exe = os.path.abspath(sys.argv[1])
    dst = sys.argv[2] if len(sys.argv) > 2 else "tests/data/contact_tangential/module3_hertz.csv"
    cases = []
    for aob in ASPECTS:
        aa, bb = C * math.sqrt(aob), C / math.sqrt(aob)
        sx, se, sp = sat(aob)
        for m in MIXES:
            cases.append((aob, aa, bb, m[0] * sx, m[1] * se, m[2] * sp))
    deck = ""
    for k, (aob, aa, bb, x, e, p) in enumerate(cases):
        deck += block("exact", k == 0, x, e, p, aa, bb)
        deck += block("fastsim", False, x, e, p, aa, bb)
        deck += block("fastsim", False, x, e, p, aa, bb, MXY_FINE)
    deck += " 0 MODULE\n"
    with tempfile.TemporaryDirectory() as d:
        open(os.path.join(d, "tang.inp"), "w").write(deck)
        subprocess.run([exe, "2", "tang"], cwd=d, check=True, stdout=subprocess.DEVNULL)
        res = parse(open(os.path.join(d, "tang.out")).read())
    assert len(res) == 3 * len(cases), (len(res), len(cases))
    cols = ("a_over_b,a_mm,b_mm,FN_N,mu,nu,G_MPa,mx,my,scale,xi,eta,phi_per_mm,"
            "exact_Fx_N,exact_Fy_N,exact_Mz_Nmm,exact_adhesion_fraction,"
            "fastsim_Fx_N,fastsim_Fy_N,fastsim_Mz_Nmm,fastsim_adhesion_fraction,"
            "fastsim_fine_Fx_N,fastsim_fine_Fy_N,fastsim_fine_Mz_Nmm,fastsim_fine_adhesion_fraction")
    with open(dst, "w") as f:
        f.write(cols + "\n")
        for k, (aob, aa, bb, x, e, p) in enumerate(cases):
            ex, fs, ff = res[3 * k], res[3 * k + 1], res[3 * k + 2]
            row = [aob, aa, bb, FN, MU, NU, G, MXY, MXY, SCALE, x, e, p,
                   ex["FX"], ex["FY"], ex["MZ"], ex["NADH"] / ex["NCON"],
                   fs["FX"], fs["FY"], fs["MZ"], fs["NADH"] / fs["NCON"],
                   ff["FX"], ff["FY"], ff["MZ"], ff["NADH"] / ff["NCON"]]
            f.write(",".join(f"{v:.10g}" if isinstance(v, float) else str(v) for v in row) + "\n")
    print(f"wrote {dst}: {len(cases)} cases")

if __name__ == "__main__":
    main()
