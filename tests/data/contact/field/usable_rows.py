#!/usr/bin/env python3
"""Keep the rows of a CONTACT sweep table whose case is a usable reference.

    usable_rows.py RUNS IN.csv OUT.csv

IN.csv is run_sweep.py's table of the sweep run in RUNS (the CONTACT build tools of the
project's shared workspace; README.md here). A case is dropped when its RUNS/<case>.out says
"potential contact area too small": CONTACT's potential contact area is bounded by the end of a
profile and the patch reaches that boundary, so the patch is cut there and its pressure is not
the contact's (on S1002/avg_low2 at t_Y = 8 mm the flange patch reaches the clipped end of the
measured rail). A case CONTACT could not solve (e.g. "contact detected at the first or last rail
profile point") has no row in IN.csv already. Prints the dropped cases.
"""
import csv
import os
import sys


def main():
    runs, src, dst = sys.argv[1:4]
    rows = list(csv.DictReader(open(src)))
    keep, dropped = [], []
    for r in rows:
        out = open(os.path.join(runs, r["case"] + ".out"), errors="replace").read()
        (dropped if "potential contact area too small" in out else keep).append(r)
    with open(dst, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()), lineterminator="\n")
        w.writeheader()
        w.writerows(keep)
    for r in dropped:
        print("dropped %s (y_ws %s mm, Fz %s N): potential contact area too small" % (r["case"], r["y_ws_mm"], r["Fz_target_N"]))
    print("%d rows kept, %d dropped" % (len(keep), len(dropped)))


if __name__ == "__main__":
    main()
