#!/usr/bin/env bash
# `mhcontact wheelset`: the worked example (EN 15302 wheel A on rail A) against the standard's
# tables, solved roll, a fleet with a refused wheel, must-fail inputs, and the plots (headless,
# when matplotlib is present). Usage: bash wheelset.sh <mhcontact binary> <source dir>
set -u
BIN="$1"; SRC="$2"
TMP="$(mktemp -d)"; trap 'rm -rf "$TMP"' EXIT
cd "$TMP" || exit 1
fail=0
check() { local what="$1"; shift; if ! "$@"; then echo "FAIL: $what"; fail=1; fi; }

# --- the worked example ----------------------------------------------------------------------
"$BIN" wheelset "$SRC/cases/en15302-wheel-a.json" -o out >stdout.txt 2>stderr.txt
# Exit 1: the standard's amplitudes beyond the pair's flangeway clearance (4.89 mm per side) are
# flange_contact (docs/wheelset.md "Where the conicity is ok"), their tan gamma_e still written.
check "worked example exit 1 (amplitudes beyond the clearance)" test $? -eq 1
check "amplitudes up to 4.8 mm ok, from 5 mm flange_contact" awk -F, '
  FNR > 1 { want = ($1 <= 4.8001) ? "ok" : "flange_contact"; if ($7 != want) { print "A", $1, $7; bad = 1 } }
  END { exit bad }' out/conicity.csv
check "summary.json clearance" grep -q '"flangeway_clearance_mm"' out/summary.json
check "headline tan gamma_e at 3 mm" grep -qx "tan_gamma_e at 3 mm: 0.1882" stdout.txt
check "wheelset.csv header" test "$(head -1 out/wheelset.csv | cut -d, -f1-7)" = "y_mm,delta_r_mm,r_left_mm,r_right_mm,gamma_left_deg,gamma_right_deg,delta_tan_gamma"
check "wheelset.csv rows" test "$(wc -l < out/wheelset.csv)" -eq 1602
check "conicity.csv header" test "$(head -1 out/conicity.csv | cut -d, -f1-2)" = "amplitude_mm,tan_gamma_e"
check "summary.json tan_gamma_e_3mm" grep -q '"tan_gamma_e_3mm": 0.188' out/summary.json
# Against the EN 15302 tables (tests/data/en15302): delta_r within 0.005 mm where the table's
# slope is below 1, tan gamma_e within 0.005 (the unit test holds the full rule).
check "delta_r against the table" awk -F, '
  NR == FNR { if (FNR > 1) ref[sprintf("%.2f", $1)] = $2; next }
  FNR > 1 && (sprintf("%.2f", $1) in ref) { d = $2 - ref[sprintf("%.2f", $1)]; if (d < 0) d = -d; if ($1 > -6.15 && $1 < 6.15 && d > 0.005) { print "y", $1, d; bad = 1 } }
  END { exit bad }' "$SRC/tests/data/en15302/wheelA_railA_delta_r.csv" out/wheelset.csv
check "tan gamma_e against the table" awk -F, '
  NR == FNR { if (FNR > 1) ref[$1 + 0] = $2; next }
  FNR > 1 { d = $2 - ref[$1 + 0]; if (d < 0) d = -d; if (d > 0.005) { print "A", $1, d; bad = 1 } }
  END { exit bad }' "$SRC/tests/data/en15302/wheelA_railA_conicity.csv" out/conicity.csv
# Same bytes whatever the thread count.
"$BIN" wheelset "$SRC/cases/en15302-wheel-a.json" -o out1 --threads 1 -q >/dev/null
check "same bytes with 1 thread" cmp -s out/wheelset.csv out1/wheelset.csv

# --- solved roll, asymmetric radii (920/918 mm), rails by gauge ------------------------------
# (the radii move the equilibrium to y = 2.96 mm: ŷ 3 mm would reach 5.52 mm, beyond the 4.89 mm
# clearance, flange_contact; 1 and 2 mm stay inside it)
sed -e 's|"../profiles/|"'"$SRC"'/profiles/|g' -e 's|"roll": "none"|"roll": "solved"|' \
    -e 's|"nominal_radius_mm": 460|"nominal_radius_mm": {"left": 460, "right": 459}|' \
    -e 's|"placement": "absolute", "origin_mm": 750|"placement": "gauge", "gauge_mm": 1435.164, "gauge_height_mm": 14|' \
    -e 's|"step": 0.01}|"step": 0.1}|' -e 's|"amplitudes_mm": {[^}]*}|"amplitudes_mm": [1, 2]|' \
    "$SRC/cases/en15302-wheel-a.json" > solved.json
"$BIN" wheelset solved.json -o solved -q >/dev/null
check "solved roll exit 0" test $? -eq 0
check "solved roll has roll_deg" grep -q "delta_tan_gamma,roll_deg," solved/wheelset.csv
check "solved roll: 1 and 2 mm ok" awk -F, 'FNR > 1 && $7 != "ok" { bad = 1 } END { exit bad }' solved/conicity.csv
check "asymmetric: delta_r(0) < 0, roll(0) < 0" awk -F, '$1 == "0" { exit !($2 < -0.5 && $8 < 0) }' solved/wheelset.csv

# --- a fleet with a wheel that cannot be placed ----------------------------------------------
# Profiles named relative to the manifest: fleet.csv names them as given (never resolved: the
# output does not depend on where the repository lives). Each measure's source is in its column's
# name: Sd/Sh/qR_en15313_mm computed from the profile, Sd/Sh/qR_file_mm as a file's header states
# them (the MiniProf wheel; a header edited to Sd 36.4 mm, thick.whl, stays beside the profile's
# 32.5 mm and is not checked: a header's reference heights are its own). A wheel without a flange
# (field/flat_wheel.txt) is profile_incomplete; the constructed thick flange (Sd 36.4 mm from its
# profile) is flagged outside EN 15313 (measures_check), its conicity kept. The amplitude list
# repeats the headline 3 mm: one tan_gamma_e_3mm column.
ln -s "$SRC/profiles" profiles; ln -s "$SRC/tests/data/field" field; ln -s "$SRC/tests/data/profiles/constructed" constructed
sed 's/^Sd=32.50/Sd=36.40/' field/kv_wheel_measures.whl > thick.whl
cat > fleet.json <<EOF2
{"wheels": ["profiles/EN15302_wheel_A.dat", "field/kv_wheel_measures.whl", "profiles/60E1.csv", "field/flat_wheel.txt", "thick.whl", "constructed/thick_flange_wheel.csv"],
 "rail": {"profile": "profiles/EN15302_rail_A.dat", "inclination": "as-is", "placement": "absolute", "origin_mm": 750},
 "y_mm": {"from": -8, "to": 8, "step": 0.02}, "amplitudes_mm": [2, 3, 4]}
EOF2
"$BIN" wheelset fleet.json -o fleet >stdout.txt 2>stderr.txt
check "fleet with a refused wheel exits 1" test $? -eq 1
check "fleet header" test "$(head -1 fleet/fleet.csv)" = "wheel,source,status,tan_gamma_e_3mm,tan_gamma_e_2mm,tan_gamma_e_4mm,Sd_en15313_mm,Sh_en15313_mm,qR_en15313_mm,Sd_file_mm,Sh_file_mm,qR_file_mm,measures_check,message"
check "fleet wheel A row: computed measures, none from a header" awk -F, '$1 == "0" { exit !($2 == "profiles/EN15302_wheel_A.dat" && $3 == "ok" && $4 > 0.187 && $4 < 0.189 && $7 > 32 && $10 == "" && $11 == "" && $13 == "ok") }' fleet/fleet.csv
check "the MiniProf file: header measures beside the computed ones" awk -F, '$1 == "1" { exit !($2 == "field/kv_wheel_measures.whl" && $10 == 32.5 && $11 == 28 && $12 == 10.8 && $7 > 32 && $7 < 33 && $13 == "ok") }' fleet/fleet.csv
check "a wheel without a flange is profile_incomplete" awk -F, '$1 == "3" { exit !($2 == "field/flat_wheel.txt" && $3 == "profile_incomplete" && $7 == "" && $13 == "unknown") }' fleet/fleet.csv
check "a header's Sd 36.4 mm is written, not checked" awk -F, '$1 == "4" { exit !($3 == "ok" && $10 == 36.4 && $7 < 33 && $13 == "ok") }' fleet/fleet.csv
check "the profile's Sd 36.4 mm flagged outside EN 15313" awk -F, '$1 == "5" { exit !($7 > 36.3 && $7 < 36.5 && $10 == "" && $13 == "outside_en15313") }' fleet/fleet.csv
check "the flag names the limit" grep -q "Sd 36.4 mm > 33 mm (EN 15313, D 920 mm)" fleet/fleet.csv
check "a rail given as a wheel is refused, no figures" awk -F, '$1 == "2" { exit !($3 == "invalid_wheel" && $4 == "nan") }' fleet/fleet.csv
check "no resolved path in fleet.csv" sh -c "! grep -q '$SRC' fleet/fleet.csv"
check "summary.json names the profiles as given" grep -q '"wheel_left": "../profiles/EN15302_wheel_A.dat"' out/summary.json

# --- must fail: exit 2, message with the JSON path, no output -------------------------------
must_fail() {  # must_fail MESSAGE JSON
  echo "$2" > bad.json
  "$BIN" wheelset bad.json -o bad >out.txt 2>err.txt
  local rc=$?
  [ "$rc" -eq 2 ] || { echo "FAIL: exit $rc for $2"; fail=1; }
  grep -qF -- "$1" err.txt || { echo "FAIL: message lacks '$1':"; cat err.txt; fail=1; }
  [ ! -e bad ] || { echo "FAIL: wrote output for $2"; fail=1; }
}
must_fail "/rail/inclination: missing" '{"wheel": {"profile": {"standard": "S1002"}}, "rail": {"profile": {"standard": "60E1"}}}'
must_fail "/wheelset/roll: value \"free\"" '{"wheel": {"profile": {"standard": "S1002"}}, "rail": {"profile": {"standard": "60E1"}, "inclination": "1:40"}, "wheelset": {"roll": "free"}}'
must_fail "/rail/origin_mm: missing" '{"wheel": {"profile": {"standard": "S1002"}}, "rail": {"profile": {"standard": "60E1"}, "inclination": "1:40", "placement": "absolute"}}'
must_fail "give either \"wheel\"" '{"rail": {"profile": {"standard": "60E1"}, "inclination": "1:40"}}'
# A contact case file's keys: where they go here, not only "unknown key".
must_fail "/track: a key of a contact case file (mhcontact run), not of a wheelset case file (a wheelset case places the rails by rail.gauge_mm" '{"wheel": {"profile": {"standard": "S1002"}}, "rail": {"profile": {"standard": "60E1"}, "inclination": "1:40"}, "track": {"gauge_mm": 1435}}'
must_fail "/wheel/nominal_radius_mm: value 460: the wheels' radius is a key of \"wheelset\" here (write it as wheelset.nominal_radius_mm" '{"wheel": {"profile": {"standard": "S1002"}, "nominal_radius_mm": 460}, "rail": {"profile": {"standard": "60E1"}, "inclination": "1:40"}}'

# --- plots (when matplotlib is present) ------------------------------------------------------
py=/usr/bin/python3; [ -x "$py" ] || py=python3
if "$py" -c "import matplotlib" 2>/dev/null; then
  MPLBACKEND=Agg "$py" "$SRC/scripts/plot_wheelset.py" out --reference "$SRC/tests/data/en15302"
  MPLBACKEND=Agg "$py" "$SRC/scripts/plot_wheelset.py" fleet --fleet-x Sh
  for f in out/wheelset_delta_r.png out/wheelset_conicity.png fleet/wheelset_fleet.png; do
    check "$f is a PNG" sh -c "head -c 8 $f | od -An -c | grep -q 'P   N   G'"
  done
  # The plots sit in the run's directory: a new run still replaces it.
  "$BIN" wheelset "$SRC/cases/en15302-wheel-a.json" -o out -q >/dev/null
  check "rerun over the plotted directory" test $? -eq 1
else
  echo "wheelset: matplotlib missing, plots not tested"
fi
exit $fail
