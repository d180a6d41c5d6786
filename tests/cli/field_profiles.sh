#!/usr/bin/env bash
# Field-like files of tests/data/field: placement check, MiniProf variants,
# worn-rail cant checks, a batch's warnings once. Usage: bash field_profiles.sh <mhcontact> <source-dir>
set -euo pipefail
MH=$1; SRC=$2
. "$(dirname "$0")/lib/csv_col.sh"
F=$SRC/tests/data/field
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
sweep='"sweep": {"tY_mm": {"from": -4, "to": 8, "step": 2}, "Q_kN": [20, 80]}'
rail40='{"standard": "60E1"}, "inclination": "1:40"'
run() {  # $1 name, $2 wheel json, $3 rail json (with inclination), [$4 more keys]; sets rc, writes $T/$1.err
  echo "{\"wheel\": {\"profile\": $2}, \"rail\": {\"profile\": $3}${4:+, $4}, $sweep}" > "$T/$1.json"
  set +e; "$MH" run "$T/$1.json" -o "$T/$1" 2>"$T/$1.err"; rc=$?; set -e
}

# 1. The old wheel with a loop at the flange tip: placed on its tread (before: flange tip on the
#    crown, pmax 4.9-6.4 GPa at gamma 0, every case ok).
run loop "\"$F/old_wheel_loop.whl\"" "$rail40"
[ $rc -le 1 ] || fail "loop wheel: exit $rc: $(cat "$T/loop.err")"
csv_col "$T/loop/cases.csv" tY_mm gamma_main_deg r_roll_main_mm > "$T/loop.col"
awk -F, '$1 == 0 { n++; if ($2 < 0 || $2 > 3 || $3 < 459.5 || $3 > 460.5) bad++ } END { exit !(n == 2 && !bad) }' "$T/loop.col" \
  || fail "loop wheel at t_Y = 0 not on its tread: $(grep '^0,' "$T/loop.col")"

# 2. The wheel scanned from its flange tip: refused before any case is solved, exit 2, the numbers
#    and explicit positioning named; with explicit positioning it runs.
run tip "\"$F/tip_start_wheel.whl\"" "$rail40"
[ $rc -eq 2 ] || fail "tip-start wheel: exit $rc, expected 2"
[ ! -e "$T/tip/cases.csv" ] || fail "tip-start wheel: cases written"
grep -q "value t_Y = 0: contact at rail y 11.965 mm, wheel y 15 mm .*gauge positioning misplaces the wheel: the wheel's origin y = 0, its taping line, lies outside its profile" "$T/tip.err" \
  || fail "tip-start message: $(cat "$T/tip.err")"
grep -q 'track.positioning "explicit" with track.lateral_offset_mm' "$T/tip.err" || fail "no way out named: $(cat "$T/tip.err")"
# the message ends with the explicit placement that reproduces the refused gauge placement (the
# gauge rule's offset on 60E1 at 1:40): copied, it runs, the user's placement, unchecked
placed=$(grep -o '"track": {"positioning": "explicit", "lateral_offset_mm": [-0-9.e]*}' "$T/tip.err")
[ "$placed" = '"track": {"positioning": "explicit", "lateral_offset_mm": -3.034716}' ] || fail "no explicit placement to copy: $(cat "$T/tip.err")"
run tipg "\"$F/tip_start_wheel.whl\"" "$rail40" "$placed"
[ $rc -le 1 ] || fail "tip-start wheel, the printed placement: exit $rc: $(cat "$T/tipg.err")"
# the placement that is meant: the wheel's origin (its flange back) 70 mm further in
run tipx "\"$F/tip_start_wheel.whl\"" "$rail40" '"track": {"positioning": "explicit", "lateral_offset_mm": -73.4}'
[ $rc -le 1 ] || fail "tip-start wheel, explicit: exit $rc: $(cat "$T/tipx.err")"

# 3. A batch: the refused pairs are invalid_pair with the message, the others run; a profile's
#    warnings are printed once, not once per pair (two rails here).
"$MH" profile generate 60E1 --inclination 1:40 -o "$T/r40.csv" >/dev/null
"$MH" profile generate 60E1 --inclination 1:40 --step 0.2 -o "$T/r40b.csv" >/dev/null
cat > "$T/fleet.json" <<JSON
{"wheels": ["$F/old_wheel_loop.whl", "$F/tip_start_wheel.whl"], "rails": ["$T/r40.csv", "$T/r40b.csv"],
 "inclination": "as-is", $sweep}
JSON
set +e; "$MH" run "$T/fleet.json" -o "$T/fleet" 2>"$T/fleet.err"; rc=$?; set -e
[ $rc -eq 1 ] || fail "batch: exit $rc: $(cat "$T/fleet.err")"
[ "$(csv_col "$T/fleet/pairs.csv" status | sort | uniq -c | awk '{printf "%s %s;", $2, $1}')" = "invalid_pair 2;ok 2;" ] \
  || fail "batch pair statuses: $(cat "$T/fleet/pairs.csv")"
grep -q "invalid_pair,.*taping line, lies outside its profile" "$T/fleet/pairs.csv" || fail "batch: no message in pairs.csv"
[ "$(grep -c "old_wheel_loop.whl: clean-up extended over 260 points of the flange back" "$T/fleet.err")" -eq 1 ] \
  || fail "batch: the wheel's warning not printed exactly once: $(cat "$T/fleet.err")"

# 4. A multi-profile .mpt: refused without a section (the list of profiles), read with one.
run mpt "{\"standard\": \"S1002\"}" "{\"file\": \"$F/multi_profile.mpt\"}, \"inclination\": \"as-is\""
[ $rc -eq 2 ] || fail "mpt without section: exit $rc"
grep -q "1 'Base line' 150 mm wide.*2 'Head measured' 72.55 mm wide, 979 points" "$T/mpt.err" || fail "mpt list: $(cat "$T/mpt.err")"
run mpt2 "{\"standard\": \"S1002\"}" "{\"file\": \"$F/multi_profile.mpt\", \"section\": 2}, \"inclination\": \"as-is\""
[ $rc -le 1 ] || fail "mpt section 2: exit $rc: $(cat "$T/mpt2.err")"
# The resolved inputs name the section (shards reading different sections must not merge).
grep -q '"section": *2' "$T/mpt2/results.json" || fail "results.json: the section is not in the resolved inputs"
run mpt0 "{\"standard\": \"S1002\"}" "{\"file\": \"$F/multi_profile.mpt\", \"section\": 0}, \"inclination\": \"as-is\""
[ $rc -eq 2 ] && grep -q "/rail/profile/section" "$T/mpt0.err" || fail "section 0: exit $rc $(cat "$T/mpt0.err")"
# A standard's name given as a file name: exit 2, the object that generates it named.
run bare "{\"standard\": \"S1002\"}" '"60E1", "inclination": "1:40"'
[ $rc -eq 2 ] && grep -qF '/rail/profile: value "60E1": no such profile file' "$T/bare.err" \
  && grep -qF 'write {"standard": "60E1"}' "$T/bare.err" || fail "bare standard name: exit $rc $(cat "$T/bare.err")"
run bare_lc "{\"standard\": \"S1002\"}" '"60e1", "inclination": "1:40"'
[ $rc -eq 2 ] && grep -qF '/rail/profile: value "60e1": no such profile file' "$T/bare_lc.err" \
  && grep -qF 'write {"standard": "60E1"}' "$T/bare_lc.err" || fail "bare standard name as typed: exit $rc $(cat "$T/bare_lc.err")"
"$MH" profile info --section 2 "$F/multi_profile.mpt" > "$T/info2" || fail "profile info --section 2"
grep -q "^points: 979$" "$T/info2" && grep -q "read profile 2 'Head measured' (section 2 as asked" "$T/info2" || fail "info --section 2: $(cat "$T/info2")"
set +e; "$MH" profile info "$F/multi_profile.mpt" >/dev/null 2>"$T/info.err"; rc=$?; set -e
[ $rc -eq 2 ] && grep -q -- "--section K" "$T/info.err" || fail "profile info without --section: exit $rc"
set +e; "$MH" profile info --section 2 "$F/worn_rail_1-40.csv" >/dev/null 2>"$T/info.err"; rc=$?; set -e
[ $rc -eq 2 ] && grep -q "only to multi-profile MiniProf files" "$T/info.err" || fail "--section on a table: exit $rc"

# 5. MiniProf rail with stray MPDC=/MPDN= keys; a wheel header's measures.
"$MH" profile info "$F/kv_rail_stray_mpd.ban" | grep -q "^points: 979$" || fail "stray MPD keys"
"$MH" profile info "$F/kv_wheel_measures.whl" | grep -q "^file_measures: Sd=32.50 Sh=28.00 qR=10.80$" || fail "KV wheel measures"

# 6. A worn rail laid at 1:40 (estimate not confident): canted again it warns; as is it does not.
run worn_asis "{\"standard\": \"S1002\"}" "\"$F/worn_rail_1-40.csv\", \"inclination\": \"as-is\""
[ $rc -le 1 ] || fail "worn as-is: exit $rc"
! grep -q "cant:" "$T/worn_asis.err" || fail "worn as-is warns: $(grep cant "$T/worn_asis.err")"
run worn40 "{\"standard\": \"S1002\"}" "\"$F/worn_rail_1-40.csv\", \"inclination\": \"1:40\""
grep -q "cant: the rail file looks canted already (2.98 deg.*estimate not confident" "$T/worn40.err" || fail "worn 1:40: $(cat "$T/worn40.err")"
grep -q "more than the usual 1:20" "$T/worn40.err" || fail "worn 1:40, 4.4 deg: $(cat "$T/worn40.err")"

# 7. A wheel without a flange: a warning with the gauge rule, none when placed explicitly.
run flat "\"$F/flat_wheel.txt\"" "$rail40"
grep -q "flat_wheel.txt: the wheel has no flange" "$T/flat.err" || fail "flat wheel: no warning: $(cat "$T/flat.err")"
run flatx "\"$F/flat_wheel.txt\"" "$rail40" '"track": {"positioning": "explicit", "lateral_offset_mm": -3.4}'
! grep -q "has no flange" "$T/flatx.err" || fail "flat wheel, explicit: warned"
echo PASS
