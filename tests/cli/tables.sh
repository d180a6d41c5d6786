#!/usr/bin/env bash
# `mhcontact table` (docs/tables.md): the shipped example's exit code, summary and header, the
# Python reader of docs/tables.md run as written (its node values are those `mhcontact run`
# writes for the same node), and must-fail inputs with their messages and exit code 2.
# Usage: bash tables.sh <mhcontact binary> <source dir>
set -u
BIN="$1"; SRC="$2"
TMP="$(mktemp -d)"; trap 'rm -rf "$TMP"' EXIT
cd "$TMP" || exit 1
fail=0
check() { local what="$1"; shift; if ! "$@"; then echo "FAIL: $what"; fail=1; fi; }
PY=/usr/bin/python3; command -v "$PY" >/dev/null || PY=python3

mkdir -p out
"$BIN" table "$SRC/cases/s1002-60e1-table.json" -o out/table.csv --threads 2 2>stderr.txt
rc=$?
# Exit 1: coarse cells at flange onset and a validation point beyond a tolerance (docs/tables.md).
check "example exit 1" test $rc -eq 1
check "summary line" grep -q '^mhcontact table: 30 x 5 nodes, 14 contact tracks, .* 25 coarse cells, 0 t_Y nodes without an answer (dropped)$' stderr.txt
# The validation points (docs/tables.md "How it is made", step 6): the summary's last line and
# the header's `validation`.
check "validation line" grep -q '^mhcontact table: validation at 100 random points: ok table [0-9]*, direct [0-9]*, both [0-9]*, table and not direct [0-9]*; where both ok: .*ok answers beyond a tolerance$' stderr.txt
check "validation in the header" grep -q '"validation":{.*"points":100,' out/table.csv
check "header schema" grep -q '^# {.*"schema":"mhcontact.table/2"' out/table.csv
check "column line" test "$(sed -n 2p out/table.csv)" = "tY_mm,Q_kN,roll_mrad,status,contact,present,N_kN,y_rail_mm,z_rail_mm,y_wheel_mm,gamma_deg,r_roll_mm,pmax_MPa,area_mm2,a_mm,b_mm,a_el_mm,b_el_mm,C11,C22,C23"
check "rows: 30 x 5 nodes x 14 tracks" test "$(tail -n +3 out/table.csv | wc -l)" -eq 2100
check "no dropped nodes in the header" grep -q '"dropped_tY_mm":\[\]' out/table.csv
check "profiles with checksums" grep -q '"sha256"' out/table.csv
# The same table whatever the thread count.
"$BIN" table "$SRC/cases/s1002-60e1-table.json" -o out/table1.csv --threads 1 -q
check "thread count" cmp out/table.csv out/table1.csv

# The Python reader of docs/tables.md, as written.
awk '/^```python/ { b = 1; next } /^```/ { b = 0 } b' "$SRC/docs/tables.md" > reader.py
check "reader extracted" grep -q "def read_table" reader.py
"$PY" reader.py > reader.txt 2>&1
check "reader runs" test $? -eq 0
check "reader header line" grep -q '^strips 30 x 5 nodes, 14 tracks; N within ' reader.txt
# Its rows at t_Y = 6 mm, Q = 60 kN against `mhcontact run` of that node (patches.csv).
"$PY" - "$SRC/cases/s1002-60e1-table.json" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
c["sweep"] = {"tY_mm": [6], "Q_kN": [60]}
json.dump(c, open("node.json", "w"))
PY
"$BIN" run node.json -o run6 -q --digits max
check "reader rows are the run's patches" "$PY" - <<'PY'
import csv, sys
rows = [l.split() for l in open("reader.txt").read().splitlines()[1:]]
patches = list(csv.DictReader(open("run6/patches.csv")))
if len(rows) != len(patches) or not rows:
    sys.exit(f"{len(rows)} rows against {len(patches)} patches")
for r, p in zip(sorted(rows, key=lambda r: float(r[3])), sorted(patches, key=lambda p: float(p["y_rail_mm"]))):
    for a, b in ((float(r[1]), float(p["N_kN"])), (float(r[2]), float(p["pmax_MPa"])), (float(r[3]), float(p["y_rail_mm"]))):
        if abs(a - b) > 1e-9 * max(1.0, abs(b)):
            sys.exit(f"reader {r} against run {p['N_kN']}, {p['pmax_MPa']}, {p['y_rail_mm']}")
PY

# The force-history plot of docs/tables.md on a small history in the bench's columns (headless).
if "$PY" -c 'import matplotlib' 2>/dev/null; then
  printf 'step,tY_mm,N1_kN,N2_kN,Fy_table_kN,dFy_dtY_kN_per_mm,Fy_direct_kN,status_table\n0,0,10,0,1,0,1,ok\n1,0.5,8,2,2,1,,ok\n2,1,5,5,3,1,3.1,outside_validity\n' > hist.csv
  MPLBACKEND=Agg "$PY" "$SRC/scripts/plot_table_history.py" hist.csv -o hist.png --steps 0:2
  check "history plot written" test -s hist.png
fi

# The export for MBS codes (docs/tables.md "Export for MBS codes"): a regular grid, the source's
# checksum in its header, the measured error; a step that does not divide the range refused.
"$BIN" table-export out/table.csv -o out/export.csv --tY-step-mm 0.25 --Q-step-kN 10 2>stderr.txt
check "export exit 0" test $? -eq 0
check "export summary" grep -q '^mhcontact table-export: 57 x 13 points, 14 contact tracks; linear error at the table.s ok nodes, ' stderr.txt
check "export schema" grep -q '^# {.*"schema":"mhcontact.table-export/2"' out/export.csv
check "export names the table's checksum" grep -q "\"sha256\":\"$(sha256sum out/table.csv | cut -c1-64)\"" out/export.csv
check "export columns: the table's" test "$(sed -n 2p out/export.csv)" = "$(sed -n 2p out/table.csv)"
check "rows: 57 x 13 points x 14 tracks" test "$(tail -n +3 out/export.csv | wc -l)" -eq 10374
"$BIN" table-export out/table.csv -o out/x.csv --tY-step-mm 0.3 2>err.txt; rc=$?
check "export step refused (exit 2)" test $rc -eq 2
check "export step message" grep -q -- '--tY-step-mm: value 0.3.*must divide the table.s range -4 ... 10 mm' err.txt
"$BIN" table-export "$SRC/cases/s1002-60e1-table.json" -o out/x.csv 2>err.txt; rc=$?
check "export of a non-table refused (exit 2)" test $rc -eq 2

# Shards (docs/tables.md "Shards"): the merged table byte for byte the one-process table.
cp "$SRC/tests/data/tables/worn-table-q.json" q.json
sed -i "s|\.\./profiles|$SRC/tests/data/profiles|g" q.json
"$BIN" table q.json -o out/q.csv -q --threads 2
for k in 1 2; do "$BIN" table q.json --shard $k/2 -o out/q$k.json -q --threads 2; done
"$BIN" table q.json --merge out/q2.json out/q1.json -o out/q-merged.csv -q --threads 2
check "sharded table = one-process table" cmp out/q.csv out/q-merged.csv
"$BIN" table q.json --merge out/q1.json out/q2.json --next out/q-next.json -o out/q-x.csv -q; rc=$?
check "merge --next: the refinement's points needed (exit 5)" test $rc -eq 5
check "merge --next: no table written" test ! -e out/q-x.csv
check "merge --next: the points of pass 1" grep -q '"pass":1,.*"schema":"mhcontact.table-points/1"' out/q-next.json
"$BIN" table q.json --points out/q-next.json -o out/q-x.csv 2>err.txt; rc=$?
check "--points without --shard refused" test $rc -ge 100
"$BIN" table q.json --merge out/q1.json -o out/x.csv 2>err.txt; rc=$?
check "missing shard refused (exit 2)" test $rc -eq 2
check "missing shard message" grep -q 'shard 2/2 is missing' err.txt
# A validation point where the table answers ok beyond a tolerance is a known miss: exit 1 (the
# worn pair's table, exit 0 with the default 100 points, finds 2 at 1,000; 1 Dec 2026).
cp "$SRC/tests/data/tables/worn-table.json" worn.json
sed -i "s|\.\./profiles|$SRC/tests/data/profiles|g" worn.json
"$BIN" table worn.json -o out/worn.csv -q --threads 2; rc=$?
check "worn table, 100 validation points: exit 0" test $rc -eq 0
"$BIN" table worn.json -o out/worn1000.csv --threads 2 --validate 1000 2>err.txt; rc=$?
check "worn table, 1,000 validation points: exit 1" test $rc -eq 1
check "worn table, 1,000 validation points: the misses counted" grep -q '^mhcontact table: validation at 1000 random points: .*; [1-9][0-9]* ok answers beyond a tolerance$' err.txt
check "worn table, 1,000 validation points: no coarse cell" grep -q ' 0 coarse cells, 0 t_Y nodes without an answer' err.txt
# --validate 0 leaves the validation points out; shards made with another --validate are refused
# (the first round's points differ).
"$BIN" table q.json -o out/q0.csv -q --refine 0 --validate 0
check "--validate 0: no validation" bash -c '! grep -q "\"validation\"" out/q0.csv'
"$BIN" table q.json --shard 1/1 --validate 7 -o out/q7.json -q
"$BIN" table q.json --merge out/q7.json -o out/x.csv 2>err.txt; rc=$?
check "shard of another --validate refused (exit 2)" test $rc -eq 2
check "shard of another --validate: message" grep -q '/validate.*--validate differs' err.txt
"$BIN" table q.json -o out/x.csv --validate -3 2>err.txt; rc=$?
check "--validate -3 refused" test $rc -ne 0 -a $rc -ne 1

# Must-fail inputs: exit 2, the message names the file and the rule.
cp "$SRC/cases/manchester.json" mh.json
sed -i "s|\.\./profiles|$SRC/profiles|g" mh.json
"$BIN" table mh.json -o out/x.csv 2>err.txt; rc=$?
check "multi-hertzian refused (exit 2)" test $rc -eq 2
check "multi-hertzian message" grep -q 'mh.json: /method: value multi-hertzian: a table is made by a grid method' err.txt
sed 's/"method": "multi-hertzian"/"method": "strips"/; s/"Q_kN": \[[^]]*\]/"Q_kN": [50]/' mh.json > one_q.json
grep -q '"method"' one_q.json || sed -i 's/"model": "elastic",/"model": "elastic", "method": "strips",/' one_q.json
"$BIN" table one_q.json -o out/x.csv 2>err.txt; rc=$?
check "one load refused (exit 2)" test $rc -eq 2
check "one load message" grep -q 'one_q.json: /sweep: a table needs a sweep with at least two t_Y and two Q values' err.txt
check "nothing written on bad input" test ! -e out/x.csv

# The roll is an axis of tables only: `run` refuses it, naming the key (exit 2).
sed 's/"Q_kN": \[[^]]*\]/"Q_kN": [50], "roll_mrad": [0, 1]/' mh.json > roll_run.json
"$BIN" run roll_run.json -o out/rr 2>err.txt; rc=$?
check "run with a roll axis refused (exit 2)" test $rc -eq 2
check "run with a roll axis message" grep -q 'roll_run.json: /sweep/roll_mrad: value 0: the roll is an axis of contact tables' err.txt
# A roll axis of a table: its nodes in the summary, the column, the header.
sed 's/"tY_mm": {[^}]*}/"tY_mm": [0, 1]/; s/"Q_kN": \[[^]]*\]/"Q_kN": [40, 80], "roll_mrad": [-1, 0, 1]/' one_q.json > roll.json
"$BIN" table roll.json -o out/roll.csv --refine 0 2>err.txt
check "roll table summary" grep -q '^mhcontact table: 2 x 2 x 3 nodes, ' err.txt
check "roll table nodes in the header" grep -q '"roll_mrad_nodes":\[-1.0,0.0,1.0\]' out/roll.csv
check "roll table rows: roll outer" test "$(sed -n 3p out/roll.csv | cut -d, -f1-3)" = "0,40,-1"
# A wheelset table of that pair on both wheels (docs/tables.md "A wheelset table"): three header
# lines (its own, then each pair's), the pair's text twice; what is refused, exit 2.
"$BIN" table-wheelset out/roll.csv out/roll.csv -o out/ws.csv 2>err.txt; rc=$?
check "table-wheelset exit 0" test $rc -eq 0
check "table-wheelset summary" grep -q '^mhcontact table-wheelset: left 2 x 2 x 3 nodes, roll -1 ... 1 mrad; right 2 x 2 x 3 nodes' err.txt
check "table-wheelset: each pair's validation" grep -q '^mhcontact table-wheelset: validation: left both ok at [0-9]* of 100 points, [0-9]* beyond a tolerance, table ok and direct not [0-9]*; right both ok at ' err.txt
"$BIN" table roll.json -o out/roll0.csv --refine 0 --validate 0 -q
"$BIN" table-wheelset out/roll.csv out/roll0.csv -o out/ws0.csv 2>err.txt
check "table-wheelset: a table without validation said" grep -q 'right none (made with --validate 0 or --no-check)$' err.txt
check "wheelset table: three header lines" test "$(grep -c '^#' out/ws.csv)" -eq 3
check "wheelset table: the pair's text twice" cmp <(tail -n +2 out/ws.csv) <(cat out/roll.csv out/roll.csv)
sed '1s/,"wheelset_placement":{[^}]*}//' out/roll.csv > old_table.csv
"$BIN" table-wheelset old_table.csv out/roll.csv -o out/ws2.csv 2>err.txt; rc=$?
check "table-wheelset: a table without placement refused (exit 2)" test $rc -eq 2
check "table-wheelset: its message" grep -q 'old_table.csv:1: the table.s header has no wheelset_placement' err.txt
check "table-wheelset: nothing written" test ! -e out/ws2.csv
"$BIN" table-export out/ws.csv -o out/x.csv 2>err.txt; rc=$?
check "table-export of a wheelset table refused (exit 2)" test $rc -eq 2
check "table-export of a wheelset table: the hint" grep -q 'a wheelset table (two pairs. tables): give one pair.s table' err.txt

test $fail -eq 0 && echo "tables: OK"
exit $fail
