#!/usr/bin/env bash
# profile info: text and JSON output on the Manchester wheel and rail, a MiniProf wheel, and
# rejected inputs (exit 2). Usage: bash profile_info.sh <mhcontact> <source-dir>
set -u
MH="$1"; SRC="$2"; D="$SRC/tests/data/profiles"
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# README example: mhcontact profile info MBench_S1002_v3.prw
"$MH" profile info "$D/MBench_S1002_v3.prw" >"$T/out" 2>&1 || fail "info wheel exit $?"
for l in "format: simpack" "kind: wheel" "points: 399" "y_range_mm: -69.612628 60" \
         "flange_tip_mm: y -54.892493 z -27.999518"; do
  grep -qx "$l" "$T/out" || fail "missing '$l' in: $(cat "$T/out")"
done
grep -q "^sha256: $(sha256sum "$D/MBench_S1002_v3.prw" | cut -c1-64)\$" "$T/out" || fail "sha256"

# README example: the shipped copies in profiles/ read the same
"$MH" profile info "$SRC/profiles/MBench_S1002_v3.prw" | grep -qx "flange_tip_mm: y -54.892493 z -27.999518" || fail "profiles/ wheel"
"$MH" profile info "$SRC/profiles/MBench_UIC60_v3.prr" | grep -qx "head_top_mm: y -0.18441236 z -6.0323487e-05" || fail "profiles/ rail"

# README example: mhcontact profile info MBench_UIC60_v3.prr --json
"$MH" profile info "$D/MBench_UIC60_v3.prr" --json >"$T/j" 2>&1 || fail "info rail json exit $?"
/usr/bin/python3 - "$T/j" <<'PY' || fail "json content: $(cat "$T/j")"
import json, sys
j = json.load(open(sys.argv[1]))
assert j["kind"] == "rail" and j["format"] == "simpack" and j["points"] == 495, j
assert abs(j["head_top_z_mm"]) < 1e-4                        # origin at the highest point
assert abs(j["gauge_point_z_mm"] - (j["head_top_z_mm"] - 14)) < 1e-9
assert -44 < j["gauge_point_y_mm"] < -42                     # gauge face at negative y
assert abs(j["y_min_mm"] + 43.704898) < 1e-9 and abs(j["y_max_mm"] - 30.595912) < 1e-9
assert j["warnings"] == []
PY

# MiniProf wheel measured from the flange back: taping-line rule and clipping warnings
"$MH" profile info "$D/avg_wheel.whl" >"$T/out" 2>&1 || fail "whl exit $?"
grep -q "^y_range_mm: -70 " "$T/out" || fail "whl range: $(cat "$T/out")"
grep -q "warning: y = 0 moved to the taping line, 70 mm from the flange back at file y = 1.55 mm" "$T/out" || fail "taping warning"
grep -q "^taping_line: file y = 71.55 mm, 70 mm from the flange back, the innermost point at file y = 1.55 mm: the file is measured from the flange back" "$T/out" || fail "taping_line: $(grep taping "$T/out")"
"$MH" profile info "$D/MBench_S1002_v3.prw" | grep -qx "taping_line: y = 0 as in the file" || fail "taping_line of a wheel at its taping line"

# README example: --kind and --mirror-z on a table
awk -F'[ \t]+' 'NF>=2 {print $1, -$2}' "$D/EN15302_rail_A.dat" >"$T/zdown.txt"
"$MH" profile info "$T/zdown.txt" --kind rail >"$T/out" 2>&1; rc=$?
[ $rc -eq 2 ] || fail "upside-down rail: exit $rc"
grep -q "use mirror_z" "$T/out" || fail "upside-down message: $(cat "$T/out")"
"$MH" profile info "$T/zdown.txt" --kind rail --mirror-z >"$T/out" 2>&1 || fail "--mirror-z exit $?"
grep -qx "kind: rail" "$T/out" || fail "--mirror-z kind"

# measured rail with 0.01 mm of jitter on the tread: read, the point dropped with a warning
"$MH" profile info "$D/avg_HR.BAN" >"$T/out" 2>&1; rc=$?
[ $rc -eq 0 ] || fail "avg_HR exit $rc"
grep -q "warning: dropped 1 points that stepped back in y by at most 0.01 mm" "$T/out" || fail "avg_HR warning"
# measured rail whose gauge face turns under the head (a 0.06 mm backward step at line 537):
# cleaned by default, the report in the output; rejected with --cleanup strict
"$MH" profile info "$D/avg_low2.ban" >"$T/out" 2>&1; rc=$?
[ $rc -eq 0 ] || fail "avg_low2 exit $rc"
grep -q "^cleanup: envelope" "$T/out" || fail "avg_low2 cleanup line"
grep -q "gauge face turns under the head" "$T/out" || fail "avg_low2 warning"
"$MH" profile info "$D/avg_low2.ban" --cleanup strict >"$T/out" 2>&1; rc=$?
[ $rc -eq 2 ] || fail "avg_low2 strict exit $rc"
grep -q "avg_low2.ban:537" "$T/out" || fail "avg_low2 line"
# the clean-up of folds and loops, in text and JSON
"$MH" profile info "$SRC/tests/data/profiles/constructed/folded_rail.txt" --kind rail --json >"$T/out" 2>&1 || fail "folded json"
grep -q '"folds_removed": 2' "$T/out" || fail "folded json report: $(cat "$T/out")"
# MiniProf old style: the wheel measures of the file
"$MH" profile info "$SRC/tests/data/profiles/constructed/old_style_wheel.whl" >"$T/out" 2>&1 || fail "old style"
grep -q "file_measures: .*Sd=32.50 Sh=28.00 qR=10.80" "$T/out" || fail "old style measures"
# bad option values are CLI11 errors (not 0)
"$MH" profile info "$D/avg_HR.BAN" --kind tram >/dev/null 2>&1; rc=$?
[ $rc -ne 0 ] || fail "--kind tram accepted"
echo PASS
