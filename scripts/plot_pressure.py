#!/usr/bin/env python3
"""Plot elastic versus plastic contact pressure for one case of `mhcontact run`.

    plot_pressure.py DIR --case K [--pair P] [-o FILE.png]

DIR is the output directory of `mhcontact run` (CSV format: ellipses.csv and profiles.csv are
read). For a batch (DIR/pairs.csv), --pair P picks the profile pair: its rows of ellipses.csv and
DIR/pairs/P/profiles.csv. The title names the pair, the case, the model and p_lim; the pressure
panels draw the p_lim line. Three panels: the rail section with the contact patches of case K (the plastic patch
and, in plastic mode, the elastic patch at the same load), and the pressure along the patch
axes x (rolling) and y (lateral) of every loaded ellipse: the capped pressure
min(p0 sqrt(1 - x^2/a^2 - y^2/b^2), p_lim) against the elastic Hertz pressure at the same load
(docs/method.md §5). Needs matplotlib (Debian: python3-matplotlib); runs headless.
"""
import argparse
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def hertz(p0, a, b, x, y):
    q = 1.0 - (x / a) ** 2 - (y / b) ** 2
    return p0 * math.sqrt(q) if q > 0 else 0.0


def run_info(d, pair):
    """(pair label, model, p_lim in MPa or None) from the run's JSON records, when present."""
    label, model, plim = None, None, None
    inputs = None
    try:
        if pair is not None:
            inputs = json.load(open(os.path.join(d, "pairs", str(pair), "geometry.json"))).get("inputs")
        else:
            with open(os.path.join(d, "results.json")) as f:
                head = f.read(1 << 20)  # the inputs come first; the cases may be huge
            i = head.find('"inputs"')
            if i >= 0:
                inputs, _ = json.JSONDecoder().raw_decode(head, head.index("{", i))
    except (OSError, ValueError):
        inputs = None
    if isinstance(inputs, dict):
        model = inputs.get("model")
        mat = inputs.get("material") or {}
        if isinstance(mat, dict):
            for k in ("p_lim_MPa", "p_lim"):
                if isinstance(mat.get(k), (int, float)):
                    plim = float(mat[k])
        if isinstance(inputs.get("p_lim_MPa"), (int, float)):
            plim = float(inputs["p_lim_MPa"])
        w, r = inputs.get("wheel", {}), inputs.get("rail", {})

        def name(side):
            p = side.get("profile", side) if isinstance(side, dict) else side
            if isinstance(p, dict):
                p = p.get("file") or p.get("standard") or ""
            return os.path.basename(str(p))
        label = f"{name(w)} / {name(r)}"
    return label, model, plim


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir", help="output directory of `mhcontact run`")
    ap.add_argument("--case", type=int, required=True, help="case number (column `case`)")
    ap.add_argument("--pair", type=int, help="profile pair of a batch directory (column `pair` of pairs.csv)")
    ap.add_argument("-o", "--output", help="PNG file (default DIR/pressure_case_K.png)")
    a = ap.parse_args(argv)
    batch = os.path.exists(os.path.join(a.dir, "pairs.csv"))
    if batch and a.pair is None:
        sys.exit(f"plot_pressure.py: {a.dir} is a batch over several profile pairs (pairs.csv): "
                 f"give --pair P with P from the column `pair` of {a.dir}/pairs.csv")
    if not batch and a.pair is not None:
        sys.exit(f"plot_pressure.py: --pair is for batch directories; {a.dir} holds a single run (no pairs.csv)")
    try:
        ell = [r for r in read_csv(os.path.join(a.dir, "ellipses.csv"))
               if int(r["case"]) == a.case and (a.pair is None or int(r["pair"]) == a.pair)]
        prof = read_csv(os.path.join(a.dir, "pairs", str(a.pair), "profiles.csv") if batch
                        else os.path.join(a.dir, "profiles.csv"))
    except OSError as e:
        sys.exit(f"plot_pressure.py: {e} (run `mhcontact run CASE_OR_MANIFEST -o DIR` with CSV output first)")
    if not ell:
        where = f"pair {a.pair}, " if batch else ""
        sys.exit(f"plot_pressure.py: {where}case {a.case} has no loaded ellipse in {a.dir}/ellipses.csv")
    plastic = "plastic" in ell[0]
    label, model, plim_in = run_info(a.dir, a.pair)
    model = model or ("plastic" if plastic else "elastic")
    if plim_in is None and plastic:  # a plastic ellipse's p_max is p_lim
        caps = [float(e["p_max_MPa"]) for e in ell if e.get("plastic") == "1"]
        plim_in = max(caps) if caps else None
    plim_txt = f"p_lim = {plim_in:g} MPa" if plim_in is not None else "p_lim = none (elastic)"
    out = a.output or os.path.join(a.dir, f"pressure_case_{a.case}.png" if not batch
                                   else f"pressure_case_{a.case}_pair_{a.pair}.png")
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]

    fig, axs = plt.subplots(3, 1, figsize=(10, 10))
    ry = [float(r["y_mm"]) for r in prof if r["kind"] == "rail"]
    rz = [float(r["z_mm"]) for r in prof if r["kind"] == "rail"]
    ax = axs[0]
    ax.plot(ry, rz, "k-", lw=1)
    for i, e in enumerate(ell):
        c = colors[i % len(colors)]
        yr, g = float(e["y_rail_mm"]), math.radians(float(e["gamma_deg"]))
        j = max(1, min(len(ry) - 1, next((m for m in range(len(ry)) if ry[m] >= yr), len(ry) - 1)))
        zr = rz[j - 1] + (yr - ry[j - 1]) / (ry[j] - ry[j - 1]) * (rz[j] - rz[j - 1])
        for half, style, lab in ((float(e["b_mm"]), "-", "patch"),) + (
                ((float(e["b_el_mm"]), ":", "elastic patch"),) if plastic else ()):
            dy, dz = half * math.cos(g), half * math.sin(g)
            ax.plot([yr - dy, yr + dy], [zr - dz, zr + dz], style, color=c, lw=4 if style == "-" else 2,
                    label=f"#{e['ellipse']} {lab}")
    ax.set_aspect("equal")
    ax.set_xlabel("y [mm]")
    ax.set_ylabel("z [mm]")
    pair_txt = (f"pair {a.pair}" + (f" ({label})" if label else "")) if batch else (label or "")
    fig.suptitle(f"{pair_txt}\ncase {a.case}: t_Y = {ell[0]['tY_mm']} mm, Q = {ell[0]['Q_kN']} kN; "
                 f"{model}, {plim_txt}", fontsize=10)
    ax.set_title("rail section with the contact patches", fontsize=9)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0)
    ax.grid(True, alpha=0.3)

    for k, (ax, axis) in enumerate(zip(axs[1:], ("x", "y"))):
        for i, e in enumerate(ell):
            c = colors[i % len(colors)]
            A, B = float(e["a_mm"]), float(e["b_mm"])
            p0, N = float(e["p0_MPa"]), float(e["N_kN"])
            half = A if axis == "x" else B
            s = [-1.2 * half + 2.4 * half * t / 400 for t in range(401)]
            if plastic:
                plim = float(e["p_max_MPa"]) if e["plastic"] == "1" else float("inf")
                ae, be = float(e["a_el_mm"]), float(e["b_el_mm"])
                p0e = 1.5 * N * 1e3 / (math.pi * ae * be)
                cap = [min(hertz(p0, A, B, v, 0) if axis == "x" else hertz(p0, A, B, 0, v), plim) for v in s]
                el = [hertz(p0e, ae, be, v, 0) if axis == "x" else hertz(p0e, ae, be, 0, v) for v in s]
                ax.plot(s, el, ":", color=c, label=f"#{e['ellipse']} elastic (p0 {p0e:.0f} MPa)")
                ax.plot(s, cap, "-", color=c, label=f"#{e['ellipse']} plastic (p_max {min(p0, plim):.0f} MPa)")
            else:
                ax.plot(s, [hertz(p0, A, B, v, 0) if axis == "x" else hertz(p0, A, B, 0, v) for v in s], "-",
                        color=c, label=f"#{e['ellipse']} elastic (p0 {p0:.0f} MPa)")
        ax.set_xlabel(f"{axis} [mm] ({'rolling direction' if axis == 'x' else 'lateral, in the contact plane'})")
        ax.set_ylabel("p [MPa]")
        if plim_in is not None:
            ax.axhline(plim_in, color="r", ls="--", lw=1, label=f"p_lim {plim_in:g} MPa")
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0)
        ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=110, bbox_inches="tight")  # legends sit outside the axes, right
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
