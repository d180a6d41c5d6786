#!/usr/bin/env bash
# Batch manifests with every method:
# "method" and its options are shared keys of a manifest; a pair's rows in patches.csv (and, for
# "auto", in ellipses.csv) are exactly those of the single run of that pair; sharding over pairs
# + merge and any thread count give the same bytes; a bad method option names its JSON path.
set -euo pipefail
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
sed -e "s|\"\\.\\./profiles/|\"$src/profiles/|g" -e 's|"sweep": .*|"sweep": {"tY_mm": [-3, 0, 5, 8], "Q_kN": [50]}|' \
    "$src/cases/fleet.json" > "$tmp/fleet.json"
for m in strips auto half-space; do
  sed "s|\"model\": \"elastic\",|\"model\": \"elastic\", \"method\": \"$m\",|" "$tmp/fleet.json" > "$tmp/$m.json"
done
# t_Y = 0 mm on the Manchester pair: a patch whose strip extents are refined (docs/strips.md).
"$bin" run "$tmp/strips.json" -o "$tmp/strips" -q --threads 1
"$bin" run "$tmp/strips.json" -o "$tmp/strips2" -q --threads 2
for f in cases.csv patches.csv pairs.csv results.json; do cmp "$tmp/strips/$f" "$tmp/strips2/$f"; done
test "$(tail -n +2 "$tmp/strips/pairs.csv" | wc -l)" -eq 4
test "$(grep -c ',ok,strips,' "$tmp/strips/cases.csv")" -eq 16
head -1 "$tmp/strips/patches.csv" | grep -q '^pair,case,tY_mm,Q_kN,patch,.*,extents,end_gap_error,elements_across,element_mm$'
grep -q '^0,1,0,50,1,.*,end_gap,' "$tmp/strips/patches.csv"
test ! -e "$tmp/strips/ellipses.csv"
# Pair 0 (the Manchester pair) equals the single run of its case file.
sed -e "s|\"\\.\\./profiles/|\"$src/profiles/|g" -e 's|"sweep": .*|"sweep": {"tY_mm": [-3, 0, 5, 8], "Q_kN": [50]}|' \
    "$src/cases/manchester-strips.json" > "$tmp/single.json"
"$bin" run "$tmp/single.json" -o "$tmp/single" -q
for t in cases patches; do
  awk -F, 'NR>1 && $1==0' "$tmp/strips/$t.csv" | cut -d, -f2- | cmp - <(tail -n +2 "$tmp/single/$t.csv")
done
# Shards over pairs and merge.
"$bin" run "$tmp/strips.json" -o "$tmp/s1" --shard 1/2 -q
"$bin" run "$tmp/strips.json" -o "$tmp/s2" --shard 2/2 -q
"$bin" merge "$tmp/s1" "$tmp/s2" -o "$tmp/merged" -q
for f in cases.csv patches.csv pairs.csv; do cmp "$tmp/strips/$f" "$tmp/merged/$f"; done
# "auto": each case in the table of its method; the half-space method: patches without extents.
"$bin" run "$tmp/auto.json" -o "$tmp/auto" -q
grep -q '^0,1,0,50,ok,strips,' "$tmp/auto/cases.csv"
grep -q '^0,0,-3,50,ok,multi-hertzian,' "$tmp/auto/cases.csv"
test -s "$tmp/auto/ellipses.csv"; test -s "$tmp/auto/patches.csv"
"$bin" run "$tmp/half-space.json" -o "$tmp/hs" -q
grep -q '^0,1,0,50,1,.*,,,[0-9][0-9]*,[0-9.][0-9.]*$' "$tmp/hs/patches.csv"
# A bad strip option in a manifest: exit 2, the manifest and the JSON path named.
sed 's|"method": "strips",|"method": "strips", "strips": {"end_gap_tol": -1},|' "$tmp/strips.json" > "$tmp/bad.json"
set +e; "$bin" run "$tmp/bad.json" -o "$tmp/bad" -q 2> "$tmp/err"; rc=$?; set -e
test $rc -eq 2; grep -q 'bad.json' "$tmp/err"; grep -q '/strips/end_gap_tol' "$tmp/err"
echo "batch_methods: OK"
