#!/usr/bin/env bash
# An interrupted run leaves no file that looks complete: SIGTERM and SIGINT in the middle of a
# large sweep leave neither cases.csv nor a temporary behind.
set -euo pipefail
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
sed -e 's|"sweep": .*|"sweep": {"tY_mm": {"from": -6, "to": 10, "step": 0.0005}, "Q_kN": {"from": 10, "to": 150, "step": 1}}|' \
    -e "s|\"\\.\\./profiles/|\"$src/profiles/|g" "$src/cases/manchester.json" > "$tmp/big.json"
for sig in TERM INT; do
  out="$tmp/out_$sig"
  "$bin" run "$tmp/big.json" -o "$out" -q --threads 1 &
  pid=$!
  # Wait until the run is writing (a temporary exists), then interrupt it.
  for i in $(seq 1 200); do
    ls "$out"/*.tmp.* >/dev/null 2>&1 && break
    sleep 0.05
  done
  sleep 0.3
  kill -s "$sig" "$pid"
  if wait "$pid"; then echo "run was not interrupted (too fast?)" >&2; exit 1; fi
  for f in cases.csv ellipses.csv results.json; do
    if [ -e "$out/$f" ]; then echo "SIG$sig left $f behind" >&2; exit 1; fi
  done
  if ls "$out"/*.tmp.* >/dev/null 2>&1; then echo "SIG$sig left a temporary behind" >&2; ls "$out" >&2; exit 1; fi
done
echo "interrupted_run: OK"
