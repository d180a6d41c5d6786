#!/usr/bin/env bash
# Run one case file as N shards in separate processes on this machine (P at a time), then merge:
#   scripts/run_sharded.sh CASE.json OUT_DIR N [P] [extra run options...]
# With GNU parallel installed the same is
#   parallel mhcontact run CASE.json -o OUT.shards/shard{} --shard {}/N -q ::: $(seq 1 N)
#   mhcontact merge OUT.shards/shard* -o OUT
# Exit code: merge's (0 every case ok, 1 some not, 2 a shard failed on input).
set -euo pipefail
bin=${MHCONTACT:-$(dirname "$0")/../build/mhcontact}
case_file=$1; out=$2; n=$3; p=${4:-$(nproc)}
shift $(( $# >= 4 ? 4 : 3 ))
mkdir -p "$out.shards"  # shards beside OUT: an output directory holds the files of one run only
pids=()
status=0
for k in $(seq 1 "$n"); do
  "$bin" run "$case_file" -o "$out.shards/shard$k" --shard "$k/$n" --threads 1 -q "$@" &
  pids+=($!)
  if (( ${#pids[@]} >= p )); then
    wait "${pids[0]}" || { rc=$?; [ $rc -eq 1 ] || status=$rc; }
    pids=("${pids[@]:1}")
  fi
done
for pid in "${pids[@]}"; do wait "$pid" || { rc=$?; [ $rc -eq 1 ] || status=$rc; }; done
if [ $status -ne 0 ]; then echo "run_sharded.sh: a shard failed with exit $status" >&2; exit $status; fi
dirs=()
for k in $(seq 1 "$n"); do dirs+=("$out.shards/shard$k"); done
"$bin" merge "${dirs[@]}" -o "$out"
