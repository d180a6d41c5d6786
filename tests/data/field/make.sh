#!/usr/bin/env bash
# Re-creates the field-like test profiles of this folder (issue #22) from the standard profiles
# that mhcontact generates, with awk/printf only. Usage: bash make.sh <mhcontact binary>
# Each file shows the features of a measured file seen in the field (README.md in this folder);
# the points are S1002 (wheels) and 60E1 (rails), so that the tests know the true surface.
set -euo pipefail
MH=$1
cd "$(dirname "$0")"
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
"$MH" profile generate S1002 --step 0.1 -o "$T/w.csv" >/dev/null
"$MH" profile generate 60E1 --step 0.1 -o "$T/r.csv" >/dev/null
"$MH" profile generate 60E1 --step 0.1 --inclination 1:40 -o "$T/r40.csv" >/dev/null

# 1. Old-style MiniProf wheel (#MINIWHEELPROF) measured from the flange back (X = y + 70,
#    Y = -z, 0.01 mm), with a 0.6 mm loop at the flange tip (the scan goes 0.6 mm back into the
#    flange and comes forward again: two points inserted before the tip) and ten points of the
#    rim face at the field-side end.
{
  printf '#MINIWHEELPROF\nfield wheel L1, loop at the flange tip\nMINIPROF 2004 12 3\nStock.......: 0815\nWheel ID....: L1\n'
  printf '32.50 28.00 10.80  (Sd/Sh/qR)\n\n'
  awk -F, 'NR>1 {
    printf "%.2f %.2f\n", $1 + 70, -$2
    if (!done && $1 >= -55.25) {                      # just before the tip (y = -55)
      printf "%.2f %.2f\n", $1 + 70 - 0.60, -$2 - 0.05
      printf "%.2f %.2f\n", $1 + 70 + 0.10, -$2 - 0.15
      done = 1
    }
    last = $1 + 70; lastz = -$2 }
    END { for (k = 1; k <= 10; k++) printf "%.2f %.2f\n", last, lastz - 0.5 * k }' "$T/w.csv"
} > old_wheel_loop.whl
