#!/usr/bin/env bash
# `diff` for CI with a loose tolerance. A copy of the Manchester reference cases.csv
# with last-bit noise in `residual` (1e-16 against 3e-16), a number inside a warning moved by
# 0.4 % (gap_mean_error=0.314 -> 0.315) and pmax_MPa moved by 0.5 %: `--rtol 1e-2` passes (the
# residual by its solver-noise rule); with `--exact-noise` it reports only the residual cells, and
# `--ignore-columns residual` makes that OK; an unconverged residual, a doubled iteration count, a
# changed warning class or index, or a status, is still reported. The copy is made by column name.
# Usage: bash diff_tolerant.sh <mhcontact-binary> <source-dir>
set -euo pipefail
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
py=/usr/bin/python3; [ -x "$py" ] || py=python3
ref=$src/tests/ref/manchester/cases.csv
perturb() {  # out-file python-statements-on-row-r
  "$py" - "$ref" "$1" "$2" <<'PY'
import csv, sys
src, dst, stmt = sys.argv[1:4]
with open(src, newline="") as f:
    rd = csv.DictReader(f)
    rows, fields = list(rd), rd.fieldnames
for r in rows:
    if r["residual"] not in ("", "0"):
        r["residual"] = repr(-3 * float(r["residual"]))
    r["pmax_MPa"] = repr(float(r["pmax_MPa"]) * 1.005)
    exec(stmt)
with open(dst, "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=fields, lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
PY
}
perturb "$tmp/noise.csv" 'r["warnings"] = r["warnings"].replace("gap_mean_error=0.314>", "gap_mean_error=0.315>")'
grep -q 'gap_mean_error=0.315>' "$tmp/noise.csv"
# The residual's last-bit noise passes by its rule (both converged, <= 1e-6) by default: only the
# issue-38 complaint's --rtol is needed; --exact-noise compares it like any column and reports it.
"$bin" diff "$ref" "$tmp/noise.csv" --rtol 1e-2 > "$tmp/r1" || { echo "FAIL: residual noise not passed by its rule"; cat "$tmp/r1"; exit 1; }
grep -q '^column residual: 0 of 99 cells out of tolerance (solver noise, rule: both |value| <= 1e-6 (converged))' "$tmp/r1" || { echo "FAIL: rule not named"; cat "$tmp/r1"; exit 1; }
set +e
"$bin" diff "$ref" "$tmp/noise.csv" --rtol 1e-2 --exact-noise > "$tmp/r1x"; rc=$?
set -e
[ "$rc" = 1 ] || { echo "FAIL: --exact-noise: residual noise not reported (exit $rc)"; cat "$tmp/r1x"; exit 1; }
grep -q '^column residual: ' "$tmp/r1x"
! grep -q '^column \(warnings\|pmax_MPa\): [1-9]' "$tmp/r1x" || { echo "FAIL: warnings or pmax reported at rtol 1e-2"; cat "$tmp/r1x"; exit 1; }
"$bin" diff "$ref" "$tmp/noise.csv" --rtol 1e-2 --exact-noise --ignore-columns residual --quiet | grep -qx 'diff: OK'
# A residual that is not converged, and iterations more than doubled, are still reported.
perturb "$tmp/unconv.csv" 'r["residual"] = "0.002" if r["case"] == "5" else r["residual"]; r["iterations"] = str(3 * int(r["iterations"]) + 4) if r["case"] == "6" else r["iterations"]'
set +e; "$bin" diff "$ref" "$tmp/unconv.csv" --rtol 1e-2 > "$tmp/r1u"; rc=$?; set -e
[ "$rc" = 1 ] && grep -q '^column residual: 1 of 99' "$tmp/r1u" && grep -q '^column iterations: 1 of 99' "$tmp/r1u" || { echo "FAIL: unconverged residual / doubled iterations not reported"; cat "$tmp/r1u"; exit 1; }
# At the default tolerance the warning and pmax_MPa differ.
set +e; "$bin" diff "$ref" "$tmp/noise.csv" --ignore-columns residual > "$tmp/r2"; set -e
grep -q '^column warnings: 1 of 99 cells out of tolerance' "$tmp/r2"
grep -q '^column pmax_MPa: ' "$tmp/r2"
# A warning of another class, an ellipse index, a status: reported whatever the tolerance.
perturb "$tmp/class.csv" 'r["warnings"] = r["warnings"].replace("non_hertzian:ellipse=2:gap_error=0.587", "non_hertzian:ellipse=3:gap_error=0.587").replace("flange_climb:", "off_profile:")'
set +e; "$bin" diff "$ref" "$tmp/class.csv" --rtol 0.5 --ignore-columns residual > "$tmp/r3"; set -e
grep -q '^column warnings: 13 of 99 cells out of tolerance' "$tmp/r3" || { echo "FAIL: class/index changes"; cat "$tmp/r3"; exit 1; }
perturb "$tmp/status.csv" 'r["status"] = "ok"'
set +e; "$bin" diff "$ref" "$tmp/status.csv" --rtol 0.5 --ignore-columns residual > "$tmp/r4"; set -e
grep -q '^column status: 27 of 99 cells out of tolerance' "$tmp/r4" || { echo "FAIL: status changes"; cat "$tmp/r4"; exit 1; }
echo "diff_tolerant: OK"
