#!/usr/bin/env bash
# run --shard K/N --shard-by cases on a batch manifest: the shards slice the list of every pair's
# cases, so one pair's cases are spread over shards, and merge joins them back byte for byte into
# the one-process run's tables, results.json and pairs/<k>/ (a pair split in 3, an invalid pair
# split in 2, more shards than cases). A missing shard is named by merge; the shard re-run alone
# completes the run. A continuation record without its pair's start is refused. Tapered slices
# (--shard-sizes tapered) merge to the same bytes; shards cut both ways are refused.
set -euo pipefail
bin=$1; src=$(cd "$2" && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
same_run() {  # $1 = the one-process run, $2 = the merged one: every file but run.json
  (cd "$1" && find . -type f ! -name run.json | sort) > "$tmp/files1"
  (cd "$2" && find . -type f ! -name run.json | sort) > "$tmp/files2"
  cmp "$tmp/files1" "$tmp/files2"
  while read -r f; do cmp "$1/$f" "$2/$f"; done < "$tmp/files1"
}
# cases/fleet.json: 4 pairs of 99 cases, 396 in all; 10 shards of 39-40 cases: pair 0's cases
# are [0, 39) in shard 1, [39, 79) in shard 2, [79, 99) in shard 3.
sed -e "s|\"\\.\\./profiles/|\"$src/profiles/|g" "$src/cases/fleet.json" > "$tmp/fleet.json"
"$bin" run "$tmp/fleet.json" -o "$tmp/full" -q || test $? -eq 1
for k in $(seq 1 10); do "$bin" run "$tmp/fleet.json" -o "$tmp/s$k" --shard $k/10 --shard-by cases -q || test $? -eq 1; done
grep -q '"unit": "pair_case"' "$tmp/s2/shard.json"
# pair 0 in shards 1, 2 and 3: its pairs.csv row and pairs/0/ only in shard 1
test "$(grep -c '^0,' "$tmp/s1/cases.csv")" -eq 39
test "$(grep -c '^0,' "$tmp/s2/cases.csv")" -eq 40
test "$(grep -c '^0,' "$tmp/s3/cases.csv")" -eq 20
test "$(wc -l < "$tmp/s2/pairs.csv")" -eq 1 && test ! -e "$tmp/s2/pairs/0"
"$bin" merge "$tmp"/s{1,2,3,4,5,6,7,8,9,10} -o "$tmp/merged" -q || test $? -eq 1
same_run "$tmp/full" "$tmp/merged"
# A lost shard: merge names it; the shard run again alone completes the run.
rm -rf "$tmp/s5"
set +e; "$bin" merge "$tmp"/s{1,2,3,4,6,7,8,9,10} -o "$tmp/m2" 2>"$tmp/err"; rc=$?; set -e
test $rc -eq 2 && grep -q "shard 5/10 missing" "$tmp/err" || { cat "$tmp/err"; exit 1; }
"$bin" run "$tmp/fleet.json" -o "$tmp/s5" --shard 5/10 --shard-by cases -q || test $? -eq 1
"$bin" merge "$tmp"/s{1,2,3,4,5,6,7,8,9,10} -o "$tmp/m2" -q || test $? -eq 1
same_run "$tmp/full" "$tmp/m2"
# A continuation record (only "pair" and "cases") of a pair the shard before does not end with
# (shard 3's continuation of pair 0 renumbered): refused, naming the file.
cp -r "$tmp/s3" "$tmp/s3x"
sed -i '0,/"pair": 0,/s//"pair": 2,/' "$tmp/s3x/results.json"
set +e; "$bin" merge "$tmp"/s1 "$tmp"/s2 "$tmp"/s3x "$tmp"/s{4,5,6,7,8,9,10} -o "$tmp/m3" 2>"$tmp/err"; rc=$?; set -e
test $rc -eq 2 && grep -q "s3x/results.json: .*continues pair 2, which the shard before does not end with" "$tmp/err" || { cat "$tmp/err"; exit 1; }
test ! -e "$tmp/m3/cases.csv"

# Tapered slices: 10 shards of 72, 64, 58, 50, 44, 36, 28, 22, 14 and 8 cases (test_shard_slice.cpp).
for k in $(seq 1 10); do "$bin" run "$tmp/fleet.json" -o "$tmp/p$k" --shard $k/10 --shard-by cases --shard-sizes tapered -q || test $? -eq 1; done
test "$(($(wc -l < "$tmp/p1/cases.csv") - 1))" -eq 72 && test "$(($(wc -l < "$tmp/p10/cases.csv") - 1))" -eq 8
grep -q '"sizes": "tapered"' "$tmp/p10/shard.json"
"$bin" merge "$tmp"/p{1,2,3,4,5,6,7,8,9,10} -o "$tmp/pmerged" -q || test $? -eq 1
same_run "$tmp/full" "$tmp/pmerged"
# a missing tapered shard: the command that remakes it says --shard-sizes tapered
set +e; "$bin" merge "$tmp"/p{1,2,3,4,5,6,7,8,9} -o "$tmp/pm2" 2>"$tmp/err"; rc=$?; set -e
test $rc -eq 2 && grep -q -- "--shard K/10 --shard-sizes tapered" "$tmp/err" || { cat "$tmp/err"; exit 1; }
# an equal shard among tapered ones: refused by name
set +e; "$bin" merge "$tmp"/p{1,2,3,4,5,6,7,8,9} "$tmp/s10" -o "$tmp/pm3" 2>"$tmp/err"; rc=$?; set -e
test $rc -eq 2 && grep -q "s10/shard.json: value sizes equal: shards cut with different --shard-sizes" "$tmp/err" || { cat "$tmp/err"; exit 1; }
test ! -e "$tmp/pm3/cases.csv"

# Invalid pairs (a missing profile file: pairs 0 and 1), every pair's cases split between 2 shards; and more
# shards than cases (cases 0.. of a 2-case sweep over 2 pairs in 6 shards, some empty).
/usr/bin/python3 - "$tmp/fleet.json" "$tmp/bad.json" "$tmp/tiny.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
m["wheels"] = ["/nonexistent/wheel.prw"] + m["wheels"]
json.dump(m, open(sys.argv[2], "w"))
m = json.load(open(sys.argv[1]))
m["rails"] = m["rails"][:1]; m["wheels"] = m["wheels"][:2]
m["sweep"] = {"tY_mm": [0], "Q_kN": [50, 100]}
json.dump(m, open(sys.argv[3], "w"))
PY
set +e; "$bin" run "$tmp/bad.json" -o "$tmp/badfull" -q; rc=$?; set -e; test $rc -eq 1
n=$(($(wc -l < "$tmp/badfull/pairs.csv") - 1))
dirs=()
for k in $(seq 1 $((2 * n))); do
  "$bin" run "$tmp/bad.json" -o "$tmp/b$k" --shard $k/$((2 * n)) --shard-by cases -q || test $? -eq 1
  dirs+=("$tmp/b$k")
done
set +e; "$bin" merge "${dirs[@]}" -o "$tmp/badmerged" -q; rc=$?; set -e; test $rc -eq 1
same_run "$tmp/badfull" "$tmp/badmerged"
grep -q invalid_pair "$tmp/badmerged/pairs.csv"
"$bin" run "$tmp/tiny.json" -o "$tmp/tinyfull" -q || test $? -eq 1
for k in 1 2 3 4 5 6; do "$bin" run "$tmp/tiny.json" -o "$tmp/t$k" --shard $k/6 --shard-by cases -q || test $? -eq 1; done
"$bin" merge "$tmp"/t{1,2,3,4,5,6} -o "$tmp/tinymerged" -q || test $? -eq 1
same_run "$tmp/tinyfull" "$tmp/tinymerged"
echo "shard_pair_cases: OK ($n pairs)"
