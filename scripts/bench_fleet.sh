#!/usr/bin/env bash
# The fleet benchmark (figures printed, never asserted): a fleet of N measured wheel files through
# `mhcontact wheelset --threads 2`, the five measured wheels shipped in tests/data listed N/5 times
# each on EN 15302 rail A (placement, sweep and amplitudes of cases/en15302-fleet.json: y = -8 ... 8
# mm every 0.02 mm, tan γe at 3 mm and 2, 4, 6 mm), reading, checks, measures and fleet.csv
# included. Per run: CPU time (user + sys, /usr/bin/time) per wheel, what 10,000 such wheels take
# on 2 free cores, and the wall time of the 2-thread run (stretched by other jobs on a shared
# machine). Prints the median of RUNS runs.
# OLD=path/to/mhcontact alternates each run with that binary (the same machine state for both) and
# prints its figures and the ratio too.
# Usage: scripts/bench_fleet.sh [N (default 1000)] [RUNS (default 5)]
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-1000}; runs=${2:-5}
new=./build/mhcontact
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
wheels="tests/data/profiles/avg_wheel.whl tests/data/profiles/worn_high_mileage.prw tests/data/profiles/MBench_S1002_v3.prw tests/data/field/kv_wheel_measures.whl tests/data/field/old_wheel_loop.whl"
{
  printf '{"wheels": ['
  sep=""
  for ((i = 0; i < n / 5; ++i)); do
    for w in $wheels; do printf '%s"%s"' "$sep" "$PWD/$w"; sep=", "; done
  done
  printf '],\n "rail": {"profile": "%s", "inclination": "as-is", "placement": "absolute", "origin_mm": 750},\n' "$PWD/profiles/EN15302_rail_A.dat"
  printf ' "y_mm": {"from": -8, "to": 8, "step": 0.02}, "amplitudes_mm": [2, 4, 6]}\n'
} > "$tmp/fleet.json"
nw=$(( (n / 5) * 5 ))
once() {  # $1 = binary, $2 = file to append "cpu wall" to
  rm -rf "$tmp/out"
  /usr/bin/time -f "%U %S %e" -o "$tmp/time" "$1" wheelset "$tmp/fleet.json" -o "$tmp/out" --threads 2 -q >/dev/null 2>&1 || true
  tail -n 1 "$tmp/time" | awk '{printf "%.3f %.2f\n", $1 + $2, $3}' >> "$2"  # the last line: time prints a line of its own for exit 1
}
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
: > "$tmp/t_new"; : > "$tmp/t_old"
for ((r = 0; r < runs; ++r)); do
  once "$new" "$tmp/t_new"
  if [ -n "${OLD:-}" ]; then once "$OLD" "$tmp/t_old"; fi
done
report() {  # $1 = label, $2 = times file
  local cpu wall
  cpu=$(cut -d' ' -f1 "$2" | median); wall=$(cut -d' ' -f2 "$2" | median)
  awk -v l="$1" -v c="$cpu" -v w="$wall" -v n="$nw" -v r="$runs" 'BEGIN{printf "fleet of %d measured wheel files, %s, --threads 2, median of %d: %.2f ms CPU per wheel, so %.0f s for 10,000 wheels on 2 free cores; %.1f s wall for %d\n", n, l, r, 1e3 * c / n, c / n * 1e4 / 2, w, n}'
  echo "  all runs [ms CPU per wheel]: $(cut -d' ' -f1 "$2" | sort -g | awk -v n="$nw" '{printf "%.2f ", 1e3 * $1 / n}')"
}
report "this build" "$tmp/t_new"
if [ -n "${OLD:-}" ]; then
  report "OLD=$OLD" "$tmp/t_old"
  paste -d' ' "$tmp/t_new" "$tmp/t_old" | awk '{printf "%.3f\n", $1 / $3}' > "$tmp/ratio"
  echo "  CPU ratio this/OLD per alternated pair: $(sort -g "$tmp/ratio" | tr '\n' ' ')"
fi
