#!/usr/bin/env bash
# Benchmarks: prints figures (medians), never asserts. Usage: scripts/bench.sh [CASES_tY] [CASES_Q]
# Default sweep 2000 t_Y x 500 Q = 1,000,000 cases on the Manchester pair, to CSV.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh >/dev/null
ny=${1:-2000}; nq=${2:-500}
./build/mhcontact_bench . 7
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
step=$(awk -v n="$ny" 'BEGIN{printf "%.10g", 16/(n-1)}')
qstep=$(awk -v n="$nq" 'BEGIN{printf "%.10g", 140/(n-1)}')
sed -e "s|\"sweep\": .*|\"sweep\": {\"tY_mm\": {\"from\": -6, \"to\": 10, \"step\": $step}, \"Q_kN\": {\"from\": 10, \"to\": 150, \"step\": $qstep}}|" \
    -e "s|\"\\.\\./profiles/|\"$PWD/profiles/|g" cases/manchester.json > "$tmp/big.json"
ncases=$((ny * nq))
run() {  # $1 = threads; prints the median wall seconds and the median peak RSS [KB] of 3 runs
  : > "$tmp/times"
  for r in 1 2 3; do
    /usr/bin/time -f "%e %M" -o "$tmp/time" ./build/mhcontact run "$tmp/big.json" -o "$tmp/out" --format csv --threads "$1" -q || true
    cat "$tmp/time" >> "$tmp/times"
  done
  echo "$(cut -d' ' -f1 "$tmp/times" | sort -g | sed -n 2p) $(cut -d' ' -f2 "$tmp/times" | sort -g | sed -n 2p)"
}
read -r t1 m1 < <(run 1)
read -r tn mn < <(run 0)
echo "end-to-end run, $ncases cases to CSV, median of 3:"
awk -v t="$t1" -v m="$m1" -v n="$ncases" 'BEGIN{printf "  --threads 1:      %.2f s wall, %.0f cases/s, peak RSS %.0f MB\n", t, n/t, m/1024}'
awk -v t="$tn" -v m="$mn" -v n="$ncases" -v c="$(nproc)" 'BEGIN{printf "  all %d cores:     %.2f s wall, %.0f cases/s, peak RSS %.0f MB\n", c, t, n/t, m/1024}'
awk -v a="$t1" -v b="$tn" 'BEGIN{printf "  speed-up:         %.2f\n", a/b}'
ls -la "$tmp/out" | awk 'NR>1{print "  " $5 " bytes  " $9}'
# The grid methods (half-space, strips) on the CONTACT benchmark sweep (median and worst per case).
./build/mhcontact_bench_grid . 3
