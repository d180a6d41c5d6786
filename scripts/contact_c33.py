#!/usr/bin/env python3
"""Kalker's creepage coefficients C11, C22, C23, C33 from CONTACT's exact steady-rolling solver.

At a small creepage (1e-4 of the creepage that saturates the patch) the whole ellipse adheres and
CONTACT's exact solution is Kalker's linear theory on its grid:
    Fx = -G c² C11 ξ,   Fy = -G c² C22 η,   Fy = -G c³ C23 φ,   Mz = -G c⁴ C33 φ   (c = √(ab)),
forces on body 1 (module 3's signs). Each coefficient is read back from one solve with one creepage,
on a sequence of grids, so that its grid convergence shows: MX × MX elements over MX/(MX − 4) × the
ellipse, as CONTACT's own src/test_table.f90 lays them, so that each semi-axis spans (MX − 4)/2
elements exactly and the ellipse's edge falls at the same place in its elements on every grid (a
fixed scale moves it, and the coefficients then scatter by about 1 % from grid to grid).

Usage: python3 scripts/contact_c33.py CONTACT_LIBRARY OUT_CSV [MX ...]
       python3 scripts/contact_c33.py --summary CSV
CONTACT_LIBRARY: contact_addon_linux64.so of a CONTACT 25.2 build (tests/data/contact_tangential/
README.md). Writes one row per (ν, a/b, MX) as it goes, so a partial run is usable. --summary prints
the convergence table of docs/tangential.md: per aspect and grid each coefficient over Kalker's
Table E.3 value at ν = 0.25 (C11, C22, C23 as the project and CONTACT's linrol have them; C33 as
lib/contact/tangential/kalker.hpp has it), and its extrapolation to zero element size within each family of grids (below).
"""
import math, sys, time
from contact_library import Contact

G = 82000.0          # N/mm²
FN = 82000.0         # N (any: linear theory does not depend on it)
MU = 0.3
C_MM = 6.0           # √(ab) [mm]
# (ν, a/b): the rows of Kalker's Table E.3 at ν = 0.25 (g = min(a/b, b/a) = 0.2, 0.5, 1), and
# a/b = 4 (g = 0.25, between two rows: how the table is interpolated matters there).
CASES = [(0.25, 0.2), (0.25, 0.5), (0.25, 1.0), (0.25, 2.0), (0.25, 5.0), (0.25, 4.0)]
FRACTION = 1e-4      # of the saturating creepage: the patch stays in full adhesion
# Kalker 1990, Table E.3, ν = 0.25, at the rows g = 0.2, 0.5, 1 (a/b = 0.2, 0.5, 1, 2 = 1/0.5, 5 = 1/0.2);
# a/b = 4 lies between the rows g = 0.2 and 0.3 and is given both ways: linear in g (the project's
# and CONTACT's linrol's interpolation) and linear in log C over log g.
TABLE = {0.2: (3.37, 2.63, 0.603, 4.27), 0.5: (3.62, 3.01, 0.929, 1.93), 1.0: (4.12, 3.67, 1.47, 1.19),
         2.0: (5.10, 4.90, 2.62, 0.82), 5.0: (7.78, 8.14, 6.63, 0.60)}
ROW_03 = (6.34, 6.40, 4.32, 0.67)      # g = b/a = 0.3, ν = 0.25


def table_at_4(loglog):
    if not loglog:
        return tuple((p + q) / 2 for p, q in zip(TABLE[5.0], ROW_03))
    t = math.log(0.25 / 0.2) / math.log(0.3 / 0.2)
    return tuple(math.exp((1 - t) * math.log(p) + t * math.log(q)) for p, q in zip(TABLE[5.0], ROW_03))


def summary(path):
    import csv
    rows = list(csv.DictReader(open(path)))
    names = ("C11", "C22", "C23", "C33")
    print("| a/b | MX (elements across) | " + " | ".join(f"{n} / table" for n in names) + " |")
    print("|---|---|---|---|---|---|")
    for aob in sorted({float(r["a_over_b"]) for r in rows}):
        rs = sorted((r for r in rows if float(r["a_over_b"]) == aob), key=lambda r: int(r["mx"]))
        ref = TABLE.get(aob) or table_at_4(False)
        for r in rs:
            mx = int(r["mx"])
            print(f"| {aob:g} | {mx} ({mx - 4}) | " + " | ".join(f"{float(r[n]) / t:.4f}" for n, t in zip(names, ref)) + " |")
        # Richardson to zero element size between grids of one family, h halved (20 → 40 and
        # 28 → 56 elements across): the coefficients zigzag by 1–2 % between the families (where the
        # ellipse's edge cuts the elements), so only grids of one family are extrapolated together;
        # first order in h, C0 = 2 C(h/2) − C(h). The two families' answers bracket the error.
        by_n = {int(r["mx"]) - 4: r for r in rs}
        for n1, n2 in ((20, 40), (28, 56), (38, 76)):
            if n1 in by_n and n2 in by_n:
                ext = [2 * float(by_n[n2][n]) - float(by_n[n1][n]) for n in names]
                print(f"| {aob:g} | extrapolated {n1} → {n2} | " + " | ".join(f"{e / t:.4f}" for e, t in zip(ext, ref)) + " |")
                if aob == 4.0:
                    ll = table_at_4(True)
                    print(f"| 4 | the same over the table read linear in log C, log g | "
                          + " | ".join(f"{e / t:.4f}" for e, t in zip(ext, ll)) + " |")


def main():
    if sys.argv[1] == "--summary":
        return summary(sys.argv[2])
    lib, out = sys.argv[1], sys.argv[2]
    mxs = [int(m) for m in sys.argv[3:]] or [24, 32, 44, 60]
    with open(out, "w") as f:
        f.write("nu,a_over_b,a_mm,b_mm,mx,scale,h_over_a,C11,C22,C23,C33,adhesion_min,seconds\n")
        assert len({nu for nu, _ in CASES}) == 1   # one CONTACT instance, one material
        c = Contact(lib, G=G, nu=CASES[0][0], mu=MU, fn=FN)
        for mx in mxs:
            for nu, aob in CASES:
                aa, bb = C_MM * math.sqrt(aob), C_MM / math.sqrt(aob)
                s = MU * FN / (G * C_MM * C_MM) * FRACTION   # creepage of the order of saturation × FRACTION
                scale = mx / (mx - 4)
                t = time.time()
                rx = c.solve(aa, bb, mx, mx, scale, s, 0, 0)
                ry = c.solve(aa, bb, mx, mx, scale, 0, s, 0)
                rp = c.solve(aa, bb, mx, mx, scale, 0, 0, s / C_MM)
                dt = time.time() - t
                for r in (rx, ry, rp):
                    assert r["ierr"] == 0, (nu, aob, mx, r)
                C11 = -rx["FX"] / (G * C_MM**2 * s)
                C22 = -ry["FY"] / (G * C_MM**2 * s)
                C23 = -rp["FY"] / (G * C_MM**3 * s / C_MM)
                C33 = -rp["MZ"] / (G * C_MM**4 * s / C_MM)
                adh = min(rx["adhesion"], ry["adhesion"], rp["adhesion"])
                row = [nu, aob, aa, bb, mx, scale, 2 * scale / mx, C11, C22, C23, C33, adh, dt]
                f.write(",".join(f"{v:.10g}" if isinstance(v, float) else str(v) for v in row) + "\n")
                f.flush()
                print(row, flush=True)
        c.close()


if __name__ == "__main__":
    main()
