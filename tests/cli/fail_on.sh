#!/usr/bin/env bash
# `run --fail-on CLASSES` exits 1 when a case carries a warning of one of the classes
# (outputs still written, a line says why), 0 otherwise; an unknown class exits 2 and writes
# nothing; `--fail-on-warning` still means any warning; a batch obeys it too (docs/status.md).
# Usage: bash fail_on.sh <mhcontact-binary> <source-dir>
set -uo pipefail
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0
expect() {  # expected-exit stderr-substring output-dir args...
  local code=$1 msg=$2 dir=$3; shift 3
  "$bin" run "$@" -o "$dir" 2>"$tmp/err"; local rc=$?
  [ "$rc" = "$code" ] || { echo "FAIL (exit $rc, wanted $code): run $*"; cat "$tmp/err"; fails=1; }
  [ -z "$msg" ] || grep -qF -- "$msg" "$tmp/err" || { echo "FAIL (stderr lacks '$msg'): run $*"; cat "$tmp/err"; fails=1; }
}
m=$src/cases/manchester.json
# The classes the shipped Manchester sweep must never show: exit 0, as CI uses it.
expect 0 "ok 72, outside_validity 27" "$tmp/ok" "$m" --fail-on off_profile,non_hertzian_excluded,pressure_spike,strip_outlier,cant
# Its flange-climb and non-Hertzian rows: exit 1, outputs written.
expect 1 "mhcontact run: 12 cases with flange_climb (--fail-on): exit 1" "$tmp/fc" "$m" --fail-on off_profile,flange_climb
[ -s "$tmp/fc/cases.csv" ] || { echo "FAIL: --fail-on: outputs not written"; fails=1; }
expect 1 "27 cases with non_hertzian, 10 cases with interacting (--fail-on): exit 1" "$tmp/nh" "$m" --fail-on non_hertzian,interacting
# Any warning.
expect 1 "46 cases with warnings, 0 cant warning(s) (--fail-on-warning): exit 1" "$tmp/any" "$m" --fail-on-warning
# A misspelt class is an input error: exit 2, the classes listed, nothing written.
expect 2 '--fail-on: value "off-profile": not a warning class (the classes are non_hertzian, ' "$tmp/bad" "$m" --fail-on off-profile
[ ! -e "$tmp/bad" ] || { echo "FAIL: a refused run wrote $tmp/bad"; fails=1; }
expect 2 '--fail-on: value "": empty warning class' "$tmp/bad2" "$m" --fail-on ""
# A batch: the fleet's flange-climb rows.
expect 1 "48 cases with flange_climb (--fail-on): exit 1" "$tmp/fleet" "$src/cases/fleet.json" --fail-on flange_climb
expect 0 "" "$tmp/fleet0" "$src/cases/fleet.json" --fail-on off_profile -q
# A wheel on its flange tip (S1002/60E1 1:40, t_Y 30 mm, 80 kN; docs/status.md "Derailed"): status
# derailed, an answer like outside_validity (exit 0), a failure only when asked for.
cat > "$tmp/derail.json" <<'JSON'
{"wheel": {"profile": {"standard": "S1002"}, "nominal_radius_mm": 460},
 "rail": {"profile": {"standard": "60E1"}, "inclination": "1:40"},
 "material": {"E_GPa": 210, "nu": 0.28}, "model": "elastic", "method": "auto",
 "sweep": {"tY_mm": [0, 30], "Q_kN": [80]}}
JSON
expect 0 "2 cases, derailed 1, ok 1," "$tmp/der0" "$tmp/derail.json"
grep -q '^1,30,80,derailed,' "$tmp/der0/cases.csv" || { echo "FAIL: t_Y 30 mm not derailed"; cat "$tmp/der0/cases.csv"; fails=1; }
expect 1 "1 cases with derailed (--fail-on): exit 1" "$tmp/der1" "$tmp/derail.json" --fail-on derailed
expect 1 "(--fail-on-warning): exit 1" "$tmp/der2" "$tmp/derail.json" --fail-on-warning
exit $fails
