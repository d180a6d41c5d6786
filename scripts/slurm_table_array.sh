#!/usr/bin/env bash
# The shards of one pass of making a contact table (docs/tables.md "Shards") as a Slurm job array:
# array task K solves the K-th of N slices of the pass's points.
#   sbatch --wait --array=1-N scripts/slurm_table_array.sh CASE.json PARTS_DIR PASS N [NEXT.json]
# PASS 0: the first round's points (no NEXT.json); PASS >= 1: the points a merge wrote with
# `--next NEXT.json`. Task K writes PARTS_DIR/pass<PASS>-<K>.json. The passes are driven by merges
# (docs/cluster.md "Slurm: contact tables"): a merge with --next exits 5 while the making needs
# more points and writes the table once the parts hold them all.
#SBATCH --job-name=mhcontact-table
#SBATCH --cpus-per-task=1
#SBATCH --time=01:00:00
set -euo pipefail
bin=${MHCONTACT:-mhcontact}
case_file=$1; parts=$2; pass=$3; n=$4; next=${5:-}
k=${SLURM_ARRAY_TASK_ID:?run this with sbatch --array=1-N}
points=()
if [ "$pass" -gt 0 ]; then
  [ -n "$next" ] || { echo "slurm_table_array.sh: pass $pass needs the points file of the merge (NEXT.json)" >&2; exit 2; }
  points=(--points "$next")
fi
mkdir -p "$parts"
exec "$bin" table "$case_file" --shard "$k/$n" "${points[@]}" --threads "${SLURM_CPUS_PER_TASK:-1}" -q \
  -o "$parts/pass$pass-$k.json"
