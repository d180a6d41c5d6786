#!/usr/bin/env python3
"""Plot the tangential traction and the adhesion and slip areas of one case of `mhcontact run`.

    plot_traction.py DIR --case K [--pair P] [--arrows N] [-o FILE.png]

DIR is the output directory of a run of a case file with friction (friction.coefficient) and
--pressure-grid N: its pressure.csv then ends with the traction columns px_MPa, py_MPa, slip
(docs/outputs.md, "pressure.csv"). One panel per contact of case K (a multi-Hertzian ellipse on
its N x N grid, or a grid method's patch on its elements), in the contact frame: x along the
rolling direction (the leading edge at +x), y (s for a patch) lateral in the contact plane
towards the field side. The adhesion area is shaded blue, the slip area orange; the arrows are
the tangential traction the wheel exerts on the rail, one scale for every panel (the key gives
it). Each panel's title gives the contact's creep forces on the rail and adhesion fraction
(ellipses.csv or patches.csv). For a batch (DIR/pairs.csv), --pair P picks the profile pair.
Needs matplotlib and numpy (Debian: python3-matplotlib); runs headless.
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_pressure import fnum, of_case, read_csv, regular_grid, run_info  # noqa: E402

NAME = "plot_traction.py"


def contact_grid(rows, xkey, ykey):
    """The regular grid of one contact's rows: x and y values, and (ny, nx) arrays of p, px, py
    and the state (0 outside the contact, 1 adhesion, 2 slip)."""
    x, y, _, _, g = regular_grid(rows, xkey, ykey, ["p_MPa", "px_MPa", "py_MPa", "slip"], 0.0, step=1.0)
    p = g["p_MPa"]
    state = np.where(p > 0, np.where(g["slip"] == 1, 2, 1), 0)
    return x, y, p, g["px_MPa"], g["py_MPa"], state


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir", help="output directory of `mhcontact run` with friction and --pressure-grid N")
    ap.add_argument("--case", type=int, required=True, help="case number (column `case`)")
    ap.add_argument("--pair", type=int, help="profile pair of a batch directory (column `pair` of pairs.csv)")
    ap.add_argument("--arrows", type=int, default=15, help="arrows along each axis of a contact (default 15)")
    ap.add_argument("-o", "--output", help="PNG file (default DIR/traction_case_K.png)")
    a = ap.parse_args(argv)
    if not os.path.isdir(a.dir):
        sys.exit(f"{NAME}: {a.dir} is not a directory (give the output directory of `mhcontact run`)")
    batch = os.path.exists(os.path.join(a.dir, "pairs.csv"))
    if batch and a.pair is None:
        sys.exit(f"{NAME}: {a.dir} is a batch over several profile pairs (pairs.csv): "
                 f"give --pair P with P from the column `pair` of {a.dir}/pairs.csv")
    if not batch and a.pair is not None:
        sys.exit(f"{NAME}: --pair is for batch directories; {a.dir} holds a single run (no pairs.csv)")
    if a.arrows < 2:
        sys.exit(f"{NAME}: --arrows {a.arrows}: give at least 2 arrows per axis")
    pressure_csv = os.path.join(a.dir, "pressure.csv")
    if not os.path.exists(pressure_csv):
        sys.exit(f"{NAME}: {a.dir} has no pressure.csv: run the case file with --pressure-grid N")
    try:
        rows = read_csv(pressure_csv)
    except (OSError, ValueError) as e:
        sys.exit(f"{NAME}: cannot read {pressure_csv}: {e}")
    if rows and "px_MPa" not in rows[0]:
        sys.exit(f"{NAME}: {pressure_csv} has no traction columns (px_MPa, py_MPa, slip): run a case file "
                 "with friction (friction.coefficient and kinematics or creepages) and --pressure-grid N")
    rows = [r for r in of_case(rows, a) if r["px_MPa"] != ""]
    if not rows:
        sys.exit(f"{NAME}: case {a.case} has no traction rows in {pressure_csv} (no contact, its tangential "
                 "problem not solved, or the case not among --pressure-cases)")
    grid = "patch" in rows[0]
    cid, ykey = ("patch", "s_mm") if grid else ("ellipse", "y_mm")
    try:
        contacts = of_case(read_csv(os.path.join(a.dir, "patches.csv" if grid else "ellipses.csv")), a)
        cases = of_case(read_csv(os.path.join(a.dir, "cases.csv")), a)
    except (OSError, KeyError, ValueError) as e:
        sys.exit(f"{NAME}: cannot read {a.dir}: {e} (run with CSV output)")
    info = {c[cid]: c for c in contacts}
    ids = sorted({r[cid] for r in rows}, key=int)
    grids = {k: contact_grid([r for r in rows if r[cid] == k], "x_mm", ykey) for k in ids}

    n = len(ids)
    fig, axs = plt.subplots(1, n, figsize=(5.2 * n + 2.6, 5.4), squeeze=False)
    pt_max = max(float(np.max(np.hypot(g[3], g[4]))) for g in grids.values()) or 1.0
    # One arrow scale for every panel: the largest traction as long as 1.3 arrow spacings of the
    # smallest contact.
    spacing = min(max(g[0][-1] - g[0][0], g[1][-1] - g[1][0]) / a.arrows for g in grids.values())
    scale = pt_max / (1.3 * spacing)  # MPa per mm of arrow
    cmap = ListedColormap(["white", "#9ecae1", "#fdae6b"])
    for ax, k in zip(axs[0], ids):
        x, y, p, px, py, state = grids[k]
        dx = x[1] - x[0] if len(x) > 1 else 1.0
        dy = y[1] - y[0] if len(y) > 1 else 1.0
        ax.pcolormesh(x, y, state, cmap=cmap, vmin=0, vmax=2, shading="nearest")
        if np.any(p > 0) and len(x) > 1 and len(y) > 1:
            ax.contour(x, y, p, levels=np.max(p) * np.array([0.2, 0.4, 0.6, 0.8]), colors="0.55", linewidths=0.5)
        # Arrows on a subsample of the points in contact.
        si = max(1, int(round(len(x) / a.arrows)))
        sj = max(1, int(round(len(y) / a.arrows)))
        X, Y = np.meshgrid(x[::si], y[::sj])
        U, V, S = px[::sj, ::si], py[::sj, ::si], state[::sj, ::si]
        m = S > 0
        q = ax.quiver(X[m], Y[m], U[m], V[m], angles="xy", scale_units="xy", scale=scale, width=0.004,
                      color="k")
        c = info.get(k, {})
        title = f"{cid} {k}: Fx = {fnum(c.get('Fx_kN')):.3g} kN, Fy = {fnum(c.get('Fy_kN')):.3g} kN,\n" \
                f"adhesion {fnum(c.get('adhesion_fraction')):.2f}, N = {fnum(c.get('N_kN')):.3g} kN"
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("x (rolling direction, leading edge at +x) [mm]")
        ax.set_ylabel(("s" if grid else "y") + " (lateral, contact plane) [mm]")
        ax.set_aspect("equal")
        ax.set_xlim(x[0] - dx, x[-1] + dx)
        ax.set_ylim(y[0] - dy, y[-1] + dy)
    key = float(f"{pt_max / 2:.1g}")
    axs[0][-1].quiverkey(q, 1.05, 0.05, key, f"{key:g} MPa", labelpos="E", coordinates="axes")
    handles = [Patch(facecolor="#9ecae1", label="adhesion"), Patch(facecolor="#fdae6b", label="slip"),
               plt.Line2D([], [], color="0.55", lw=0.5, label="pressure: 0.2 ... 0.8 of its peak"),
               plt.Line2D([], [], color="k", marker=r"$\rightarrow$", ls="", markersize=12,
                          label="traction on the rail")]
    axs[0][-1].legend(handles=handles, loc="upper left", bbox_to_anchor=(1.03, 1.0), fontsize=8, frameon=False)

    label, model, _ = run_info(a.dir, a.pair)
    cs = cases[0] if cases else {}
    head = f"{label + ': ' if label else ''}case {a.case}"
    if a.pair is not None:
        head += f" (pair {a.pair})"
    if cs:
        head += f", t_Y = {fnum(cs.get('tY_mm')):g} mm, Q = {fnum(cs.get('Q_kN')):g} kN, {cs.get('method', '')}"
        if cs.get("F_over_muN", "") != "":
            head += f", |F|/(mu N) = {fnum(cs['F_over_muN']):.3f}"
    if model:
        head += f", {model}"
    fig.suptitle(head, fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    out = a.output or os.path.join(
        a.dir, f"traction_case_{a.case}" + (f"_pair_{a.pair}" if a.pair is not None else "") + ".png")
    fig.savefig(out, dpi=110)
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
