#!/usr/bin/env bash
# The memory a shard's process touches for its rows in flight (docs/cluster.md#cost): every
# shard maps its working set afresh (page faults, system time), so it must not grow with the
# sweep. A shard of 24,003 multi-Hertzian cases with results.json (cases/fleet.json at a t_Y step
# of 0.002 mm, --shard 1/4, --threads 1) against one of 99 cases (step 0.5 mm): the peak resident
# set may grow by at most 12 MB (formatted rows of 2,048 cases in one chunk are about 4 MB; with
# 8,192 cases in two chunks it grew by 29 MB). Release build only: the sanitizers' allocator keeps
# freed memory.
set -euo pipefail
bin=$1; src=$(cd "$2" && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
peak_kb() {  # the peak resident set (kB) of `run $1 --shard 1/4 --threads 1`
  /usr/bin/python3 -c '
import resource, subprocess, sys
rc = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL).returncode
assert rc in (0, 1), rc
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)' "$bin" run "$1" -o "$tmp/out$2" -q --shard 1/4 --threads 1
}
for step in 0.5 0.002; do
  sed -e "s|\"step\": 0.5|\"step\": $step|" -e "s|\"\\.\\./profiles/|\"$src/profiles/|g" "$src/cases/fleet.json" > "$tmp/fleet$step.json"
done
small=$(peak_kb "$tmp/fleet0.5.json" 1)
large=$(peak_kb "$tmp/fleet0.002.json" 2)
test "$(($(wc -l < "$tmp/out2/cases.csv") - 1))" -eq 24003
echo "peak resident set: 99 cases $small kB, 24,003 cases $large kB (+$((large - small)) kB)"
test $((large - small)) -le 12288 || { echo "a shard's working set grows with its cases" >&2; exit 1; }
echo "shard_working_set: OK"
