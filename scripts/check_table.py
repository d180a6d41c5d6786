#!/usr/bin/env python3
"""A contact table against direct solves at random points (docs/tables.md "Checking a table at
random points"): the maker checks one point per cell (its centre) and validates the table at 100
random points of a fixed seed (the header's `validation`); this draws as many points as asked, of
any seed, uniformly over the table's t_Y, Q and roll ranges, looks each up in the table
(mhcontact.Table) and solves it directly by the case's own pair and method (mhcontact.Pair.from_case_file, the wheel rolled by
the point's roll), and reports the statuses and the errors of the peak pressure, the total area
and Fy where both answers are `ok`, against the tolerances in the table's header.

    PYTHONPATH=build/python python3 scripts/check_table.py TABLE.csv CASE.json [--points N] [--seed S]

Exit 0 when every point where both are `ok` is within the tolerances, 1 when some are not
(listed), 2 for bad input.
"""
import argparse
import json
import sys

import numpy as np

import mhcontact


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("table", help="a table written by `mhcontact table`")
    ap.add_argument("case", help="the case file it was made from (its pair and method solve the points)")
    ap.add_argument("--points", type=int, default=300, help="random points (default 300)")
    ap.add_argument("--seed", type=int, default=1, help="seed of the points (default 1)")
    ap.add_argument("--show", type=int, default=5, help="worst points listed (default 5)")
    a = ap.parse_args(argv)
    if a.points < 1:
        print("check_table.py: --points must be at least 1", file=sys.stderr)
        return 2
    try:
        table = mhcontact.Table(a.table)
        pair = mhcontact.Pair.from_case_file(a.case)
    except (mhcontact.InputError, OSError) as e:
        print(f"check_table.py: {e}", file=sys.stderr)
        return 2
    header = json.loads(table.header)
    tol = {"pmax": 0.03, "area": 0.05, "Fy": 0.01}
    for k in tol:
        tol[k] = header.get("error", {}).get(k, {}).get("tolerance", tol[k])
    t0, t1, q0, q1 = table.range
    r0, r1, _ = table.roll_range
    rng = np.random.default_rng(a.seed)
    pts = np.column_stack([rng.uniform(t0, t1, a.points), rng.uniform(q0, q1, a.points),
                           rng.uniform(r0, r1, a.points)])
    direct_ok = table_ok = both = table_only = 0
    errs = []  # (worst ratio to its tolerance, tY, Q, roll, e_pmax, e_area, e_Fy)
    for tY, Q, roll in pts:
        t = table.lookup(tY, Q, roll_rad=roll)
        d = pair.solve(tY, Q_N=Q, roll_rad=roll)
        dok, tok = d["status"] == "ok", t["status"] == "ok"
        direct_ok += dok
        table_ok += tok
        table_only += tok and not dok
        if not (dok and tok):
            continue
        both += 1
        pmax_t = max((c["p_max_Pa"] for c in t["contacts"]), default=0.0)
        area_t = sum(c["area_m2"] for c in t["contacts"])
        e_p = abs(pmax_t - d["pmax_MPa"] * 1e6) / (d["pmax_MPa"] * 1e6)
        e_a = abs(area_t - d["area_mm2"] * 1e-6) / (d["area_mm2"] * 1e-6)
        e_f = abs(t["Fy_N"] - d["Fy_kN"] * 1e3) / Q
        errs.append((max(e_p / tol["pmax"], e_a / tol["area"], e_f / tol["Fy"]), tY, Q, roll, e_p, e_a, e_f))
    print(f"check_table.py: {a.table}: {a.points} random points (seed {a.seed}) over t_Y {t0 * 1e3:g} ... {t1 * 1e3:g} mm, "
          f"Q {q0 * 1e-3:g} ... {q1 * 1e-3:g} kN, roll {r0 * 1e3:g} ... {r1 * 1e3:g} mrad")
    print(f"ok: direct {direct_ok}, table {table_ok}, both {both}, table ok and direct not {table_only}")
    beyond = [e for e in errs if e[0] > 1]
    if errs:
        E = np.array([e[4:] for e in errs])
        for j, (name, unit) in enumerate((("pmax", "%"), ("area", "%"), ("Fy", "% of Q"))):
            col = 100 * E[:, j]
            print(f"{name}: median {np.median(col):.3g}, p95 {np.percentile(col, 95):.3g}, max {col.max():.3g} {unit} "
                  f"(tolerance {100 * tol[name]:g} {unit})")
    print(f"ok answers beyond a tolerance: {len(beyond)} of {both}")
    for e in sorted(errs, reverse=True)[:a.show]:
        print(f"  t_Y {e[1] * 1e3:.3f} mm, Q {e[2] * 1e-3:.2f} kN, roll {e[3] * 1e3:.3f} mrad: pmax {100 * e[4]:.3g} %, "
              f"area {100 * e[5]:.3g} %, Fy {100 * e[6]:.3g} % of Q")
    return 1 if beyond else 0


if __name__ == "__main__":
    sys.exit(main())
