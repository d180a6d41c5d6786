#!/usr/bin/env bash
# Regenerate tests/ref/ from the shipped cases. Review the change (git diff) before committing:
# the references are what CI holds every later build to.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build/mhcontact}
for c in manchester manchester-plastic s1002-60e1 fleet; do
  "$bin" run "cases/$c.json" -o "tests/ref/$c" --format csv -q || test $? -eq 1
  rm -f "tests/ref/$c/profiles.csv"   # a copy of the inputs, not a result
done
echo "updated tests/ref/: review with git diff"
