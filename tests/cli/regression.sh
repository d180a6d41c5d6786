#!/usr/bin/env bash
# Change detectors: every table listed in tests/ref/detectors.txt (multi-Hertzian, half-space,
# strips, plastic strips, auto, wheelset and EN 15302 conicity) recomputed and compared with its
# stored copy by `mhcontact diff`, with the options the list gives each table (as users do in
# their own CI; the rules are in tests/ref/README.md). A failure means a result CHANGED, not that
# it is wrong: review it, and if intended, regenerate with scripts/update_refs.sh.
set -euo pipefail
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1"); src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$src"
bash scripts/run_detectors.sh "$bin" "$tmp"
n=0
while read -r dir _ _ table opts; do
  case "$dir" in ''|'#'*) continue ;; esac
  # shellcheck disable=SC2086  # the options are words
  if ! "$bin" diff "tests/ref/$dir/$table" "$tmp/$dir/$table" $opts > "$tmp/report.txt"; then
    echo "CHANGED: tests/ref/$dir/$table (mhcontact diff $opts):" >&2; cat "$tmp/report.txt" >&2; exit 1
  fi
  n=$((n + 1))
done < tests/ref/detectors.txt
# Every stored table is in the list (none left unchecked).
for f in tests/ref/*/*.csv; do
  d=$(basename "$(dirname "$f")"); t=$(basename "$f")
  grep -Eq "^$d +[a-z]+ +[^ ]+ +$t( |$)" tests/ref/detectors.txt || { echo "$f is not in tests/ref/detectors.txt" >&2; exit 1; }
done
# The guard must be able to fail: a perturbed reference is caught.
sed '2s/,ok,multi-hertzian,\([0-9.e-]*\),/,ok,multi-hertzian,1\1,/' tests/ref/manchester/cases.csv > "$tmp/perturbed.csv"
if "$bin" diff "$tmp/perturbed.csv" "$tmp/manchester/cases.csv" --rtol 1e-7 --atol 1e-9 --quiet >/dev/null; then
  echo "diff did not catch a perturbed reference" >&2; exit 1
fi
echo "regression: $n tables OK"
