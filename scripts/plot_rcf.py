#!/usr/bin/env python3
"""RCF indicators over t_Y from one or more `mhcontact run` directories written with the case-file
key "rcf" (docs/outputs.md "RCF columns"): FI_surf_el (elastic Hertz p0) per contact, and each contact's point on the
shakedown map (p0_el/k against f, with its limits). Reads ellipses.csv or patches.csv.

Usage: scripts/plot_rcf.py DIR [DIR ...] [-o rcf.png]
"""
import argparse
import csv
import os
import sys


def rows(d):
    for name in ("ellipses.csv", "patches.csv"):
        p = os.path.join(d, name)
        if os.path.exists(p):
            with open(p, newline="") as fh:
                r = list(csv.DictReader(fh))
            if r and "FI_surf_el" not in r[0]:
                sys.exit(f"{p}: no RCF columns (run with the case-file key \"rcf\", docs/outputs.md)")
            return name, r
    sys.exit(f"{d}: neither ellipses.csv nor patches.csv")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dirs", nargs="+")
    ap.add_argument("-o", "--output", default="rcf.png")
    a = ap.parse_args()
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    for d in a.dirs:
        name, r = rows(d)
        label = os.path.basename(os.path.normpath(d)) + (" (patches)" if name == "patches.csv" else "")
        key = "ellipse" if name == "ellipses.csv" else "patch"
        for c in sorted({x[key] for x in r}, key=int):
            sel = [x for x in r if x[key] == c and x["FI_surf_el"] != ""]
            if not sel:
                continue
            t = [float(x["tY_mm"]) for x in sel]
            ax1.plot(t, [float(x["FI_surf_el"]) for x in sel], "o-", ms=3, label=f"{label} {key} {c}")
            ax2.plot(t, [float(x["p0_el_over_k"]) for x in sel], "o-", ms=3, label=f"{label} {key} {c}: p0_el/k")
            ax2.plot(t, [float(x["shakedown_limit_p0_over_k"]) for x in sel], "--", lw=1,
                     label=f"{label} {key} {c}: shakedown limit")
            ax2.plot(t, [float(x["elastic_limit_p0_over_k"]) for x in sel], ":", lw=1,
                     label=f"{label} {key} {c}: first yield")
    ax1.axhline(0, color="k", lw=0.8)
    ax1.set_xlabel("t_Y [mm]"); ax1.set_ylabel("FI_surf_el = f − k/p0_el")
    ax1.set_title("surface fatigue index (> 0: surface RCF)")
    ax2.set_xlabel("t_Y [mm]"); ax2.set_ylabel("p0_el / k")
    ax2.set_title("shakedown map: load factor and limits")
    ax1.legend(fontsize=7); ax2.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(a.output, dpi=120)
    print(a.output)


if __name__ == "__main__":
    main()
