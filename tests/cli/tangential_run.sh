#!/usr/bin/env bash
# The tangential problem through `run` (docs/tangential.md): with friction and kinematics the
# tables end with the tangential columns (forces on the rail, Tγ = Fx ξ + Fy η, Y_kN = Fy_kN + Fy_creep_kN,
# Y_over_Q = Y_kN / Fz_kN), the worked example of docs/tangential.md prints what the page shows;
# the strip method fills them too (its patches solved exactly on the strips' pressure:
# tests/unit/contact/test_strips_tangential.cpp); without friction no column is
# added. Breaks seen to fail: the sign of the output forces flipped (Tgamma check), Y_over_Q
# without the creep forces (Y check).
set -euo pipefail
bin=$1; src=$(cd "$2" && pwd)
py=/usr/bin/python3; [ -x "$py" ] || py=python3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cp -r "$src/cases" "$src/profiles" "$tmp/"
cd "$tmp"
"$bin" run cases/manchester-tangential.json -o out/t -q
"$py" - cases/manchester-tangential.json <<'PY' > strips.json
import json, sys
j = json.load(open(sys.argv[1])); j["method"] = "strips"; j["sweep"]["tY_mm"] = [0]
json.dump(j, sys.stdout)
PY
sed -i 's#"\.\./profiles/#"profiles/#g' strips.json
"$bin" run strips.json -o out/s -q || true
"$bin" run cases/manchester.json -o out/plain -q
"$py" - <<'PY'
import csv, math
def rows(p): return list(csv.DictReader(open(p)))
c, e = rows("out/t/cases.csv"), rows("out/t/ellipses.csv")
geo = {(r["tY_mm"], r["ellipse"]): r for r in rows("out/t/geometry.csv")}
for col in ("Fx_kN", "Fy_creep_kN", "Mz_Nm", "F_over_muN", "Y_kN"): assert col in c[0], col
for col in ("xi", "eta", "phi_per_mm", "Fx_kN", "Fy_kN", "Mz_Nm", "adhesion_fraction", "Tgamma_N", "Tgamma_spin_N"): assert col in e[0], col
for r in c:
    assert r["status"] in ("ok", "outside_validity"), r["status"]
    Y = float(r["Y_kN"])
    assert abs(Y - (float(r["Fy_kN"]) + float(r["Fy_creep_kN"]))) < 1e-9 * max(1, abs(Y))
    assert abs(float(r["Y_over_Q"]) - Y / float(r["Fz_kN"])) < 1e-9
    assert 0 <= float(r["F_over_muN"]) <= 1 + 1e-9
for r in e:
    # forces on the rail: Tγ = Fx ξ + Fy η (the Fy of spin may make it negative at small η)
    tg = float(r["Fx_kN"]) * 1e3 * float(r["xi"]) + float(r["Fy_kN"]) * 1e3 * float(r["eta"])
    assert abs(tg - float(r["Tgamma_N"])) <= 1e-6 * max(1, abs(tg)), (tg, r["Tgamma_N"])
    assert 0 <= float(r["adhesion_fraction"]) <= 1
    # yaw 2.4 mrad per mm of t_Y: η = −ψ (r / r0) / cos γ = −ψ R_wyy / r0 (R_wyy = r / cos γ, method.md §2, §10)
    psi = 2.4e-3 * float(r["tY_mm"])
    Rwyy = float(geo[(r["tY_mm"], r["ellipse"])]["R_wyy_mm"])
    assert abs(float(r["eta"]) + psi * Rwyy / 460) <= 1e-9 + 1e-6 * abs(psi), (r["eta"], psi, Rwyy)
s = rows("out/s/cases.csv"); p = rows("out/s/patches.csv")
# The strip method solves each patch's tangential problem on its strips' pressure (exact solver).
assert all("tangential_unsupported" not in r["warnings"] and r["Fx_kN"] != "" for r in s)
assert all(r["Fx_kN"] != "" and r["xi"] != "" and 0 <= float(r["adhesion_fraction"]) <= 1 for r in p)
assert all(0 < float(r["F_over_muN"]) <= 1 + 1e-9 for r in s)
plain = rows("out/plain/cases.csv")
assert "Fx_kN" not in plain[0] and "Y_kN" not in plain[0]
print("tangential_run: ok")
PY
