#!/usr/bin/env bash
# Failures are never silent: a write to standard output that fails (/dev/full) exits 4 with a
# message; unknown commands, -V and `version` give the documented error format and a hint; a
# pressure grid that would be too large is refused before solving (unless --force); `-o -
# --format csv` is refused.
# Usage: bash output_errors.sh <mhcontact-binary> <source-dir>
set -uo pipefail
bin="$1"
src="$(cd "$2" && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cd "$src" || exit 1
fails=0
expect() {  # expected-code message-substring stdout-target args...
  local code="$1" msg="$2" target="$3"; shift 3
  local err rc
  err="$("$bin" "$@" 2>&1 >"$target")"; rc=$?
  [ "$rc" = "$code" ] || { echo "FAIL (exit $rc, wanted $code): $*"; fails=1; }
  case "$err" in *"$msg"*) ;; *) echo "FAIL (message lacks '$msg'): $* -> $err"; fails=1 ;; esac
}
if [ -w /dev/full ]; then
  expect 4 "mhcontact: error: standard output: output could not be written" /dev/full run cases/manchester.json -o - -q
  expect 4 "standard output: output could not be written" /dev/full profile info profiles/60E1.csv
  expect 4 "standard output: output could not be written" /dev/full diff tests/data/diff/cases_ref.csv tests/data/diff/cases_ref.csv
  expect 4 "standard output: output could not be written" /dev/full hertz --A 0.001 --B 0.002 --N 100 --E 210 --nu 0.28
  expect 4 "standard output: output could not be written" /dev/full --help
else
  echo "skipped the /dev/full checks: /dev/full is not writable here"
fi
expect 2 "mhcontact: error: command: value version: unknown command or option (the version is printed by \`mhcontact --version\`)" /dev/null version
expect 2 "mhcontact: error: command: value -V: unknown command or option" /dev/null -V
expect 2 "mhcontact: error: command: value rnu: unknown command (did you mean \`run\`?" /dev/null rnu cases/manchester.json -o "$tmp/x"
expect 2 "mhcontact: error: command: a command is required (commands: " /dev/null
expect 2 "mhcontact: error: --format: value csv: -o - writes results.json to standard output" /dev/null run cases/manchester.json -o - --format csv
# 330 cases x 1000 x 1000 points: at least 17 GB of pressure.csv, refused before solving.
python3 - "$src" "$tmp/big.json" <<'PY'
import json, sys
src, out = sys.argv[1], sys.argv[2]
c = json.load(open(src + "/cases/manchester.json"))
c["wheel"]["profile"] = src + "/profiles/MBench_S1002_v3.prw"
c["rail"]["profile"] = src + "/profiles/MBench_UIC60_v3.prr"
c["sweep"]["Q_kN"] = [10 * k for k in range(1, 11)]
json.dump(c, open(out, "w"))
PY
expect 2 "mhcontact: error: --pressure-grid: value 1000: pressure.csv would be at least 17.2 GB" /dev/null run "$tmp/big.json" -o "$tmp/big" --pressure-grid 1000 -q
[ ! -e "$tmp/big" ] || { echo "FAIL: a refused run left $tmp/big behind"; fails=1; }
# An output directory that cannot be created is an output error (exit 4).
touch "$tmp/file"
expect 4 "output directory cannot be created" /dev/null run cases/manchester.json -o "$tmp/file/sub" -q
"$bin" version >/dev/null 2>&1; [ $? = 2 ] || { echo "FAIL: version"; fails=1; }
"$bin" --version >/dev/null || { echo "FAIL: --version"; fails=1; }
exit $fails
