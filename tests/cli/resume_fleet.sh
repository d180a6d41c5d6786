#!/usr/bin/env bash
# `run MANIFEST --resume` after a kill: a fleet of 8 pairs is killed (SIGKILL, no clean-up) once
# some pairs are complete; the same command then skips those pairs (their directories in
# OUT.parts are not rewritten: same inode of shard.json) and the merged tables equal one
# uninterrupted run byte for byte. Also: --resume refuses what it cannot honour.
set -euo pipefail
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
p=$src/profiles
cat > "$tmp/fleet.json" <<JSON
{
  "pairs": [
    {"name": "a", "wheel": "$p/MBench_S1002_v3.prw", "rail": "$p/MBench_UIC60_v3.prr"},
    {"name": "b", "wheel": "$p/S1002.csv", "rail": "$p/MBench_UIC60_v3.prr"},
    {"name": "c", "wheel": "$p/MBench_S1002_v3.prw", "rail": "$p/60E1_1-40.csv"},
    {"name": "d", "wheel": "$p/S1002.csv", "rail": "$p/60E1_1-40.csv"},
    {"name": "e", "wheel": "$p/MBench_S1002_v3.prw", "rail": "$p/MBench_UIC60_v3.prr"},
    {"name": "f", "wheel": "$p/S1002.csv", "rail": "$p/MBench_UIC60_v3.prr"},
    {"name": "g", "wheel": "$p/MBench_S1002_v3.prw", "rail": "$p/60E1_1-40.csv"},
    {"name": "h", "wheel": "$p/S1002.csv", "rail": "$p/60E1_1-40.csv"}
  ],
  "inclination": "as-is",
  "nominal_radius_mm": 460,
  "sweep": {"tY_mm": {"from": -6, "to": 10, "step": 0.02}, "Q_kN": [10, 50, 100]}
}
JSON
cd "$tmp"
"$bin" run fleet.json -o out/single -q --threads 1 || [ $? -eq 1 ]
"$bin" run fleet.json -o out/fleet --resume -q --threads 1 &
pid=$!
for _ in $(seq 600); do
  n=$( (ls out/fleet.parts/pair*/shard.json 2>/dev/null || true) | wc -l)
  [ "$n" -ge 2 ] && break
  sleep 0.05
done
kill -9 "$pid"; wait "$pid" 2>/dev/null || true
stat -c '%n %i' out/fleet.parts/pair*/shard.json > before.txt
done_pairs=$(wc -l < before.txt)
echo "killed with $done_pairs of 8 pairs complete"
[ "$done_pairs" -ge 2 ] && [ ! -e out/fleet ]
"$bin" run fleet.json -o out/fleet --resume --threads 1 2> resume.err || [ $? -eq 1 ]
cat resume.err
if [ "$done_pairs" -lt 8 ]; then
  grep -q "resuming: $done_pairs of 8 pairs already complete in out/fleet.parts, $((8 - done_pairs)) to run" resume.err
fi
stat -c '%n %i' out/fleet.parts/pair*/shard.json > after.txt
# the complete pairs were not recomputed: their directories are the ones of the killed run
while read -r line; do grep -qxF "$line" after.txt; done < before.txt
for f in cases.csv ellipses.csv geometry.csv pairs.csv results.json pairs/0/geometry.json pairs/7/caf.csv; do
  cmp out/single/$f out/fleet/$f
done
# A second --resume recomputes nothing and writes the same tables.
"$bin" run fleet.json -o out/fleet --resume 2> again.err || [ $? -eq 1 ]
grep -q "resuming: 8 of 8 pairs already complete" again.err
cmp out/single/cases.csv out/fleet/cases.csv
# What --resume refuses (exit 2, naming the option).
rc=0; "$bin" run "$src/cases/manchester.json" -o out/m --resume 2> e1 || rc=$?
[ $rc -eq 2 ] && grep -q -- "--resume.*is for batch manifests" e1
rc=0; "$bin" run fleet.json -o out/x --resume --shard 1/2 2> e2 || rc=$?
[ $rc -eq 2 ] && grep -q -- "--resume: value --shard 1/2" e2
echo "resume_fleet: OK"
