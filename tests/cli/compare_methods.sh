#!/usr/bin/env bash
# scripts/compare_methods.py on three cases of the Manchester pair with the three methods and
# CONTACT's reference: a PNG and a table whose numbers are those of the runs.
set -euo pipefail
. "$(dirname "$0")/lib/csv_col.sh"
bin=$1; src=$2
py=/usr/bin/python3; [ -x "$py" ] || py=python3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
sed -e "s|\"\\.\\./profiles/|\"$src/profiles/|g" -e 's|"tY_mm": {"from": -6, "to": 10, "step": 1}|"tY_mm": [-3, 5]|' \
    "$src/cases/manchester-halfspace.json" > "$tmp/c.json"
MPLBACKEND=Agg "$py" "$src/scripts/compare_methods.py" "$tmp/c.json" --mhcontact "$bin" \
  --reference "$src/tests/data/contact/contact_mbench_right_q50_dx0.2.csv" -o "$tmp/c.png" --table "$tmp/c.csv"
head -c 8 "$tmp/c.png" | od -An -c | grep -q 'P   N   G'
# 2 cases x 3 methods + 17 CONTACT rows, plus the header.
test "$(wc -l < "$tmp/c.csv")" -eq 24
grep -q '^half-space,5.0,' "$tmp/c.csv"
grep -q '^strips,-3.0,' "$tmp/c.csv"
# An unknown method is refused.
if "$py" "$src/scripts/compare_methods.py" "$tmp/c.json" --mhcontact "$bin" --methods bogus 2>/dev/null; then exit 1; fi
# A plastic case: each method also run elastic; the area ratio in the table and the Markdown table.
sed -e "s|\"\\.\\./profiles/|\"$src/profiles/|g" -e 's|"tY_mm": {"from": -6, "to": 10, "step": 0.5}|"tY_mm": [0, 8]|' \
    "$src/cases/manchester-plastic.json" > "$tmp/p.json"
MPLBACKEND=Agg "$py" "$src/scripts/compare_methods.py" "$tmp/p.json" --mhcontact "$bin" \
  --methods multi-hertzian,half-space -o "$tmp/p.png" --table "$tmp/p.csv" --markdown "$tmp/p.md"
head -c 8 "$tmp/p.png" | od -An -c | grep -q 'P   N   G'
tr -d '\r' < "$tmp/p.csv" > "$tmp/p.lf.csv"  # the csv module ends rows with CR LF
head -1 "$tmp/p.lf.csv" | grep -q ',area_elastic_mm2,pmax_elastic_MPa,area_ratio$'
test "$(wc -l < "$tmp/p.lf.csv")" -eq 5
# At t_Y = 8 mm (flange, elastic peak ~5 GPa) both methods are ok and the patch grows > 3 times.
csv_col "$tmp/p.lf.csv" tY_mm status area_ratio > "$tmp/p.col"
awk -F, '$1 == "8.0" { if ($2 != "ok" || $3 < 3) exit 1; n++ } END { exit n == 2 ? 0 : 1 }' "$tmp/p.col"
grep -q '^| t_Y mm | multi-hertzian area mm² | pmax MPa | area ratio | half-space area mm² |' "$tmp/p.md"
test "$(wc -l < "$tmp/p.md")" -eq 4
# A case file that cannot be read is a clear error.
if "$py" "$src/scripts/compare_methods.py" "$tmp/missing.json" --mhcontact "$bin" 2>"$tmp/err"; then exit 1; fi
grep -q "cannot read the case file" "$tmp/err"
echo "compare_methods: OK"
