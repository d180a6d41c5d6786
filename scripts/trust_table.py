#!/usr/bin/env python3
"""Field trust table: how often does each method answer `ok` while it is wrong?

    trust_table.py [SPEC.json] [--mhcontact build/mhcontact] [--pairs NAME,...] [--methods M,...] [--only TY:Q,...]
                   [--markdown] [--cases] [--by-pair] [--keep DIR] [--jobs N] [--assert-targets]

SPEC (default tests/data/contact/field/trust.json) lists profile pairs with a t_Y x Q sweep and,
per pair, a reference table (paths relative to the spec file):

  {"tolerances": {"pmax": 0.10, "area": 0.15},
   "methods": ["multi-hertzian", "strips", "half-space", "auto"],
   "fine_half_space_mm": 0.1,
   "pairs": [
     {"name": "avg_wheel/avg_HR",
      "case": {... a case file without "method" and "sweep"; relative profile paths are taken
               relative to the spec file ...},
      "sweep": {"tY_mm": [...] or {"from", "to", "step"}, "Q_kN": [...]},
      "reference": "contact_avg_wheel_avg_HR.csv",      optional: a CONTACT table (run_sweep.py
                                                        columns y_ws_mm, Fz_target_N, pmax_MPa,
                                                        area_mm2; one row per patch)
      "only": [[tY, Q], ...]                             optional: run only these cases
     }]}

Every pair is run with every method (`mhcontact run`, the case's "method" replaced, csv output).
The reference of a case is CONTACT's (peak pressure: the largest of its patches; area: their sum)
where the pair has a table with that case, otherwise this project's half-space method on a fine
grid (dx = ds = fine_half_space_mm, 0.1 mm) when that row is `ok`; a case without a usable
reference is counted under "no reference" and not judged; "of them ok" counts those whose status
is `ok` (a row that claims to be usable where nothing can check it; JSON key noref_ok).

Per method it prints: the cases `ok`, the cases of every other status, and the SILENT cases: `ok`
rows whose peak pressure differs from the reference by more than the pmax tolerance (10 %) or
whose area by more than the area tolerance (15 %). "beyond tol" counts every answered row
(`ok` or `outside_validity`) beyond a tolerance: the issue's targets are zero silent cases for
`strips` and `auto`, and for `multi-hertzian` every case beyond tolerance non-`ok` (i.e. zero
silent cases there as well).

--cases lists every silent case; --by-pair prints the counts per pair; --markdown prints the table in Markdown; --assert-targets exits 1
when a target is missed (silent > 0 for strips, auto or multi-hertzian), 0 otherwise.
Python 3 standard library only.
"""
import argparse
import concurrent.futures as cf
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DEFAULT_SPEC = os.path.join(ROOT, "tests", "data", "contact", "field", "trust.json")
ALL_METHODS = ["multi-hertzian", "strips", "half-space", "auto"]
STATUS_ORDER = ["ok", "outside_validity", "not_converged", "no_contact", "out_of_range", "invalid_pair"]
TARGET_METHODS = ("multi-hertzian", "strips", "auto")


def fnum(s):
    try:
        return float(s)
    except (TypeError, ValueError):
        return math.nan


def frange(spec):
    if isinstance(spec, list):
        return [float(v) for v in spec]
    a, b, s = float(spec["from"]), float(spec["to"]), float(spec["step"])
    n = int(round((b - a) / s))
    return [round(a + i * s, 9) for i in range(n + 1)]


def key(tY, Q):
    return (round(float(tY), 6), round(float(Q), 6))


def cases_of(pair):
    if "only" in pair:
        return [key(t, q) for t, q in pair["only"]]
    ys = frange(pair["sweep"]["tY_mm"])
    qs = [float(q) for q in pair["sweep"]["Q_kN"]]
    return [key(t, q) for q in qs for t in ys]


def read_reference(path):
    """CONTACT table (one row per patch) -> {(tY, Q): (pmax_MPa, area_mm2)}."""
    out = {}
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            k = key(r["y_ws_mm"], fnum(r["Fz_target_N"]) / 1000.0)
            p, a = fnum(r["pmax_MPa"]), fnum(r["area_mm2"])
            if k in out:
                p0, a0 = out[k]
                out[k] = (max(p0, p), a0 + a)
            else:
                out[k] = (p, a)
    return out


def absolutise(case, base):
    """Profile paths relative to the spec file stay valid wherever the case file is written."""
    for side in ("wheel", "rail"):
        ent = case.get(side, {})
        prof = ent.get("profile") if isinstance(ent, dict) else None
        if isinstance(prof, str) and not os.path.isabs(prof) and not prof.startswith("standard:"):
            ent["profile"] = os.path.normpath(os.path.join(base, prof))
        elif isinstance(prof, dict) and isinstance(prof.get("file"), str) and not os.path.isabs(prof["file"]):
            prof["file"] = os.path.normpath(os.path.join(base, prof["file"]))
    return case


def run_case_file(mhcontact, case, cases, workdir, name):
    """Run `case` over the given (tY, Q) list; returns {(tY, Q): row of cases.csv}."""
    case = json.loads(json.dumps(case))
    tys = sorted({t for t, _ in cases})
    qs = sorted({q for _, q in cases})
    case["sweep"] = {"tY_mm": tys, "Q_kN": qs}
    path = os.path.join(workdir, name + ".json")
    with open(path, "w") as f:
        json.dump(case, f, indent=1)
    out = os.path.join(workdir, name)
    if os.path.exists(out):
        shutil.rmtree(out)
    res = subprocess.run([mhcontact, "run", path, "-o", out, "--format", "csv", "-q"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
    if res.returncode not in (0, 1):
        sys.exit("trust_table.py: mhcontact run failed for %s (exit %d): %s"
                 % (name, res.returncode, res.stderr.strip()[-500:]))
    rows = {}
    with open(os.path.join(out, "cases.csv"), newline="") as f:
        for r in csv.DictReader(f):
            k = key(r["tY_mm"], r["Q_kN"])
            if k in cases:
                rows[k] = r
    return rows


def classify(row, ref, tol_p, tol_a):
    """-> (status, beyond, dp, da); beyond is None without a reference or an answer."""
    st = row["status"]
    if ref is None or st not in ("ok", "outside_validity"):
        return st, None, math.nan, math.nan
    p, a = fnum(row["pmax_MPa"]), fnum(row["area_mm2"])
    dp = p / ref[0] - 1.0 if ref[0] > 0 else math.nan
    da = a / ref[1] - 1.0 if ref[1] > 0 else math.nan
    beyond = not (abs(dp) <= tol_p and abs(da) <= tol_a)   # a NaN counts as beyond
    return st, beyond, dp, da


def evaluate(spec, spec_dir, mhcontact, methods, pair_names, workdir, jobs):
    tol_p = float(spec.get("tolerances", {}).get("pmax", 0.10))
    tol_a = float(spec.get("tolerances", {}).get("area", 0.15))
    fine = float(spec.get("fine_half_space_mm", 0.1))
    jobs_list = []
    pairs = [p for p in spec["pairs"] if not pair_names or p["name"] in pair_names]
    if pair_names:
        missing = set(pair_names) - {p["name"] for p in pairs}
        if missing:
            sys.exit("trust_table.py: no pair named %s in the spec" % ", ".join(sorted(missing)))
    prepared = []
    for i, pair in enumerate(pairs):
        base = absolutise(dict(json.loads(json.dumps(pair["case"]))), spec_dir)
        cases = cases_of(pair)
        ref = {}
        if pair.get("reference"):
            rpath = os.path.join(spec_dir, pair["reference"])
            if not os.path.exists(rpath):
                sys.exit("trust_table.py: pair %s: reference table %s not found" % (pair["name"], rpath))
            ref = read_reference(rpath)
        need_fine = [k for k in cases if k not in ref]
        prepared.append((i, pair, base, cases, ref, need_fine))
        for m in methods:
            c = dict(base, method=m)
            jobs_list.append(((i, m), c, cases, "p%d_%s" % (i, m)))
        if need_fine:
            c = dict(base, method="half-space")
            c["half_space"] = dict(c.get("half_space", {}), dx_mm=fine, ds_mm=fine)
            jobs_list.append(((i, "fine"), c, need_fine, "p%d_fine" % i))
    results = {}

    with cf.ThreadPoolExecutor(max_workers=max(1, jobs)) as ex:
        futs = {ex.submit(run_case_file, mhcontact, c, cs, workdir, n): k for k, c, cs, n in jobs_list}
        for fu in cf.as_completed(futs):
            results[futs[fu]] = fu.result()

    def fresh():
        return {m: {"n": 0, "status": {}, "silent": 0, "beyond": 0, "noref": 0, "noref_ok": 0} for m in methods}
    stats = fresh()
    by_pair = {}
    silent_list = []
    refsrc = {"CONTACT": 0, "half-space fine": 0, "none": 0}
    for i, pair, base, cases, ref, need_fine in prepared:
        fine_rows = results.get((i, "fine"), {})
        refs = {}
        for k in cases:
            if k in ref:
                refs[k] = (ref[k], "CONTACT")
            else:
                r = fine_rows.get(k)
                if r is not None and r["status"] == "ok":
                    refs[k] = ((fnum(r["pmax_MPa"]), fnum(r["area_mm2"])), "half-space fine")
                else:
                    refs[k] = (None, "none")
            refsrc[refs[k][1]] += 1
        by_pair[pair["name"]] = fresh()
        for m in methods:
            rows = results[(i, m)]
            for k in cases:
                row = rows.get(k)
                if row is None:
                    st, beyond, dp, da = "missing", None, math.nan, math.nan
                else:
                    st, beyond, dp, da = classify(row, refs[k][0], tol_p, tol_a)
                for s in (stats[m], by_pair[pair["name"]][m]):
                    s["n"] += 1
                    s["status"][st] = s["status"].get(st, 0) + 1
                    if refs[k][0] is None:
                        s["noref"] += 1
                        if st == "ok":
                            s["noref_ok"] += 1
                    if beyond:
                        s["beyond"] += 1
                        if st == "ok":
                            s["silent"] += 1
                if beyond and st == "ok":
                    silent_list.append(dict(pair=pair["name"], method=m, tY=k[0], Q=k[1], dp=dp, da=da,
                                            pmax=fnum(row["pmax_MPa"]), ref_pmax=refs[k][0][0],
                                            area=fnum(row["area_mm2"]), ref_area=refs[k][0][1], ref=refs[k][1]))
    return dict(stats=stats, by_pair=by_pair, silent=silent_list, refsrc=refsrc, tol_p=tol_p, tol_a=tol_a,
                pairs=[p["name"] for p in pairs], n_cases=sum(len(p[3]) for p in prepared))


def status_columns(stats):
    seen = set()
    for s in stats.values():
        seen.update(s["status"])
    return [x for x in STATUS_ORDER if x in seen] + sorted(seen - set(STATUS_ORDER))


def print_table(ev, methods, markdown, out=sys.stdout):
    cols = status_columns(ev["stats"])
    head = ["method", "cases"] + cols + ["beyond tol", "SILENT", "no reference", "of them ok"]
    rows = []
    for m in methods:
        s = ev["stats"][m]
        rows.append([m, s["n"]] + [s["status"].get(c, 0) for c in cols] + [s["beyond"], s["silent"], s["noref"],
                                                                        s["noref_ok"]])
    if markdown:
        out.write("| " + " | ".join(head) + " |\n")
        out.write("|" + "---|" * len(head) + "\n")
        for r in rows:
            out.write("| " + " | ".join(str(x) for x in r) + " |\n")
    else:
        w = [max(len(str(x)) for x in col) for col in zip(head, *rows)]
        out.write("  ".join(str(h).ljust(w[j]) for j, h in enumerate(head)) + "\n")
        for r in rows:
            out.write("  ".join(str(x).ljust(w[j]) for j, x in enumerate(r)) + "\n")
    out.write("\n%d pairs (%s), %d cases; reference: CONTACT %d, half-space fine %d, none %d; "
              "SILENT: ok and |dpmax| > %g %% or |darea| > %g %%\n"
              % (len(ev["pairs"]), ", ".join(ev["pairs"]), ev["n_cases"], ev["refsrc"]["CONTACT"],
                 ev["refsrc"]["half-space fine"], ev["refsrc"]["none"], 100 * ev["tol_p"], 100 * ev["tol_a"]))


def print_by_pair(ev, methods, markdown, out=sys.stdout):
    """One line per pair and method: cases, ok, other statuses, beyond tolerance, silent."""
    head = ["pair", "method", "cases", "ok", "other statuses", "beyond tol", "SILENT"]
    rows = []
    for name in ev["pairs"]:
        for m in methods:
            s = ev["by_pair"][name][m]
            other = ", ".join("%s %d" % (k, v) for k, v in sorted(s["status"].items()) if k != "ok") or "-"
            rows.append([name, m, str(s["n"]), str(s["status"].get("ok", 0)), other, str(s["beyond"]),
                         str(s["silent"])])
    out.write("\nper pair:\n")
    if markdown:
        out.write("| " + " | ".join(head) + " |\n|" + "---|" * len(head) + "\n")
        for r in rows:
            out.write("| " + " | ".join(r) + " |\n")
    else:
        w = [max(len(x) for x in col) for col in zip(head, *rows)]
        for r in [head] + rows:
            out.write("  ".join(x.ljust(w[j]) for j, x in enumerate(r)) + "\n")


def print_cases(ev, markdown, out=sys.stdout):
    if not ev["silent"]:
        out.write("\nno silent case\n")
        return
    head = ["pair", "method", "tY_mm", "Q_kN", "pmax_MPa", "ref", "dpmax", "area_mm2", "ref", "darea", "reference"]
    rows = [[s["pair"], s["method"], "%g" % s["tY"], "%g" % s["Q"], "%.0f" % s["pmax"], "%.0f" % s["ref_pmax"],
             "%+.1f %%" % (100 * s["dp"]), "%.1f" % s["area"], "%.1f" % s["ref_area"], "%+.1f %%" % (100 * s["da"]),
             s["ref"]] for s in ev["silent"]]
    rows.sort(key=lambda r: (r[1], r[0], float(r[3]), float(r[2])))
    out.write("\nsilent cases:\n")
    if markdown:
        out.write("| " + " | ".join(head) + " |\n|" + "---|" * len(head) + "\n")
        for r in rows:
            out.write("| " + " | ".join(r) + " |\n")
    else:
        for r in [head] + rows:
            out.write("  ".join(r) + "\n")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("spec", nargs="?", default=DEFAULT_SPEC)
    ap.add_argument("--mhcontact", default=os.path.join(ROOT, "build", "mhcontact"))
    ap.add_argument("--pairs", default="", help="comma-separated pair names (default: all)")
    ap.add_argument("--methods", default=",".join(ALL_METHODS))
    ap.add_argument("--only", default="", help="run only these cases of each pair: TY:Q,... (mm:kN), e.g. 2:60,8:120")
    ap.add_argument("--markdown", action="store_true", help="print Markdown tables")
    ap.add_argument("--cases", action="store_true", help="list every silent case")
    ap.add_argument("--by-pair", action="store_true", help="also print the counts per pair")
    ap.add_argument("--keep", help="keep the runs in this directory (default: a temporary one, removed)")
    ap.add_argument("--jobs", type=int, default=2, help="mhcontact runs at once (default 2)")
    ap.add_argument("--json", help="also write the counts and silent cases to this JSON file")
    ap.add_argument("--assert-targets", action="store_true",
                    help="exit 1 unless strips, auto and multi-hertzian have zero silent cases")
    a = ap.parse_args(argv)
    methods = [m.strip() for m in a.methods.split(",") if m.strip()]
    for m in methods:
        if m not in ALL_METHODS:
            ap.error("unknown method '%s' (expected %s)" % (m, ", ".join(ALL_METHODS)))
    if not os.path.exists(a.mhcontact):
        sys.exit("trust_table.py: %s not found (build first, or give --mhcontact)" % a.mhcontact)
    mh = os.path.abspath(a.mhcontact)
    with open(a.spec) as f:
        spec = json.load(f)
    spec_dir = os.path.dirname(os.path.abspath(a.spec))
    names = [n.strip() for n in a.pairs.split(",") if n.strip()]
    if a.only:
        try:
            only = [[float(v) for v in c.split(":")] for c in a.only.split(",") if c.strip()]
            assert all(len(c) == 2 for c in only)
        except (ValueError, AssertionError):
            ap.error("--only wants TY:Q,... (e.g. 2:60,8:120)")
        for p in spec["pairs"]:
            p["only"] = only
    if a.keep:
        os.makedirs(a.keep, exist_ok=True)
        work = a.keep
    else:
        work = tempfile.mkdtemp(prefix="trust_table_")
    try:
        ev = evaluate(spec, spec_dir, mh, methods, names, work, a.jobs)
    finally:
        if not a.keep:
            shutil.rmtree(work, ignore_errors=True)
    print_table(ev, methods, a.markdown)
    if a.by_pair:
        print_by_pair(ev, methods, a.markdown)
    if a.cases:
        print_cases(ev, a.markdown)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(dict(stats=ev["stats"], by_pair=ev["by_pair"], silent=ev["silent"], refsrc=ev["refsrc"], pairs=ev["pairs"]), f,
                      indent=1)
    if a.assert_targets:
        bad = [m for m in methods if m in TARGET_METHODS and ev["stats"][m]["silent"] > 0]
        if bad:
            sys.stderr.write("trust_table.py: target missed: silent cases for %s\n"
                             % ", ".join("%s (%d)" % (m, ev["stats"][m]["silent"]) for m in bad))
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
