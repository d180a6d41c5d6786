#!/usr/bin/env python3
"""Plot the contact pressure of one case of `mhcontact run`.

    plot_pressure.py DIR --case K [--pair P] [--ellipses MH_DIR] [-o FILE.png]

Multi-Hertzian runs (DIR holds ellipses.csv, joined with geometry.csv for the contact point and
angle): elastic versus plastic pressure. For a batch
(DIR/pairs.csv), --pair P picks the profile pair: its rows of ellipses.csv and
DIR/pairs/P/profiles.csv. The title names the pair, the case, the model and p_lim; the pressure
panels draw the p_lim line. Three panels: the rail section with the contact patches of case K (the plastic patch
and, in plastic mode, the elastic patch at the same load), and the pressure along the patch
axes x (rolling) and y (lateral) of every loaded ellipse: the capped pressure
min(p0 sqrt(1 - x^2/a^2 - y^2/b^2), p_lim) against the elastic Hertz pressure at the same load
(docs/method.md §5).

Grid methods (DIR holds patches.csv): a 2-D map of the pressure of every contact patch of case K,
x along the rolling direction against s, lateral in the patch's plane, with the multi-Hertzian
ellipses of the same case outlined over it when --ellipses names the output directory of a
multi-Hertzian run of the same case file (CSV format; the ellipse at s = (y - y_ref)/cos(gamma) of
the patch, its plastic patch solid and, plastic, its elastic patch dotted), and beside each map
the pressure across the patch (along s, at the x of the peak) with the p_lim line. Half-space
runs need --pressure-grid N (pressure.csv: every element in contact); strip runs need --strips
(strips.csv; each strip carries amplitude sqrt(1 - ((x - x_c)/half_length)^2), capped at p_lim
for a plastic strip). Needs matplotlib (Debian: python3-matplotlib); runs headless.
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


def read_ellipses(d):
    """ellipses.csv of run directory d, each row completed with its candidate's columns of
    geometry.csv (y_rail_mm, gamma_deg, radii, ...), joined on the text of (pair,) tY_mm, ellipse."""
    rows = read_csv(os.path.join(d, "ellipses.csv"))
    key = lambda r: (r.get("pair"), r["tY_mm"], r["ellipse"])  # noqa: E731
    geo = {key(g): g for g in read_csv(os.path.join(d, "geometry.csv"))}
    for r in rows:
        g = geo.get(key(r))
        if g is None:
            raise ValueError(f"{d}/geometry.csv has no row for tY_mm={r['tY_mm']}, ellipse={r['ellipse']}")
        for k, v in g.items():
            r.setdefault(k, v)
    return rows


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


def fnum(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return math.nan


def of_case(rows, a):
    return [r for r in rows if int(r["case"]) == a.case and (a.pair is None or int(r.get("pair", -1)) == a.pair)]


def regular_grid(rows, xkey, ykey, columns, fill, step=0.2):
    """The rows of one contact of pressure.csv on their regular grid: the x and y node values
    (numpy arrays), the spacings dx, dy (`step` where a direction has one node) and a dict of
    (ny, nx) arrays, one per name in `columns`, `fill` where no row stands."""
    import numpy as np  # noqa: E402

    xs = sorted({fnum(r[xkey]) for r in rows})
    ys = sorted({fnum(r[ykey]) for r in rows})
    dx = min(np.diff(xs)) if len(xs) > 1 else step
    dy = min(np.diff(ys)) if len(ys) > 1 else step
    nx, ny = int(round((xs[-1] - xs[0]) / dx)) + 1, int(round((ys[-1] - ys[0]) / dy)) + 1
    out = {c: np.full((ny, nx), fill, dtype=float) for c in columns}
    for r in rows:
        i = int(round((fnum(r[xkey]) - xs[0]) / dx))
        j = int(round((fnum(r[ykey]) - ys[0]) / dy))
        for c in columns:
            out[c][j, i] = fnum(r[c])
    return xs[0] + dx * np.arange(nx), ys[0] + dy * np.arange(ny), dx, dy, out


def grid_map(a, batch):
    """The 2-D pressure map of a half-space or strip run (module docstring)."""
    import matplotlib.patches as mpatches  # noqa: E402
    import numpy as np  # noqa: E402

    pressure_csv = os.path.join(a.dir, "pressure.csv")
    strips_csv = os.path.join(a.dir, "strips.csv")
    try:
        patches = of_case(read_csv(os.path.join(a.dir, "patches.csv")), a)
        cases = of_case(read_csv(os.path.join(a.dir, "cases.csv")), a)
    except (OSError, KeyError, ValueError) as e:
        sys.exit(f"plot_pressure.py: cannot read {a.dir}: {e}")
    if not patches:
        where = f"pair {a.pair}, " if batch else ""
        sys.exit(f"plot_pressure.py: {where}case {a.case} has no contact patch in {a.dir}/patches.csv")
    method = cases[0].get("method", "") if cases else ""
    try:
        if os.path.exists(pressure_csv):
            kind = "grid"
            rows = [r for r in of_case(read_csv(pressure_csv), a)]
            if rows and "s_mm" not in rows[0]:
                sys.exit(f"plot_pressure.py: {pressure_csv} is not a half-space pressure grid (no s_mm column)")
        elif os.path.exists(strips_csv):
            kind = "strips"
            rows = of_case(read_csv(strips_csv), a)
        else:
            sys.exit(f"plot_pressure.py: {a.dir} has neither pressure.csv nor strips.csv: run the half-space "
                     "method with --pressure-grid N, or the strip method with --strips")
    except (OSError, KeyError, ValueError) as e:
        sys.exit(f"plot_pressure.py: cannot read the pressures of {a.dir}: {e}")
    if not rows:
        sys.exit(f"plot_pressure.py: case {a.case} has no pressure rows in {pressure_csv if kind == 'grid' else strips_csv}")
    label, model, plim = run_info(a.dir, a.pair)
    plastic_cols = "plastic_area_mm2" in patches[0]
    model = model or ("plastic" if plastic_cols else "elastic")
    if plim is None and plastic_cols:
        caps = [fnum(r["pmax_MPa"]) for r in patches if fnum(r.get("plastic_area_mm2")) > 0]
        plim = max(caps) if caps else None

    ellipses = []
    if a.ellipses:
        try:
            ellipses = of_case(read_ellipses(a.ellipses), a)
        except (OSError, KeyError, ValueError) as e:
            sys.exit(f"plot_pressure.py: --ellipses {a.ellipses}: {e} (give the output directory of a "
                     "multi-Hertzian `mhcontact run` with CSV output)")
        if not ellipses:
            sys.exit(f"plot_pressure.py: --ellipses {a.ellipses}: case {a.case} has no loaded ellipse")
        t0, q0 = fnum(patches[0]["tY_mm"]), fnum(patches[0]["Q_kN"])
        t1, q1 = fnum(ellipses[0]["tY_mm"]), fnum(ellipses[0]["Q_kN"])
        if abs(t0 - t1) > 1e-9 or abs(q0 - q1) > 1e-9:
            sys.exit(f"plot_pressure.py: --ellipses {a.ellipses}: its case {a.case} is t_Y = {t1:g} mm, Q = {q1:g} kN, "
                     f"not t_Y = {t0:g} mm, Q = {q0:g} kN: run the same case file with the multi-Hertzian method")

    n = len(patches)
    fig, axs = plt.subplots(n, 2, figsize=(13, 4.8 * n), squeeze=False,
                            gridspec_kw={"width_ratios": [1.6, 1]})
    vmax = max(fnum(r["pmax_MPa"]) for r in patches)
    for k, P in enumerate(patches):
        ax, cut = axs[k]
        pid = P["patch"]
        gamma = math.radians(fnum(P["gamma_deg"]))
        y_ref = fnum(P["y_rail_mm"])
        if kind == "grid":
            pr = [r for r in rows if r["patch"] == pid]
            xv, sv, dx, ds, g = regular_grid(pr, "x_mm", "s_mm", ["p_MPa"], np.nan)
            grid = g["p_MPa"]
            x0, s0, ns = xv[0], sv[0], len(sv)
            ext = (x0 - dx / 2, xv[-1] + dx / 2, s0 - ds / 2, sv[-1] + ds / 2)
        else:
            pr = [r for r in rows if r["patch"] == pid]
            ss = sorted(fnum(r["s_mm"]) for r in pr)
            ds = min(np.diff(ss)) if len(ss) > 1 else 0.2
            xmax = max(abs(fnum(r["x_centre_mm"])) + fnum(r["half_length_mm"]) for r in pr)
            nx = 401
            dx = 2 * xmax / (nx - 1)
            x0, s0 = -xmax, ss[0]
            ns = int(round((ss[-1] - s0) / ds)) + 1
            grid = np.full((ns, nx), np.nan)
            xv = np.linspace(-xmax, xmax, nx)
            for r in pr:
                c, h, q = fnum(r["x_centre_mm"]), fnum(r["half_length_mm"]), fnum(r["amplitude_MPa"])
                u = 1 - ((xv - c) / h) ** 2
                pv = np.where(u > 0, q * np.sqrt(np.clip(u, 0, None)), np.nan)
                if r.get("plastic") == "1" and plim is not None:
                    pv = np.minimum(pv, plim)
                grid[int(round((fnum(r["s_mm"]) - s0) / ds))] = pv
            xs = list(xv)
            ext = (-xmax - dx / 2, xmax + dx / 2, s0 - ds / 2, ss[-1] + ds / 2)
        elongated = (ext[1] - ext[0]) > 4 * (ext[3] - ext[2]) or (ext[3] - ext[2]) > 4 * (ext[1] - ext[0])
        im = ax.imshow(grid, origin="lower", extent=ext, aspect="auto" if elongated else "equal", cmap="viridis",
                       vmin=0, vmax=vmax, interpolation="nearest")
        cb = fig.colorbar(im, ax=ax, shrink=0.9, pad=0.02)
        cb.set_label("p [MPa]")
        if plim is not None:
            cb.ax.axhline(plim, color="red", lw=1.5)
            if np.nanmax(grid) >= plim * (1 - 1e-9):
                ax.contour(np.where(np.isnan(grid), 0, grid), levels=[plim * (1 - 1e-6)], extent=ext, origin="lower",
                           colors="red", linewidths=0.8)
        # Multi-Hertzian ellipses nearest this patch, in its plane.
        near = [e for e in ellipses
                if min(range(n), key=lambda j: abs(fnum(patches[j]["y_rail_mm"]) - fnum(e["y_rail_mm"]))) == k]
        handles = []
        for e in near:
            sc = (fnum(e["y_rail_mm"]) - y_ref) / math.cos(gamma)
            A, B = fnum(e["a_mm"]), fnum(e["b_mm"])
            ax.add_patch(mpatches.Ellipse((0, sc), 2 * A, 2 * B, fill=False, color="white", lw=1.6))
            handles.append(mpatches.Patch(fill=False, edgecolor="black", lw=1.6,
                                          label=f"MH ellipse #{e['ellipse']}: {2 * A:.1f} × {2 * B:.1f} mm"))
            if "a_el_mm" in e and e.get("plastic") == "1":
                ax.add_patch(mpatches.Ellipse((0, sc), 2 * fnum(e["a_el_mm"]), 2 * fnum(e["b_el_mm"]), fill=False,
                                              color="white", lw=1.2, ls=":"))
                handles.append(mpatches.Patch(fill=False, edgecolor="black", lw=1.2, ls=":",
                                              label=f"  its elastic patch: {2 * fnum(e['a_el_mm']):.1f} × "
                                                    f"{2 * fnum(e['b_el_mm']):.1f} mm"))
            ext = (min(ext[0], -A), max(ext[1], A), min(ext[2], sc - B), max(ext[3], sc + B))
        ax.set_xlim(ext[0] - 0.5, ext[1] + 0.5)
        ax.set_ylim(ext[2] - 0.5, ext[3] + 0.5)
        ax.set_xlabel("x [mm] (rolling direction)" + ("; axes not to scale" if elongated else ""))
        ax.set_ylabel("s [mm] (lateral, in the patch plane)")
        ax.set_title(f"patch {pid}: y_rail {y_ref:.2f} mm, γ {fnum(P['gamma_deg']):.1f}°, N {fnum(P['N_kN']):.1f} kN, "
                     f"area {fnum(P['area_mm2']):.1f} mm², p_max {fnum(P['pmax_MPa']):.0f} MPa", fontsize=9)
        if plim is not None:
            handles.append(mpatches.Patch(fill=False, edgecolor="red", lw=0.8, label=f"p = p_lim ({plim:g} MPa)"))
        if handles:
            ax.legend(handles=handles, fontsize=8, loc="upper left", bbox_to_anchor=(0.0, -0.16), borderaxespad=0,
                      ncol=2, frameon=False)
        # The cut across the patch at the loaded column nearest x = 0 (the ellipses' centre line).
        loaded = [i for i in range(grid.shape[1]) if np.nanmax(np.nan_to_num(grid[:, i])) > 0]
        i_peak = min(loaded, key=lambda i: abs(x0 + i * dx))
        xc = x0 + i_peak * dx
        s_axis = [s0 + j * ds for j in range(ns)]
        cut.step(s_axis, np.nan_to_num(grid[:, i_peak]), where="mid", color="tab:green",
                 label=f"{method or kind} at x = {xc:.1f} mm")
        for e in near:
            sc = (fnum(e["y_rail_mm"]) - y_ref) / math.cos(gamma)
            A, B, p0 = fnum(e["a_mm"]), fnum(e["b_mm"]), fnum(e["p0_MPa"])
            cap = fnum(e.get("p_max_MPa")) if e.get("plastic") == "1" else math.inf
            sv = np.linspace(sc - B, sc + B, 201)
            qv = [min(p0 * math.sqrt(max(0.0, 1 - (xc / A) ** 2 - ((v - sc) / B) ** 2)), cap) for v in sv]
            cut.plot(sv, qv, color="tab:blue", lw=1.2, label=f"MH ellipse #{e['ellipse']} at x = {xc:.1f} mm")
        if plim is not None:
            cut.axhline(plim, color="red", ls="--", lw=1, label=f"p_lim {plim:g} MPa")
        cut.set_xlabel("s [mm]")
        cut.set_ylabel("p [MPa]")
        cut.grid(True, alpha=0.3)
        cut.legend(fontsize=8, loc="upper left", bbox_to_anchor=(0.0, -0.16), borderaxespad=0, frameon=False)
    pair_txt = (f"pair {a.pair}" + (f" ({label})" if label else "")) if batch else (label or "")
    plim_txt = f"p_lim = {plim:g} MPa" if plim is not None else "p_lim = none (elastic)"
    fig.suptitle(f"{pair_txt}\ncase {a.case}: t_Y = {patches[0]['tY_mm']} mm, Q = {patches[0]['Q_kN']} kN; "
                 f"{method or kind} method, {model}, {plim_txt}"
                 + ("; multi-Hertzian ellipses from " + os.path.basename(os.path.normpath(a.ellipses)) if a.ellipses else ""),
                 fontsize=10)
    out = a.output or os.path.join(a.dir, f"pressure_case_{a.case}.png" if not batch
                                   else f"pressure_case_{a.case}_pair_{a.pair}.png")
    fig.tight_layout()
    fig.savefig(out, dpi=110, bbox_inches="tight")
    print(f"wrote {out}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir", help="output directory of `mhcontact run`")
    ap.add_argument("--case", type=int, required=True, help="case number (column `case`)")
    ap.add_argument("--pair", type=int, help="profile pair of a batch directory (column `pair` of pairs.csv)")
    ap.add_argument("-o", "--output", help="PNG file (default DIR/pressure_case_K.png)")
    ap.add_argument("--ellipses", metavar="MH_DIR",
                    help="grid methods: outline the ellipses of this multi-Hertzian run of the same case file")
    a = ap.parse_args(argv)
    if not os.path.isdir(a.dir):
        sys.exit(f"plot_pressure.py: {a.dir} is not a directory (give the output directory of `mhcontact run`)")
    batch = os.path.exists(os.path.join(a.dir, "pairs.csv"))
    if batch and a.pair is None:
        sys.exit(f"plot_pressure.py: {a.dir} is a batch over several profile pairs (pairs.csv): "
                 f"give --pair P with P from the column `pair` of {a.dir}/pairs.csv")
    if not batch and a.pair is not None:
        sys.exit(f"plot_pressure.py: --pair is for batch directories; {a.dir} holds a single run (no pairs.csv)")
    if os.path.exists(os.path.join(a.dir, "patches.csv")):
        return grid_map(a, batch)
    if a.ellipses:
        sys.exit("plot_pressure.py: --ellipses is for half-space and strip runs (patches.csv); "
                 f"{a.dir} is a multi-Hertzian run")
    try:
        ell = [r for r in read_ellipses(a.dir)
               if int(r["case"]) == a.case and (a.pair is None or int(r["pair"]) == a.pair)]
        prof = read_csv(os.path.join(a.dir, "pairs", str(a.pair), "profiles.csv") if batch
                        else os.path.join(a.dir, "profiles.csv"))
    except (OSError, ValueError) as e:
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
