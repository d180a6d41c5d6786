#!/usr/bin/env python3
"""Plot the outputs of `mhcontact wheelset CASE -o DIR` (docs/wheelset.md).

    plot_wheelset.py DIR [--reference DIR_OR_NONE] [--fleet-x qR|Sh|Sd]

One wheelset (DIR/wheelset.csv, DIR/conicity.csv): DIR/wheelset_delta_r.png, the rolling-radius
difference dr(y), and DIR/wheelset_conicity.png, tan gamma_e against the amplitude with the
EN 15302 window; --reference DIR adds the points of wheelA_railA_delta_r.csv and
wheelA_railA_conicity.csv found in that directory (tests/data/en15302).
A fleet (DIR/fleet.csv): DIR/wheelset_fleet.png, tan gamma_e at 3 mm against qR (or Sh, Sd),
refused wheels left out and counted in the title.
Needs matplotlib (Debian: python3-matplotlib); runs headless.
"""
import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def num(s):
    try:
        return float(s)
    except (TypeError, ValueError):
        return math.nan


def plot_single(d, ref):
    rows = read_csv(os.path.join(d, "wheelset.csv"))
    y = [num(r["y_mm"]) for r in rows]
    dr = [num(r["delta_r_mm"]) for r in rows]
    jumps = [num(r["y_mm"]) for r in rows if r["two_point_left"] == "1" or r["two_point_right"] == "1"]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot(y, dr, "-", lw=1.2, label="mhcontact")
    if jumps:
        ax.plot(jumps, [dr[y.index(v)] for v in jumps], "rx", ms=5, label="two-point / jump")
    if ref:
        t = read_csv(os.path.join(ref, "wheelA_railA_delta_r.csv"))
        ax.plot([num(r["y_mm"]) for r in t], [num(r["delta_r_mm"]) for r in t], "k.", ms=3, label="EN 15302 table")
    ax.set_xlabel("lateral displacement y [mm]")
    ax.set_ylabel("rolling-radius difference Δr = r_right − r_left [mm]")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(d, "wheelset_delta_r.png"), dpi=120)
    plt.close(fig)

    con = read_csv(os.path.join(d, "conicity.csv"))
    a = [num(r["amplitude_mm"]) for r in con]
    t = [num(r["tan_gamma_e"]) for r in con]
    lo = [num(r["window_lo"]) for r in con]
    hi = [num(r["window_hi"]) for r in con]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.fill_between(a, lo, hi, color="0.85", label="EN 15302 window ± min(0.05, 0.5 tan γe)")
    ax.plot(a, t, "-", lw=1, color="C0")
    ok = [i for i, r in enumerate(con) if r["status"] == "ok"]
    ax.plot([a[i] for i in ok], [t[i] for i in ok], "o", ms=3, color="C0", label="mhcontact, ok")
    out = [i for i, r in enumerate(con) if r["status"] != "ok" and not math.isnan(t[i])]
    if out:  # a figure outside the conicity's domain (docs/wheelset.md "Where the conicity is ok")
        labels = sorted({con[i]["status"] for i in out})
        ax.plot([a[i] for i in out], [t[i] for i in out], "o", ms=4, mfc="none", color="C3",
                label="mhcontact, " + " / ".join(labels))
    if ref:
        k = read_csv(os.path.join(ref, "wheelA_railA_conicity.csv"))
        ax.plot([num(r["amplitude_mm"]) for r in k], [num(r["tan_gamma_e"]) for r in k], "k+", ms=7, label="EN 15302 table")
    ax.set_xlabel("amplitude ŷ [mm]")
    ax.set_ylabel("equivalent conicity tan γe")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(d, "wheelset_conicity.png"), dpi=120)
    plt.close(fig)


def plot_fleet(d, xname):
    rows = read_csv(os.path.join(d, "fleet.csv"))
    ok = [r for r in rows if r["status"] == "ok" and not math.isnan(num(r[xname + "_en15313_mm"]))]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot([num(r[xname + "_en15313_mm"]) for r in ok], [num(r["tan_gamma_e_3mm"]) for r in ok], "o", ms=4)
    ax.set_xlabel(f"{xname} [mm] (EN 15313, from the profile)")
    ax.set_ylabel("tan γe at ŷ = 3 mm")
    ax.set_title(f"{len(ok)} wheels plotted, {len(rows) - len(ok)} refused or without {xname}")
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "wheelset_fleet.png"), dpi=120)
    plt.close(fig)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("dir")
    p.add_argument("--reference", help="directory holding the EN 15302 tables to overlay")
    p.add_argument("--fleet-x", default="qR", choices=["qR", "Sh", "Sd"])
    a = p.parse_args()
    if os.path.exists(os.path.join(a.dir, "fleet.csv")):
        plot_fleet(a.dir, a.fleet_x)
    elif os.path.exists(os.path.join(a.dir, "wheelset.csv")):
        plot_single(a.dir, a.reference)
    else:
        sys.exit(f"plot_wheelset.py: {a.dir} holds neither wheelset.csv nor fleet.csv (run `mhcontact wheelset` first)")


if __name__ == "__main__":
    main()
