#!/usr/bin/env bash
# scripts/compare_methods.py on three cases of the Manchester pair with the three methods and
# CONTACT's reference: a PNG and a table whose numbers are those of the runs.
set -euo pipefail
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
echo "compare_methods: OK"
