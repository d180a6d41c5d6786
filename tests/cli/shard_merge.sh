#!/usr/bin/env bash
# --shard K/N and merge: N shards run as separate processes, merged, give byte for byte the
# tables of the unsharded run (also with more shards than cases, a failing case, and pressure
# grids). Missing, doubled or foreign shards are refused with exit 2.
set -euo pipefail
. "$(dirname "$0")/lib/csv_col.sh"
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
check_equal() {  # $1 = reference dir, $2 = merged dir
  for f in cases.csv ellipses.csv geometry.csv results.json profiles.csv; do cmp "$1/$f" "$2/$f"; done
}
"$bin" run "$src/cases/manchester.json" -o "$tmp/full" -q
for k in 1 2 3; do "$bin" run "$src/cases/manchester.json" -o "$tmp/s$k" --shard $k/3 -q & done
wait
test -s "$tmp/s2/shard.json"
"$bin" merge "$tmp/s3" "$tmp/s1" "$tmp/s2" -o "$tmp/merged" -q
check_equal "$tmp/full" "$tmp/merged"
# --shard-sizes tapered on a case file: shard K's share of the 99 cases ∝ N − K + 1 (33, 26, 20,
# 13, 7), recorded in shard.json, merged to the one run's bytes.
for k in 1 2 3 4 5; do "$bin" run "$src/cases/manchester.json" -o "$tmp/t$k" --shard $k/5 --shard-sizes tapered -q; done
counts=$(for k in 1 2 3 4 5; do echo $(($(wc -l < "$tmp/t$k/cases.csv") - 1)); done | tr '\n' ' ')
test "$counts" = "33 26 20 13 7 " || { echo "tapered shards: $counts" >&2; exit 1; }
grep -q '"sizes": *"tapered"' "$tmp/t1/shard.json"
"$bin" merge "$tmp"/t5 "$tmp"/t3 "$tmp"/t1 "$tmp"/t2 "$tmp"/t4 -o "$tmp/tmerged" -q
check_equal "$tmp/full" "$tmp/tmerged"
# 4 shards cut the loads of one t_Y between shards 2 and 3 (cases 49 .. 50 share t_Y = 2 mm):
# both shards write its geometry rows, the merge keeps them once, where one run writes them.
for k in 1 2 3 4; do "$bin" run "$src/cases/manchester.json" -o "$tmp/q$k" --shard $k/4 -q; done
test "$(csv_col "$tmp/q2/geometry.csv" tY_mm | tail -n 1)" = "$(csv_col "$tmp/q3/geometry.csv" tY_mm | head -n 1)"
"$bin" merge "$tmp"/q1 "$tmp"/q2 "$tmp"/q3 "$tmp"/q4 -o "$tmp/qmerged" -q
check_equal "$tmp/full" "$tmp/qmerged"

# More shards than cases, a failing case (exit 1 kept by merge), pressure grids.
sed -e 's|"sweep": .*|"cases": [{"tY_mm": 0, "Q_kN": 50}, {"tY_mm": 40, "Q_kN": 50}, {"tY_mm": 5, "Q_kN": 80}]|' \
    -e "s|\"model\": \"plastic\",|\"model\": \"plastic\", \"geometry\": {\"tY_min_mm\": -10, \"tY_max_mm\": 12},|" \
    -e "s|\"\\.\\./profiles/|\"$src/profiles/|g" "$src/cases/manchester-plastic.json" > "$tmp/few.json"
set +e
"$bin" run "$tmp/few.json" -o "$tmp/ffull" --pressure-grid 5 -q; test $? -eq 1 || exit 1
for k in 1 2 3 4 5; do "$bin" run "$tmp/few.json" -o "$tmp/f$k" --shard $k/5 --pressure-grid 5 -q; done
"$bin" merge "$tmp"/f1 "$tmp"/f2 "$tmp"/f3 "$tmp"/f4 "$tmp"/f5 -o "$tmp/fmerged" -q; test $? -eq 1 || exit 1
set -e
check_equal "$tmp/ffull" "$tmp/fmerged"
cmp "$tmp/ffull/pressure.csv" "$tmp/fmerged/pressure.csv"

# Refused: a missing shard, a shard twice, shards of another run, a bad --shard.
expect2() { set +e; "$@" 2>"$tmp/err"; rc=$?; set -e; test $rc -eq 2 || { echo "expected exit 2: $*" >&2; exit 1; }; }
# the message names the shard that is missing, and how to make it
expect2 "$bin" merge "$tmp/s1" "$tmp/s2" -o "$tmp/m2"
grep -q "split into 3 shards: shard 3/3 missing (run the missing shard(s) .* --shard K/3)" "$tmp/err" || { cat "$tmp/err"; exit 1; }
expect2 "$bin" merge "$tmp/s3" "$tmp/s1" -o "$tmp/m2"
grep -q "shard 2/3 missing" "$tmp/err" || { cat "$tmp/err"; exit 1; }
expect2 "$bin" merge "$tmp/s1" "$tmp/s2" "$tmp/s2" -o "$tmp/m3"
grep -q "shard 3/3 missing; shard 2/3 in $tmp/s2 $tmp/s2 given twice" "$tmp/err" || { cat "$tmp/err"; exit 1; }
"$bin" run "$src/cases/s1002-60e1.json" -o "$tmp/o2" --shard 2/3 -q
expect2 "$bin" merge "$tmp/s1" "$tmp/o2" "$tmp/s3" -o "$tmp/m4"
grep -q "different runs" "$tmp/err"
expect2 "$bin" run "$src/cases/manchester.json" -o "$tmp/x" --shard 4/3
grep -q "K/N" "$tmp/err"
test ! -e "$tmp/m2/cases.csv"
# results.json is merged as text, checked against shard.json: its "results_json" gives the
# document's size and the byte range and count of each array of records (the merge copies those
# ranges without reading them). Each span's records are where it says:
/usr/bin/python3 -c '
import json, sys
d = sys.argv[1]; t = open(d + "/results.json", "rb").read(); L = json.load(open(d + "/shard.json"))["results_json"]
assert L["bytes"] == len(t), (L["bytes"], len(t))
assert len(L["spans"]) == 2, L["spans"]  # "geometry" and "cases"
for b, e, n in L["spans"]:
    assert t[b - 2:b] == b"[\n" and t[e:e + 4] == b"\n  ]" and t[b:e].count(b"\n") == n - 1, (b, e, n)
assert L["spans"][1][2] == 33' "$tmp/s2"
# A shard's document that lost a case record (cut by hand, a disk full) is refused by its size,
# naming it; where shard.json gives no ranges (a shard of an earlier version), by its records
# counted line by line; one not in the layout run writes, by its layout.
cp -r "$tmp/s2" "$tmp/s2cut"
awk '/^  "cases": \[/ {c = 1; print; next} c == 1 {c = 2; next} {print}' "$tmp/s2/results.json" > "$tmp/s2cut/results.json"
expect2 "$bin" merge "$tmp/s1" "$tmp/s2cut" "$tmp/s3" -o "$tmp/m5"
grep -q "$tmp/s2cut/results.json: .*not a results.json as mhcontact run writes it: [0-9]* bytes, its shard.json says [0-9]* (cut short or edited)" "$tmp/err" || { cat "$tmp/err"; exit 1; }
/usr/bin/python3 -c '
import json, sys
j = json.load(open(sys.argv[1])); del j["results_json"]; json.dump(j, open(sys.argv[1], "w"), indent=2)' "$tmp/s2cut/shard.json"
expect2 "$bin" merge "$tmp/s1" "$tmp/s2cut" "$tmp/s3" -o "$tmp/m5"
grep -q "$tmp/s2cut/results.json: .*holds 32 cases, its shard.json 33" "$tmp/err" || { cat "$tmp/err"; exit 1; }
cp "$tmp/s2/shard.json" "$tmp/s2cut/shard.json"
/usr/bin/python3 -c 'import json, sys; json.dump(json.load(open(sys.argv[1])), open(sys.argv[2], "w"))' "$tmp/s2/results.json" "$tmp/s2cut/results.json"
expect2 "$bin" merge "$tmp/s1" "$tmp/s2cut" "$tmp/s3" -o "$tmp/m5"
grep -q "$tmp/s2cut/results.json: .*not a results.json as mhcontact run writes it" "$tmp/err" || { cat "$tmp/err"; exit 1; }
test ! -e "$tmp/m5/cases.csv"
# ... and so is one with a member after its records (the run writes "summary" alone there; the
# merge copies only the members before the records, so it would be lost), its size in shard.json
# made to match.
/usr/bin/python3 -c '
import json, sys
t = open(sys.argv[1]).read(); i = t.index("\n  \"summary\"")
t = t[:i] + "\n  \"extra\": 1," + t[i:]
open(sys.argv[2], "w").write(t)
j = json.load(open(sys.argv[3])); j["results_json"]["bytes"] = len(t.encode()); json.dump(j, open(sys.argv[3], "w"), indent=2)' \
  "$tmp/s2/results.json" "$tmp/s2cut/results.json" "$tmp/s2cut/shard.json"
expect2 "$bin" merge "$tmp/s1" "$tmp/s2cut" "$tmp/s3" -o "$tmp/m5"
grep -q "$tmp/s2cut/results.json: .*\"summary\" alone must follow the \"cases\"" "$tmp/err" || { cat "$tmp/err"; exit 1; }
# ... and a span of shard.json that does not fall on the records (moved by one byte).
cp "$tmp/s2/results.json" "$tmp/s2/shard.json" "$tmp/s2cut/"
/usr/bin/python3 -c '
import json, sys
j = json.load(open(sys.argv[1])); j["results_json"]["spans"][1][0] += 1; json.dump(j, open(sys.argv[1], "w"), indent=2)' "$tmp/s2cut/shard.json"
expect2 "$bin" merge "$tmp/s1" "$tmp/s2cut" "$tmp/s3" -o "$tmp/m5"
grep -q "$tmp/s2cut/results.json: .*record span .* is not an array's records in the document" "$tmp/err" || { cat "$tmp/err"; exit 1; }

# Shards whose tables and records are large (64 kB and more a piece): merge copies those pieces
# inside the kernel (copy_file_range) instead of writing them; the bytes are the same. A case
# file's shards (2,403 cases, about 0.4 MB of records each) and a manifest's (99 cases a pair).
sed -e 's|"step": 0.5|"step": 0.02|' -e "s|\"\\.\\./profiles/|\"$src/profiles/|g" "$src/cases/manchester.json" > "$tmp/big.json"
"$bin" run "$tmp/big.json" -o "$tmp/bigfull" -q || test $? -eq 1
for k in 1 2 3; do "$bin" run "$tmp/big.json" -o "$tmp/big$k" --shard $k/3 -q || test $? -eq 1; done
test "$(wc -c < "$tmp/big2/cases.csv")" -gt 65536
"$bin" merge "$tmp"/big1 "$tmp"/big2 "$tmp"/big3 -o "$tmp/bigmerged" -q || test $? -eq 1
check_equal "$tmp/bigfull" "$tmp/bigmerged"
sed -e "s|\"\\.\\./profiles/|\"$src/profiles/|g" "$src/cases/fleet.json" > "$tmp/fleet.json"
"$bin" run "$tmp/fleet.json" -o "$tmp/fleetfull" -q || test $? -eq 1
for k in 1 2; do "$bin" run "$tmp/fleet.json" -o "$tmp/fleet$k" --shard $k/2 -q || test $? -eq 1; done
"$bin" merge "$tmp"/fleet1 "$tmp"/fleet2 -o "$tmp/fleetmerged" -q || test $? -eq 1
for f in cases.csv ellipses.csv geometry.csv pairs.csv results.json; do cmp "$tmp/fleetfull/$f" "$tmp/fleetmerged/$f"; done
echo "shard_merge: OK"
