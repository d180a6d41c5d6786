#!/usr/bin/env bash
# Warnings reach the user. avg_wheel.whl on site_b_hr.prr has cases with
# non_hertzian_excluded warnings: the summary line and results.json's summary count them by kind,
# the run exits 0 (the 50 rows outside validity are answers), and --fail-on-warning makes it exit 1
# (outputs still written). The counts: 5 of the 51 rows outside validity fail only the Hertz
# test's edge gaps on the contact surface of the measured wheel (docs/method.md §4 item 4),
# and 4 only the gap-corner test (gap_kink, docs/methods.md "auto"), which the judge applies to
# every multi-Hertzian row.
# Range values are written as the decimals the user meant (0.9, not
# 0.8999999999999999).
# Usage: bash warnings_summary.sh <mhcontact-binary> <source-dir>
set -euo pipefail
. "$(dirname "$0")/lib/csv_col.sh"
bin="$1"
src="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
d="$src/tests/data/profiles"
cat > "$tmp/c.json" <<JSON
{"wheel": {"profile": "$d/avg_wheel.whl"}, "rail": {"profile": "$d/site_b_hr.prr", "inclination": "as-is"},
 "sweep": {"tY_mm": {"from": -8, "to": 12, "step": 0.1}, "Q_kN": [20, 100]}}
JSON
set +e
"$bin" run "$tmp/c.json" -o "$tmp/o" 2>"$tmp/err"; rc=$?
set -e
[ "$rc" = 0 ] || { echo "FAIL: exit $rc without --fail-on-warning"; cat "$tmp/err"; exit 1; }
grep -q "402 cases, ok 351, outside_validity 51, .*6 with non_hertzian_excluded" "$tmp/err" || { echo "FAIL: summary line lacks the warnings"; cat "$tmp/err"; exit 1; }
python3 - "$tmp/o/results.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))["summary"]
# Rows with a validity warning are outside_validity: answers, not failures.
assert s["by_status"] == {"ok": 351, "outside_validity": 51}, s
assert s["failed"] == 0, s
assert s["warnings"]["non_hertzian_excluded"] == 6, s
assert s["cases_with_warnings"] >= 6, s
PY
set +e
"$bin" run "$tmp/c.json" -o "$tmp/o2" --fail-on-warning 2>"$tmp/err2"; rc=$?
set -e
[ "$rc" = 1 ] || { echo "FAIL: --fail-on-warning exit $rc, wanted 1"; exit 1; }
grep -q "(--fail-on-warning): exit 1" "$tmp/err2" || { echo "FAIL: no --fail-on-warning message"; exit 1; }
[ -s "$tmp/o2/cases.csv" ] || { echo "FAIL: outputs not written"; exit 1; }
# Item 6: the sweep's values as written.
cat > "$tmp/s.json" <<JSON
{"wheel": {"profile": {"standard": "S1002"}}, "rail": {"profile": {"standard": "60E1"}, "inclination": "1:40"},
 "sweep": {"tY_mm": {"from": 0, "to": 1, "step": 0.3}, "Q_kN": [100]}}
JSON
"$bin" run "$tmp/s.json" -o "$tmp/s" -q || true
csv_col "$tmp/s/cases.csv" tY_mm | tr '\n' ' ' > "$tmp/ty"
[ "$(cat "$tmp/ty")" = "0 0.3 0.6 0.9 " ] || { echo "FAIL: tY_mm column: $(cat "$tmp/ty")"; head -3 "$tmp/s/cases.csv"; exit 1; }
echo "warnings_summary: OK"
