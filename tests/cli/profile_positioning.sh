#!/usr/bin/env bash
# Explicit positioning and roller rigs. Usage: bash profile_positioning.sh <mhcontact> <source-dir>
#  1. explicit positioning at the offset that gauge positioning computes gives the same results;
#  2. a rail scanned only over its head has no gauge point: the error names explicit positioning,
#     and with it the pair runs;
#  3. the roller-rig example runs, and the roller's curvature (A grows) raises the approach dz at
#     every case against the same pair on a straight rail;
#  4. a thick flange (Sd 36.4 mm), placed by the gauge rule, whose contact at t_Y = 0 is on its
#     flange root (17 deg), runs: placement is judged from the placement, not from that contact.
set -euo pipefail
MH=$1; SRC=$2
. "$(dirname "$0")/lib/csv_col.sh"
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
sweep='"sweep": {"tY_mm": {"from": -4, "to": 8, "step": 0.5}, "Q_kN": [10, 80]}'
pair='"wheel": {"profile": {"standard": "S1002"}}, "rail": {"profile": {"standard": "60E1"}, "inclination": "1:40"}'
echo "{$pair, $sweep}" > "$T/gauge.json"
"$MH" run "$T/gauge.json" -o "$T/gauge" -q || fail "gauge run"
off=$(grep -ho "\"y_offset_mm\": [-0-9.e]*" "$T/gauge/results.json" 2>/dev/null | head -1 | awk "{print \$2}" || true)
if [ -z "$off" ]; then
  "$MH" geometry "$T/gauge.json" -o "$T/geo" -q >/dev/null 2>&1 || fail "geometry"
  off=$(grep -o '"y_offset_mm": [-0-9.e]*' "$T/geo/geometry.json" | awk '{print $2}')
fi
[ -n "$off" ] || fail "no y_offset_mm"
echo "{$pair, \"track\": {\"positioning\": \"explicit\", \"lateral_offset_mm\": $off}, $sweep}" > "$T/explicit.json"
"$MH" run "$T/explicit.json" -o "$T/explicit" -q || fail "explicit run"
cmp -s "$T/gauge/cases.csv" "$T/explicit/cases.csv" || fail "explicit at the gauge offset ($off mm) differs from gauge positioning"

# 2. the 60E1 head only, down to 8 mm below the top: no gauge point 14 mm below
"$MH" profile generate 60E1 --inclination 1:40 -o "$T/r.csv" >/dev/null
awk -F, 'NR == 1 || $2 > -8' "$T/r.csv" > "$T/head.csv"
echo "{\"wheel\": {\"profile\": {\"standard\": \"S1002\"}}, \"rail\": {\"profile\": {\"file\": \"$T/head.csv\"}, \"inclination\": \"as-is\"}, $sweep}" > "$T/head.json"
set +e; "$MH" run "$T/head.json" -o "$T/head" -q 2>"$T/err"; rc=$?; set -e
[ $rc -eq 2 ] || fail "head only: exit $rc, expected 2"
grep -q 'no gauge point found 14 mm below' "$T/err" || fail "head only message: $(cat "$T/err")"
grep -q 'track.positioning \\"explicit\\"\|track.positioning "explicit"' "$T/err" || fail "head only: no hint at explicit positioning: $(cat "$T/err")"
sed 's/"inclination": "as-is"}/"inclination": "as-is"}, "track": {"positioning": "explicit", "lateral_offset_mm": 0}/' "$T/head.json" > "$T/head2.json"
"$MH" run "$T/head2.json" -o "$T/head2" -q || fail "head only, explicit"
# a lateral offset without explicit positioning is an error
echo "{$pair, \"track\": {\"lateral_offset_mm\": 1}, $sweep}" > "$T/bad.json"
set +e; "$MH" run "$T/bad.json" -o "$T/bad" -q 2>"$T/err"; rc=$?; set -e
[ $rc -eq 2 ] && grep -q "only used with positioning" "$T/err" || fail "lateral offset without explicit: $rc $(cat "$T/err")"

# 3. roller rig example
"$MH" run "$SRC/cases/roller-rig.json" -o "$T/roller" -q || fail "roller-rig example"
grep -q '"roller_radius_mm": 700' "$T/roller/results.json" || fail "roller radius not in the resolved inputs"
sed 's/, "roller_radius_mm": 700//' "$SRC/cases/roller-rig.json" > "$T/straight.json"
"$MH" run "$T/straight.json" -o "$T/straight" -q || fail "straight"
# columns by name (tests/cli/lib/csv_col.sh): compared by position, added columns made this
# compare the method with the plastic flag, as strings, and it could no longer fail
csv_col "$T/roller/cases.csv" case status dz_virtual_mm > "$T/roller.col"
csv_col "$T/straight/cases.csv" case status dz_virtual_mm > "$T/straight.col"
paste -d, "$T/roller.col" "$T/straight.col" |
  awk -F, '$1 != $4 {bad++} $2 == "ok" && $5 == "ok" {n++; if (!($3 + 0 > $6 + 0)) bad++} END {exit (n < 10 || bad)}' \
  || fail "the roller's curvature did not raise dz at every case: $(paste -d, "$T/roller.col" "$T/straight.col" | head -5)"
# 4. the thick flange (tests/data/profiles/constructed/make.sh): runs, its t_Y = 0 row on the root
echo "{\"wheel\": {\"profile\": \"$SRC/tests/data/profiles/constructed/thick_flange_wheel.csv\"}, \"rail\": {\"profile\": {\"standard\": \"60E1\"}, \"inclination\": \"1:40\"}, $sweep}" > "$T/thick.json"
set +e; "$MH" run "$T/thick.json" -o "$T/thick" -q 2>"$T/err"; rc=$?; set -e
[ $rc -le 1 ] || fail "thick flange: exit $rc: $(cat "$T/err")"
csv_col "$T/thick/cases.csv" tY_mm gamma_main_deg > "$T/thick.col"
awk -F, '$1 == 0 { n++; if ($2 < 15) bad++ } END { exit !(n == 2 && !bad) }' "$T/thick.col" \
  || fail "thick flange at t_Y = 0 not on its flange root: $(grep '^0,' "$T/thick.col")"
echo PASS
