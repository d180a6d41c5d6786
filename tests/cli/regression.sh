#!/usr/bin/env bash
# Regression of the shipped cases against the reviewed reference tables in tests/ref/, compared
# with `mhcontact diff` (as users do in their own CI). Tolerances: rtol 1e-7 and atol 1e-9 in each
# column's unit: far above last-bit noise of another compiler or libm, far below any change in
# the method (a 0.01 mm change of a semi-axis is 1e-3 relative), and far above the rounding of
# the tables to 10 significant digits (at most 5e-10 relative, also when a last-bit difference
# flips the rounding of the 10th digit).
set -euo pipefail
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for c in manchester manchester-plastic s1002-60e1 fleet; do
  "$bin" run "$src/cases/$c.json" -o "$tmp/$c" --format csv -q
  for t in cases ellipses geometry; do
    "$bin" diff "$src/tests/ref/$c/$t.csv" "$tmp/$c/$t.csv" --rtol 1e-7 --atol 1e-9 --quiet
  done
done
# The guard must be able to fail: a perturbed reference is caught.
sed '2s/,ok,multi-hertzian,\([0-9.e-]*\),/,ok,multi-hertzian,1\1,/' "$src/tests/ref/manchester/cases.csv" > "$tmp/perturbed.csv"
if "$bin" diff "$tmp/perturbed.csv" "$tmp/manchester/cases.csv" --rtol 1e-7 --atol 1e-9 --quiet; then
  echo "diff did not catch a perturbed reference" >&2; exit 1
fi
echo "regression: OK"
