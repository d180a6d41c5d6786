#!/usr/bin/env bash
# The RCF columns (docs/outputs.md "RCF columns") with the case-file key "rcf": ellipses.csv and
# patches.csv end with them, by their definitions with the ELASTIC Hertz p0 of the load (against
# the closed form from N, A, B, E*, for ellipses and grid patches, plastic ones included), a run
# without the key has none, a bad key is refused, and
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
 "sweep": {"tY_mm": [-2, 0, 4, 9], "Q_kN": [100]}}
JSON
  "$bin" run "$tmp/$m.json" -o "$tmp/$m" -q --format csv
done
"$py" - "$tmp" <<'PY'
import csv, math, sys
t = sys.argv[1]

def KE(e):
    """Complete elliptic integrals K(e), E(e) of modulus e by the AGM (Abramowitz & Stegun 17.6)."""
    a, b, c, s, p = 1.0, math.sqrt(1 - e * e), e, 0.5 * e * e, 0.5
    while abs(c) > 1e-16:
        a, b, c = 0.5 * (a + b), math.sqrt(a * b), 0.5 * (a - b)
        p *= 2
        s += p * c * c
    K = math.pi / (2 * a)
    return K, K * (1 - s)

def hertz_p0(N, A, B, Es):
    """Elastic Hertz peak pressure of load N [N] between curvatures A, B [1/m], E* [Pa] (Johnson 1985
    §4.2, written out: A = 3N (K - E) / (2 pi E* a^3 e^2), B/A = ((a/b)^2 E - K) / (K - E), a >= b,
    e^2 = 1 - b^2/a^2, p0 = 3N / (2 pi a b)); independent of the library's Hertz routine."""
    A, B = min(A, B), max(A, B)
    if B / A - 1 < 1e-12:
        a = (3 * N / (4 * Es * (A + B))) ** (1 / 3)
        return 1.5 * N / (math.pi * a * a)
    def ratio(e):
        K, E = KE(e)
        return (E / (1 - e * e) - K) / (K - E)
    lo, hi = 1e-9, 1 - 1e-15
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if ratio(mid) < B / A else (lo, mid)
    e = 0.5 * (lo + hi)
    K, E = KE(e)
    a = (3 * N * (K - E) / (2 * math.pi * Es * A * e * e)) ** (1 / 3)
    return 1.5 * N / (math.pi * a * a * math.sqrt(1 - e * e))

Es = 210e9 / (2 * (1 - 0.28 ** 2))  # E* of two equal steels, E 210 GPa, nu 0.28 (the case's)
k = 300e6
tail = ["traction_coefficient", "k_MPa", "p0_el_over_k", "elastic_limit_p0_over_k",
        "shakedown_limit_p0_over_k", "shakedown_regime", "FI_surf_el"]
# Ellipses: p0_el against the closed form from N (ellipses.csv) and A, B (geometry.csv, the same
# t_Y and ellipse); under the plastic law the plastic p0 / area never enter.
geo = {(g["tY_mm"], g["ellipse"]): g for g in csv.DictReader(open(f"{t}/multi-hertzian/geometry.csv"))}
rows = list(csv.DictReader(open(f"{t}/multi-hertzian/ellipses.csv")))
assert rows and list(rows[0])[-7:] == tail, list(rows[0])[-7:]
worst, plastic_rows = 0, 0
for x in rows:
    N = float(x["N_kN"]) * 1e3
    g = geo[(x["tY_mm"], x["ellipse"])]
    p0 = hertz_p0(N, float(g["A_per_mm"]) * 1e3, float(g["B_per_mm"]) * 1e3, Es)
    p0_el = float(x["p0_el_over_k"]) * k
    dev = abs(p0_el / p0 - 1)
    worst = max(worst, dev)
    assert dev < 2e-4, (x["tY_mm"], x["ellipse"], p0_el / 1e6, p0 / 1e6)
    assert abs(float(x["FI_surf_el"]) - (0.3 - k / p0)) < 1e-4, x
    if x["plastic"] == "1":
        plastic_rows += 1
        assert float(x["p0_MPa"]) < 0.99 * p0_el, x  # the plastic peak is not what enters
assert plastic_rows > 0, "no plastic ellipse: the case does not test the definition"
print(f"rcf_columns: p0_el within {worst:.1e} of the closed-form Hertz p0 on {len(rows)} ellipses ({plastic_rows} plastic)")
# Patches: the elastic Hertz p0 of the patch's N on the curvatures A, B of the multi-Hertzian
# ellipse inside it (contact/grid/patch_elastic.hpp): the closed form with one of that t_Y's
# candidates (the multi-Hertzian run's geometry.csv: the same pair and t_Y), whether or not the
# patch is capped.
geo_t = {}
for g in csv.DictReader(open(f"{t}/multi-hertzian/geometry.csv")):
    geo_t.setdefault(g["tY_mm"], []).append(g)
rows = list(csv.DictReader(open(f"{t}/strips/patches.csv")))
assert rows and list(rows[0])[-7:] == tail, list(rows[0])[-7:]
worst, capped = 0, 0
for x in rows:
    N = float(x["N_kN"]) * 1e3
    cands = [hertz_p0(N, float(g["A_per_mm"]) * 1e3, float(g["B_per_mm"]) * 1e3, Es)
             for g in geo_t[x["tY_mm"]] if float(g["A_per_mm"]) > 0 and float(g["B_per_mm"]) > 0]
    p0 = float(x["p0_el_over_k"]) * k
    dev = min(abs(p0 / c - 1) for c in cands)
    worst = max(worst, dev)
    assert dev < 2e-4, (x["tY_mm"], x["patch"], p0 / 1e6, [c / 1e6 for c in cands])
    assert abs(float(x["FI_surf_el"]) - (0.3 - k / p0)) < 1e-8, x
    capped += float(x["plastic_area_mm2"]) > 0
assert capped > 0, "no capped patch: the case does not test the definition"
print(f"rcf_columns: patches' p0_el within {worst:.1e} of the closed form on {len(rows)} patches ({capped} capped)")
for f in ("multi-hertzian/ellipses.csv", "strips/patches.csv"):
    for x in csv.DictReader(open(f"{t}/{f}")):
        reg = x["shakedown_regime"]
        if reg == "":
            continue
        assert reg in ("elastic", "elastic_shakedown", "plastic_shakedown", "ratchetting"), reg
        assert (reg == "ratchetting") == (float(x["FI_surf_el"]) > 0 and float(x["p0_el_over_k"]) > float(x["shakedown_limit_p0_over_k"])), x
PY
# cases.csv carries the worst contact's indicators (issue 38: an auto run splits the per-contact
# columns between ellipses.csv and patches.csv): per case, the contact of the largest p0_el/k of
# either file, its regime and FI_surf_el; for the multi-Hertzian and strip runs and an auto run
# that mixes both.
sed 's/"method": "strips"/"method": "auto"/; s/"tY_mm": \[-2, 0, 4, 9\]/"tY_mm": [-2, 0, 0.5, 4, 5, 9]/' "$tmp/strips.json" > "$tmp/auto.json"
"$bin" run "$tmp/auto.json" -o "$tmp/auto" -q --format csv || true
"$py" - "$tmp" <<'PY'
import csv, os, sys
t = sys.argv[1]
for run in ("multi-hertzian", "strips", "auto"):
    cases = {c["case"]: c for c in csv.DictReader(open(f"{t}/{run}/cases.csv"))}
    per = {}
    for f, key in (("ellipses.csv", "ellipse"), ("patches.csv", "patch")):
        if os.path.exists(f"{t}/{run}/{f}"):
            for x in csv.DictReader(open(f"{t}/{run}/{f}")):
                if x["p0_el_over_k"] != "":
                    per.setdefault(x["case"], []).append((float(x["p0_el_over_k"]), x[key], x["shakedown_regime"], x["FI_surf_el"], f))
    methods = set()
    for n, c in cases.items():
        methods.add(c["method"])
        if n not in per:
            assert c["rcf_worst_contact"] == "" and c["rcf_worst_p0_el_over_k"] == "", c
            continue
        w = max(per[n])
        assert float(c["rcf_worst_p0_el_over_k"]) == w[0], (run, n, c["rcf_worst_p0_el_over_k"], w)
        assert c["rcf_worst_contact"] == w[1] and c["rcf_worst_shakedown_regime"] == w[2], (run, n, w)
        assert c["rcf_worst_FI_surf_el"] == w[3], (run, n, w)
        assert (w[4] == "patches.csv") == (c["method"] != "multi-hertzian"), (run, n, c["method"], w)
    if run == "auto":
        assert methods >= {"multi-hertzian", "strips"}, methods  # the case that motivated the columns
print("rcf_columns: cases.csv's worst contact is the largest p0_el/k of ellipses.csv and patches.csv")
PY
# Without the key: no RCF columns.
sed 's/"rcf": {[^}]*},//' "$tmp/strips.json" > "$tmp/plain.json"
"$bin" run "$tmp/plain.json" -o "$tmp/plain" -q --format csv
if head -1 "$tmp/plain/patches.csv" | grep -q FI_surf_el; then echo "RCF columns without rcf" >&2; exit 1; fi
if head -1 "$tmp/plain/cases.csv" | grep -q rcf_worst; then echo "RCF case columns without rcf" >&2; exit 1; fi
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
