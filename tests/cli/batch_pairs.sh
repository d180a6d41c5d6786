#!/usr/bin/env bash
# Fleets pair by pair: a batch writes pairs/<k>/profiles.csv, caf.csv and
# geometry.json (potential ellipses) per pair, the same as `mhcontact geometry` of that pair;
# `geometry MANIFEST` writes the same; both plot scripts take --pair and refuse a batch directory
# without it with a clear message; a rerun over a batch directory is accepted.
set -euo pipefail
. "$(dirname "$0")/lib/csv_col.sh"
bin=$1; src=$2
py=/usr/bin/python3; [ -x "$py" ] || py=python3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$bin" run "$src/cases/fleet.json" -o "$tmp/fleet" --format csv -q
n=$(tail -n +2 "$tmp/fleet/pairs.csv" | wc -l)
for k in $(seq 0 $((n - 1))); do
  for f in profiles.csv caf.csv geometry.json; do test -s "$tmp/fleet/pairs/$k/$f"; done
done
# Pair 0 is the Manchester pair: its files equal those of the single run and of `geometry`.
"$bin" run "$src/cases/manchester.json" -o "$tmp/m" --format csv -q
cmp "$tmp/m/profiles.csv" "$tmp/fleet/pairs/0/profiles.csv"
"$bin" geometry "$src/cases/manchester.json" -o "$tmp/g" -q
cmp "$tmp/g/caf.csv" "$tmp/fleet/pairs/0/caf.csv"
"$py" -c "import json,sys; a=json.load(open(sys.argv[1])); b=json.load(open(sys.argv[2])); assert a['potential_ellipses']==b['potential_ellipses'] and len(a['potential_ellipses'])>0" "$tmp/g/geometry.json" "$tmp/fleet/pairs/0/geometry.json"
grep -q '"pairs/0/caf.csv"' "$tmp/fleet/run.json"
# geometry MANIFEST: the same files per pair.
"$bin" geometry "$src/cases/fleet.json" -o "$tmp/fg" -q
for k in $(seq 0 $((n - 1))); do cmp "$tmp/fleet/pairs/$k/caf.csv" "$tmp/fg/pairs/$k/caf.csv"; done
test "$(tail -n +2 "$tmp/fg/pairs.csv" | wc -l)" -eq "$n"
# Rerun over a batch directory (it holds pairs/): accepted.
"$bin" run "$src/cases/fleet.json" -o "$tmp/fleet" --format csv -q
# Plots: --pair for batch directories; without it a clear error naming --pair.
case=$(csv_col "$tmp/fleet/ellipses.csv" pair case | awk -F, '$1 == 0 {print $2; exit}')
MPLBACKEND=Agg "$py" "$src/scripts/plot_pressure.py" "$tmp/fleet" --pair 0 --case "$case" -o "$tmp/p.png"
head -c 8 "$tmp/p.png" | od -An -c | grep -q 'P   N   G'
if MPLBACKEND=Agg "$py" "$src/scripts/plot_pressure.py" "$tmp/fleet" --case "$case" 2>"$tmp/err"; then exit 1; fi
grep -q -- "--pair" "$tmp/err"
MPLBACKEND=Agg "$py" "$src/scripts/plot_geometry.py" "$tmp/fg" --pair 1 -o "$tmp/g1"
for f in "$tmp/g1_caf.png" "$tmp/g1_profiles.png"; do head -c 8 "$f" | od -An -c | grep -q 'P   N   G'; done
if MPLBACKEND=Agg "$py" "$src/scripts/plot_geometry.py" "$tmp/fleet" 2>"$tmp/err"; then exit 1; fi
grep -q -- "--pair" "$tmp/err"
echo "batch_pairs: OK"
