#!/usr/bin/env bash
# FASTSIM's SSE2 and plain C++ marches give the same bits (tests/fastsim_paths/fastsim_paths.cpp).
# Usage: bash compare.sh <program, default path> <program, plain C++ path>
set -u
TMP="$(mktemp -d)"; trap 'rm -rf "$TMP"' EXIT
"$1" > "$TMP/default.txt" || { echo "FAIL: $1 exited $?"; exit 1; }
"$2" > "$TMP/scalar.txt" || { echo "FAIL: $2 exited $?"; exit 1; }
if ! grep -q '^200 cases$' "$TMP/scalar.txt"; then echo "FAIL: expected 200 cases"; exit 1; fi
if ! cmp -s "$TMP/default.txt" "$TMP/scalar.txt"; then
  echo "FAIL: the two marches differ:"; diff "$TMP/default.txt" "$TMP/scalar.txt" | head -20; exit 1
fi
echo "fastsim paths: $(grep -c ': ' "$TMP/default.txt") results, the same bits"
