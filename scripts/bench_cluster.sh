#!/usr/bin/env bash
# The cost of the Slurm route against the local run, per case (docs/cluster.md#cost): a fleet
# (cases/fleet.json, 4 pairs, with a finer t_Y step) run (1) locally in one process on every
# core, (2) as a Slurm job array of 4 tasks (one pair each, 1 CPU each) on the private
# single-node cluster of tests/cluster/slurm_cluster.sh, from sbatch to the merged directory
# (the merge as a job with afterok), then (3) locally again. Needs root, slurm-wlm and munge.
#   bash scripts/bench_cluster.sh [tY step in mm, default 0.005] [run options, e.g. --format csv]
# METHOD=half-space (or strips, auto) sets the fleet's method (default: the manifest's, multi-Hertzian).
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
bin=$(realpath "${MHCONTACT:-$src/build/mhcontact}")
step=${1:-0.005}
shift $(( $# > 0 ? 1 : 0 ))  # the rest: run options for the local runs and every task
tmp=$(mktemp -d)
# shellcheck source=tests/cluster/slurm_cluster.sh
source "$src/tests/cluster/slurm_cluster.sh"
trap 'slurm_stop; rm -rf "$tmp"' EXIT
slurm_start "$tmp/slurm"
sed -e "s|\"step\": 0.5|\"step\": $step|" -e "s|\"model\": \"elastic\",|\"model\": \"elastic\", \"method\": \"${METHOD:-multi-hertzian}\",|" -e "s|\"\\.\\./profiles/|\"$src/profiles/|g" "$src/cases/fleet.json" > "$tmp/fleet.json"
cd "$tmp"
now() { date +%s.%N; }
cases=$("$bin" run fleet.json -o out/probe -q --shard 1/4 --format csv >/dev/null 2>&1; echo $(( ($(wc -l < out/probe/cases.csv) - 1) * 4 )))
rm -rf out/probe
local_run() {
  local t0; t0=$(now)
  "$bin" run fleet.json -o "out/$1" -q --threads "$(nproc)" "${@:2}" || [ $? -eq 1 ]
  echo "$(now) - $t0" | bc -l
}
t_local1=$(local_run local1 "$@")
t0=$(now)
jid=$(MHCONTACT=$bin sbatch --parsable --array=1-4 --time=00:30:00 --output=/dev/null "$src/scripts/slurm_array.sh" fleet.json out/slurm 4 "$@")
mid=$(sbatch --parsable --dependency="afterok:$jid" --output=/dev/null --wrap "date +%s.%N > merge_start; $bin merge out/slurm.shards/shard* -o out/slurm -q; rc=\$?; date +%s.%N > merge_end; exit \$rc")
slurm_wait "$jid" > /dev/null
t_array=$(echo "$(now) - $t0" | bc -l)
slurm_wait "$mid" > /dev/null
t_slurm=$(echo "$(now) - $t0" | bc -l)
echo "slurm: array done after $t_array s; merge job ran from $(echo "$(cat merge_start) - $t0" | bc -l) to $(echo "$(cat merge_end) - $t0" | bc -l) s; merged (seen) after $t_slurm s"
t_local2=$(local_run local2 "$@")
# the merge's own share: the same merge, run here
t0=$(now)
"$bin" merge out/slurm.shards/shard* -o out/merge_here -q || [ $? -eq 1 ]
echo "merge alone (outside Slurm): $(echo "$(now) - $t0" | bc -l) s"
cmp out/local1/cases.csv out/slurm/cases.csv
printf 'cases %d on %d cores; local %.2f s and %.2f s (%.1f and %.1f us/case); slurm %.2f s (%.1f us/case): %.1f %% over the mean local\n' \
  "$cases" "$(nproc)" "$t_local1" "$t_local2" "$(echo "$t_local1 / $cases * 1000000" | bc -l)" "$(echo "$t_local2 / $cases * 1000000" | bc -l)" \
  "$t_slurm" "$(echo "$t_slurm / $cases * 1000000" | bc -l)" "$(echo "($t_slurm / (($t_local1 + $t_local2) / 2) - 1) * 100" | bc -l)"
