#!/usr/bin/env bash
# Regenerate tests/ref/ from the shipped cases. Review the change (git diff) before committing:
# the references are what CI holds every later build to.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build/mhcontact}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# Only the result tables are references (not profiles.csv, a copy of the inputs, nor run.json,
# which names the build); default digits (10 significant), as users get them.
for c in manchester manchester-plastic s1002-60e1 fleet; do
  "$bin" run "cases/$c.json" -o "$tmp/$c" --format csv -q || test $? -eq 1
  cp "$tmp/$c/cases.csv" "$tmp/$c/ellipses.csv" "$tmp/$c/geometry.csv" "tests/ref/$c/"
  if [ -f "$tmp/$c/pairs.csv" ]; then cp "$tmp/$c/pairs.csv" "tests/ref/$c/"; fi
done
echo "updated tests/ref/: review with git diff"
