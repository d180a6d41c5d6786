#!/usr/bin/env bash
# The library's layers, in the order of the data flow: a file of a layer may include headers of
# its own layer and of the layers before it, never of a later one (no cycles, includes point down
# the flow). The core layers (core, profile, geometry, contact) include neither nlohmann-json nor
# CLI11; nothing in lib/ includes CLI11 (only apps/mhcontact does).
set -uo pipefail
src=$1
layers=(core profile geometry contact input output jobs)
rank() { local i; for i in "${!layers[@]}"; do [ "${layers[$i]}" = "$1" ] && { echo "$i"; return; }; done; echo -1; }
check_tree() {  # prints the violations of the tree $1, returns 1 if any
  local root=$1 bad=0 f own r_own inc layer r
  for f in $(cd "$root" && find lib -name '*.hpp' -o -name '*.cpp' | sort); do
    own=$(echo "$f" | cut -d/ -f2)
    r_own=$(rank "$own")
    if [ "$r_own" -lt 0 ]; then echo "layering: $f is in no known layer (lib/<layer>/)"; bad=1; continue; fi
    while IFS= read -r inc; do
      [ -z "$inc" ] && continue
      layer=${inc%%/*}
      r=$(rank "$layer")
      if [ "$r" -lt 0 ]; then echo "layering: $f includes \"$inc\": not a lib/<layer>/ header"; bad=1
      elif [ "$r" -gt "$r_own" ]; then echo "layering: $f ($own) includes \"$inc\" of the later layer $layer"; bad=1; fi
    done < <(grep -o '#include "[^"]*"' "$root/$f" | sed 's/#include "//; s/"$//')
    if grep -q '#include <CLI/' "$root/$f"; then echo "layering: $f includes CLI11 (only apps/ may)"; bad=1; fi
    if [ "$r_own" -le 3 ] && grep -q '#include <nlohmann/' "$root/$f"; then echo "layering: $f ($own) includes nlohmann-json (the core layers may not)"; bad=1; fi
  done
  return $bad
}
check_tree "$src" || exit 1
# The check must be able to fail: an upward include and a JSON include in the core are caught.
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/lib/core" "$tmp/lib/contact"
echo '#include "jobs/run.hpp"' > "$tmp/lib/core/x.hpp"
echo '#include <nlohmann/json.hpp>' > "$tmp/lib/contact/y.cpp"
out=$(check_tree "$tmp") && { echo "layering: the self-test was not caught"; exit 1; }
[ "$(echo "$out" | wc -l)" = 2 ] || { echo "layering: self-test expected 2 violations, got: $out"; exit 1; }
echo "layering: OK"
