#!/usr/bin/env bash
# Regenerate every change detector of tests/ref/ (the tables listed in tests/ref/detectors.txt)
# in one command. Review the change (git diff tests/ref) before committing: the tables are what
# CI holds every later build to. Usage: scripts/update_refs.sh [mhcontact binary]
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build/mhcontact}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# Only result tables are kept (not profiles.csv, a copy of the inputs, nor run.json, which names
# the build); default digits (10 significant), as users get them. Exit 1 (some case or wheel not
# ok) is a result like any other: the tables hold the statuses.
done_dirs=" "
while read -r dir cmd case table _; do
  case "$dir" in ''|'#'*) continue ;; esac
  if [[ "$done_dirs" != *" $dir "* ]]; then
    if [ "$cmd" = run ]; then
      "$bin" run "$case" -o "$tmp/$dir" --format csv -q || test $? -eq 1
    else
      "$bin" "$cmd" "$case" -o "$tmp/$dir" -q >/dev/null || test $? -eq 1
    fi
    done_dirs="$done_dirs$dir "
  fi
  mkdir -p "tests/ref/$dir"
  cp "$tmp/$dir/$table" "tests/ref/$dir/$table"
done < tests/ref/detectors.txt
echo "updated tests/ref/: review with git diff tests/ref"
