#!/usr/bin/env bash
# Conventions that can be checked are checked. profile info prints a rail's cant
# (the Manchester rail: 1:40 in its file, Shackleton & Iwnicki 2008) and warns about a canted rail
# mirrored in y; a run that cants an already canted rail warns, in results.json's summary too.
# Measured or exact from the printed digits: S1002 printed with 3 decimals is
# exact, the choice is reported by profile info and the run, and geometry.noise forces it.
# Usage: bash conventions.sh <mhcontact-binary> <source-dir>
set -euo pipefail
bin="$1"
src="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
d="$src/tests/data/profiles"
fail() { echo "FAIL: $*"; exit 1; }

# Cant in profile info: 1.432 deg, 1:40; no warning.
"$bin" profile info "$d/MBench_UIC60_v3.prr" > "$tmp/info"
grep -q "^cant: 1.432 deg (1:40;" "$tmp/info" || fail "cant line: $(grep cant "$tmp/info")"
grep -q "warning: cant" "$tmp/info" && fail "a 1:40 rail warned about"
"$bin" profile info "$d/MBench_UIC60_v3.prr" --json | python3 -c '
import json, sys
c = json.load(sys.stdin)["cant"]
assert c["confident"] and abs(c["angle_deg"] - 1.4321) < 0.01 and c["ratio"] == "1:40", c'
# Mirrored in y: negative, warned.
"$bin" profile info "$d/MBench_UIC60_v3.prr" --mirror-y > "$tmp/info"
grep -q "^cant: -1.432 deg (-1:40;" "$tmp/info" || fail "mirrored cant: $(grep cant "$tmp/info")"
grep -q "warning: cant: .*mirrored in y" "$tmp/info" || fail "mirrored rail not warned about"

# A run that cants the (already canted) Manchester rail again.
cat > "$tmp/twice.json" <<JSON
{"wheel": {"profile": "$d/MBench_S1002_v3.prw"}, "rail": {"profile": "$d/MBench_UIC60_v3.prr", "inclination": "1:40"},
 "sweep": {"tY_mm": [0, 2], "Q_kN": [50]}}
JSON
"$bin" run "$tmp/twice.json" -o "$tmp/o" 2> "$tmp/err" || fail "run exit $?"
grep -q "warning: .*cant: the rail file looks canted already (1.432 deg, 1:40) and the case cants it again by 1:40: 2.86[0-9] deg" "$tmp/err" \
  || fail "double cant not warned about: $(cat "$tmp/err")"
grep -q "rail cant 2.86[0-9] deg (1:20" "$tmp/err" || fail "summary lacks the cant: $(cat "$tmp/err")"
python3 - "$tmp/o/results.json" <<'PY' || fail "results.json summary lacks the cant warning"
import json, sys
j = json.load(open(sys.argv[1]))
s = j["summary"]
assert len(s["pair_warnings"]) == 1 and "canted already" in s["pair_warnings"][0], s
assert abs(s["rail_cant_deg"] - 2.864) < 0.01, s
c = j["profiles"]["rail"]["cant"]
assert abs(c["file_angle_deg"] - 1.432) < 0.01 and abs(c["inclination_deg"] - 1.432) < 0.01, c
PY
# --fail-on-warning counts a cant warning (no case of this run warns; the pair does): exit 1.
# (a light load at t_Y = 0: a small patch that passes the Hertz validity test, so no case warns)
sed -e 's/"tY_mm": \[0, 2\]/"tY_mm": [0]/' -e 's/"Q_kN": \[50\]/"Q_kN": [1]/' "$tmp/twice.json" > "$tmp/twice0.json"
set +e
"$bin" run "$tmp/twice0.json" -o "$tmp/of" --fail-on-warning 2> "$tmp/err"; rc=$?
set -e
[ "$rc" = 1 ] || fail "--fail-on-warning with a cant warning: exit $rc"
grep -q "0 cases with warnings, 1 cant warning(s) (--fail-on-warning): exit 1" "$tmp/err" || fail "no fail-on-warning line: $(cat "$tmp/err")"
# A batch counts the pairs with cant warnings in its summary, and --fail-on-warning applies.
cat > "$tmp/m.json" <<JSON
{"pairs": [{"name": "twice", "wheel": "$d/MBench_S1002_v3.prw", "rail": "$d/MBench_UIC60_v3.prr"},
           {"name": "once", "wheel": "$d/MBench_S1002_v3.prw", "rail": {"standard": "60E1"}}],
 "inclination": "1:40", "sweep": {"tY_mm": [0], "Q_kN": [50]}}
JSON
set +e
"$bin" run "$tmp/m.json" -o "$tmp/ob" 2> "$tmp/err"; rc0=$?
"$bin" run "$tmp/m.json" -o "$tmp/obf" --fail-on-warning 2> "$tmp/errf"; rc1=$?
set -e
[ "$rc0" = 0 ] || fail "batch exit $rc0: $(cat "$tmp/err")"
[ "$rc1" = 1 ] || fail "batch --fail-on-warning exit $rc1"
grep -q ", 1 pairs with cant warnings;" "$tmp/err" || fail "batch summary line: $(tail -1 "$tmp/err")"
python3 -c 'import json,sys; s=json.load(open(sys.argv[1]))["summary"]; assert s["pairs_with_cant_warnings"] == 1, s' "$tmp/ob/results.json" \
  || fail "batch results.json summary"
# The same rail as-is: no cant warning.
sed 's/"1:40"/"as-is"/' "$tmp/twice.json" > "$tmp/once.json"
"$bin" run "$tmp/once.json" -o "$tmp/o1" 2> "$tmp/err"
grep -q "cant:" "$tmp/err" && fail "as-is run warned: $(cat "$tmp/err")"

# S1002 printed with 3 decimals: exact (residual 0.27 um, noise sigma 0.30 um: the rounding's
# 0.29 um, below the sqrt(2) x 0.29 um that makes a profile measured).
"$bin" profile generate S1002 -o "$tmp/s.csv" > /dev/null
awk -F, 'NR > 1 { printf "%.3f %.3f\n", $1, $2 }' "$tmp/s.csv" > "$tmp/s3.dat"
"$bin" profile info "$tmp/s3.dat" --kind wheel > "$tmp/info"
grep -q "^noise: exact: median residual 0.2[0-9]* µm <= 0.3[0-9]* µm (the residual of a noise sigma of 1.41 x 0.289 µm, rounding to the printed 0.001 mm" "$tmp/info" \
  || fail "3 decimals: $(grep noise "$tmp/info")"
"$bin" profile info "$tmp/s3.dat" --kind wheel --noise measured | grep -q "^noise: measured: forced" || fail "--noise measured"
# The run reports the classes; geometry.noise forces the rail.
cat > "$tmp/n.json" <<JSON
{"wheel": {"profile": {"file": "$tmp/s3.dat", "format": "table"}}, "rail": {"profile": {"standard": "60E1"}, "inclination": "1:40"},
 "geometry": {"noise": {"rail": "measured"}}, "sweep": {"tY_mm": [0], "Q_kN": [50]}}
JSON
"$bin" run "$tmp/n.json" -o "$tmp/n" 2> "$tmp/err" || fail "noise run exit $?"
grep -q "profiles: wheel exact: .*; rail measured: forced" "$tmp/err" || fail "run summary: $(cat "$tmp/err")"
python3 - "$tmp/n/results.json" <<'PY' || fail "results.json lacks the classes"
import json, sys
j = json.load(open(sys.argv[1]))
assert j["summary"]["profiles"] == {"wheel": "exact", "rail": "measured"}, j["summary"]
assert j["profiles"]["wheel"]["noise"]["print_step_mm"] == 0.001, j["profiles"]["wheel"]["noise"]
assert j["profiles"]["rail"]["noise"]["forced"] is True
assert j["inputs"]["geometry"]["noise"] == {"wheel": "auto", "rail": "measured"}
PY
echo "{\"wheel\": {\"profile\": {\"standard\": \"S1002\"}}, \"rail\": {\"profile\": {\"standard\": \"60E1\"}, \"inclination\": \"1:40\"}, \"geometry\": {\"noise\": \"noisy\"}, \"sweep\": {\"tY_mm\": [0], \"Q_kN\": [50]}}" > "$tmp/bad.json"
set +e
"$bin" run "$tmp/bad.json" -o "$tmp/b" 2> "$tmp/err"; rc=$?
set -e
[ "$rc" = 2 ] || fail "bad noise: exit $rc"
grep -q '/geometry/noise' "$tmp/err" || fail "bad noise message: $(cat "$tmp/err")"
# Flange climb reaches the summary: on the Manchester pair the contact angle, 70° on the straight
# flange section up to t_Y = 8 mm, falls to 67.4° at 8.5 mm (caf.csv): the 12 cases at t_Y 8.5 ... 10
# mm (3 loads each) warn flange_climb, the others not.
"$bin" run "$src/cases/manchester.json" -o "$tmp/m" 2> "$tmp/err" || fail "manchester exit $?"
grep -q ", 12 with flange_climb" "$tmp/err" || fail "summary line: $(tail -1 "$tmp/err")"
python3 - "$tmp/m/results.json" <<'PY' || fail "results.json: flange_climb count"
import json, sys
j = json.load(open(sys.argv[1]))
assert j["summary"]["warnings"]["flange_climb"] == 12, j["summary"]
climb = sorted({c["tY_mm"] for c in j["cases"] if any(w.startswith("flange_climb") for w in c["warnings"])})
assert climb == [8.5, 9, 9.5, 10], climb
PY
echo "ok"
