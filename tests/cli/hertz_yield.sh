#!/usr/bin/env bash
# `mhcontact hertz --yield`: the yield stress as input. p_lim = 2.1 sigma_y
# (method.md §5.1); --p-lim takes precedence; errors name the option. Worked example of
# method.md §5 (R_wyy 460, R_rxx 300, N 100 kN, E 210 GPa, nu 0.3) with sigma_y = 380 MPa:
# p_lim = 798 MPa, the same law as --p-lim 798.
# Usage: bash hertz_yield.sh <mhcontact-binary> <source-dir>
set -euo pipefail
bin="$1"
py=/usr/bin/python3
[ -x "$py" ] || py=python3
args=(hertz --R-wyy 460 --R-rxx 300 --N 100 --E 210 --nu 0.3)

y="$("$bin" "${args[@]}" --yield 380 --json)"
p="$("$bin" "${args[@]}" --p-lim 798 --json)"
both="$("$bin" "${args[@]}" --yield 380 --p-lim 900 --json)"
"$py" - "$y" "$p" "$both" <<'PY'
import json, sys
y, p, both = (json.loads(a) for a in sys.argv[1:4])
bad = []
if abs(y["p_lim_MPa"] - 798) > 1e-9: bad.append(f"p_lim_MPa = {y['p_lim_MPa']}, expected 2.1 x 380 = 798")
if y["yield_MPa"] != 380: bad.append("yield_MPa not echoed")
for k in ("a_mm", "b_mm", "p_max_MPa", "area_ratio", "approach_mm", "h_y_mm"):
    if abs(y[k] - p[k]) > 1e-12 * max(1, abs(p[k])): bad.append(f"{k}: --yield 380 gives {y[k]}, --p-lim 798 gives {p[k]}")
if abs(both["p_lim_MPa"] - 900) > 1e-9 or abs(both["p_max_MPa"] - 900) > 1e-6:
    bad.append(f"--p-lim should take precedence: p_lim {both['p_lim_MPa']}, p_max {both['p_max_MPa']}")
if bad:
    print("\n".join(bad)); sys.exit(1)
PY
txt="$("$bin" "${args[@]}" --yield 380)"
printf '%s\n' "$txt" | grep -q '^yield = 380 MPa$' || { echo "no 'yield = 380 MPa' line"; exit 1; }
printf '%s\n' "$txt" | grep -Eq '^p_lim = 798(\.0*[0-9]?)? MPa$' || { echo "no 'p_lim = 798 MPa' line"; exit 1; }
set +e
err="$("$bin" "${args[@]}" --yield 0.4 2>&1)"; rc=$?
set -e
[ "$rc" = 2 ] || { echo "--yield 0.4: exit $rc, expected 2"; exit 1; }
printf '%s\n' "$err" | grep -q -- "--yield" || { echo "error does not name --yield: $err"; exit 1; }
printf '%s\n' "$err" | grep -q "is it in GPa" || { echo "error has no unit hint: $err"; exit 1; }
echo ok
