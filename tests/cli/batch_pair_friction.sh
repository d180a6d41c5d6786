#!/usr/bin/env bash
# Friction and rcf per pair in a batch manifest (docs/batch-and-shards.md "Friction and RCF per
# pair"): a two-pair manifest whose pairs share the Manchester profiles but not the friction
# (mu 0.3 from the manifest's shared keys, 0.15 given by pair 1) gives, pair by pair, the RCF,
# tangential, damage and wear columns of the two single runs of the same case files, every cell
# equal; a pair key that breaks a case-file rule names the pair's JSON path with exit code 2; a
# pair that drops a column-deciding key (friction) is refused at its path.
# Broken once to see it fail: pair_case ignoring the pair's own keys (pair 1 solved with mu 0.3):
# the comparison of pair 1 failed at its first ellipse (h0_mm: the creep forces' vertical share
# moves the approach).
set -euo pipefail
bin=$1; src=$(cd "$2" && pwd)
py=/usr/bin/python3; [ -x "$py" ] || py=python3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
W="$src/profiles/MBench_S1002_v3.prw"; R="$src/profiles/MBench_UIC60_v3.prr"
common='"track": {"gauge_mm": 1435, "gauge_height_mm": 14, "flange_back_distance_mm": 1360, "flange_back_position_mm": -70},
 "material": {"E_GPa": 210, "nu": 0.28},
 "kinematics": {"speed_m_s": 30, "yaw_mrad_per_mm": 2.4},
 "sweep": {"tY_mm": [0, 3, 6], "Q_kN": 100}'
single() {  # $1: mu
  cat <<JSON
{"wheel": {"profile": "$W", "nominal_radius_mm": 460}, "rail": {"profile": "$R", "inclination": "as-is"},
 "friction": {"coefficient": $1}, "rcf": {"shear_yield_MPa": 300}, $common}
JSON
}
single 0.3 > "$tmp/a.json"
single 0.15 > "$tmp/b.json"
cat > "$tmp/m.json" <<JSON
{"pairs": [{"name": "dry", "wheel": "$W", "rail": "$R"},
           {"name": "wet", "wheel": "$W", "rail": "$R", "friction": {"coefficient": 0.15}}],
 "inclination": "as-is", "nominal_radius_mm": 460,
 "friction": {"coefficient": 0.3}, "rcf": {"shear_yield_MPa": 300}, $common}
JSON
"$bin" run "$tmp/a.json" -o "$tmp/a" -q --format csv
"$bin" run "$tmp/b.json" -o "$tmp/b" -q --format csv
"$bin" run "$tmp/m.json" -o "$tmp/m" -q --format csv
"$py" - "$tmp" <<'PY'
import csv, sys
d = sys.argv[1]
def rows(p): return list(csv.DictReader(open(p)))
for table in ("ellipses.csv", "cases.csv"):
    M = rows(f"{d}/m/{table}")
    for pair, run in (("0", "a"), ("1", "b")):
        S = rows(f"{d}/{run}/{table}")
        P = [r for r in M if r["pair"] == pair]
        assert len(P) == len(S) and S, (table, pair, len(P), len(S))
        for p, s in zip(P, S):
            for k, v in s.items():
                assert p[k] == v, (table, pair, s.get("case"), k, p[k], v)
E = rows(f"{d}/m/ellipses.csv")
f = {pr: max(float(e["traction_coefficient"]) for e in E if e["pair"] == pr and e["traction_coefficient"]) for pr in "01"}
assert f["1"] < 0.16 < f["0"], f  # the two pairs' own friction
print(f"batch_pair_friction: pair by pair equal to the single runs (largest |F|/N {f['0']:.3f} and {f['1']:.3f})")
PY
# A pair's key against a case-file rule: exit 2, the pair's JSON path named.
sed 's/"friction": {"coefficient": 0.15}/"friction": {"coefficient": 1.5}/' "$tmp/m.json" > "$tmp/bad.json"
set +e; "$bin" run "$tmp/bad.json" -o "$tmp/x" -q 2>"$tmp/err"; rc=$?; set -e
test "$rc" -eq 2 || { echo "exit $rc, expected 2" >&2; cat "$tmp/err" >&2; exit 1; }
grep -q "/pairs/1/friction/coefficient" "$tmp/err" || { cat "$tmp/err" >&2; exit 1; }
# rcf.traction_coefficient in a pair while the manifest gives friction: the pair's path.
sed 's/"friction": {"coefficient": 0.15}/"rcf": {"traction_coefficient": 0.2, "shear_yield_MPa": 300}/' "$tmp/m.json" > "$tmp/bad2.json"
set +e; "$bin" run "$tmp/bad2.json" -o "$tmp/x" -q 2>"$tmp/err"; rc=$?; set -e
test "$rc" -eq 2 && grep -q "/pairs/1/rcf/traction_coefficient" "$tmp/err" || { cat "$tmp/err" >&2; exit 1; }
# Friction for pair 1 only (the manifest gives none): pair 0's tables would lack its columns.
cat > "$tmp/bad3.json" <<JSON
{"pairs": [{"wheel": "$W", "rail": "$R"},
           {"wheel": "$W", "rail": "$R", "friction": {"coefficient": 0.15}, "creepages": {"xi": 0.001}}],
 "inclination": "as-is", "nominal_radius_mm": 460, "sweep": {"tY_mm": [0], "Q_kN": 100}}
JSON
set +e; "$bin" run "$tmp/bad3.json" -o "$tmp/x" -q 2>"$tmp/err"; rc=$?; set -e
test "$rc" -eq 2 && grep -q "/pairs/1/friction" "$tmp/err" && grep -q "for every pair or for none" "$tmp/err" || { cat "$tmp/err" >&2; exit 1; }
echo "batch_pair_friction: errors at the pair's JSON path"
