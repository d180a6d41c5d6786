#!/usr/bin/env python3
"""Run one case file with several methods and plot them against t_Y.

    compare_methods.py CASE.json [--methods multi-hertzian,strips,half-space] [--Q 50]
                       [--mhcontact build/mhcontact] [--reference CONTACT.csv] [-o FILE.png]
                       [--table FILE.csv] [--markdown FILE.md]

The case file's sweep is solved by each method (`mhcontact run` with the case's "method"
replaced), and one figure shows, against t_Y, for the load Q (kN; default: the first load of
the sweep): the peak pressure, the total contact area, and the share of Q carried by the main
contact (the load split), one curve per method. --reference adds CONTACT's results (a table like
tests/data/contact/*.csv: y_ws_mm, pmax_MPa, area_mm2). --table writes the numbers plotted.
This is the picture that shows where the fast method can be trusted for your own profiles.
On measured profiles smoothed for contact, a shaded range around each grid method's peak pressure
and area is its smoothing uncertainty band: the same cases with every smoothing length halved
and doubled (cases.csv pmax_half_L_MPa ...; docs/profiles.md §7).

A plastic case ("model": "plastic") is also run elastic (the same case without p_lim) with every
method, and a fourth panel shows the area ratio plastic/elastic at the same load; the table gains
the columns area_elastic_mm2, pmax_elastic_MPa, area_ratio. --markdown writes, per t_Y, the total
area, the peak pressure and (plastic) the area ratio of each method as a Markdown table (the one
in docs/half_space.md).
Needs matplotlib (Debian: python3-matplotlib); runs headless.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Statuses of rows with an answer: `outside_validity` rows are plotted too (the picture is about
# where each method can be trusted; the table's status column says which rows are not).
ANSWERS = ("ok", "outside_validity")
STYLE = {"multi-hertzian": ("tab:blue", "o"), "strips": ("tab:orange", "s"), "half-space": ("tab:green", "^"),
         "auto": ("tab:purple", "x"), "CONTACT": ("black", "+")}


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def fnum(s):
    try:
        return float(s)
    except (TypeError, ValueError):
        return math.nan


def run_method(mhcontact, case_path, method, out_dir, elastic=False):
    with open(case_path) as f:
        case = json.load(f)
    name = method + ("-elastic" if elastic else "")
    if elastic:  # the same case without the cap (p_lim is refused with the elastic model)
        case["model"] = "elastic"
        if isinstance(case.get("material"), dict):
            case["material"].pop("p_lim_MPa", None)
    base = os.path.dirname(os.path.abspath(case_path))
    for side in ("wheel", "rail"):  # profile paths relative to the case file stay valid
        prof = case.get(side, {}).get("profile")
        if isinstance(prof, str) and not os.path.isabs(prof) and not prof.startswith("standard:"):
            candidate = os.path.join(base, prof)
            if os.path.exists(candidate):
                case[side]["profile"] = candidate
    case["method"] = method
    path = os.path.join(out_dir, name + ".json")
    with open(path, "w") as f:
        json.dump(case, f)
    res = subprocess.run([mhcontact, "run", path, "-o", os.path.join(out_dir, name), "--format", "csv", "-q"])
    if res.returncode not in (0, 1):
        sys.exit(f"compare_methods.py: mhcontact run failed for method {name} (exit {res.returncode})")
    return os.path.join(out_dir, name)


def method_rows(run_dir, Q):
    cases = [r for r in read_csv(os.path.join(run_dir, "cases.csv")) if abs(fnum(r["Q_kN"]) - Q) < 1e-9]
    # Load split: the main contact's share of the normal loads (ellipses or patches of each case).
    main = {}
    for name, force in (("ellipses.csv", "N_kN"), ("patches.csv", "N_kN")):
        p = os.path.join(run_dir, name)
        if not os.path.exists(p):
            continue
        for r in read_csv(p):
            main.setdefault(r["case"], []).append(fnum(r[force]))
    out = []
    for r in cases:
        loads = main.get(r["case"], [])
        share = max(loads) / sum(loads) if loads and sum(loads) > 0 else math.nan
        out.append((fnum(r["tY_mm"]), fnum(r["pmax_MPa"]), fnum(r["area_mm2"]), share, r["status"], r["method"]))
    return sorted(out)


def band_rows(run_dir, Q):
    """The smoothing's uncertainty band of each row with one (docs/profiles.md §7): (t_Y, pmax low,
    pmax high, area low, area high), each range the row's own value and its values at L/2 and 2L."""
    out = []
    for r in read_csv(os.path.join(run_dir, "cases.csv")):
        if abs(fnum(r["Q_kN"]) - Q) > 1e-9 or r["status"] not in ANSWERS or not r.get("pmax_half_L_MPa"):
            continue
        p = [fnum(r[k]) for k in ("pmax_MPa", "pmax_half_L_MPa", "pmax_double_L_MPa") if r.get(k)]
        ar = [fnum(r[k]) for k in ("area_mm2", "area_half_L_mm2", "area_double_L_mm2") if r.get(k)]
        out.append((fnum(r["tY_mm"]), min(p), max(p), min(ar), max(ar)))
    return sorted(out)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case", help="case file (JSON)")
    ap.add_argument("--methods", default="multi-hertzian,strips,half-space",
                    help="comma-separated methods (default: multi-hertzian,strips,half-space)")
    ap.add_argument("--Q", type=float, help="load in kN (default: the first load of the sweep)")
    ap.add_argument("--mhcontact", default=os.path.join("build", "mhcontact"), help="the mhcontact binary")
    ap.add_argument("--reference", help="CONTACT reference table (y_ws_mm, pmax_MPa, area_mm2)")
    ap.add_argument("-o", "--output", default="compare_methods.png", help="PNG file (default compare_methods.png)")
    ap.add_argument("--table", help="also write the plotted numbers to this CSV file")
    ap.add_argument("--markdown", help="also write area, peak pressure (and plastic/elastic area ratio) per t_Y "
                                       "and method as a Markdown table to this file")
    a = ap.parse_args(argv)
    methods = [m.strip() for m in a.methods.split(",") if m.strip()]
    for m in methods:
        if m not in STYLE or m == "CONTACT":
            ap.error(f"unknown method '{m}' (expected multi-hertzian, strips, half-space or auto)")
    if not os.path.exists(a.mhcontact):
        sys.exit(f"compare_methods.py: {a.mhcontact} not found (build first, or give --mhcontact)")
    try:
        with open(a.case) as f:
            case = json.load(f)
    except (OSError, ValueError) as e:
        sys.exit(f"compare_methods.py: cannot read the case file: {e}")
    model = case.get("model", "elastic")
    plim = case.get("material", {}).get("p_lim_MPa")
    plastic = model == "plastic"
    data, elastic, bands = {}, {}, {}
    with tempfile.TemporaryDirectory() as tmp:
        for m in methods:
            d = run_method(a.mhcontact, a.case, m, tmp)
            if a.Q is None:
                a.Q = fnum(read_csv(os.path.join(d, "cases.csv"))[0]["Q_kN"])
            data[m] = method_rows(d, a.Q)
            bands[m] = band_rows(d, a.Q)
            if plastic:
                elastic[m] = {r[0]: r for r in method_rows(run_method(a.mhcontact, a.case, m, tmp, elastic=True), a.Q)}
    if a.reference:
        ref = [r for r in read_csv(a.reference) if abs(fnum(r.get("Fz_target_N")) / 1000 - a.Q) < 1e-6]
        data["CONTACT"] = sorted((fnum(r["y_ws_mm"]), fnum(r["pmax_MPa"]), fnum(r["area_mm2"]), math.nan, "ok", "CONTACT")
                                 for r in ref)
    def elastic_of(name, r):  # (area, pmax) of the elastic run at the same t_Y, or NaNs
        e = elastic.get(name, {}).get(r[0])
        return (e[2], e[1]) if e and e[4] in ANSWERS else (math.nan, math.nan)

    title = os.path.basename(a.case) + f": model {model}" + (f", p_lim {plim:g} MPa" if plim else "")
    fig, axes = plt.subplots(4 if plastic else 3, 1, figsize=(9, 13 if plastic else 10), sharex=True)
    for name, rows in data.items():
        color, marker = STYLE[name]
        t = [r[0] for r in rows if r[4] in ANSWERS]
        for ax, k in zip(axes, (1, 2, 3)):
            v = [r[k] for r in rows if r[4] in ANSWERS]
            if all(math.isnan(x) for x in v):
                continue
            ax.plot(t, v, marker=marker, color=color, label=name, linewidth=1.2, markersize=4)
        # The smoothing's uncertainty band (measured profiles: the same cases at L/2 and 2L).
        b = bands.get(name, [])
        if b:
            tb = [r[0] for r in b]
            axes[0].fill_between(tb, [r[1] for r in b], [r[2] for r in b], color=color, alpha=0.18, linewidth=0,
                                 label=f"{name}: smoothing L/2 … 2L")
            axes[1].fill_between(tb, [r[3] for r in b], [r[4] for r in b], color=color, alpha=0.18, linewidth=0)
        if plastic and name in elastic:
            ratio = [r[2] / elastic_of(name, r)[0] for r in rows if r[4] in ANSWERS]
            axes[3].plot(t, ratio, marker=marker, color=color, label=name, linewidth=1.2, markersize=4)
    if plastic:
        axes[3].set_ylabel("area ratio plastic / elastic")
        axes[3].axhline(1.0, color="grey", linewidth=0.8)
    axes[0].set_ylabel("peak pressure [MPa]")
    axes[1].set_ylabel("contact area [mm²]")
    axes[2].set_ylabel("main contact's share of the load")
    axes[-1].set_xlabel("t_Y [mm]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    axes[0].legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=9)
    if plim:
        axes[0].axhline(plim, color="red", linestyle="--", linewidth=0.8, label="p_lim")
    fig.suptitle(f"{title}, Q = {a.Q:g} kN", fontsize=10)
    fig.tight_layout()
    fig.savefig(a.output, dpi=110)
    if a.table:
        with open(a.table, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["method", "tY_mm", "pmax_MPa", "area_mm2", "main_share", "status", "solved_by"] +
                       (["area_elastic_mm2", "pmax_elastic_MPa", "area_ratio"] if plastic else []))
            for name, rows in data.items():
                for r in rows:
                    extra = []
                    if plastic:
                        ae, pe = elastic_of(name, r)
                        extra = [ae, pe, r[2] / ae if ae > 0 else math.nan]
                    w.writerow([name] + list(r) + extra)
    if a.markdown:
        names = [m for m in methods]
        tys = sorted({r[0] for m in names for r in data[m]})
        by = {m: {r[0]: r for r in data[m]} for m in names}
        head = "| t_Y mm |"
        rule = "|---|"
        for m in names:
            head += f" {m} area mm² | pmax MPa |" + (" area ratio |" if plastic else "")
            rule += "---|---|" + ("---|" if plastic else "")
        lines = [head, rule]
        for t in tys:
            line = f"| {t:g} |"
            for m in names:
                r = by[m].get(t)
                if r is None or r[4] not in ANSWERS:
                    line += f" {r[4] if r else '-'} | |" + (" |" if plastic else "")
                    continue
                # A row outside its method's validity is an answer, not a trusted one: said so.
                line += f" {r[2]:.1f}{' (' + r[4] + ')' if r[4] != 'ok' else ''} | {r[1]:.0f} |"
                if plastic:
                    ae = elastic_of(m, r)[0]
                    line += f" {r[2] / ae:.2f} |" if ae > 0 else " - |"
            lines.append(line)
        with open(a.markdown, "w") as f:
            f.write("\n".join(lines) + "\n")
    print(f"compare_methods.py: wrote {a.output}" + (f" and {a.table}" if a.table else "") +
          (f" and {a.markdown}" if a.markdown else ""))


if __name__ == "__main__":
    main()
