#!/usr/bin/env bash
# `mhcontact profile generate`: the README examples, the shipped files in profiles/ (regenerated
# byte for byte, so they never drift from the generator), and must-fail cases with their exit
# codes. Usage: bash profile_generate.sh <mhcontact binary> <source dir>
set -u
BIN="$1"
SRC="$2"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
cd "$TMP" || exit 1
fail=0
check() {  # check DESCRIPTION COMMAND...: the command must succeed
  local what="$1"; shift
  if ! "$@"; then echo "FAIL: $what"; fail=1; fi
}

# --- README examples -------------------------------------------------------------------------
"$BIN" profile generate S1002 -o S1002.csv >out.txt 2>err.txt
check "S1002 exit 0" test $? -eq 0
check "S1002 message" grep -qx "wrote S1002.csv (S1002 wheel, inclination none, 1541 points)" out.txt
check "S1002 header" test "$(head -1 S1002.csv)" = "y_mm,z_mm"
check "S1002 first point (flange back)" grep -qx -- "-70,-9.519259302" S1002.csv
check "S1002 flange tip" grep -qx -- "-55,-28" S1002.csv
check "S1002 taping line" grep -qx "0,0" S1002.csv

"$BIN" profile generate 60E1 --inclination 1:40 -o 60E1_1-40.csv >out.txt 2>err.txt
check "60E1 1:40 exit 0" test $? -eq 0
check "60E1 1:40 message" grep -qx "wrote 60E1_1-40.csv (60E1 rail, inclination 1:40, 979 points)" out.txt
check "60E1 1:40 crown top stays at the origin" grep -qx "0,0" 60E1_1-40.csv

"$BIN" profile generate 60E1 --inclination 1:20 --step 0.05 -o 60E1_1-20.prr >out.txt 2>err.txt
check "60E1 1:20 .prr exit 0" test $? -eq 0
check "60E1 1:20 message" grep -qx "wrote 60E1_1-20.prr (60E1 rail, inclination 1:20, 1951 points, 115 of them on the gauge face)" out.txt
check "60E1 1:20 notes the vertical gauge flank kept as the face" grep -qx "warning: 60E1: gauge-side flank vertical at 1:20: kept as the gauge face below the R13/flank tangency point, where z(y) ends" err.txt
"$BIN" profile info 60E1_1-20.prr >info.txt 2>&1
check "60E1 1:20 .prr reads back as a rail" grep -qx "kind: rail" info.txt
check "60E1 1:20 .prr reads back with its gauge face (1836 + 115 points)" grep -qx "points: 1836" info.txt
check "60E1 1:20 .prr gauge face down to 21.79 mm below the top" grep -q "^gauge_face_mm: y -35.24078.* down to -21.787.* (115 points besides those above)$" info.txt
check "60E1 1:20 .prr reads back without warnings" bash -c '! grep -q "^warning" info.txt'

"$BIN" profile generate S1002 -o S1002.prw >out.txt 2>err.txt
check "S1002 .prw exit 0" test $? -eq 0
"$BIN" profile info S1002.prw >info.txt 2>&1
check "S1002 .prw flange tip at (-55, -28) mm" grep -qx "flange_tip_mm: y -55 z -28" info.txt

# 60E2 and 49E1 (EN 13674-1:2017) work like 60E1: crown top at the origin; the 60E2 gauge flank
# turns vertical at 1:20 (kept as the gauge face, the note names its last arc R8), 49E1's 1:17.2 does not.
"$BIN" profile generate 60E2 -o 60E2.csv >out.txt 2>err.txt
check "60E2 exit 0" test $? -eq 0
check "60E2 crown top" grep -qx "0,0" 60E2.csv
check "60E2 ends 20 mm below the crown" awk -F, 'END { exit !($2 + 20 < 1e-9 && $2 + 20 > -1e-9) }' 60E2.csv
"$BIN" profile generate 60E2 --inclination 1:20 -o 60E2_1-20.csv >out.txt 2>err.txt
check "60E2 1:20 notes the vertical gauge flank" grep -qx "warning: 60E2: gauge-side flank vertical at 1:20: kept as the gauge face below the R8/flank tangency point, where z(y) ends" err.txt
"$BIN" profile generate 49E1 --inclination 1:20 -o 49E1_1-20.csv >out.txt 2>err.txt
check "49E1 1:20 exit 0" test $? -eq 0
check "49E1 1:20 keeps its 1:17.2 flank (no warning)" test ! -s err.txt
"$BIN" profile info 49E1_1-20.csv >info.txt 2>&1
check "49E1 1:20 reads back as a rail canted 1:20" grep -q "^cant: 2.86[0-9] deg (1:20" info.txt

# --- the shipped files are exactly what the generator writes ---------------------------------
for spec in "S1002:none:S1002.csv" "60E1:none:60E1.csv" "60E1:1:40:60E1_1-40.csv" \
            "54E1:none:54E1.csv" "54E1:1:40:54E1_1-40.csv" \
            "EN15302-wheel-A:none:EN15302_wheel_A.dat" "EN15302-rail-A:none:EN15302_rail_A.dat"; do
  name="${spec%%:*}"; rest="${spec#*:}"; file="${rest##*:}"; incl="${rest%:*}"
  "$BIN" profile generate "$name" --inclination "$incl" -o "fresh_$file" >/dev/null 2>&1
  check "generate $name $incl" test $? -eq 0
  check "profiles/$file is identical to a fresh generation" cmp -s "fresh_$file" "$SRC/profiles/$file"
done

# --- must fail: exit code, message, no file -------------------------------------------------
must_fail() {  # must_fail CODE MESSAGE ARGS...
  local code="$1" msg="$2"; shift 2
  "$BIN" "$@" >out.txt 2>err.txt
  local rc=$?
  if [ "$code" = "1xx" ]; then
    [ "$rc" -ge 100 ] || { echo "FAIL: $* -> exit $rc, expected 1xx"; fail=1; }
  else
    [ "$rc" -eq "$code" ] || { echo "FAIL: $* -> exit $rc, expected $code"; fail=1; }
  fi
  grep -qF -- "$msg" err.txt || { echo "FAIL: $* -> message lacks '$msg':"; cat err.txt; fail=1; }
  if [ -e bad.csv ] || [ -e bad.prw ] || [ -e bad.txt ] || [ -e bad.xlsx ]; then echo "FAIL: $* wrote a file"; fail=1; fi
}
must_fail 2 'mhcontact: error: standard profile: value "UIC60": unknown standard profile name (valid names: S1002, 60E1, 54E1, 60E2, 49E1, EN15302-wheel-A, EN15302-rail-A)' profile generate UIC60 -o bad.csv
must_fail 2 "a wheel profile has no inclination" profile generate S1002 --inclination 1:40 -o bad.csv
must_fail 2 "this rail is defined already canted (1:20)" profile generate EN15302-rail-A --inclination 1:20 -o bad.csv
must_fail 2 "a rail cannot be written as a SIMPACK wheel (.prw)" profile generate 60E1 -o bad.prw
must_fail 2 "step must lie in 0.001 … 5 mm" profile generate 60E1 --step 10 -o bad.csv
must_fail 2 "unknown output profile format" profile generate 60E1 -o bad.xlsx
must_fail 1xx "N >= 5" profile generate 60E1 --inclination 1:3 -o bad.csv

exit $fail
