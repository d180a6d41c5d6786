#!/usr/bin/env bash
# The sharded route's own cost in CPU time (user + sys, /usr/bin/time; figures printed, never
# asserted), without a scheduler: cases/fleet.json (4 pairs, multi-Hertzian unless METHOD is set)
# with a t_Y step of STEP mm, run (1) in one process (--threads 1), (2) as 4 shards (--shard K/4,
# one process each, one after the other) and (3) merged, with the run options given (e.g.
# --format csv). CPU time, unlike wall time, is not stretched by other jobs on a shared machine.
# Prints the median of RUNS runs of each step and the overhead per case of (2) + (3) over (1);
# the merged cases.csv and results.json are compared with the one-process run's.
# OLD=path/to/mhcontact alternates each run with that binary and prints its figures too.
# Usage: scripts/bench_shards.sh [STEP (default 0.002)] [RUNS (default 3)] [run options]
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
step=${1:-0.002}; runs=${2:-3}
shift $(( $# > 2 ? 2 : $# ))
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
sed -e "s|\"step\": 0.5|\"step\": $step|" -e "s|\"model\": \"elastic\",|\"model\": \"elastic\", \"method\": \"${METHOD:-multi-hertzian}\",|" -e "s|\"\\.\\./profiles/|\"$src/profiles/|g" "$src/cases/fleet.json" > "$tmp/fleet.json"
cpu() {  # $1 = file to append the CPU seconds to, the rest: the command (exit 1, cases not ok, is fine)
  local f=$1; shift
  /usr/bin/time -f "%U %S" -o "$tmp/time" "$@" >/dev/null 2>&1 || true
  tail -n 1 "$tmp/time" | awk '{printf "%.3f\n", $1 + $2}' >> "$f"
}
once() {  # $1 = binary, $2 = label
  local bin=$1 l=$2 k
  rm -rf "$tmp/one" "$tmp/shards" "$tmp/merged"; mkdir -p "$tmp/shards"
  cpu "$tmp/$l.one" "$bin" run "$tmp/fleet.json" -o "$tmp/one" -q --threads 1 "${@:3}"
  : > "$tmp/$l.k"
  for k in 1 2 3 4; do cpu "$tmp/$l.k" "$bin" run "$tmp/fleet.json" -o "$tmp/shards/shard$k" -q --threads 1 --shard "$k/4" "${@:3}"; done
  awk '{s += $1} END {printf "%.3f\n", s}' "$tmp/$l.k" >> "$tmp/$l.shards"
  cpu "$tmp/$l.merge" "$bin" merge "$tmp"/shards/shard* -o "$tmp/merged" -q
  for f in cases.csv results.json; do
    if [ -e "$tmp/one/$f" ]; then cmp "$tmp/one/$f" "$tmp/merged/$f"; fi
  done
}
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
labels="new"; [ -n "${OLD:-}" ] && labels="new old"
for l in $labels; do : > "$tmp/$l.one"; : > "$tmp/$l.shards"; : > "$tmp/$l.merge"; done
for ((r = 0; r < runs; ++r)); do
  once "$src/build/mhcontact" new "$@"
  if [ -n "${OLD:-}" ]; then once "$OLD" old "$@"; fi
done
rm -rf "$tmp/probe"
"$src/build/mhcontact" run "$tmp/fleet.json" -o "$tmp/probe" -q --format csv >/dev/null 2>&1 || true
cases=$(( $(wc -l < "$tmp/probe/cases.csv") - 1 ))
for l in $labels; do
  one=$(median < "$tmp/$l.one"); sh=$(median < "$tmp/$l.shards"); mg=$(median < "$tmp/$l.merge")
  awk -v l="$l" -v n="$cases" -v o="$one" -v s="$sh" -v m="$mg" -v r="$runs" -v opt="$*" 'BEGIN {
    printf "%s binary, %d cases, options [%s], median of %d, CPU s: one process %.2f (%.1f us/case); 4 shards %.2f; merge %.2f (%.1f us/case); shards + merge over one process: %+.1f %%\n",
      l, n, opt, r, o, 1e6 * o / n, s, m, 1e6 * m / n, 100 * ((s + m) / o - 1) }'
done
