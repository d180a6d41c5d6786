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
  grep -q '"schema": "mhcontact.results/6"' "$tmp/$c/results.json" || fail "$c: schema version"
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
exit $fails
