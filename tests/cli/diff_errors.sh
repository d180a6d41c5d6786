#!/usr/bin/env bash
# Must-fail tests of `mhcontact diff`: unreadable or malformed input and bad option values exit
# 2 with a message naming the file and line or the option; nothing on stdout.
# Usage: bash diff_errors.sh <mhcontact-binary> <source-dir>
set -uo pipefail
bin="$1"
cd "$2/tests/data/diff" || exit 1
fails=0
expect() {  # expected-code message-substring args...
  local code="$1" msg="$2"; shift 2
  local out err rc
  err="$("$bin" diff "$@" 2>&1 >/dev/null)"; rc=$?
  out="$("$bin" diff "$@" 2>/dev/null)"
  [ "$rc" = "$code" ] || { echo "FAIL (exit $rc, wanted $code): diff $*"; fails=1; }
  case "$err" in *"$msg"*) ;; *) echo "FAIL (message lacks '$msg'): diff $* -> $err"; fails=1 ;; esac
  [ -z "$out" ] || { echo "FAIL (stdout not empty): diff $*"; fails=1; }
}
expect 2 "ragged.csv:3: value 12 fields: row has 12 fields but the header has 11" cases_ref.csv ragged.csv
expect 2 "no_such.csv: cannot open file for reading" no_such.csv cases_ref.csv
expect 2 "dupkey.csv:4: value case=c1: duplicate key: the same key is on line 2" dupkey.csv cases_ref.csv
expect 2 "caf_ref.csv:3: value ellipse=1: duplicate key" caf_ref.csv caf_out.csv --key ellipse
expect 2 "--column-tol: value \"Fz_kN:0.01\": expected COL=TOL" cases_ref.csv cases_ref.csv --column-tol Fz_kN:0.01
expect 2 "--column-tol Fz_kN: value \"x\": not a number" cases_ref.csv cases_ref.csv --column-tol Fz_kN=x
expect 2 "--column-tol Fz_kN: value -1: tolerance must be finite and >= 0" cases_ref.csv cases_ref.csv --column-tol Fz_kN=-1
expect 2 "--column-tol: value F_kN: not a column of" cases_ref.csv cases_ref.csv --column-tol F_kN=1
expect 2 "--column-tol: value case: is a key column" cases_ref.csv cases_ref.csv --column-tol case=1
expect 2 "--rtol: value \"abc\": not a number" cases_ref.csv cases_ref.csv --rtol abc
expect 2 "--atol: value -0.1" cases_ref.csv cases_ref.csv --atol -0.1
expect 2 "cases_ref.csv: value pair: key column is not in the header" cases_ref.csv cases_ref.csv --key pair
expect 2 ".: is a directory, not a CSV file" . cases_ref.csv
expect 2 "pressure_ref.csv:3: value case=c1, ellipse=1: duplicate key" pressure_ref.csv pressure_out.csv
expect 2 "--key case,ellipse,x_mm,y_mm for pressure.csv" pressure_ref.csv pressure_out.csv
exit $fails
