#!/usr/bin/env bash
# README example: plastic Manchester run with a pressure grid, then the elastic-versus-plastic
# pressure plot of one case, headless.
set -euo pipefail
bin=$1; src=$2
py=/usr/bin/python3; [ -x "$py" ] || py=python3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$bin" run "$src/cases/manchester-plastic.json" -o "$tmp/mp" --pressure-grid 21 -q
test -s "$tmp/mp/pressure.csv"
test -s "$tmp/mp/profiles.csv"
MPLBACKEND=Agg "$py" "$src/scripts/plot_pressure.py" "$tmp/mp" --case 23 -o "$tmp/p23.png"
head -c 8 "$tmp/p23.png" | od -An -c | grep -q 'P   N   G'
# A case without contact rows is a clear error, not an empty plot.
if "$py" "$src/scripts/plot_pressure.py" "$tmp/mp" --case 9999 2>"$tmp/err"; then exit 1; fi
grep -q "no loaded ellipse" "$tmp/err"
echo "plot_pressure: OK"
