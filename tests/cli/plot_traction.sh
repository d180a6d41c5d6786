#!/usr/bin/env bash
# The traction grid (docs/tangential.md, "The traction grid") and its plot (docs/plots.md): a
# run with friction and --pressure-grid writes px_MPa, py_MPa, slip beside the pressure, for the
# selected cases only, the same points as the pressure; plot_traction.py draws one case of a
# multi-Hertzian and of a half-space run; bad input fails with a message that says what to do.
# Break seen to fail: the sweep solving the grid's cases without keeping their tractions (the
# empty-cell check).
set -euo pipefail
bin=$1; src=$(cd "$2" && pwd)
py=/usr/bin/python3; [ -x "$py" ] || py=python3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
sed -e "s|\"\\.\\./profiles/|\"$src/profiles/|g" "$src/cases/manchester-rcf.json" > rcf.json
"$bin" run rcf.json -o out/t --pressure-grid 11 --pressure-cases 1,8 -q
test "$(head -1 out/t/pressure.csv)" = "case,ellipse,x_mm,y_mm,p_MPa,px_MPa,py_MPa,slip"
test "$(cut -d, -f1 out/t/pressure.csv | tail -n +2 | sort -u | tr '\n' ' ')" = "1 8 "
"$py" - <<'PY'
import csv, math
rows = list(csv.DictReader(open("out/t/pressure.csv")))
inside = [r for r in rows if float(r["p_MPa"]) > 0]
assert inside and all(r["px_MPa"] != "" and r["slip"] in ("0", "1") for r in rows)
# Coulomb: never above mu times FASTSIM's bound (within its 0.3 % normalisation), on it in slip.
for r in inside:
    pt, p = math.hypot(float(r["px_MPa"]), float(r["py_MPa"])), float(r["p_MPa"])
    assert pt <= 0.3 * p * 1.003 + 1e-9, r
    if r["slip"] == "1": assert abs(pt - 0.3 * p) <= 0.003 * 0.3 * p, r
assert any(r["slip"] == "0" for r in inside) and any(r["slip"] == "1" for r in inside)
PY
# Without friction: the pressure table of before.
sed -e "s|\"\\.\\./profiles/|\"$src/profiles/|g" "$src/cases/manchester.json" > plain.json
"$bin" run plain.json -o out/plain --pressure-grid 3 --pressure-cases 0 -q
test "$(head -1 out/plain/pressure.csv)" = "case,ellipse,x_mm,y_mm,p_MPa"

if "$py" -c "import matplotlib, numpy" 2>/dev/null; then
  MPLBACKEND=Agg "$py" "$src/scripts/plot_traction.py" out/t --case 1 -o t1.png
  head -c 8 t1.png | od -An -c | grep -q 'P   N   G'
  # A half-space run of the same pair, one case.
  "$py" - rcf.json <<'PY' > hs.json
import json, sys
j = json.load(open(sys.argv[1])); j["method"] = "half-space"; j["sweep"]["tY_mm"] = [1]; j.pop("rcf", None)
json.dump(j, sys.stdout)
PY
  "$bin" run hs.json -o out/hs --pressure-grid 2 -q
  head -1 out/hs/pressure.csv | grep -q '^case,patch,x_mm,s_mm,y_rail_mm,p_MPa,px_MPa,py_MPa,slip$'
  MPLBACKEND=Agg "$py" "$src/scripts/plot_traction.py" out/hs --case 0 --arrows 10 -o hs0.png
  head -c 8 hs0.png | od -An -c | grep -q 'P   N   G'
  fails() {  # fails EXPECTED_TEXT ARGS...
    local want=$1; shift
    if MPLBACKEND=Agg "$py" "$src/scripts/plot_traction.py" "$@" 2>err; then echo "should fail: $*"; exit 1; fi
    grep -q "$want" err || { echo "expected '$want', got:"; cat err; exit 1; }
  }
  fails "has no traction columns" out/plain --case 0 -o x.png
  fails "has no traction rows" out/t --case 2 -o x.png
  mkdir -p out/empty
  fails "has no pressure.csv" out/empty --case 0 -o x.png
  fails "is not a directory" out/nowhere --case 0 -o x.png
  fails "at least 2 arrows" out/t --case 1 --arrows 1 -o x.png
  test ! -e x.png
fi
echo "plot_traction: OK"
