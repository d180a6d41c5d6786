#!/usr/bin/env bash
# profile convert: SIMPACK -> CSV -> SIMPACK round trip, MiniProf -> CSV, and a bad input (exit 2,
# nothing written). Usage: bash profile_convert.sh <mhcontact> <source-dir>
set -u
MH="$1"; SRC="$2"; D="$SRC/tests/data/profiles"
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# README example: mhcontact profile convert MBench_S1002_v3.prw -o s1002.csv
"$MH" profile convert "$D/MBench_S1002_v3.prw" -o "$T/s1002.csv" >"$T/out" 2>"$T/err" || fail "convert prw->csv exit $?"
grep -q "wrote $T/s1002.csv (wheel, 399 points)" "$T/out" || fail "convert message: $(cat "$T/out")"
[ "$(head -1 "$T/s1002.csv")" = "y_mm,z_mm" ] || fail "csv header"
[ "$(wc -l <"$T/s1002.csv")" -eq 400 ] || fail "csv rows"
# first canonical point: flange back, y = -69.612628 mm, z = -13.485642 mm (file row, y and z mirrored)
[ "$(sed -n 2p "$T/s1002.csv")" = "-69.612628,-13.485642" ] || fail "first row: $(sed -n 2p "$T/s1002.csv")"

# csv -> prw -> csv gives the same points (to 1e-9 mm)
"$MH" profile convert "$T/s1002.csv" --kind wheel -o "$T/s1002.prw" >/dev/null 2>&1 || fail "csv->prw"
grep -q "written by mhcontact from $T/s1002.csv" "$T/s1002.prw" || fail "prw provenance comment"
"$MH" profile convert "$T/s1002.prw" -o "$T/again.csv" >/dev/null 2>&1 || fail "prw->csv"
paste -d, "$T/s1002.csv" "$T/again.csv" | awk -F, 'NR>1 {d=$1-$3; if (d<0) d=-d; e=$2-$4; if (e<0) e=-e;
  if (d>1e-9 || e>1e-9) bad=1} END {exit bad}' || fail "round trip changed the points"

# README example: MiniProf rail, same rail as the .prr
"$MH" profile convert "$D/MBench_UIC60_v3.ban" -o "$T/uic_ban.csv" >/dev/null 2>&1 || fail "ban->csv"
"$MH" profile convert "$D/MBench_UIC60_v3.prr" -o "$T/uic_prr.csv" >/dev/null 2>&1 || fail "prr->csv"
[ "$(wc -l <"$T/uic_ban.csv")" -eq 496 ] || fail "ban rows"

# README example: a table in metres needs --scale 1000
awk -F, 'NR>1 {printf "%.9f %.9f\n", $1/1000, $2/1000}' "$T/s1002.csv" >"$T/metres.txt"
"$MH" profile convert "$T/metres.txt" -o "$T/m.csv" >/dev/null 2>"$T/err"; rc=$?
[ $rc -eq 2 ] || fail "metres: exit $rc, expected 2"
grep -q "looks like metres; use scale 1000" "$T/err" || fail "metres message: $(cat "$T/err")"
[ ! -e "$T/m.csv" ] || fail "output written despite the error"
"$MH" profile convert "$T/metres.txt" --scale 1000 --kind wheel -o "$T/m.csv" >/dev/null 2>&1 || fail "--scale 1000"

# wrong side: exit 2 with the fix
"$MH" profile convert "$D/MBench_S1002_v3.prw" --mirror-y -o "$T/bad.csv" >/dev/null 2>"$T/err"; rc=$?
[ $rc -eq 2 ] || fail "mirror-y: exit $rc"
grep -q "use mirror_y" "$T/err" || fail "mirror-y message"
# unknown output extension
"$MH" profile convert "$D/MBench_S1002_v3.prw" -o "$T/x.xlsx" >/dev/null 2>"$T/err"; rc=$?
[ $rc -eq 2 ] || fail "xlsx: exit $rc"
[ ! -e "$T/x.xlsx" ] || fail "xlsx written"

# A wheel is not written into a rail file (exit 2, the right extension named, nothing
# written); every reading format is also written and reads back with the same points
"$MH" profile convert "$D/MBench_S1002_v3.prw" -o "$T/out.prr" >"$T/out" 2>"$T/err"; rc=$?
[ $rc -eq 2 ] || fail "wheel as .prr: exit $rc"
grep -q "use .prw" "$T/err" || fail "wheel as .prr message: $(cat "$T/err")"
[ ! -e "$T/out.prr" ] || fail "wheel written as .prr"
for e in whl wheel whe txt; do
  "$MH" profile convert "$D/MBench_S1002_v3.prw" -o "$T/rt.$e" >/dev/null 2>&1 || fail "prw -> $e"
  "$MH" profile convert "$T/rt.$e" --kind wheel -o "$T/rt_$e.csv" >/dev/null 2>&1 || fail "$e -> csv"
  cmp -s "$T/s1002.csv" "$T/rt_$e.csv" || fail "round trip through .$e changed the points"
done
for e in ban rail rai prr; do
  "$MH" profile convert "$D/MBench_UIC60_v3.prr" -o "$T/rt.$e" >/dev/null 2>&1 || fail "prr -> $e"
  "$MH" profile convert "$T/rt.$e" --kind rail -o "$T/rt_$e.csv" >/dev/null 2>&1 || fail "$e -> csv"
  cmp -s "$T/uic_prr.csv" "$T/rt_$e.csv" || fail "round trip through .$e changed the points"
done
# the cleaned profile is what convert writes (avg_low2.ban: the hidden gauge face clipped)
"$MH" profile convert "$D/avg_low2.ban" -o "$T/low2.csv" >"$T/out" 2>"$T/err" || fail "avg_low2 convert"
grep -q "wrote $T/low2.csv (rail, 334 points)" "$T/out" || fail "avg_low2 message: $(cat "$T/out")"
grep -q "gauge face turns under" "$T/err" || fail "avg_low2 warning on stderr"
echo PASS
