#!/usr/bin/env bash
# `mhcontact hertz --json` on the worked example of method.md §5 (README example):
# E = 210 GPa, nu = 0.3, R_wyy = 460 mm, R_rxx = 300 mm, flat wheel profile, N = 100 kN,
# p_lim = 800 MPa. Reference values from method.md §5, tolerance half a unit of the last
# printed digit. Also the elastic text form (one `name = value unit` line each).
# Usage: bash hertz_worked_example.sh <mhcontact-binary> <source-dir>
set -euo pipefail
bin="$1"
py=/usr/bin/python3
[ -x "$py" ] || py=python3

out="$("$bin" hertz --R-wyy 460 --R-rxx 300 --N 100 --E 210 --nu 0.3 --p-lim 800 --json)"
"$py" - "$out" <<'PY'
import json, sys
j = json.loads(sys.argv[1])
ref = {  # key: (value, tolerance) from method.md §5
    "a_el_mm": (7.162, 5e-4), "b_el_mm": (5.387, 5e-4), "h_y_mm": (0.02021, 5e-6),
    "N_y_kN": (27.0, 0.05), "a_mm": (7.748, 5e-4), "b_mm": (5.829, 5e-4),
    "area_ratio": (1.171, 5e-4), "p_max_MPa": (800, 0),
}
bad = [f"{k} = {j[k]}, expected {v} ± {t}" for k, (v, t) in ref.items() if abs(j[k] - v) > t]
for k in ["schema", "lambda", "m", "n", "p0_MPa", "pmean_MPa", "h0_mm", "approach_mm", "plastic",
          "plateau_a_mm", "plateau_b_mm"]:
    if k not in j: bad.append(f"missing key {k}")
if j.get("plastic") is not True: bad.append("plastic should be true")
if bad:
    print("\n".join(bad)); sys.exit(1)
PY

txt="$("$bin" hertz --R-wyy 460 --R-rxx 300 --N 100 --E 210 --nu 0.3)"
val() { printf '%s\n' "$txt" | awk -v k="$1" -v u="$2" '$1 == k && $2 == "=" && $4 == u { print $3; f = 1 } END { if (!f) exit 1 }'; }
check() {  # name unit ref tol
  local v; v="$(val "$1" "$2")" || { echo "no line '$1 = ... $2'"; exit 1; }
  awk -v v="$v" -v r="$3" -v t="$4" 'BEGIN { d = v - r; if (d < 0) d = -d; exit !(d <= t) }' \
    || { echo "$1 = $v $2, expected $3 ± $4"; exit 1; }
}
check a mm 7.162 5e-4
check b mm 5.387 5e-4
check p0 MPa 1238 0.5
check lambda - 0.652174 1e-6
for k in "m -" "n -" "p_mean MPa" "h0 mm" "approach mm"; do val $k > /dev/null || { echo "no line for $k"; exit 1; }; done
echo ok
