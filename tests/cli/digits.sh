#!/usr/bin/env bash
# Numbers a person can read: 10 significant digits by default, --digits N to choose, --digits
# max for the shortest round-trip; straight profiles give radii of inf, not huge finite numbers.
set -uo pipefail
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=1; }
# The most significant digits of any number in the given CSV files.
maxdig() {
  python3 - "$@" <<'PY'
import re, sys
m = 0
for p in sys.argv[1:]:
    for line in open(p).read().splitlines()[1:]:
        for cell in line.split(","):
            if re.fullmatch(r"-?[0-9.]+(e[-+][0-9]+)?", cell):
                mant = cell.lstrip("-").split("e")[0].replace(".", "").lstrip("0")
                m = max(m, len(mant))
print(m)
PY
}
"$bin" run "$src/cases/manchester-plastic.json" -o "$tmp/d10" --pressure-grid 5 -q || fail "default run"
"$bin" run "$src/cases/manchester-plastic.json" -o "$tmp/d4" --pressure-grid 5 --digits 4 -q || fail "--digits 4"
"$bin" run "$src/cases/manchester-plastic.json" -o "$tmp/dmax" --pressure-grid 5 --digits max -q || fail "--digits max"
n=$(maxdig "$tmp/d10/cases.csv" "$tmp/d10/ellipses.csv" "$tmp/d10/geometry.csv" "$tmp/d10/pressure.csv"); [ "$n" -le 10 ] || fail "default: $n digits"
[ "$n" -ge 9 ] || fail "default: only $n digits"
n=$(maxdig "$tmp/d4/cases.csv" "$tmp/d4/ellipses.csv" "$tmp/d4/geometry.csv" "$tmp/d4/pressure.csv"); [ "$n" -le 4 ] || fail "--digits 4: $n digits"
n=$(maxdig "$tmp/dmax/cases.csv" "$tmp/dmax/ellipses.csv"); [ "$n" -ge 15 ] || fail "--digits max: only $n digits"
grep -q '"digits": 10' "$tmp/d10/run.json" || fail "run.json does not record the digits"
# The rounded tables agree with the exact ones to 10 digits.
"$bin" diff "$tmp/dmax/cases.csv" "$tmp/d10/cases.csv" --rtol 1e-9 --atol 1e-12 --quiet || fail "10 digits differ from max by more than rounding"
"$bin" diff "$tmp/dmax/ellipses.csv" "$tmp/d10/ellipses.csv" --rtol 1e-9 --atol 1e-12 --quiet || fail "ellipses: 10 digits differ from max"
# The JSON records are rounded the same way.
python3 - "$tmp/d10/results.json" <<'PY' || fail "results.json has numbers with more than 10 digits"
import json, sys
def walk(v):
    if isinstance(v, float):
        mant = repr(abs(v)).split("e")[0].replace(".", "").lstrip("0").rstrip("0")
        assert len(mant) <= 10, v
    elif isinstance(v, dict):
        for x in v.values(): walk(x)
    elif isinstance(v, list):
        for x in v: walk(x)
walk(json.load(open(sys.argv[1]))["cases"])
PY
for bad in 0 18 abc 3x; do
  "$bin" run "$src/cases/manchester.json" -o "$tmp/bad" --digits "$bad" -q 2>"$tmp/err"; rc=$?
  [ $rc = 2 ] || fail "--digits $bad: exit $rc"
  grep -q "mhcontact: error: --digits: value $bad: must be an integer from 1 to 17, or max" "$tmp/err" || fail "--digits $bad: $(cat "$tmp/err")"
  [ ! -e "$tmp/bad" ] || fail "--digits $bad left a directory"
done
# Straight profile parts (60E1's flat head ends): inf, never a finite radius beyond 1e9 mm.
"$bin" run "$src/cases/s1002-60e1.json" -o "$tmp/s" --format csv -q
"$bin" geometry "$src/cases/s1002-60e1.json" -o "$tmp/g" -q
python3 - "$tmp/s/geometry.csv" "$tmp/g/caf.csv" <<'PY' || fail "radii of straight profiles"
import csv, math, sys
infs = 0
for p in sys.argv[1:]:
    for row in csv.DictReader(open(p)):
        for k in ("R_rxx_mm", "R_wxx_mm"):
            v = float(row[k])
            if math.isinf(v): infs += 1
            else: assert abs(v) < 1e9, (p, k, v)
assert infs > 0
PY
exit $fails
