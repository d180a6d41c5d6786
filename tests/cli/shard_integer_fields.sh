#!/usr/bin/env bash
# The integer fields of shard.json are range-checked as integers before any
# conversion: a count of 4294967297 (which would wrap to 1) or a string index is an input error
# (exit 2) naming the field, never a wrapped value or an internal error.
# Usage: bash shard_integer_fields.sh <mhcontact-binary> <source-dir>
set -uo pipefail
bin="$1"
src="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
fails=0
for k in 1 2; do "$bin" run "$src/cases/manchester.json" -o "$tmp/s$k" --shard $k/2 -q || true; done
"$bin" merge "$tmp/s1" "$tmp/s2" -o "$tmp/m" -q || { echo "FAIL: clean merge"; fails=1; }
try() {  # field json-value message
  rm -rf "$tmp/b1"; cp -r "$tmp/s1" "$tmp/b1"
  python3 -c "import json,sys; p=sys.argv[1]; j=json.load(open(p)); j[sys.argv[2]]=json.loads(sys.argv[3]); json.dump(j,open(p,'w'))" \
    "$tmp/b1/shard.json" "$1" "$2"
  local err rc
  err="$("$bin" merge "$tmp/b1" "$tmp/s2" -o "$tmp/mb" -q 2>&1)"; rc=$?
  [ "$rc" = 2 ] || { echo "FAIL: $1=$2: exit $rc, wanted 2 ($err)"; fails=1; }
  case "$err" in *"/$1"*"$3"*) ;; *) echo "FAIL: $1=$2: message $err"; fails=1 ;; esac
}
try count 4294967298 "must be an integer in"
try index '"1"' "must be an integer in"
try index 2.5 "must be an integer in"
try first -1 "must be an integer in"
exit $fails
