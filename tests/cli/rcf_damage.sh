#!/usr/bin/env bash
# RCF from the computed forces (docs/outputs.md "Damage and wear columns", "Subsurface columns";
# docs/methods.md "Damage and wear functions"): with friction given, every ellipse row's
# traction_coefficient is its own |F|/N, its damage and wear are the published functions of its own
# Tgamma_N and area (re-evaluated here from their definitions, independently of the library), the
# case sums are the sums of the rows, the subsurface columns come with "subsurface", and the
# inputs that contradict each other are refused with exit code 2 naming the JSON path.
# Broken once each: damage from Tgamma_N + Tgamma_spin_N, the wear's second break from the
# literal intercept (-4778.7), and the sums over the main contact only, each failed here.
set -euo pipefail
bin=$1; src=$(cd "$2" && pwd)
py=/usr/bin/python3; [ -x "$py" ] || py=python3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
base() {  # $1: the "rcf" object, $2: extra keys
  cat <<JSON
{"wheel": {"profile": "$src/profiles/MBench_S1002_v3.prw", "nominal_radius_mm": 460},
 "rail": {"profile": "$src/profiles/MBench_UIC60_v3.prr", "inclination": "as-is"},
 "track": {"gauge_mm": 1435, "gauge_height_mm": 14, "flange_back_distance_mm": 1360, "flange_back_position_mm": -70},
 "material": {"E_GPa": 210, "nu": 0.28}, $2
 "rcf": $1,
 "sweep": {"tY_mm": [0, 2, 4, 6, 7, 8], "Q_kN": 100}}
JSON
}
fric='"friction": {"coefficient": 0.3}, "kinematics": {"speed_m_s": 30, "yaw_mrad_per_mm": 2.4},'
base '{"shear_yield_MPa": 300, "tY_distribution": {"mean_mm": 3, "sd_mm": 2}}' "$fric" > "$tmp/f.json"
"$bin" run "$tmp/f.json" -o "$tmp/f" -q --format both
"$py" - "$tmp/f" <<'PY'
import csv, math, sys
d = sys.argv[1]
E = list(csv.DictReader(open(d + "/ellipses.csv")))
C = {c["case"]: c for c in csv.DictReader(open(d + "/cases.csv"))}
assert E, "no ellipses"

def burstow(T):  # Burstow 2004: 0 to 15 J/m, up to 1e-5 at 65, down to 0 at 175
    if T <= 15 or T >= 175: return 0.0
    return 1e-5 * (T - 15) / 50 if T <= 65 else 1e-5 * (175 - T) / 110

def usfd(x):  # Lewis & Dwyer-Joyce 2004, continuous at 77.2 (docs/methods.md)
    if x < 10.4: return 5.3 * max(x, 0.0)
    if x <= 77.2: return 55.0
    return 55.0 + 61.9 * (x - 77.2)

sums = {}
regimes = set()
for e in E:
    if e["Tgamma_N"] == "": continue
    N = float(e["N_kN"]) * 1e3
    F = math.hypot(float(e["Fx_kN"]), float(e["Fy_kN"])) * 1e3
    f = F / N
    assert abs(float(e["traction_actual"]) - f) < 1e-6 * max(f, 1e-3), (e["case"], e["traction_actual"], f)
    assert abs(float(e["traction_coefficient"]) - f) < 1e-6 * max(f, 1e-3), e["case"]
    p0 = 300 * float(e["p0_el_over_k"])
    assert abs(float(e["FI_surf_el"]) - (f - 300 / p0)) < 1e-6, e["case"]
    regimes.add(e["shakedown_regime"])
    T, A = float(e["Tgamma_N"]), float(e["area_mm2"])
    D = burstow(T)
    assert abs(float(e["D_burstow_per_axle"]) - D) <= 1e-9 * 1e-5 + 1e-6 * D, (e["case"], T, e["D_burstow_per_axle"], D)
    w = usfd(T / A)
    assert abs(float(e["wear_rate_ug_per_m_mm2"]) - w) <= 1e-6 * max(w, 1), (e["case"], T / A, e["wear_rate_ug_per_m_mm2"], w)
    assert abs(float(e["wear_ug_per_m"]) - w * A) <= 1e-6 * max(w * A, 1), e["case"]
    s = sums.setdefault(e["case"], [0.0, 0.0])
    s[0] += D; s[1] += w * A
for n, (D, W) in sums.items():
    c = C[n]
    assert abs(float(c["D_burstow_per_axle"]) - D) <= 1e-6 * max(D, 1e-12), (n, c["D_burstow_per_axle"], D)
    assert abs(float(c["wear_ug_per_m"]) - W) <= 1e-6 * max(W, 1), (n, c["wear_ug_per_m"], W)
# The sweep spans the damage function: some contact damaged, and some flange contact beyond it.
assert any(float(e["D_burstow_per_axle"]) > 0 for e in E if e["D_burstow_per_axle"]), "no contact damaged"
print("rcf_damage: per-contact traction, damage, wear and case sums by their definitions;", sorted(regimes))
PY
# results.json echoes the inputs (the distribution, the constants) and carries the same keys.
grep -q '"tY_distribution"' "$tmp/f/results.json"
grep -q '"D_burstow_per_axle"' "$tmp/f/results.json"
# The damage and wear weighted by the t_Y distribution N(3 mm, 2 mm) in the run's summary
# (results.json and run.json "rcf_tY_weighted"), against the trapezoid weights computed here from
# cases.csv: node i stands for the interval between the midpoints to its neighbours.
"$py" - "$tmp/f" <<'PY'
import csv, json, math, sys
d = sys.argv[1]
C = [c for c in csv.DictReader(open(d + "/cases.csv")) if c["D_burstow_per_axle"] != ""]
t = [float(c["tY_mm"]) for c in C]
assert t == sorted(t) and len(t) >= 3, t
w = []
for i in range(len(t)):
    lo = (t[i - 1] + t[i]) / 2 if i > 0 else t[i]
    hi = (t[i] + t[i + 1]) / 2 if i + 1 < len(t) else t[i]
    w.append(math.exp(-0.5 * ((t[i] - 3) / 2) ** 2) * (hi - lo))
D = sum(wi * float(c["D_burstow_per_axle"]) for wi, c in zip(w, C)) / sum(w)
W = sum(wi * float(c["wear_ug_per_m"]) for wi, c in zip(w, C)) / sum(w)
for name in ("results.json", "run.json"):
    s = json.load(open(d + "/" + name))["summary"]["rcf_tY_weighted"]
    assert len(s) == 1 and s[0]["Q_kN"] == 100 and s[0]["cases"] == len(C), s
    assert abs(s[0]["D_burstow_per_axle"] - D) <= 1e-6 * D, (name, s[0], D)
    assert abs(s[0]["wear_ug_per_m"] - W) <= 1e-6 * W, (name, s[0], W)
    assert s[0]["tY_mean_mm"] == 3 and s[0]["tY_sd_mm"] == 2 and s[0]["tY_from_mm"] == t[0] and s[0]["tY_to_mm"] == t[-1], s
print(f"rcf_damage: t_Y-weighted damage {D:.6g} per axle, wear {W:.6g} ug/m in the summary")
PY
# The damage weighted by the t_Y distribution (scripts/plot_rcf.py), when matplotlib is present.
if "$py" -c "import matplotlib" 2>/dev/null; then
  MPLBACKEND=Agg "$py" "$src/scripts/plot_rcf.py" "$tmp/f" -o "$tmp/rcf.png" > "$tmp/plot.txt"
  grep -q "damage per axle" "$tmp/plot.txt"
  head -c 8 "$tmp/rcf.png" | od -An -c | grep -q 'P   N   G' || { echo "rcf.png is not a PNG" >&2; exit 1; }
fi
# Subsurface columns: after FI_surf_el, bounded as any stress state is, FI_sub by its definition.
base '{"shear_yield_MPa": 300, "subsurface": {"dang_van_c": 0.3}}' "$fric" | sed 's/"tY_mm": \[0, 2, 4, 6, 7, 8\]/"tY_mm": [2]/' > "$tmp/s.json"
"$bin" run "$tmp/s.json" -o "$tmp/s" -q --format csv
"$py" - "$tmp/s" <<'PY'
import csv, math, sys
E = list(csv.DictReader(open(sys.argv[1] + "/ellipses.csv")))
cols = ["sub_source", "sub_vm_max_MPa", "sub_vm_depth_mm", "sub_tau_max_MPa", "sub_tau_depth_mm", "sub_tau_orth_amp_MPa",
        "sub_tau_orth_depth_mm", "sub_tau_eq_amp_MPa", "sub_sigma_h_MPa", "FI_sub_MPa"]
h = list(E[0])
i = h.index("FI_surf_el")
assert h[i + 1:i + 1 + len(cols)] == cols, h[i + 1:i + 10]
for e in E:
    assert e["sub_source"] == "hertz_ellipse_fastsim_traction", e["sub_source"]  # friction given: FASTSIM's traction
    p0 = 300 * float(e["p0_el_over_k"])
    vm, tau = float(e["sub_vm_max_MPa"]), float(e["sub_tau_max_MPa"])
    # Any stress state: τ_max ≤ σ_vM/√3 ≤ (2/√3) τ_max; a Hertz contact's peaks 0.55–0.75 p0 (von Mises)
    assert tau <= vm / math.sqrt(3) * (1 + 1e-9) and vm / math.sqrt(3) <= 2 / math.sqrt(3) * tau * (1 + 1e-9), e
    assert 0.5 * p0 < vm < 0.8 * p0, (vm, p0)
    fi = float(e["sub_tau_eq_amp_MPa"]) + 0.3 * float(e["sub_sigma_h_MPa"])
    assert abs(float(e["FI_sub_MPa"]) - fi) < 1e-6 * abs(fi) + 1e-9, e
print("rcf_damage: subsurface columns present and consistent")
PY
# Below a grid patch's own pressure ("grid": true): a half-space patch (882 elements, about 1 s),
# without friction (then only this option keeps the patch's pressure for the columns: broken once,
# not keeping it, the row fell back to its Hertz ellipse).
base '{"traction_coefficient": 0.3, "shear_yield_MPa": 300, "subsurface": {"grid": true}}' "\"method\": \"half-space\"," |
  sed 's/"tY_mm": \[0, 2, 4, 6, 7, 8\], "Q_kN": 100/"tY_mm": [4], "Q_kN": 20/' > "$tmp/g.json"
"$bin" run "$tmp/g.json" -o "$tmp/g" -q --format csv
"$py" - "$tmp/g" <<'PY'
import csv, math, sys
P = list(csv.DictReader(open(sys.argv[1] + "/patches.csv")))
assert len(P) == 1 and P[0]["sub_source"] == "grid_patch", [p["sub_source"] for p in P]
p = P[0]
vm, tau, pmax = float(p["sub_vm_max_MPa"]), float(p["sub_tau_max_MPa"]), float(p["pmax_MPa"])
assert tau <= vm / math.sqrt(3) * (1 + 1e-9) and vm / math.sqrt(3) <= 2 / math.sqrt(3) * tau * (1 + 1e-9), p
assert 0.5 * pmax < vm < 0.8 * pmax, (vm, pmax)
assert float(p["sub_vm_depth_mm"]) >= float(p["element_mm"]), p  # searched from one element deep
print("rcf_damage: a grid patch's subsurface columns from its own pressure")
PY
# With friction given, the grid patch's own solved traction (the run keeps it for these rows).
base '{"shear_yield_MPa": 300, "subsurface": {"grid": true}}' "\"method\": \"half-space\", $fric" |
  sed 's/"tY_mm": \[0, 2, 4, 6, 7, 8\], "Q_kN": 100/"tY_mm": [4], "Q_kN": 20/' > "$tmp/gf.json"
"$bin" run "$tmp/gf.json" -o "$tmp/gf" -q --format csv
"$py" - "$tmp/gf" <<'PY'
import csv, sys
P = list(csv.DictReader(open(sys.argv[1] + "/patches.csv")))
assert len(P) == 1 and P[0]["sub_source"] == "grid_patch_solved_traction", [p["sub_source"] for p in P]
print("rcf_damage: a grid patch's subsurface columns from its own solved traction")
PY
# Contradicting inputs: exit code 2, the JSON path named.
expect_error() {  # $1: file, $2: the path the message must name
  set +e; "$bin" run "$1" -o "$tmp/x" -q 2>"$tmp/err"; rc=$?; set -e
  [ "$rc" = 2 ] || { echo "expected exit code 2, got $rc for $1" >&2; cat "$tmp/err" >&2; exit 1; }
  grep -q "$2" "$tmp/err" || { echo "message does not name $2:" >&2; cat "$tmp/err" >&2; exit 1; }
}
base '{"traction_coefficient": 0.3, "shear_yield_MPa": 300}' "$fric" > "$tmp/e1.json"
expect_error "$tmp/e1.json" "/rcf/traction_coefficient"
base '{"traction_coefficient": 0.3, "shear_yield_MPa": 300, "burstow": {"Tgamma_peak_N": 70}}' "" > "$tmp/e2.json"
expect_error "$tmp/e2.json" "/rcf/burstow"
base '{"shear_yield_MPa": 300, "burstow": {"Tgamma_peak_N": 200}}' "$fric" > "$tmp/e3.json"
expect_error "$tmp/e3.json" "/rcf/burstow"
base '{"shear_yield_MPa": 300, "tY_distribution": {"mean_mm": 0, "sd_mm": 0}}' "$fric" > "$tmp/e4.json"
expect_error "$tmp/e4.json" "/rcf/tY_distribution"
base '{"shear_yield_MPa": 300, "usfd_wear": {"x1_N_per_mm2": 90}}' "$fric" > "$tmp/e5.json"
expect_error "$tmp/e5.json" "/rcf/usfd_wear"
echo "rcf_damage: OK"
