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
# A manifest's pairs cut across tasks (--shard-by cases after N): 3 tasks of 132 of its 396 cases.
"$bin" run "$src/cases/fleet.json" -o "$tmp/fleetfull" -q
for k in 1 2 3; do SLURM_ARRAY_TASK_ID=$k bash "$src/scripts/slurm_array.sh" "$src/cases/fleet.json" "$tmp/fleet" 3 --shard-by cases; done
grep -q '"unit": "pair_case"' "$tmp/fleet.shards/shard2/shard.json"
"$bin" merge "$tmp"/fleet.shards/shard* -o "$tmp/fleet" -q
for f in cases.csv ellipses.csv geometry.csv pairs.csv results.json; do cmp "$tmp/fleetfull/$f" "$tmp/fleet/$f"; done
# The same in 4 tapered tasks (--shard-sizes tapered after N: 158, 119, 79 and 40 cases).
for k in 1 2 3 4; do SLURM_ARRAY_TASK_ID=$k bash "$src/scripts/slurm_array.sh" "$src/cases/fleet.json" "$tmp/fleett" 4 --shard-by cases --shard-sizes tapered; done
test "$(($(wc -l < "$tmp/fleett.shards/shard4/cases.csv") - 1))" -eq 40
"$bin" merge "$tmp"/fleett.shards/shard* -o "$tmp/fleett" -q
for f in cases.csv ellipses.csv geometry.csv pairs.csv results.json; do cmp "$tmp/fleetfull/$f" "$tmp/fleett/$f"; done
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
