#!/usr/bin/env bash
# Run every case of the change detectors (tests/ref/detectors.txt) once into OUT/<folder>/, as the
# detector tables are made: result tables only matter, default digits (10 significant). Exit 1 of
# a run (some case or wheel not ok) is a result like any other: the tables hold the statuses.
# Used by scripts/update_refs.sh (to write the tables) and tests/cli/regression.sh (to compare).
# Usage: scripts/run_detectors.sh MHCONTACT_BINARY OUT   (from the source root)
set -euo pipefail
bin=$1 out=$2
done_dirs=" "
while read -r dir cmd case _; do
  case "$dir" in ''|'#'*) continue ;; esac
  [[ "$done_dirs" == *" $dir "* ]] && continue
  if [ "$cmd" = run ]; then
    "$bin" run "$case" -o "$out/$dir" --format csv -q || test $? -eq 1
  else
    "$bin" "$cmd" "$case" -o "$out/$dir" -q >/dev/null || test $? -eq 1
  fi
  done_dirs="$done_dirs$dir "
done < tests/ref/detectors.txt
