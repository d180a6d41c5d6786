#!/usr/bin/env bash
# The library's layers, in the order of the data flow: a file of a layer may include headers of
# its own layer and of the layers before it, never of a later one (no cycles, includes point down
# the flow). Inside lib/contact the same holds between its rooms, in this order:
#   tangential (tangential/*: creepages, Kalker's coefficients, FASTSIM on one ellipse and their
#     options, light: options.hpp includes them)
#   < options (options.hpp: material, method, every options struct)
#   < judge_status (judge/status.*: a case's status and warnings as data, light)
#   < ellipse (one Hertzian ellipse) < case_result (the result every method returns, and
#     pressure_grid.hpp, the points of its pressure grid)
#   < judge (judge/judge.*: the one rule that decides a solved case's status)
#   < tangential_solve (tangential/tangential_solve.*: the tangential problem of a solved case)
#   < multi_hertz < grid (what the grid methods share) < half_space | strips (siblings: neither
#   includes the other) < solve (dispatch and auto) | rcf (rcf/*: RCF indicators, damage and wear,
#   subsurface stresses; after the strips for the library's one Gauss–Legendre rule).
# After contact comes wheelset_contact (the wheelset call: both pairs of a wheelset per step,
# lib/wheelset_contact/), before input.
# Last comes capi (the C interface and the Python module's core, include/mhcontact.h): it may use
# core … contact and input (profiles and case files read as the command reads them), but not
# output or jobs, so that the embeddable library carries no table writer and no job runner.
# The core layers (core, profile, geometry, contact, wheelset_contact) include neither nlohmann-json nor CLI11;
# nothing in lib/ includes CLI11 (only apps/mhcontact does).
set -uo pipefail
src=$1
layers=(core profile geometry contact wheelset_contact input output jobs capi)
rooms=(tangential options judge_status ellipse case_result judge tangential_solve multi_hertz grid half_space strips solve rcf)
room_rank=(0 1 2 3 4 5 6 7 8 9 9 10 10)
rank() { local i; for i in "${!layers[@]}"; do [ "${layers[$i]}" = "$1" ] && { echo "$i"; return; }; done; echo -1; }
room() {  # the room of lib/contact/<rest> given <rest>: its folder, or the file's stem at the top
  case "$1" in judge/status.*) echo judge_status ;; tangential/tangential_solve.*) echo tangential_solve ;; pressure_grid.*) echo case_result ;; */*) echo "${1%%/*}" ;; *) local b=${1%.*}; echo "$b" ;; esac
}
room_rank_of() { local i; for i in "${!rooms[@]}"; do [ "${rooms[$i]}" = "$1" ] && { echo "${room_rank[$i]}"; return; }; done; echo -1; }
check_tree() {  # prints the violations of the tree $1, returns 1 if any
  local root=$1 bad=0 f own r_own inc layer r rf ri rrf rri
  for f in $(cd "$root" && find lib -name '*.hpp' -o -name '*.cpp' | sort); do
    own=$(echo "$f" | cut -d/ -f2)
    r_own=$(rank "$own")
    if [ "$r_own" -lt 0 ]; then echo "layering: $f is in no known layer (lib/<layer>/)"; bad=1; continue; fi
    if [ "$own" = contact ]; then
      rf=$(room "${f#lib/contact/}"); rrf=$(room_rank_of "$rf")
      if [ "$rrf" -lt 0 ]; then echo "layering: $f is in no known room of lib/contact (${rooms[*]})"; bad=1; continue; fi
    fi
    while IFS= read -r inc; do
      [ -z "$inc" ] && continue
      layer=${inc%%/*}
      r=$(rank "$layer")
      if [ "$r" -lt 0 ]; then echo "layering: $f includes \"$inc\": not a lib/<layer>/ header"; bad=1
      elif [ "$r" -gt "$r_own" ]; then echo "layering: $f ($own) includes \"$inc\" of the later layer $layer"; bad=1
      elif [ "$own" = capi ] && { [ "$layer" = output ] || [ "$layer" = jobs ]; }; then
        echo "layering: $f (capi) includes \"$inc\": the C interface may not use $layer"; bad=1
      elif [ "$own" = contact ] && [ "$layer" = contact ]; then
        ri=$(room "${inc#contact/}"); rri=$(room_rank_of "$ri")
        if [ "$rri" -lt 0 ]; then echo "layering: $f includes \"$inc\": no known room of lib/contact"; bad=1
        elif [ "$rri" -gt "$rrf" ]; then echo "layering: $f (contact/$rf) includes \"$inc\" of the later room contact/$ri"; bad=1
        elif [ "$rri" -eq "$rrf" ] && [ "$ri" != "$rf" ]; then echo "layering: $f (contact/$rf) includes \"$inc\" of its sibling contact/$ri"; bad=1; fi
      fi
    done < <(grep -o '#include "[^"]*"' "$root/$f" | sed 's/#include "//; s/"$//')
    if grep -q '#include <CLI/' "$root/$f"; then echo "layering: $f includes CLI11 (only apps/ may)"; bad=1; fi
    if [ "$r_own" -le 4 ] && grep -q '#include <nlohmann/' "$root/$f"; then echo "layering: $f ($own) includes nlohmann-json (the core layers may not)"; bad=1; fi
  done
  return $bad
}
check_tree "$src" || exit 1
# The check must be able to fail: an upward include, a JSON include in the core, a room of
# lib/contact including a later room and a sibling, capi including jobs are caught.
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/lib/core" "$tmp/lib/contact/ellipse" "$tmp/lib/contact/strips" "$tmp/lib/capi"
echo '#include "jobs/run.hpp"' > "$tmp/lib/core/x.hpp"
echo '#include <nlohmann/json.hpp>' > "$tmp/lib/contact/options.cpp"
echo '#include "contact/multi_hertz/multi_hertz.hpp"' > "$tmp/lib/contact/ellipse/hertz.hpp"
echo '#include "contact/half_space/influence.hpp"' > "$tmp/lib/contact/strips/strip_method.hpp"
echo '#include "jobs/run.hpp"' > "$tmp/lib/capi/x.cpp"
out=$(check_tree "$tmp") && { echo "layering: the self-test was not caught"; exit 1; }
[ "$(echo "$out" | wc -l)" = 5 ] || { echo "layering: self-test expected 5 violations, got: $out"; exit 1; }
echo "layering: OK"
