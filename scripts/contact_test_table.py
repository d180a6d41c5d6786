#!/usr/bin/env python3
"""CONTACT's 3,220-case table of Hertzian creep-force solutions, as a CSV reference.

CONTACT (E. A. H. Vollebregt, https://github.com/eve70a/CONTACT, Apache-2.0) ships src/test_table.f90,
a program that solves 3,220 Hertzian steady-rolling cases with its exact solver (module 3, T = 3,
B = 0, M = 0; Coulomb μ = 0.3; G = 82 000 N/mm², ν = 0.28; FN = 82 000 N): 5 aspects a/b = 0.2, 0.5, 1, 2,
5 (a = 4, 6, 9, 12, 20 mm) × 4 spins × 7 directions of the creepage vector × 23 magnitudes, the
creepages in units of the saturating ones (Vollebregt, Iwnicki, Xie, Shackleton, VSD 50, 2012):
    ξ = m μ cos θ c/ρ,   η = m μ sin θ c/ρ,   φ = μ s/ρ   [rad/mm]
with c = √(ab) and ρ = 2/(A + B) the effective radius of curvature of the Hertzian ellipse. Its grid
is MX × MX elements over MX/(MX − 4) × the ellipse (MX − 4 elements across it); its argument MX.

The program prints ρ and c to 4 digits; a copy with that one format widened to 16 digits
(tests/data/contact_tangential/README.md) gives them exactly (they do not depend on the grid), so
that ξ, η, φ are exact. It prints per case Fx/(μFN), Fy/(μFN), Mz/(μ FN c) to 6 decimals and the
slip area in per cent to 1 decimal.

Usage:
  python3 scripts/contact_test_table.py OUT_CSV RUN_FINE RUN_COARSE RUN_RHO
  python3 scripts/contact_test_table.py --grid-change CSV   (the reference's own grid change:
      median, 95th percentile (nearest rank) and largest |fine − coarse| per column; docs/trust.md)
RUN_FINE, RUN_COARSE: the standard output of `test_table MX` at two grids (file names containing
mxNN); the coarse one goes into the *_coarse columns, so that the table carries its own
grid-convergence evidence. RUN_RHO: the output of the 16-digit copy (any MX).
"""
import math, re, sys

MU, FN, G, NU = 0.3, 82000.0, 82000.0, 0.28
ELLIP = [0.2, 0.5, 1.0, 2.0, 5.0]
AA = [4.0, 6.0, 9.0, 12.0, 20.0]
SPIN = [0.0, 0.5, 1.0, 2.0]
ANGLE = [-90, -60, -30, 0, 30, 60, 90]          # degrees (−π/2 … π/2 in the program)
MAGN = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.7, 0.9, 1.1, 1.4, 1.7, 2.0, 2.5, 3.0, 3.5, 4.0, 5.0, 6.0,
        7.0, 8.0, 9.0, 10.0, 12.0]


def read(path):
    rho, cases, mx = {}, [], None
    for line in open(path):
        m = re.match(r"iell=(\d+), a/b=\s*[\d.]+: rho=\s*(\S+)\s*, cp=\s*(\S+)", line)
        if m:
            rho[int(m.group(1))] = (float(m.group(2)), float(m.group(3)))
        m = re.match(r"Fx=\s*(\S+), Fy=\s*(\S+), Mz=\s*(\S+), %Slip=\s*(\S+)", line)
        if m:
            cases.append([float(v) for v in m.groups()])
    assert len(rho) == 5 and len(cases) == 3220, (path, len(rho), len(cases))
    return rho, cases


def grid_change(path):
    import csv
    rows = list(csv.DictReader(l for l in open(path) if not l.startswith("#")))
    for n in ("Fx_muN", "Fy_muN", "Mz_muNc", "adhesion_fraction"):
        e = sorted(abs(float(r[n]) - float(r[n + "_coarse"])) for r in rows)
        q = lambda p: e[min(len(e) - 1, math.ceil(p * len(e)) - 1)]
        print(f"{n}: median {q(0.5):.4f} p95 {q(0.95):.4f} max {e[-1]:.4f}")


def main():
    if sys.argv[1] == "--grid-change":
        return grid_change(sys.argv[2])
    out, fine, coarse, rho_run = sys.argv[1:5]
    mx_f = int(re.search(r"mx(\d+)", fine).group(1))
    mx_c = int(re.search(r"mx(\d+)", coarse).group(1))
    rho4, cf = read(fine)
    cc = read(coarse)[1]
    rho = read(rho_run)[0]
    for k in rho:   # the same ellipses: the 4-digit print agrees with the 16-digit one
        assert all(abs(rho4[k][j] / rho[k][j] - 1) < 1e-3 for j in (0, 1)), (k, rho4[k], rho[k])
    cols = ["case", "a_over_b", "a_mm", "b_mm", "spin", "angle_deg", "magnitude", "xi", "eta", "phi_per_mm",
            "Fx_muN", "Fy_muN", "Mz_muNc", "adhesion_fraction"]
    if cc:
        cols += ["Fx_muN_coarse", "Fy_muN_coarse", "Mz_muNc_coarse", "adhesion_fraction_coarse"]
    with open(out, "w") as f:
        f.write(f"# CONTACT 25.2 test_table, exact steady rolling; FN_N={FN:g} mu={MU:g} G_MPa={G:g} nu={NU:g}; "
                f"mx={mx_f}" + (f", coarse mx={mx_c}" if cc else "") + "\n")
        f.write(",".join(cols) + "\n")
        for k in range(3220):
            # case = ivmgn + 23 (ivang − 1) + 161 (ispin − 1) + 644 (iell − 1), as in test_table.f90
            im, rem = k % 23, k // 23
            ia, rem = rem % 7, rem // 7
            isp, ie = rem % 4, rem // 4
            r, c = rho[ie + 1]
            a = AA[ie]
            b = c * c / a    # the program's b = a / (single-precision a/b)
            assert abs(b / (a / ELLIP[ie]) - 1) < 1e-7
            th = math.radians(ANGLE[ia])
            xi = MAGN[im] * MU * math.cos(th) * c / r
            eta = MAGN[im] * MU * math.sin(th) * c / r
            phi = MU * SPIN[isp] / r
            row = [k + 1, ELLIP[ie], a, b, SPIN[isp], ANGLE[ia], MAGN[im], xi, eta, phi,
                   cf[k][0], cf[k][1], cf[k][2], 1 - cf[k][3] / 100]
            if cc:
                row += [cc[k][0], cc[k][1], cc[k][2], 1 - cc[k][3] / 100]
            f.write(",".join(f"{v:.10g}" if isinstance(v, float) else str(v) for v in row) + "\n")
    print(f"wrote {out}: 3220 cases, mx {mx_f}" + (f" (coarse {mx_c})" if cc else ""))


if __name__ == "__main__":
    main()
