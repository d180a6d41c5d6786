#!/usr/bin/env bash
# The half-space method through run, shards and merge, with pressure grids and errors: the same
# tables and rules as the multi-Hertzian method, byte-identical for any thread count.
set -euo pipefail
. "$(dirname "$0")/lib/csv_col.sh"
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
sed -e "s|\"\\.\\./profiles/|\"$src/profiles/|g" -e 's|"tY_mm": {"from": -6, "to": 10, "step": 1}|"tY_mm": [-3, 5, 8]|' \
    "$src/cases/manchester-halfspace.json" > "$tmp/hs.json"
"$bin" run "$tmp/hs.json" -o "$tmp/a" --threads 1 -q --pressure-grid 2
"$bin" run "$tmp/hs.json" -o "$tmp/b" --threads 2 -q --pressure-grid 2
for f in cases.csv patches.csv pressure.csv; do cmp "$tmp/a/$f" "$tmp/b/$f"; done
head -1 "$tmp/a/cases.csv" | grep -q '^case,tY_mm,Q_kN,status,method,dz_virtual_mm,approach_mm,'
test "$(grep -c ',ok,half-space,' "$tmp/a/cases.csv")" -eq 3
test "$(wc -l < "$tmp/a/patches.csv")" -eq 4
test ! -e "$tmp/a/ellipses.csv"
test ! -e "$tmp/a/geometry.csv"
# The element pressures integrate to the patch forces (0.2 mm x 0.2 mm elements): within 1e-6.
python3 - "$tmp/a" <<'PY'
import csv, sys
d = sys.argv[1]
N = {}
for r in csv.DictReader(open(d + "/pressure.csv")):
    N[(r["case"], r["patch"])] = N.get((r["case"], r["patch"]), 0) + float(r["p_MPa"]) * 0.04 / 1000
for r in csv.DictReader(open(d + "/patches.csv")):
    s = N[(r["case"], r["patch"])]
    assert abs(s - float(r["N_kN"])) <= 1e-6 * float(r["N_kN"]), (r["case"], s, r["N_kN"])
PY
# Shards and merge give the unsharded tables.
"$bin" run "$tmp/hs.json" -o "$tmp/s1" --shard 1/2 -q
"$bin" run "$tmp/hs.json" -o "$tmp/s2" --shard 2/2 -q
"$bin" merge "$tmp/s1" "$tmp/s2" -o "$tmp/m" -q
for f in cases.csv patches.csv; do cmp "$tmp/a/$f" "$tmp/m/$f"; done
# Bad half-space options are input errors naming the JSON path.
sed 's|"half_space": {"dx_mm": 0.2, "ds_mm": 0.2}|"half_space": {"dx_mm": 5}|' "$tmp/hs.json" > "$tmp/bad.json"
set +e
"$bin" run "$tmp/bad.json" -o "$tmp/x" 2> "$tmp/err"; rc=$?
set -e
test $rc -eq 2; grep -q '/half_space' "$tmp/err"; grep -q 'dx_mm' "$tmp/err"
# "auto": each case in the table of the method that solved it (t_Y = 5 mm: interacting contacts,
# t_Y = 8 mm: a flange patch reaching the end of the wheel's R13 arc, gap_mean_error -> strips).
sed 's|"method": "half-space"|"method": "auto"|' "$tmp/hs.json" > "$tmp/auto.json"
"$bin" run "$tmp/auto.json" -o "$tmp/auto" -q --strips
grep -q '^1,5,50,ok,strips,' "$tmp/auto/cases.csv"
grep -q '^2,8,50,ok,strips,' "$tmp/auto/cases.csv"
grep -q '^0,-3,50,ok,multi-hertzian,' "$tmp/auto/cases.csv"
test "$(csv_col "$tmp/auto/patches.csv" case | sort -u | grep -c '^[0-9]')" -eq 2
test "$(csv_col "$tmp/auto/ellipses.csv" case | sort -u | grep -c '^[0-9]')" -eq 1
test "$(wc -l < "$tmp/auto/strips.csv")" -gt 10
# The same bytes for any thread count (auto mixes the multi-Hertzian and strip methods per case).
"$bin" run "$tmp/auto.json" -o "$tmp/auto1" -q --strips --threads 1
"$bin" run "$tmp/auto.json" -o "$tmp/auto2" -q --strips --threads 2
for f in cases.csv ellipses.csv geometry.csv patches.csv strips.csv results.json; do cmp "$tmp/auto1/$f" "$tmp/auto2/$f"; done
sed 's|"method": "half-space"|"method": "bogus"|' "$tmp/hs.json" > "$tmp/bogus.json"
set +e
"$bin" run "$tmp/bogus.json" -o "$tmp/x" 2> "$tmp/err"; rc=$?
set -e
test $rc -eq 2; grep -q '/method' "$tmp/err"
# --strips belongs to the strip method.
set +e
"$bin" run "$tmp/hs.json" -o "$tmp/x" --strips 2> "$tmp/err"; rc=$?
set -e
test $rc -eq 2; grep -q -- '--strips' "$tmp/err"
echo "half_space_run: OK"
