#!/usr/bin/env python3
"""Plot the force history of a contact table stepped through t_Y (docs/tables.md).

    plot_table_history.py HISTORY.csv -o OUT.png [--steps A:B] [--title TEXT]

HISTORY.csv is the file build/mhcontact_bench_tables writes (its 6th argument): per step t_Y,
the table's N per contact track, Fy and dFy/dt_Y, and the direct solve's Fy where solved. The
figure: t_Y (top), the tracks' N (middle) and Fy from the table against the direct solves
(bottom), over the steps A..B (default all).
Needs matplotlib (Debian: python3-matplotlib); runs headless.
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("history")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--steps", default="", help="A:B, the steps shown (default all)")
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    with open(a.history, newline="") as f:
        rows = list(csv.DictReader(f))
    if a.steps:
        lo, hi = (int(x) for x in a.steps.split(":"))
        rows = [r for r in rows if lo <= int(r["step"]) <= hi]
    step = [int(r["step"]) for r in rows]
    # The tracks that carry force in the steps shown (a table of many tracks would crowd the
    # legend with idle ones).
    tracks = [k for k in rows[0] if k.startswith("N") and k.endswith("_kN") and any(float(r[k]) != 0 for r in rows)]
    fig, ax = plt.subplots(3, 1, figsize=(8, 7.5), sharex=True)
    ax[0].plot(step, [float(r["tY_mm"]) for r in rows], "k-", lw=1)
    ax[0].set_ylabel("t_Y [mm]")
    for k in tracks:
        ax[1].plot(step, [float(r[k]) for r in rows], lw=1.2, label=f"track {k[1:-3]}")
    ax[1].set_ylabel("N [kN] (table)")
    ax[1].legend(loc="upper right", fontsize=8)
    ax[2].plot(step, [float(r["Fy_table_kN"]) for r in rows], "b-", lw=1.2, label="table")
    d = [(s, float(r["Fy_direct_kN"])) for s, r in zip(step, rows) if r["Fy_direct_kN"]]
    if d:
        ax[2].plot([x for x, _ in d], [y for _, y in d], "r.", ms=2.5, label="direct solve")
    ax[2].set_ylabel("Fy [kN]")
    ax[2].set_xlabel("step")
    ax[2].legend(loc="upper right", fontsize=8)
    for x in ax:
        x.grid(alpha=0.3)
    fig.suptitle(a.title or a.history, fontsize=10)
    fig.tight_layout()
    fig.savefig(a.output, dpi=110)


if __name__ == "__main__":
    main()
