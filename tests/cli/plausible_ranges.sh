#!/usr/bin/env bash
# Values no physical case has are refused by `hertz` with the same table as the
# case file (core/plausible.hpp), exit 2, a hint at the unit mistake, nothing on stdout; and a
# case file with Q_kN 1e5 is refused by `run` the same way.
# Usage: bash plausible_ranges.sh <mhcontact-binary> <source-dir>
set -uo pipefail
bin="$1"
src="$2"
fails=0
expect() {  # expected-code message-substring args...
  local code="$1" msg="$2"; shift 2
  local out err rc
  err="$("$bin" "$@" 2>&1 >/dev/null)"; rc=$?
  out="$("$bin" "$@" 2>/dev/null)"
  [ "$rc" = "$code" ] || { echo "FAIL (exit $rc, wanted $code): $*"; fails=1; }
  case "$err" in *"$msg"*) ;; *) echo "FAIL (message lacks '$msg'): $* -> $err"; fails=1 ;; esac
  [ -z "$out" ] || { echo "FAIL (stdout not empty): $*"; fails=1; }
}
R=(--R-wyy 460 --R-rxx 300)
expect 2 "is it in MPa?" hertz "${R[@]}" --N 100 --E 210000 --nu 0.3
expect 2 "is it in GPa?" hertz "${R[@]}" --N 100 --E 210 --nu 0.3 --p-lim 0.8
expect 2 "did you give newtons?" hertz "${R[@]}" --N 100000 --E 210 --nu 0.3
expect 2 "is it in metres?" hertz --R-wyy 0.46 --R-rxx 300 --N 100 --E 210 --nu 0.3
expect 2 "is it in 1/m?" hertz --A 1.08 --B 1.6 --N 100 --E 210 --nu 0.3
expect 2 "plausible range of nu" hertz "${R[@]}" --N 100 --E 210 --nu 0.49
# The worked example still runs.
"$bin" hertz "${R[@]}" --N 100 --E 210 --nu 0.3 --p-lim 800 >/dev/null || { echo "FAIL: worked example"; fails=1; }
# The case file: Q_kN 1e5 (newtons typed as kN) is an input error before anything is written.
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
cat > "$tmp/case.json" <<JSON
{"wheel": {"profile": {"standard": "S1002"}}, "rail": {"profile": {"standard": "60E1"}, "inclination": "1:40"},
 "sweep": {"tY_mm": [0], "Q_kN": [100000]}}
JSON
expect 2 "did you give newtons?" run "$tmp/case.json" -o "$tmp/out"
[ ! -e "$tmp/out/cases.csv" ] || { echo "FAIL: outputs written for an input error"; fails=1; }
exit $fails
