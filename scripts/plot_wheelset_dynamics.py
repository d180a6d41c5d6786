#!/usr/bin/env python3
"""Plots of the wheelset dynamics example (docs/wheelset-dynamics.md) from the CSV files that
examples/wheelset_dynamics writes:

  plot_wheelset_dynamics.py DIR [-o OUTDIR]

DIR holds klingel.csv and klingel_half_cycles.csv (`wheelset_dynamics klingel --csv ...
--half-cycles ...`) and critical.csv (`wheelset_dynamics critical --csv ...`); writes
OUTDIR/wheelset_dynamics_klingel.png (lateral motion and the wavelength check) and
OUTDIR/wheelset_dynamics_critical.png (below and above the critical speed). OUTDIR defaults to DIR.
"""
import argparse
import csv
import os
import sys

import matplotlib
import matplotlib.pyplot as plt


def read_runs(path):
    runs = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            r = runs.setdefault(row["run"], ([], [], []))
            r[0].append(float(row["distance_m"]))
            r[1].append(float(row["y_mm"]))
            r[2].append(float(row["psi_mrad"]))
    return runs


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dir")
    ap.add_argument("-o", "--out", default=None)
    a = ap.parse_args()
    out = a.out or a.dir
    os.makedirs(out, exist_ok=True)
    matplotlib.rcParams.update({"font.size": 9})

    k = read_runs(os.path.join(a.dir, "klingel.csv"))["klingel"]
    with open(os.path.join(a.dir, "klingel_half_cycles.csv"), newline="") as f:
        hc = list(csv.DictReader(f))
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 3.6), gridspec_kw={"width_ratios": [1.6, 1]})
    ax1.plot(k[0], k[1], lw=1, label="y [mm]")
    ax1.plot(k[0], k[2], lw=1, label="ψ [mrad]")
    for h in hc:
        ax1.axvspan(float(h["s0_m"]), float(h["s1_m"]), color="0.92" if hc.index(h) % 2 else "0.97", lw=0)
    ax1.set_xlabel("distance run [m]")
    ax1.set_title("free wheelset, S1002 / 60E1 1:40, 2 m/s")
    ax1.legend(loc="upper right")
    peak = [float(h["peak_mm"]) for h in hc]
    ax2.plot(peak, [float(h["L_sim_m"]) for h in hc], "o", label="simulated (half cycles)")
    ax2.plot(peak, [float(h["L_klingel_m"]) for h in hc], "x-", label="2π √(r0 s / tan γe(peak))")
    ax2.set_xlabel("peak of the half cycle [mm]")
    ax2.set_ylabel("wavelength [m]")
    ax2.set_title("Klingel check")
    ax2.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "wheelset_dynamics_klingel.png"), dpi=110)

    c = read_runs(os.path.join(a.dir, "critical.csv"))
    fig, ax = plt.subplots(figsize=(10, 3.2))
    for name, (s, y, _) in c.items():
        ax.plot(s, y, lw=1, label=name.replace("Vlin", " × linear critical speed"))
    ax.set_xlabel("distance run [m]")
    ax.set_ylabel("y [mm]")
    ax.set_title("suspended wheelset, S1002 / 60E1 1:20: a 0.5 mm perturbation below and above the critical speed")
    ax.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "wheelset_dynamics_critical.png"), dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
