#!/usr/bin/env bash
# scripts/run_sharded.sh and scripts/slurm_array.sh, run locally: shards as separate processes
# (the Slurm script with SLURM_ARRAY_TASK_ID set by hand), merged, equal to one run.
set -euo pipefail
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
export MHCONTACT=$bin
"$bin" run "$src/cases/s1002-60e1.json" -o "$tmp/full" -q
bash "$src/scripts/run_sharded.sh" "$src/cases/s1002-60e1.json" "$tmp/local" 4 2
for f in cases.csv ellipses.csv geometry.csv results.json; do cmp "$tmp/full/$f" "$tmp/local/$f"; done
for k in 1 2 3; do SLURM_ARRAY_TASK_ID=$k bash "$src/scripts/slurm_array.sh" "$src/cases/s1002-60e1.json" "$tmp/slurm" 3; done
"$bin" merge "$tmp"/slurm.shards/shard* -o "$tmp/slurm" -q
for f in cases.csv ellipses.csv geometry.csv results.json; do cmp "$tmp/full/$f" "$tmp/slurm/$f"; done
echo "sharded_scripts: OK"
# The README's GNU parallel form, when GNU parallel is installed (it is not a dependency).
if command -v parallel >/dev/null && parallel --version 2>/dev/null | grep -q "GNU parallel"; then
  parallel "$bin" run "$src/cases/s1002-60e1.json" -o "$tmp/par.shards/shard{}" --shard {}/3 -q ::: 1 2 3
  "$bin" merge "$tmp"/par.shards/shard* -o "$tmp/par" -q
  for f in cases.csv ellipses.csv geometry.csv results.json; do cmp "$tmp/full/$f" "$tmp/par/$f"; done
  echo "GNU parallel form: OK"
else
  echo "GNU parallel not installed: its form was not run"
fi
