#!/usr/bin/env python3
"""The plastic ellipse laws against a 3-D FE table of tests/data/fe (method.md §5.1): for each
FE row, `mhcontact hertz` at the FE load, with the yield law (`--yield sigma_y`, the default) or
the capped law (`--k K`: `--p-lim K*sigma_y`); prints a Markdown table of area and approach, both
as ratios to elastic Hertz at that load and as law/FE - 1.

  compare_law.py [--bin build/mhcontact] tests/data/fe/ellip3d_R460x300_sy350.csv   # yield law
  compare_law.py --k 2.1 TABLE                                                       # capped law
"""
import argparse, csv, math, subprocess


def law(binary, Rw, Rr, N_kN, p_lim=None, sy=None):
    out = subprocess.run([binary, "hertz", "--R-wyy", f"{Rw:g}", "--R-rxx", f"{Rr:g}", "--N", f"{N_kN:.9g}",
                          "--E", "210", "--nu", "0.3"] + ([] if p_lim is None else ["--p-lim", f"{p_lim:.9g}"])
                         + ([] if sy is None else ["--yield", f"{sy:.9g}"]),
                         capture_output=True, text=True, check=True).stdout
    v = {}
    for line in out.splitlines():
        k, _, rest = line.partition(" = ")
        try:
            v[k] = float(rest.split()[0])
        except (ValueError, IndexError):
            pass
    return v


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("table")
    ap.add_argument("--bin", default="build/mhcontact")
    ap.add_argument("--k", type=float, default=None, help="capped law with p_lim = K sigma_y (default: the yield law)")
    ap.add_argument("--Rw", type=float, default=460.0)
    ap.add_argument("--Rr", type=float, default=300.0)
    a = ap.parse_args()
    rows = list(csv.DictReader(l for l in open(a.table) if not l.startswith("#")))
    print(f"| p0_el/σ_y | FE area/el | FE δ/δ_el | FE p_max/σ_y | FE p_mean/σ_y | law p_max/σ_y | law area/el | law δ/δ_el | law/FE area | law/FE δ |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        sy, N = float(r["sigma_y_MPa"]), float(r["N_N"])
        area_el = math.pi * float(r["a_el_mm"]) * float(r["b_el_mm"])
        area_fe, d_fe, d_el = float(r["area_mm2"]), float(r["delta_mm"]), float(r["delta_el_mm"])
        v = law(a.bin, a.Rw, a.Rr, N / 1e3, sy=sy) if a.k is None else law(a.bin, a.Rw, a.Rr, N / 1e3, p_lim=a.k * sy)
        area_law = math.pi * v["a"] * v["b"]
        print(f"| {float(r['p0el_over_sy']):.2f} | {area_fe / area_el:.3f} | {d_fe / d_el:.3f} | {float(r['pmax_MPa']) / sy:.2f}"
              f" | {float(r['pmean_MPa']) / sy:.2f} | {v['p_max'] / sy:.2f} | {area_law / area_el:.3f} | {v['approach'] / d_el:.3f}"
              f" | {100 * (area_law / area_fe - 1):+.1f} % | {100 * (v['approach'] / d_fe - 1):+.1f} % |")


if __name__ == "__main__":
    main()
