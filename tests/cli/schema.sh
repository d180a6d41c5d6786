#!/usr/bin/env bash
# A schema a script can trust: the resolved inputs in results.json are a valid case file whose
# paths resolve from the output directory (rerunning them reproduces the tables byte for byte);
# batch summaries count failures as single runs do; every column of every table is documented
# in docs/outputs.md; curvature sums use the unit name of `hertz` (A_per_mm); ellipses.csv carries what
# depends on the load and joins geometry.csv (once per t_Y and ellipse) on (tY_mm, ellipse), as
# results.json's "geometry" records join its case records.
set -uo pipefail
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1"); src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=1; }
extract() {  # results.json -> its inputs as a case file beside it
  python3 -c 'import json,sys; json.dump(json.load(open(sys.argv[1]))["inputs"], open(sys.argv[2], "w"), indent=2)' "$1" "$2"
}
for c in manchester manchester-plastic s1002-60e1; do
  "$bin" run "$src/cases/$c.json" -o "$tmp/$c" -q || fail "$c"
  grep -q '"schema": "mhcontact.results/10"' "$tmp/$c/results.json" || fail "$c: schema version"
  extract "$tmp/$c/results.json" "$tmp/$c/inputs.json"
  (cd "$tmp" && "$bin" run "$c/inputs.json" -o "re_$c" -q) || fail "$c: the inputs of results.json do not run"
  for t in cases.csv ellipses.csv geometry.csv; do cmp -s "$tmp/$c/$t" "$tmp/re_$c/$t" || fail "$c: rerunning the inputs gives another $t"; done
done
# -o -: absolute paths, valid as well.
"$bin" run "$src/cases/manchester.json" -o - -q > "$tmp/stdout.json"
extract "$tmp/stdout.json" "$tmp/elsewhere.json"
mkdir -p "$tmp/sub" && mv "$tmp/elsewhere.json" "$tmp/sub/"
"$bin" run "$tmp/sub/elsewhere.json" -o "$tmp/re_stdout" --format csv -q || fail "inputs of -o - do not run"
cmp -s "$tmp/manchester/cases.csv" "$tmp/re_stdout/cases.csv" || fail "inputs of -o -: other cases.csv"
# Units: the tables name the curvature sums as hertz does.
head -1 "$tmp/manchester/geometry.csv" | grep -q ",A_per_mm,B_per_mm," || fail "geometry.csv: A_per_mm, B_per_mm"
# The split of the tables: geometry columns in geometry.csv only; every loaded ellipse has
# its (tY_mm, ellipse) row there, each key once; the JSON records mirror both tables.
for c in manchester manchester-plastic s1002-60e1; do
python3 - "$tmp/$c" <<'PY' || fail "$c: ellipses.csv / geometry.csv / results.json do not match"
import csv, json, sys
d = sys.argv[1]
geo_cols = ["y_rail_mm", "y_wheel_mm", "gamma_deg", "R_rxx_mm", "R_wxx_mm", "R_wyy_mm", "A_per_mm", "B_per_mm",
            "lambda", "m", "n", "gap_mm", "z_rail_mm", "z_wheel_mm"]
ell = list(csv.DictReader(open(f"{d}/ellipses.csv")))
geo = list(csv.DictReader(open(f"{d}/geometry.csv")))
assert list(geo[0].keys()) == ["tY_mm", "ellipse"] + geo_cols, list(geo[0].keys())
assert not set(geo_cols) & set(ell[0].keys()), "ellipses.csv still has geometry columns"
keys = [(g["tY_mm"], g["ellipse"]) for g in geo]
assert len(keys) == len(set(keys)), "geometry.csv: a (tY_mm, ellipse) twice"
assert all((e["tY_mm"], e["ellipse"]) in set(keys) for e in ell), "a loaded ellipse without its geometry row"
j = json.load(open(f"{d}/results.json"))
assert len(j["geometry"]) == len(geo), (len(j["geometry"]), len(geo))
assert all(set(r.keys()) == {"tY_mm", "ellipse", *geo_cols} for r in j["geometry"])
for c in j["cases"]:
    for e in c["ellipses"]:
        assert not set(geo_cols) & set(e.keys()), "a case's ellipse record still has geometry keys"
# The t_Y of every case inside the geometry table, each with every potential ellipse.
ne = len(j["potential_ellipses"])
tys = []
for c in j["cases"]:
    if c["status"] != "out_of_range" and c["tY_mm"] not in tys:
        tys.append(c["tY_mm"])
assert len(geo) == ne * len(tys), (len(geo), ne, len(tys))
PY
done
# Batch: invalid pairs' cases are failures, as in a single run.
cat > "$tmp/bad.json" <<JSON
{"pairs": [{"name": "good", "wheel": "$src/profiles/MBench_S1002_v3.prw", "rail": "$src/profiles/MBench_UIC60_v3.prr"},
           {"name": "missing", "wheel": "$tmp/no_such.prw", "rail": "$src/profiles/MBench_UIC60_v3.prr"}],
 "inclination": "as-is", "sweep": {"tY_mm": [0, 1], "Q_kN": [50]}}
JSON
"$bin" run "$tmp/bad.json" -o "$tmp/batch" -q; rc=$?
[ $rc = 1 ] || fail "batch with an invalid pair: exit $rc"
python3 - "$tmp/batch/results.json" <<'PY' || fail "batch summary does not count the invalid pair's cases as failed"
import json, sys
s = json.load(open(sys.argv[1]))["summary"]
assert s["failed"] == 2 and s["invalid_pairs"] == 1, s
PY
grep -q "^1,missing,$tmp/no_such.prw," "$tmp/batch/pairs.csv" || fail "pairs.csv: the source of an invalid pair is not a plain path: $(sed -n 3p "$tmp/batch/pairs.csv")"
# Every column of every table is documented in docs/outputs.md (as `name`), the page of the tables.
"$bin" run "$src/cases/manchester-plastic.json" -o "$tmp/p" --pressure-grid 3 -q
"$bin" geometry "$src/cases/manchester.json" -o "$tmp/g" -q
"$bin" run "$src/cases/manchester-strips.json" -o "$tmp/st" --strips -q || fail "strip run"
for f in "$tmp/p/cases.csv" "$tmp/p/ellipses.csv" "$tmp/p/geometry.csv" "$tmp/p/pressure.csv" "$tmp/g/caf.csv" "$tmp/g/profiles.csv" "$tmp/batch/pairs.csv" "$tmp/batch/geometry.csv" "$tmp/st/patches.csv" "$tmp/st/strips.csv"; do
  for col in $(head -1 "$f" | tr ',' ' '); do
    grep -q "\`$col\`\|[,\`]$col[,\`]" "$src/docs/outputs.md" || fail "docs/outputs.md does not document column $col of $(basename "$f")"
  done
done
# patches.csv of the strip method says per patch which extents it kept (the estimate, or refined
# until the end gap closes) and the estimate's end-gap error; the half-space method leaves both empty.
python3 - "$tmp/st/patches.csv" <<'PY' || fail "patches.csv: extents / end_gap_error"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert rows and all(r["extents"] in ("estimate", "end_gap") for r in rows), {r["extents"] for r in rows}
assert all(float(r["end_gap_error"]) >= 0 for r in rows)
assert all((r["extents"] == "end_gap") == (float(r["end_gap_error"]) > 0.05) for r in rows)
assert any(r["extents"] == "end_gap" for r in rows) and any(r["extents"] == "estimate" for r in rows)
PY
# elements_across: no ok row has a patch with fewer strips across than the strip method's minimum
# (4, lib/contact/grid/grid_checks.hpp); element_mm is the strip width, 0.2 mm or less where refined.
python3 - "$tmp/st/patches.csv" "$tmp/st/cases.csv" <<'PY' || fail "patches.csv: elements_across / element_mm"
import csv, sys
status = {r["case"]: r["status"] for r in csv.DictReader(open(sys.argv[2]))}
rows = list(csv.DictReader(open(sys.argv[1])))
assert all(int(r["elements_across"]) >= 4 for r in rows if status[r["case"]] == "ok")
assert all(0 < float(r["element_mm"]) <= 0.2 for r in rows)
PY
# results.json's case records carry the grid methods' patches as patches.csv has them (the same
# keys in the same order, the same numbers; empty cells null), and with the case-file key "rcf"
# the RCF columns of both per-contact tables; FI_surf_el = f - 2 pi a_el b_el k / (3 N) = f - k/p0_el from
# the record's own p0_el_over_k (Ekberg, Kabo & Andersson 2002; docs/outputs.md "RCF columns").
for m in strips half-space multi-hertzian; do
python3 - "$src" "$tmp/rcf_$m.json" "$m" <<'PY'
import json, sys
src, out, m = sys.argv[1:]
c = json.load(open(f"{src}/cases/manchester-strips.json"))
for side in ("wheel", "rail"):
    c[side]["profile"] = f"{src}/profiles/" + c[side]["profile"].split("/")[-1]
c["method"] = m
c["material"]["yield_MPa"] = 400
c["rcf"] = {"traction_coefficient": 0.3}
c["sweep"] = {"tY_mm": [0, 7], "Q_kN": [100]}
json.dump(c, open(out, "w"))
PY
"$bin" run "$tmp/rcf_$m.json" -o "$tmp/rcf_$m" -q || fail "rcf run, $m"
python3 - "$tmp/rcf_$m" "$m" <<'PY' || fail "results.json: the $m records do not mirror the per-contact tables"
import csv, json, math, sys
d, m = sys.argv[1:]
j = json.load(open(f"{d}/results.json"))
table, key = ("ellipses.csv", "ellipses") if m == "multi-hertzian" else ("patches.csv", "patches")
rows = list(csv.DictReader(open(f"{d}/{table}")))
recs = [(c["case"], r) for c in j["cases"] for r in c[key]]
assert rows and len(rows) == len(recs), (len(rows), len(recs))
other = "patches" if key == "ellipses" else "ellipses"
assert all(c[other] == [] for c in j["cases"]), f"{other} records in a {m} run"
for row, (case, rec) in zip(rows, recs):
    assert int(row["case"]) == case
    cols = [k for k in row if k not in ("case", "tY_mm", "Q_kN")]
    assert cols == list(rec.keys()), (cols, list(rec.keys()))
    for k in cols:
        v, t = rec[k], row[k]
        if t == "":
            assert v is None, (k, v)
        elif isinstance(v, bool):
            assert t == ("1" if v else "0"), (k, t, v)
        elif isinstance(v, str):
            assert t == v, (k, t, v)
        else:
            assert math.isclose(float(t), v, rel_tol=1e-9, abs_tol=0), (k, t, v)
    f, k_MPa, p0k = rec["traction_coefficient"], rec["k_MPa"], rec["p0_el_over_k"]
    assert f == 0.3 and math.isclose(k_MPa, 400 / math.sqrt(3), rel_tol=1e-9), (f, k_MPa)
    assert p0k is not None, rec
    assert math.isclose(rec["FI_surf_el"], f - 1 / p0k, rel_tol=0, abs_tol=1e-9), (rec["FI_surf_el"], f - 1 / p0k)
    # An ellipse: p0_el = 3N/(2 pi a_el b_el), its elastic Hertz semi-axes (a grid patch's p0_el
    # is held against the closed form in rcf_columns.sh)
    if m == "multi-hertzian":
        area = math.pi * rec.get("a_el_mm", rec["a_mm"]) * rec.get("b_el_mm", rec["b_mm"])
        assert math.isclose(p0k, 1.5 * rec["N_kN"] * 1e3 / area / k_MPa, rel_tol=1e-8), (p0k,)
PY
done
exit $fails
