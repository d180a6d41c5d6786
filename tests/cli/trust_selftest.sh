#!/usr/bin/env bash
# Self-test of scripts/trust_table.py: on two cases of the Manchester pair (Q = 50 kN),
# against CONTACT's table, strips and auto have no silent case; against a constructed copy of that
# table with one peak pressure raised by 30 % and one area by 25 %, every `ok` row of those two
# cases is counted silent, and --assert-targets fails.
set -euo pipefail
bin=$1; src=$2
py=/usr/bin/python3; [ -x "$py" ] || py=python3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
ref=$src/tests/data/contact/contact_mbench_right_q50_dx0.2.csv
"$py" - "$src" "$ref" "$tmp" <<'PY'
import csv, json, sys
src, ref, tmp = sys.argv[1:4]
P = src + "/tests/data/profiles/"
pair = {"name": "mbench",
        "case": {"wheel": {"profile": P + "MBench_S1002_v3.prw", "nominal_radius_mm": 460},
                 "rail": {"profile": P + "MBench_UIC60_v3.prr", "inclination": "as-is"},
                 "material": {"E_GPa": 210, "nu": 0.28}},
        "sweep": {"tY_mm": [-3, 2], "Q_kN": [50]}}
rows = list(csv.DictReader(open(ref)))
keep = [r for r in rows if float(r["y_ws_mm"]) in (-3.0, 2.0)]
assert len(keep) == 2, keep
with open(tmp + "/exact.csv", "w", newline="") as f:
    w = csv.DictWriter(f, rows[0].keys()); w.writeheader(); w.writerows(keep)
for r in keep:
    if float(r["y_ws_mm"]) == 2.0:
        r["pmax_MPa"] = str(1.30 * float(r["pmax_MPa"]))
    else:
        r["area_mm2"] = str(1.25 * float(r["area_mm2"]))
with open(tmp + "/perturbed.csv", "w", newline="") as f:
    w = csv.DictWriter(f, rows[0].keys()); w.writeheader(); w.writerows(keep)
for name in ("exact", "perturbed"):
    spec = {"tolerances": {"pmax": 0.10, "area": 0.15}, "pairs": [dict(pair, reference=name + ".csv")]}
    json.dump(spec, open("%s/%s.json" % (tmp, name), "w"))
PY
"$py" "$src/scripts/trust_table.py" "$tmp/exact.json" --mhcontact "$bin" --methods strips,auto,half-space \
  --json "$tmp/exact.out.json" --assert-targets > "$tmp/exact.txt"
if "$py" "$src/scripts/trust_table.py" "$tmp/perturbed.json" --mhcontact "$bin" --methods strips,auto,half-space \
  --json "$tmp/pert.out.json" --cases --markdown --assert-targets > "$tmp/pert.txt" 2> "$tmp/pert.err"; then
  echo "perturbed reference: --assert-targets should have failed"; exit 1
fi
grep -q 'target missed: silent cases for strips (2), auto (2)' "$tmp/pert.err"
grep -q '^| method | cases | ok |' "$tmp/pert.txt"
"$py" - "$tmp/exact.out.json" "$tmp/pert.out.json" <<'PY'
import json, sys
e, p = (json.load(open(f)) for f in sys.argv[1:3])
for m in ("strips", "auto", "half-space"):
    assert e["stats"][m]["n"] == 2 and e["stats"][m]["status"] == {"ok": 2}, (m, e["stats"][m])
    assert e["stats"][m]["silent"] == 0, (m, e["stats"][m])
    assert p["stats"][m]["silent"] == 2 and p["stats"][m]["beyond"] == 2, (m, p["stats"][m])
assert e["refsrc"] == {"CONTACT": 2, "half-space fine": 0, "none": 0}, e["refsrc"]
s = {(x["method"], x["tY"]): x for x in p["silent"]}
assert -0.25 < s[("strips", 2.0)]["dp"] < -0.2, s[("strips", 2.0)]     # 1/1.3 - 1 = -23 %
assert -0.22 < s[("strips", -3.0)]["da"] < -0.18, s[("strips", -3.0)]  # 1/1.25 - 1 = -20 %
PY
