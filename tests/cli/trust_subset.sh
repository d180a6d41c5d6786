#!/usr/bin/env bash
# The field trust table's targets (issue 23 §3) on a subset: the measured MiniProf pair
# avg_wheel.whl on avg_HR.BAN (1:40) at t_Y = 2 mm / 20 kN, 6 mm / 60 kN, 10 mm / 120 kN against
# the stored CONTACT table (tests/data/contact/field, README there): no `ok` row of strips or auto
# more than 10 % off in peak pressure or 15 % in area, and every multi-Hertzian row beyond those
# tolerances not `ok` (scripts/trust_table.py --assert-targets).
# Expected to FAIL until issue 23 §1 (smoothing of measured profiles) is in: on 2025-11-25
# (1106cab) strips and auto are 11-13 % high in peak pressure on these cases (docs/trust.md).
# tests/cli/trust_selftest.sh checks the instrument itself.
set -euo pipefail
bin=$1; src=$2
py=/usr/bin/python3; [ -x "$py" ] || py=python3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$py" "$src/scripts/trust_table.py" "$src/tests/data/contact/field/trust.json" --mhcontact "$bin" \
  --pairs avg_wheel/avg_HR --only 2:20,6:60,10:120 --methods multi-hertzian,strips,auto \
  --json "$tmp/t.json" --cases --assert-targets
# Every case had the CONTACT reference (none fell back to the half-space method).
"$py" -c 'import json,sys; r=json.load(open(sys.argv[1]))["refsrc"]; assert r=={"CONTACT":3,"half-space fine":0,"none":0}, r' "$tmp/t.json"
