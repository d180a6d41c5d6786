#!/usr/bin/env bash
# Regenerate every change detector of tests/ref/ (the tables listed in tests/ref/detectors.txt)
# in one command. Review the change (git diff tests/ref) before committing: the tables are what
# CI holds every later build to. Usage: scripts/update_refs.sh [mhcontact binary]
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build/mhcontact}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# Only result tables are kept (not profiles.csv, a copy of the inputs, nor run.json, which names
# the build).
bash scripts/run_detectors.sh "$bin" "$tmp"
while read -r dir _ _ table _; do
  case "$dir" in ''|'#'*) continue ;; esac
  mkdir -p "tests/ref/$dir"
  cp "$tmp/$dir/$table" "tests/ref/$dir/$table"
done < tests/ref/detectors.txt
echo "updated tests/ref/: review with git diff tests/ref"
