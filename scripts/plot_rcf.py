#!/usr/bin/env python3
"""RCF indicators, damage and wear over t_Y from one or more `mhcontact run` directories written with
the case-file key "rcf" and/or "friction" (docs/outputs.md "RCF columns", "Damage and wear columns").

Panels (each only when its columns are there): FI_surf_el per contact against t_Y; the shakedown
map, each contact of the sweep as a point (traction coefficient, p0_el/k) with the map's limit
curves at the run's aspect ratios; the Burstow damage per axle and the USFD wear per metre against
t_Y. With --tY-mean/--tY-sd (or the case file's "rcf": {"tY_distribution"} echoed in results.json)
it prints the damage and wear weighted by that normal distribution of t_Y over the sweep's t_Y
(trapezoidal weights of the normal density, normalised over the sweep's range): the numbers that a
whole run's summary carries as rcf_tY_weighted (docs/outputs.md "Damage and wear over t_Y"), here
also for a merged sharded run or another distribution.

Usage: scripts/plot_rcf.py DIR [DIR ...] [-o rcf.png] [--tY-mean MM --tY-sd MM]
"""
import argparse
import csv
import json
import math
import os
import sys


def rows(d):
    for name in ("ellipses.csv", "patches.csv"):
        p = os.path.join(d, name)
        if os.path.exists(p):
            with open(p, newline="") as fh:
                r = list(csv.DictReader(fh))
            if r and "FI_surf_el" not in r[0] and "D_burstow_per_axle" not in r[0]:
                sys.exit(f"{p}: neither RCF nor damage columns (run with the case-file key \"rcf\" or "
                         "\"friction\", docs/outputs.md)")
            return name, r
    sys.exit(f"{d}: neither ellipses.csv nor patches.csv")


def cases(d):
    p = os.path.join(d, "cases.csv")
    if not os.path.exists(p):
        return []
    with open(p, newline="") as fh:
        return list(csv.DictReader(fh))


def distribution(d, mean, sd):
    """The t_Y distribution: the command line's, else the case file's echoed in results.json."""
    if mean is not None and sd is not None:
        return mean, sd
    p = os.path.join(d, "results.json")
    if os.path.exists(p):
        try:
            with open(p) as fh:
                head = fh.read(200000)
            i = head.find('"tY_distribution"')
            if i >= 0:
                j = head.index("}", i)
                dd = json.loads("{" + head[i:j + 1] + "}")["tY_distribution"]
                return dd["mean_mm"], dd["sd_mm"]
        except (ValueError, KeyError):
            pass
    return None


def weighted(t, v, mean, sd):
    """Σ w_i v_i with w_i the normal density at t_i times its trapezoid width, normalised to 1 over the sweep."""
    pts = sorted(zip(t, v))
    t = [p[0] for p in pts]
    v = [p[1] for p in pts]
    n = len(t)
    if n == 1:
        return v[0]
    w = []
    for i in range(n):
        lo = t[i] - (t[i] - t[i - 1]) / 2 if i > 0 else t[i]
        hi = t[i] + (t[i + 1] - t[i]) / 2 if i < n - 1 else t[i]
        w.append(math.exp(-0.5 * ((t[i] - mean) / sd) ** 2) * (hi - lo))
    s = sum(w)
    return sum(wi * vi for wi, vi in zip(w, v)) / s if s > 0 else float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dirs", nargs="+")
    ap.add_argument("-o", "--output", default="rcf.png")
    ap.add_argument("--tY-mean", type=float, help="[mm] mean of a normal distribution of t_Y")
    ap.add_argument("--tY-sd", type=float, help="[mm] its standard deviation (> 0)")
    a = ap.parse_args()
    if a.tY_sd is not None and not a.tY_sd > 0:
        sys.exit(f"--tY-sd {a.tY_sd}: must be > 0 (a standard deviation in mm)")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 2, figsize=(11, 8.4))
    (ax1, ax2), (ax3, ax4) = axes
    ymax = 0.0  # the map's height: its contacts and limits, with room above
    for d in a.dirs:
        name, r = rows(d)
        label = os.path.basename(os.path.normpath(d)) + (" (patches)" if name == "patches.csv" else "")
        key = "ellipse" if name == "ellipses.csv" else "patch"
        for c in sorted({x[key] for x in r}, key=int):
            sel = [x for x in r if x[key] == c]
            t = [float(x["tY_mm"]) for x in sel]
            if "FI_surf_el" in r[0]:
                s2 = [(ti, x) for ti, x in zip(t, sel) if x["FI_surf_el"] != ""]
                if s2:
                    ax1.plot([p[0] for p in s2], [float(p[1]["FI_surf_el"]) for p in s2], "o-", ms=3,
                             label=f"{label} {key} {c}")
                    ax2.plot([float(p[1]["traction_coefficient"]) for p in s2],
                             [float(p[1]["p0_el_over_k"]) for p in s2], "o", ms=4, label=f"{label} {key} {c}")
            if "D_burstow_per_axle" in r[0]:
                s3 = [(ti, x) for ti, x in zip(t, sel) if x["D_burstow_per_axle"] != ""]
                if s3:
                    ax3.plot([p[0] for p in s3], [float(p[1]["D_burstow_per_axle"]) for p in s3], "o-", ms=3,
                             label=f"{label} {key} {c}")
                    ax4.plot([p[0] for p in s3], [float(p[1]["wear_ug_per_m"]) for p in s3], "o-", ms=3,
                             label=f"{label} {key} {c}")
        # The map's limits (docs/methods.md "RCF indicators"): first yield as a curve at the sweep's
        # largest frictionless value, capped by the surface limit 1/f; the elastic shakedown limit,
        # which falls with f, as each contact's own (its f and aspect ratio).
        if "FI_surf_el" in r[0]:
            lims = [(float(x["elastic_limit_p0_over_k"]), float(x["shakedown_limit_p0_over_k"]),
                     float(x["traction_coefficient"])) for x in r if x["FI_surf_el"] != ""]
            # a limit below 1/f is the frictionless value (the others are capped by the surface)
            free = [l[0] for l in lims if l[2] == 0 or l[0] < 1 / l[2] - 1e-9]
            fs = [i / 100 for i in range(1, 61)]
            if free:
                ax2.plot(fs, [min(max(free), 1 / f) for f in fs], "k:", lw=1, label=f"{label}: first yield")
            if lims:
                top = 1.15 * max([float(x["p0_el_over_k"]) for x in r if x["FI_surf_el"] != ""] + [l[1] for l in lims])
                ymax = max(ymax, top)
                ax2.plot([f for f in fs if 1 / f <= ymax], [1 / f for f in fs if 1 / f <= ymax], "k-", lw=0.6,
                         label="surface limit 1/f")
                ax2.plot([l[2] for l in lims], [l[1] for l in lims], "k_", ms=8,
                         label=f"{label}: elastic shakedown limit of each contact")
        dist = distribution(d, a.tY_mean, a.tY_sd)
        cs = cases(d)
        if dist and cs and "D_burstow_per_axle" in cs[0]:
            ok = [x for x in cs if x["D_burstow_per_axle"] != ""]
            if ok:
                t = [float(x["tY_mm"]) for x in ok]
                D = weighted(t, [float(x["D_burstow_per_axle"]) for x in ok], *dist)
                W = weighted(t, [float(x["wear_ug_per_m"]) for x in ok], *dist)
                print(f"{d}: t_Y ~ N({dist[0]} mm, {dist[1]} mm) over t_Y {min(t)} .. {max(t)} mm: "
                      f"damage per axle {D:.6g}, wear {W:.6g} ug/m")
    ax1.axhline(0, color="k", lw=0.8)
    ax1.set_xlabel("t_Y [mm]"); ax1.set_ylabel("FI_surf_el = f − k/p0_el")
    ax1.set_title("surface fatigue index (> 0: surface RCF)")
    ax2.set_xlabel("traction coefficient f"); ax2.set_ylabel("p0_el / k")
    ax2.set_title("shakedown map: the sweep's contacts")
    if ymax > 0:
        ax2.set_ylim(0, ymax)
    ax3.set_xlabel("t_Y [mm]"); ax3.set_ylabel("damage per axle (Burstow)")
    ax3.set_title("rail RCF damage from Tγ")
    ax4.set_xlabel("t_Y [mm]"); ax4.set_ylabel("wear [µg/m] (USFD)")
    ax4.set_title("wear per metre rolled")
    for ax in axes.flat:
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(a.output, dpi=120)
    print(a.output)


if __name__ == "__main__":
    main()
