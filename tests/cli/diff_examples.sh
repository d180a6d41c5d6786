#!/usr/bin/env bash
# The README examples of `mhcontact diff` (section "Comparing result tables"), run on the
# hand-written tables in tests/data/diff: exit codes and the key words of the report.
# Usage: bash diff_examples.sh <mhcontact-binary> <source-dir>
set -uo pipefail
bin="$1"
cd "$2/tests/data/diff" || exit 1
fails=0
expect() {  # expected-code "substring|substring|..." args...
  local code="$1" words="$2"; shift 2
  local out rc w
  out="$("$bin" diff "$@" 2>&1)"; rc=$?
  [ "$rc" = "$code" ] || { echo "FAIL (exit $rc, wanted $code): diff $*"; echo "$out"; fails=1; }
  IFS='|' read -ra ws <<< "$words"
  for w in "${ws[@]}"; do
    case "$out" in *"$w"*) ;; *) echo "FAIL (output lacks '$w'): diff $*"; echo "$out"; fails=1 ;; esac
  done
}

# Same cases, rows and columns in another order, CRLF line ends: within tolerance.
expect 0 "key: case|rows compared: 4, missing in OUT: 0, extra in OUT: 0|diff: OK" \
  cases_ref.csv cases_reordered.csv

# A changed status, a NaN that became a number, drifting dz_mm and Fz_kN, c4 gone, c5 new.
expect 1 "rows missing in OUT (1): case=c4|rows extra in OUT (1): case=c5|column status: 1 of 3 cells out of tolerance|text differs in 1 cell(s); first at case=c2: ref \"ok\", out \"max_iterations\"|column dz_mm: 2 of 3 cells out of tolerance|worst rel deviation 5.05e-09 at case=c1|nan/inf against a different value in 1 cell(s); first at case=c3: ref nan, out 0.07|column Fz_kN: 1 of 3 cells out of tolerance|worst abs deviation 0.002 at case=c1: ref 100, out 100.002|diff: 4 cells out of tolerance, 1 missing rows, 1 extra rows" \
  cases_ref.csv cases_changed.csv

# Only the final line.
out="$("$bin" diff cases_ref.csv cases_changed.csv --quiet)"; rc=$?
[ "$rc" = 1 ] && [ "$out" = "diff: 4 cells out of tolerance, 1 missing rows, 1 extra rows" ] ||
  { echo "FAIL --quiet: exit $rc, output '$out'"; fails=1; }

# Per-column absolute tolerances (in the column's unit) for the numeric drift.
expect 1 "per column |out - ref| <= Fz_kN 0.01|column Fz_kN: 0 of 3 cells out of tolerance (|out - ref| <= 0.01)|diff: 2 cells out of tolerance, 1 missing rows, 1 extra rows" \
  cases_ref.csv cases_changed.csv --column-tol Fz_kN=0.01 --column-tol dz_mm=1e-9

# ellipses.csv: key case,ellipse; p0_MPa differs by 0.4 MPa (2.4e-4 relative).
expect 1 "key: case, ellipse|worst abs deviation 0.4 at case=c2, ellipse=2: ref 1650, out 1650.4|diff: 1 cells out of tolerance" \
  ellipses_ref.csv ellipses_out.csv
expect 0 "diff: OK" ellipses_ref.csv ellipses_out.csv --column-tol p0_MPa=0.5
expect 0 "diff: OK" ellipses_ref.csv ellipses_out.csv --rtol 3e-4
expect 1 "diff: 1 cells out of tolerance" ellipses_ref.csv ellipses_out.csv --rtol 1e-4
expect 0 "diff: OK" ellipses_ref.csv ellipses_out.csv --atol 0.5

# caf.csv: give the key; numeric keys are exact text ("5" and "5.0" are different rows).
expect 1 "key: tY_mm|rows missing in OUT (1): tY_mm=5|rows extra in OUT (1): tY_mm=5.0" \
  caf_ref.csv caf_out.csv --key tY_mm
expect 0 "diff: OK" caf_ref.csv caf_ref.csv --key tY_mm,ellipse
# Without a case column, the default key is tY_mm,ellipse (geometry.csv, caf.csv).
expect 1 "key: tY_mm, ellipse|rows missing in OUT (1): tY_mm=5, ellipse=2|rows extra in OUT (1): tY_mm=5.0, ellipse=2" \
  caf_ref.csv caf_out.csv

# pressure.csv: one row per grid point, key case,ellipse,x_mm,y_mm; p_MPa off by 1e-5 MPa (8.7e-9 relative), tolerance 1e-4 MPa.
expect 1 "worst abs deviation 1e-05 at case=c1, ellipse=1, x_mm=1, y_mm=0|diff: 1 cells out of tolerance, 0 missing rows, 0 extra rows" \
  pressure_ref.csv pressure_out.csv --key case,ellipse,x_mm,y_mm
expect 0 "diff: OK" pressure_ref.csv pressure_out.csv --key case,ellipse,x_mm,y_mm --column-tol p_MPa=1e-4

# Machine-readable report.
expect 1 "\"schema\": \"mhcontact.diff\"|\"ok\": false|\"missing_rows\": [|\"case=c4\"" \
  cases_ref.csv cases_changed.csv --json
exit $fails
