#!/usr/bin/env bash
# `mhcontact hertz --yield`: the yield stress as input selects the yield law (method.md §5.1:
# Hertz up to p_y = 1.6 sigma_y, slope beta = 0.3 above); --p-lim takes precedence (the capped
# law); errors name the option. Worked example of method.md §5 (R_wyy 460, R_rxx 300, N 100 kN,
# E 210 GPa, nu 0.3) with sigma_y = 380 MPa: p_y = 608 MPa, h_y that of --p-lim 608 (the Hertz
# peak reaches p_y there), and p_max = p_y + 0.3 (p0 - p_y) of the patch.
# Usage: bash hertz_yield.sh <mhcontact-binary> <source-dir>
set -euo pipefail
bin="$1"
py=/usr/bin/python3
[ -x "$py" ] || py=python3
args=(hertz --R-wyy 460 --R-rxx 300 --N 100 --E 210 --nu 0.3)

y="$("$bin" "${args[@]}" --yield 380 --json)"
p="$("$bin" "${args[@]}" --p-lim 608 --json)"
both="$("$bin" "${args[@]}" --yield 380 --p-lim 900 --json)"
"$py" - "$y" "$p" "$both" <<'PY'
import json, sys
y, p, both = (json.loads(a) for a in sys.argv[1:4])
bad = []
if abs(y["p_y_MPa"] - 608) > 1e-9: bad.append(f"p_y_MPa = {y['p_y_MPa']}, expected 1.6 x 380 = 608")
if y["beta"] != 0.3: bad.append(f"beta = {y['beta']}, expected 0.3")
if "p_lim_MPa" in y: bad.append("--yield alone reports a p_lim_MPa the ellipse does not use")
if y["yield_MPa"] != 380: bad.append("yield_MPa not echoed")
if abs(y["h_y_mm"] - p["h_y_mm"]) > 1e-12 * p["h_y_mm"]: bad.append(f"h_y: --yield 380 gives {y['h_y_mm']}, --p-lim 608 gives {p['h_y_mm']}")
if abs(y["p_max_MPa"] - (608 + 0.3 * (y["p0_MPa"] - 608))) > 1e-6: bad.append(f"p_max_MPa = {y['p_max_MPa']}, not p_y + 0.3 (p0 - p_y)")
if not (y["area_ratio"] > 1 and y["plastic"]): bad.append("sigma_y 380 at 100 kN (p0_el/sigma_y = 3.3) should be plastic")
if abs(both["p_lim_MPa"] - 900) > 1e-9 or abs(both["p_max_MPa"] - 900) > 1e-6:
    bad.append(f"--p-lim should take precedence: p_lim {both['p_lim_MPa']}, p_max {both['p_max_MPa']}")
if bad:
    print("\n".join(bad)); sys.exit(1)
PY
txt="$("$bin" "${args[@]}" --yield 380)"
printf '%s\n' "$txt" | grep -q '^yield = 380 MPa$' || { echo "no 'yield = 380 MPa' line"; exit 1; }
printf '%s\n' "$txt" | grep -Eq '^p_y = 608(\.0*[0-9]?)? MPa$' || { echo "no 'p_y = 608 MPa' line"; exit 1; }
set +e
err="$("$bin" "${args[@]}" --yield 0.4 2>&1)"; rc=$?
set -e
[ "$rc" = 2 ] || { echo "--yield 0.4: exit $rc, expected 2"; exit 1; }
printf '%s\n' "$err" | grep -q -- "--yield" || { echo "error does not name --yield: $err"; exit 1; }
printf '%s\n' "$err" | grep -q "is it in GPa" || { echo "error has no unit hint: $err"; exit 1; }
echo ok
