#!/usr/bin/env bash
# README example: geometry of the Manchester pair, then the CAF and profile plots, headless.
set -euo pipefail
bin=$1; src=$2
py=/usr/bin/python3; [ -x "$py" ] || py=python3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$bin" geometry "$src/cases/manchester.json" -o "$tmp/geo" -q
MPLBACKEND=Agg "$py" "$src/scripts/plot_geometry.py" "$tmp/geo" --tY 5
for f in geometry_caf.png geometry_profiles.png; do
  test -s "$tmp/geo/$f"
  head -c 8 "$tmp/geo/$f" | od -An -c | grep -q 'P   N   G' || { echo "$f is not a PNG" >&2; exit 1; }
done
# A directory without geometry output is a clear error.
if "$py" "$src/scripts/plot_geometry.py" "$tmp/nothing" 2>"$tmp/err"; then exit 1; fi
grep -q "caf.csv" "$tmp/err"
echo "plot_geometry: OK"
