#!/usr/bin/env bash
# The Slurm route of docs/cluster.md against a real Slurm: a private single-node cluster
# (tests/cluster/slurm_cluster.sh) runs cases/fleet.json as a job array through
# scripts/slurm_array.sh; the merge equals the one-process run byte for byte. One array task is
# made to fail: `merge` names its shard, and re-submitting that shard alone completes the run,
# merged by a job that waits for it (afterok), as the docs show.
# Exit 77 (CTest: skipped) only when slurm-wlm and munge are not installed (scripts/deps.sh installs them).
set -euo pipefail
bin=$1; src=$2
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=tests/cluster/slurm_cluster.sh
source "$here/slurm_cluster.sh"
slurm_test_begin slurm.sh

fleet=$src/cases/fleet.json
mkdir -p "$tmp/logs"
# An mhcontact that fails once for array task 3 (as a node failure would), then runs normally.
touch "$tmp/fail3"
cat > "$tmp/flaky" <<FLAKY
#!/usr/bin/env bash
if [ "\${SLURM_ARRAY_TASK_ID:-}" = 3 ] && rm "$tmp/fail3" 2>/dev/null; then echo "injected failure" >&2; exit 3; fi
exec "$bin" "\$@"
FLAKY
chmod +x "$tmp/flaky"
export MHCONTACT=$tmp/flaky
cd "$tmp"
# The one-process run, named as the merged one will be (results.json names inputs relative to it).
"$bin" run "$fleet" -o out/single -q || [ $? -eq 1 ]

# --- docs/cluster.md, Slurm (the array, then what merge says of the failed task) ---
jid=$(sbatch --parsable --array=1-4 --time=00:05:00 --output="logs/%x_%A_%a.out" "$src/scripts/slurm_array.sh" "$fleet" out/fleet 4)
slurm_wait "$jid" | tee tasks.txt
[ "$(grep -c COMPLETED tasks.txt)" -eq 3 ] && grep "ArrayTaskId=3 " tasks.txt | grep -q "FAILED ExitCode=3:0"
grep -q "injected failure" logs/mhcontact_"$jid"_3.out
rc=0
"$bin" merge out/fleet.shards/shard* -o out/fleet -q 2> merge.err || rc=$?
cat merge.err
[ $rc -eq 2 ] && grep -q "shard 3/4 missing" merge.err && [ ! -e out/fleet ]
# --- docs/cluster.md, Slurm (re-submit the failed shard alone; the merge waits for it) ---
jid=$(sbatch --parsable --array=3 --time=00:05:00 --output="logs/%x_%A_%a.out" "$src/scripts/slurm_array.sh" "$fleet" out/fleet 4)
mid=$(sbatch --parsable --dependency="afterok:$jid" --time=00:05:00 --output=logs/merge.out \
  --wrap "$bin merge out/fleet.shards/shard* -o out/fleet -q")
slurm_wait "$mid" | tee merge.txt
grep -q "COMPLETED ExitCode=0:0" merge.txt
for f in cases.csv ellipses.csv geometry.csv pairs.csv results.json; do cmp "$tmp/out/single/$f" "out/fleet/$f"; done
for k in 0 1 2 3; do
  for f in caf.csv profiles.csv geometry.json; do cmp "$tmp/out/single/pairs/$k/$f" "out/fleet/pairs/$k/$f"; done
done
echo "slurm: OK (array of 4 with one failed task, re-submitted alone, merged: byte-identical to one run)"
