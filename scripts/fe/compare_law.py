#!/usr/bin/env python3
"""The shipped plastic ellipse law against a 3-D FE table of tests/data/fe (method.md §5.1):
for each FE row, `mhcontact hertz --p-lim K*sigma_y` at the FE load; prints a Markdown table of
area and approach, both as ratios to elastic Hertz at that load and as law/FE - 1.

  compare_law.py [--bin build/mhcontact] [--k 2.1] tests/data/fe/ellip3d_R460x300_sy350.csv
  compare_law.py --candidate 1.6 0.3 TABLE

--candidate PY BETA evaluates, instead of the shipped law, the candidate of method.md §5.1 (not
implemented in the library): Hertz up to p_y = PY sigma_y, slope BETA above it,
N = BETA N_H + (1 - BETA) pi a b p_y (1 - s^2/3), the approach as the shipped law's with r = N/N_H.
In the dimensionless form of the self-similar problem (x = Hertz peak of the patch / sigma_y,
rho = p0_el / sigma_y at the same load): rho^3 = x^3 f(x), f = BETA + (1 - BETA) (3/2)(y/x)(1 - y^2/(3 x^2)),
area/area_el = (x/rho)^2, delta/delta_el = (area/area_el) (kappa + f (1 - kappa)), kappa = delta_ov/delta_H
of the Hertz ellipse (from the elastic `mhcontact hertz`).
"""
import argparse, csv, math, subprocess


def law(binary, Rw, Rr, N_kN, p_lim):
    out = subprocess.run([binary, "hertz", "--R-wyy", f"{Rw:g}", "--R-rxx", f"{Rr:g}", "--N", f"{N_kN:.9g}",
                          "--E", "210", "--nu", "0.3"] + ([] if p_lim is None else ["--p-lim", f"{p_lim:.9g}"]),
                         capture_output=True, text=True, check=True).stdout
    v = {}
    for line in out.splitlines():
        k, _, rest = line.partition(" = ")
        try:
            v[k] = float(rest.split()[0])
        except (ValueError, IndexError):
            pass
    return v


def candidate(rho, y, beta, kappa):
    """Area and approach ratios to elastic Hertz of the candidate law (see the module docstring)."""
    if rho <= y:
        return 1.0, 1.0
    f = lambda x: beta + (1 - beta) * 1.5 * (y / x) * (1 - y * y / (3 * x * x))
    lo, hi = rho, 3 * rho                 # x^3 f(x) increases with x; x = rho sqrt(t) > rho
    for _ in range(200):
        x = 0.5 * (lo + hi)
        lo, hi = (lo, x) if x ** 3 * f(x) > rho ** 3 else (x, hi)
    t = (x / rho) ** 2
    return t, t * (kappa + f(x) * (1 - kappa))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("table")
    ap.add_argument("--bin", default="build/mhcontact")
    ap.add_argument("--k", type=float, default=2.1, help="p_lim / sigma_y")
    ap.add_argument("--Rw", type=float, default=460.0)
    ap.add_argument("--Rr", type=float, default=300.0)
    ap.add_argument("--candidate", type=float, nargs=2, metavar=("PY", "BETA"), default=None)
    a = ap.parse_args()
    rows = list(csv.DictReader(l for l in open(a.table) if not l.startswith("#")))
    print(f"| p0_el/σ_y | FE area/el | FE δ/δ_el | FE p_max/σ_y | FE p_mean/σ_y | law area/el | law δ/δ_el | law/FE area | law/FE δ |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        sy, N = float(r["sigma_y_MPa"]), float(r["N_N"])
        area_el = math.pi * float(r["a_el_mm"]) * float(r["b_el_mm"])
        area_fe, d_fe, d_el = float(r["area_mm2"]), float(r["delta_mm"]), float(r["delta_el_mm"])
        if a.candidate:
            e = law(a.bin, a.Rw, a.Rr, N / 1e3, None)
            kappa = e["a"] * e["b"] / (2 * math.sqrt(a.Rw * a.Rr)) / e["approach"]   # a b sqrt(A B) / delta
            t, d = candidate(float(r["p0el_over_sy"]), a.candidate[0], a.candidate[1], kappa)
            v = {"approach": d * d_el}
            area_law = t * area_el
        else:
            v = law(a.bin, a.Rw, a.Rr, N / 1e3, a.k * sy)
            area_law = math.pi * v["a"] * v["b"]
        print(f"| {float(r['p0el_over_sy']):.2f} | {area_fe / area_el:.3f} | {d_fe / d_el:.3f} | {float(r['pmax_MPa']) / sy:.2f}"
              f" | {float(r['pmean_MPa']) / sy:.2f} | {area_law / area_el:.3f} | {v['approach'] / d_el:.3f}"
              f" | {100 * (area_law / area_fe - 1):+.1f} % | {100 * (v['approach'] / d_fe - 1):+.1f} % |")


if __name__ == "__main__":
    main()
