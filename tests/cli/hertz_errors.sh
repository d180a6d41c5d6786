#!/usr/bin/env bash
# Must-fail tests of `mhcontact hertz`: invalid values exit 2 with a message naming the option
# and the value; command-line syntax errors are CLI11's (exit >= 100); nothing on stdout.
# Usage: bash hertz_errors.sh <mhcontact-binary> <source-dir>
set -uo pipefail
bin="$1"
fails=0
expect() {  # expected-code message-substring args...
  local code="$1" msg="$2"; shift 2
  local out err rc
  err="$("$bin" hertz "$@" 2>&1 >/dev/null)"; rc=$?
  out="$("$bin" hertz "$@" 2>/dev/null)"
  if [ "$code" = "1xx" ]; then [ "$rc" -ge 100 ] || { echo "FAIL ($rc, wanted >= 100): $*"; fails=1; }
  elif [ "$rc" != "$code" ]; then echo "FAIL (exit $rc, wanted $code): $*"; fails=1; fi
  case "$err" in *"$msg"*) ;; *) echo "FAIL (message lacks '$msg'): $* -> $err"; fails=1 ;; esac
  [ -z "$out" ] || { echo "FAIL (stdout not empty): $*"; fails=1; }
}
M=(--N 100 --E 210 --nu 0.3)
expect 2 "--B: value -0.5" --A 0.001 --B -0.5 "${M[@]}"
expect 2 "B = -0.00166" --R-wyy 460 --R-rxx -300 "${M[@]}"
expect 2 "conformal" --R-wyy 460 --R-rxx 300 --R-wxx -300 "${M[@]}"
expect 2 "--R-wyy: value -460" --R-wyy -460 --R-rxx 300 "${M[@]}"
expect 2 "--N: value -5" --R-wyy 460 --R-rxx 300 --N -5 --E 210 --nu 0.3
expect 2 "--nu: value 0.7" --R-wyy 460 --R-rxx 300 --N 5 --E 210 --nu 0.7
expect 2 "--p-lim: value -800" --R-wyy 460 --R-rxx 300 "${M[@]}" --p-lim -800
expect 1xx "excludes" --A 0.001 --B 0.002 --R-wyy 460 "${M[@]}"
expect 1xx "--N" --R-wyy 460 --R-rxx 300 --E 210 --nu 0.3
exit $fails
