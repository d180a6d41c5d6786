#!/usr/bin/env bash
# A large study as a Slurm job array: one shard per array task, then one merge job.
#   sbatch --array=1-64 scripts/slurm_array.sh CASE.json OUT_DIR 64 [extra run options...]
#   sbatch --dependency=afterok:<array job id> --wrap "mhcontact merge OUT_DIR.shards/shard* -o OUT_DIR"
# (afterok also waits for tasks that ended with exit 1, "some cases not ok", only if you let
# them succeed: this script maps exit 1 to 0 and keeps the statuses in the tables.)
#SBATCH --job-name=mhcontact
#SBATCH --cpus-per-task=1
#SBATCH --time=01:00:00
set -euo pipefail
bin=${MHCONTACT:-mhcontact}
case_file=$1; out=$2; n=$3
shift 3  # the rest: options of `mhcontact run` (e.g. --format csv), the same for every task
k=${SLURM_ARRAY_TASK_ID:?run this with sbatch --array=1-N}
rc=0
"$bin" run "$case_file" -o "$out.shards/shard$k" --shard "$k/$n" --threads "${SLURM_CPUS_PER_TASK:-1}" -q "$@" || rc=$?
[ $rc -eq 1 ] && rc=0
exit $rc
