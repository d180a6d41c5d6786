#!/usr/bin/env bash
# The RCF columns (docs/outputs.md "RCF columns") with the case-file key "rcf": ellipses.csv and
# patches.csv end with them, the values follow the formulas (FI_surf = f − k/p0 and p0/k from
# the contact's N, a, b), a run without the key has none, a bad key is refused, and
# scripts/plot_rcf.py plots them headless (when matplotlib is present).
set -euo pipefail
bin=$1; src=$(cd "$2" && pwd)
py=/usr/bin/python3; [ -x "$py" ] || py=python3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for m in multi-hertzian strips; do
  cat > "$tmp/$m.json" <<JSON
{"wheel": {"profile": "$src/profiles/MBench_S1002_v3.prw", "nominal_radius_mm": 460},
 "rail": {"profile": "$src/profiles/MBench_UIC60_v3.prr", "inclination": "as-is"},
 "track": {"gauge_mm": 1435, "gauge_height_mm": 14, "flange_back_distance_mm": 1360, "flange_back_position_mm": -70},
 "material": {"E_GPa": 210, "nu": 0.28, "p_lim_MPa": 900}, "model": "plastic", "method": "$m",
 "rcf": {"traction_coefficient": 0.3, "shear_yield_MPa": 300},
 "sweep": {"tY_mm": [-2, 9], "Q_kN": [100]}}
JSON
  "$bin" run "$tmp/$m.json" -o "$tmp/$m" -q --format csv
done
"$py" - "$tmp" <<'PY'
import csv, math, sys
t = sys.argv[1]
for f, key in (("multi-hertzian/ellipses.csv", "ellipse"), ("strips/patches.csv", "patch")):
    r = list(csv.DictReader(open(f"{t}/{f}")))
    assert r, f
    assert list(r[0])[-7:] == ["traction_coefficient", "k_MPa", "p0_over_k", "elastic_limit_p0_over_k",
                               "shakedown_limit_p0_over_k", "shakedown_regime", "FI_surf"], list(r[0])[-7:]
    for x in r:
        N = float(x["N_kN"]) * 1e3
        if key == "ellipse":
            a, b = float(x["a_mm"]) * 1e-3, float(x["b_mm"]) * 1e-3
            ab = a * b
        else:
            ab = float(x["area_mm2"]) * 1e-6 / math.pi
        p0 = 1.5 * N / (math.pi * ab)
        assert abs(float(x["p0_over_k"]) / (p0 / 300e6) - 1) < 1e-8, (f, x["p0_over_k"], p0)
        assert abs(float(x["FI_surf"]) - (0.3 - 300e6 / p0)) < 1e-8, (f, x["FI_surf"])
        reg = x["shakedown_regime"]
        assert reg in ("elastic", "elastic_shakedown", "plastic_shakedown", "ratchetting"), reg
        assert (reg == "ratchetting") == (float(x["FI_surf"]) > 0 and float(x["p0_over_k"]) > float(x["shakedown_limit_p0_over_k"])), x
PY
# Without the key: no RCF columns.
sed 's/"rcf": {[^}]*},//' "$tmp/strips.json" > "$tmp/plain.json"
"$bin" run "$tmp/plain.json" -o "$tmp/plain" -q --format csv
if head -1 "$tmp/plain/patches.csv" | grep -q FI_surf; then echo "RCF columns without rcf" >&2; exit 1; fi
# A traction coefficient out of range, and no k without a yield stress, are input errors.
sed 's/"traction_coefficient": 0.3/"traction_coefficient": 2/' "$tmp/strips.json" > "$tmp/bad.json"
if "$bin" run "$tmp/bad.json" -o "$tmp/bad" -q 2>"$tmp/err"; then exit 1; fi
grep -q "traction_coefficient" "$tmp/err"
sed 's/, "shear_yield_MPa": 300//' "$tmp/strips.json" > "$tmp/nok.json"
if "$bin" run "$tmp/nok.json" -o "$tmp/nok" -q 2>"$tmp/err"; then exit 1; fi
grep -q "shear_yield_MPa" "$tmp/err"
if "$py" -c "import matplotlib" 2>/dev/null; then
  MPLBACKEND=Agg "$py" "$src/scripts/plot_rcf.py" "$tmp/multi-hertzian" "$tmp/strips" -o "$tmp/rcf.png" >/dev/null
  head -c 8 "$tmp/rcf.png" | od -An -c | grep -q 'P   N   G' || { echo "rcf.png is not a PNG" >&2; exit 1; }
fi
echo "rcf_columns: OK"
