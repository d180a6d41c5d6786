#!/usr/bin/env bash
# --pressure-cases: the pressure grid of the cases asked for only (numbers and ranges, global case
# numbers also in shards), the same rows as the full grid for those cases; refused without --pressure-grid, with a case beyond the case file, or malformed.
set -euo pipefail
. "$(dirname "$0")/lib/csv_col.sh"
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# Elastic multi-Hertzian and half-space.
"$bin" run "$src/cases/manchester.json" -o "$tmp/all" --pressure-grid 4 -q
"$bin" run "$src/cases/manchester.json" -o "$tmp/sel" --pressure-grid 4 --pressure-cases 40-42,7,41 -q
test "$(csv_col "$tmp/sel/pressure.csv" case | sort -un | tr '\n' ' ')" = "7 40 41 42 "
# Exactly the full run's rows of those cases.
diff <(head -1 "$tmp/all/pressure.csv"; grep -E '^(7|40|41|42),' "$tmp/all/pressure.csv") "$tmp/sel/pressure.csv"
cmp "$tmp/all/cases.csv" "$tmp/sel/cases.csv"
"$bin" run "$src/cases/manchester-halfspace.json" -o "$tmp/hs" --pressure-grid 2 --pressure-cases 13 -q
test "$(csv_col "$tmp/hs/pressure.csv" case | sort -u)" = "13"
# Shards keep global case numbers: two shards merged equal the unsharded selection.
for k in 1 2; do "$bin" run "$src/cases/manchester.json" -o "$tmp/s$k" --pressure-grid 4 --pressure-cases 40-42,7 --shard $k/2 -q; done
"$bin" merge "$tmp/s1" "$tmp/s2" -o "$tmp/m" -q
cmp "$tmp/sel/pressure.csv" "$tmp/m/pressure.csv"
# Refused with exit 2 and the rule.
expect2() {
  set +e; "$bin" run "$src/cases/manchester.json" -o "$tmp/x" "$@" -q 2>"$tmp/err"; rc=$?; set -e
  test $rc -eq 2 || { echo "expected exit 2 for $*" >&2; exit 1; }
  test ! -e "$tmp/x" || { echo "output left for $*" >&2; exit 1; }
}
expect2 --pressure-cases 3;              grep -q "needs --pressure-grid" "$tmp/err"
expect2 --pressure-grid 4 --pressure-cases 99;  grep -q "no such case: the case file has 99 cases" "$tmp/err"
expect2 --pressure-grid 4 --pressure-cases 7-3; grep -q "runs backwards" "$tmp/err"
expect2 --pressure-grid 4 --pressure-cases 1,x; grep -q "'x' is not a case number" "$tmp/err"
echo "pressure_cases: OK"
