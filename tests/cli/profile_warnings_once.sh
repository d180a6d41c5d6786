#!/usr/bin/env bash
# A profile's warnings are said once per run (issue 38: "every run of a case repeats the same
# profile warnings"): a batch that pairs one warned wheel (tests/data/field/old_wheel_loop.whl,
# five clean-up warnings) with three rails and a sweep of several cases prints each of its
# warnings once, and a single run once per case file, not per case.
# Usage: bash profile_warnings_once.sh <mhcontact-binary> <source-dir>
set -euo pipefail
bin=$1; src=$(cd "$2" && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
w=$src/tests/data/field/old_wheel_loop.whl
cat > "$tmp/m.json" <<JSON
{"wheels": ["$w"],
 "rails": ["$src/profiles/MBench_UIC60_v3.prr", "$src/profiles/60E1_1-40.csv", "$src/tests/data/profiles/avg_HR.BAN"],
 "inclination": "as-is", "nominal_radius_mm": 460, "material": {"E_GPa": 210, "nu": 0.28}, "model": "elastic",
 "sweep": {"tY_mm": [0, 1, 2, 3], "Q_kN": [50, 80]}}
JSON
"$bin" run "$tmp/m.json" -o "$tmp/m" 2> "$tmp/err" || true
n=$(grep -c "^mhcontact: warning: $w: " "$tmp/err")
[ "$n" -ge 3 ] || { echo "FAIL: expected the wheel's clean-up warnings, got $n"; cat "$tmp/err"; exit 1; }
dups=$(grep "^mhcontact: warning: " "$tmp/err" | sort | uniq -d)
[ -z "$dups" ] || { echo "FAIL: warnings repeated in one run:"; echo "$dups"; exit 1; }
cat > "$tmp/s.json" <<JSON
{"wheel": {"profile": "$w", "nominal_radius_mm": 460}, "rail": {"profile": "$src/profiles/MBench_UIC60_v3.prr", "inclination": "as-is"},
 "material": {"E_GPa": 210, "nu": 0.28}, "model": "elastic", "method": "auto", "sweep": {"tY_mm": [0, 1, 2, 3], "Q_kN": [50, 80]}}
JSON
"$bin" run "$tmp/s.json" -o "$tmp/s" 2> "$tmp/err2" || true
[ "$(grep -c "^mhcontact: warning: $w: " "$tmp/err2")" = "$n" ] || { echo "FAIL: a single run says the wheel's warnings otherwise"; cat "$tmp/err2"; exit 1; }
echo "profile_warnings_once: OK ($n warnings of the wheel, each once)"
