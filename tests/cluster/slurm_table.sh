#!/usr/bin/env bash
# The Slurm route of a contact table (docs/cluster.md "Slurm: contact tables"): on a private
# single-node cluster (tests/cluster/slurm_cluster.sh), every pass of making the table of
# tests/data/tables/worn-table-q.json (refined in Q, so several passes) is a job array through
# scripts/slurm_table_array.sh, driven by merges with --next until the table is written; the table
# equals the one-process table byte for byte. A pass's array with a missing task is refused by
# the merge, naming the shard.
# Exit 77 (CTest: skipped) only when slurm-wlm and munge are not installed (scripts/deps.sh installs them).
set -euo pipefail
bin=$1; src=$2
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=tests/cluster/slurm_cluster.sh
source "$here/slurm_cluster.sh"
slurm_test_begin slurm_table.sh

cd "$tmp"
mkdir -p logs out
sed "s|\.\./profiles|$src/tests/data/profiles|g" "$src/tests/data/tables/worn-table-q.json" > q.json
export MHCONTACT=$bin
# The one-process table.
"$bin" table q.json -o out/single.csv -q --threads 1

# --- docs/cluster.md, "Slurm: contact tables": pass 0, then merge and solve the next pass until
# the merge writes the table (exit 0 or 1; 5: more points needed) ---
sbatch --parsable --wait --array=1-3 --time=00:05:00 --output="logs/%x_%A_%a.out" \
  "$src/scripts/slurm_table_array.sh" q.json out/parts 0 3 > jid0.txt
# A merge without one of the pass's shards is refused, naming it.
mkdir -p out/short && cp out/parts/pass0-1.json out/parts/pass0-2.json out/short/
rc=0; "$bin" table q.json --merge out/short/*.json --next out/next.json -o out/x.csv -q 2> short.err || rc=$?
cat short.err
[ $rc -eq 2 ] && grep -q "shard 3/3 is missing" short.err && [ ! -e out/x.csv ]
pass=0
until rc=0; "$bin" table q.json --merge out/parts/*.json --next out/next.json -o out/table.csv -q || rc=$?; [ $rc -ne 5 ]; do
  pass=$((pass + 1))
  [ $pass -le 8 ] || { echo "slurm_table.sh: more than 8 passes" >&2; exit 1; }
  sbatch --parsable --wait --array=1-2 --time=00:05:00 --output="logs/%x_%A_%a.out" \
    "$src/scripts/slurm_table_array.sh" q.json out/parts "$pass" 2 out/next.json > "jid$pass.txt"
done
[ $rc -eq 0 ] || { echo "slurm_table.sh: the last merge exited $rc" >&2; exit 1; }
[ $pass -ge 1 ] || { echo "slurm_table.sh: no refinement pass (the table should refine in Q)" >&2; exit 1; }
cmp out/single.csv out/table.csv
echo "slurm_table: OK ($((pass + 1)) passes as job arrays, merged: byte-identical to one process)"
