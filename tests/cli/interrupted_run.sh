#!/usr/bin/env bash
# An interrupted run leaves the output directory as it was: nothing when it is new, the previous
# complete set when it is a rerun. SIGTERM and SIGINT in the middle of a large sweep leave no
# file that looks complete and no temporary directory behind.
set -euo pipefail
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
sed -e 's|"sweep": .*|"sweep": {"tY_mm": {"from": -6, "to": 10, "step": 0.0005}, "Q_kN": {"from": 10, "to": 150, "step": 1}}|' \
    -e "s|\"\\.\\./profiles/|\"$src/profiles/|g" "$src/cases/manchester.json" > "$tmp/big.json"
"$bin" run "$src/cases/manchester.json" -o "$tmp/previous" -q
for sig in TERM INT; do
  for mode in new rerun; do
    out="$tmp/out_${sig}_$mode"
    [ $mode = new ] || cp -r "$tmp/previous" "$out"
    "$bin" run "$tmp/big.json" -o "$out" -q --threads 1 &
    pid=$!
    # Wait until the run is writing (its temporary directory beside $out exists), then interrupt it.
    for i in $(seq 1 200); do
      ls -d "$tmp"/.out_${sig}_$mode.mhcontact-* >/dev/null 2>&1 && break
      sleep 0.05
    done
    sleep 0.3
    kill -s "$sig" "$pid"
    if wait "$pid"; then echo "run was not interrupted (too fast?)" >&2; exit 1; fi
    if [ $mode = new ]; then
      if [ -e "$out" ]; then echo "SIG$sig left $out behind" >&2; ls -la "$out" >&2; exit 1; fi
    else
      diff -r "$tmp/previous" "$out" >&2 || { echo "SIG$sig changed the previous complete set" >&2; exit 1; }
    fi
    if ls -d "$tmp"/.out_* >/dev/null 2>&1; then echo "SIG$sig left a temporary directory behind" >&2; ls -la "$tmp" >&2; exit 1; fi
  done
done
echo "interrupted_run: OK"
