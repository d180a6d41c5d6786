#!/usr/bin/env bash
# Every command example of README.md and of the docs pages (the ```sh blocks of docs/*.md), run
# as written, in a scratch copy of the repository's cases/, profiles/, scripts/, tests/ref/ and
# tests/data/contact/, tables/ and profiles/
# with build/mhcontact pointing at the binary under test. Each block below names the page it
# comes from; the last block checks that no ```sh command of those pages is missing here, and
# that the outputs the README shows are what the commands print.
set -euo pipefail
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
self=$(cd "$(dirname "$0")" && pwd)/$(basename "$0")
mkdir -p "$tmp/build" "$tmp/tests" "$tmp/expect"
cp -r "$src/cases" "$src/profiles" "$src/scripts" "$tmp/"
cp -r "$src/tests/ref" "$tmp/tests/"
mkdir -p "$tmp/tests/data" && cp -r "$src/tests/data/contact" "$src/tests/data/tables" "$src/tests/data/profiles" "$tmp/tests/data/"
ln -s "$bin" "$tmp/build/mhcontact"
# The binary is already built: the quick start's build step (scripts/build.sh, which CI runs
# through scripts/test.sh) is a no-op in the scratch copy.
printf '#!/usr/bin/env bash\nexit 0\n' > "$tmp/scripts/build.sh"
cd "$tmp"
export MPLBACKEND=Agg
have_mpl() { "$1" -c 'import matplotlib' 2>/dev/null; }
# The fenced block that follows the ```sh block holding the command line $2 in page $1: the
# output the page shows for it.
shown_output() {
  awk -v cmd="$2" '
    state == 0 && $0 == cmd { state = 1; next }
    state == 1 && /^```/ { state = 2; next }
    state == 2 && /^```/ { state = 3; next }
    state == 3 && /^```/ { exit }
    state == 3 { print }' "$src/$1"
}
set -x

# --- README.md, "Quick start" (the second command, bash scripts/test.sh, is what CI runs) ------
bash scripts/quickstart.sh
test -s out/manchester/cases.csv

# --- README.md, "A worked example"; docs/cli.md, "run" ----------------------------------------
./build/mhcontact run cases/manchester.json -o out/manchester 2> "$tmp/run.err"
for f in cases.csv ellipses.csv geometry.csv results.json profiles.csv run.json; do test -s "out/manchester/$f"; done
grep -E '^(case|26|68|86),' out/manchester/cases.csv | cut -d, -f2-4,10,14-16 > "$tmp/cases.txt"
grep -E '^(case|68),' out/manchester/ellipses.csv | cut -d, -f4,6-9 > "$tmp/ellipses.txt"
# The outputs the README shows are the commands' outputs (the run's time masked).
shown_output README.md "./build/mhcontact run cases/manchester.json -o out/manchester" | sed 's/; [0-9.]* s;/; T s;/' > "$tmp/expect/run.err"
tail -n 1 "$tmp/run.err" | sed 's/; [0-9.]* s;/; T s;/' | diff "$tmp/expect/run.err" -
shown_output README.md "grep -E '^(case|26|68|86),' out/manchester/cases.csv | cut -d, -f2-4,10,14-16" | diff - "$tmp/cases.txt"
shown_output README.md "grep -E '^(case|68),' out/manchester/ellipses.csv | cut -d, -f4,6-9" | diff - "$tmp/ellipses.txt"
test -s "$tmp/cases.txt" && test -s "$tmp/ellipses.txt"
# docs/case-file.md's table of shipped cases states the Manchester run's counts: those of the run.
counts=$(tail -n 1 "$tmp/run.err" | sed -n 's/.*99 cases, ok \([0-9]*\), outside_validity \([0-9]*\),.*/\1 `ok`, \2 `outside_validity`/p')
test -n "$counts" && grep -qF "99 cases: $counts" "$src/docs/case-file.md"

# --- README.md, "Commands"; docs/cli.md, "run", "geometry", "hertz", "diff"; docs/plots.md -----
./build/mhcontact run cases/manchester-plastic.json -o out/mp --pressure-grid 21
./build/mhcontact run cases/manchester-strips.json -o out/manchester-strips --strips
test -s out/manchester-strips/strips.csv
./build/mhcontact geometry cases/manchester.json -o out/geo
./build/mhcontact hertz --R-wyy 460 --R-rxx 300 --N 100 --E 210 --nu 0.3 | grep -q "^a = 7.16"
./build/mhcontact diff tests/ref/manchester/cases.csv out/manchester/cases.csv --rtol 1e-7 --atol 1e-9
./build/mhcontact profile info profiles/MBench_UIC60_v3.prr
./build/mhcontact profile generate 60E1 --inclination 1:40 -o 60E1_1-40.csv
cmp 60E1_1-40.csv profiles/60E1_1-40.csv
bash scripts/run_sharded.sh cases/manchester.json out/study 8 2
cmp out/study/cases.csv out/manchester/cases.csv
if have_mpl /usr/bin/python3; then
  /usr/bin/python3 scripts/plot_pressure.py out/mp --case 23
  test -s out/mp/pressure_case_23.png
fi

# --- docs/cli.md, "run", "hertz", "diff" ------------------------------------------------------
./build/mhcontact run cases/manchester-halfspace.json -o out/hs-flange --pressure-grid 2 --pressure-cases 13-14
test "$(cut -d, -f1 out/hs-flange/pressure.csv | tail -n +2 | sort -u | tr '\n' ' ')" = "13 14 "
./build/mhcontact hertz --R-wyy 460 --R-rxx 300 --N 100 --E 210 --nu 0.3 --p-lim 800 --json | grep -q '"a_mm": 7.748'
./build/mhcontact hertz --A 0.001 --B 0.002 --N 10 --E 210 --nu 0.28 --json
./build/mhcontact run cases/manchester.json -o out/manchester --format csv -q
./build/mhcontact diff tests/ref/manchester/ellipses.csv out/manchester/ellipses.csv --column-tol p0_MPa=0.5

# --- README.md, "Commands": the wheelset of EN 15302 wheel A on rail A -------------------------
# Exit 1: the standard's amplitudes 5 ... 7.4 mm lie beyond the pair's flangeway clearance
# (flange_contact, docs/wheelset.md "Where the conicity is ok"); the files are written.
set +e
./build/mhcontact wheelset cases/en15302-wheel-a.json -o out/en15302; test $? -eq 1 || exit 1
set -e
grep -q '^y_mm,' out/en15302/wheelset.csv && test -s out/en15302/conicity.csv

# --- docs/status.md, "Failing a run on warnings", "Comparing tables" ---------------------------
./build/mhcontact run cases/manchester.json -o out/m -q --fail-on off_profile,non_hertzian_excluded,pressure_spike,strip_outlier,cant
./build/mhcontact diff tests/ref/manchester/cases.csv out/m/cases.csv --rtol 1e-2 --ignore-columns residual,iterations

# --- docs/methods.md, "Yield stress as input": two rail steels ----------------------------------
./build/mhcontact hertz --R-wyy 460 --R-rxx 300 --N 150 --E 210 --nu 0.3 --yield 500
./build/mhcontact hertz --R-wyy 460 --R-rxx 300 --N 150 --E 210 --nu 0.3 --yield 800

# --- docs/methods.md, "Damage and wear functions": the worked example -----------------------------
./build/mhcontact run cases/manchester-rcf.json -o out/manchester-rcf
grep -q '^case,tY_mm,Q_kN,ellipse' out/manchester-rcf/ellipses.csv
if have_mpl /usr/bin/python3; then
  /usr/bin/python3 scripts/plot_rcf.py out/manchester-rcf -o out/rcf.png
  test -s out/rcf.png
fi

# --- docs/methods.md, "Half-space", "Strips", "Comparing the methods" --------------------------
./build/mhcontact run cases/manchester-halfspace.json -o out/manchester-halfspace
test "$(wc -l < out/manchester-halfspace/patches.csv)" -eq 18
./build/mhcontact run cases/manchester-strips.json -o out/manchester-strips --strips
if have_mpl /usr/bin/python3; then
  /usr/bin/python3 scripts/compare_methods.py cases/manchester-halfspace.json -o out/compare.png
  test -s out/compare.png
fi

# --- docs/strips.md, "Three methods against CONTACT" ------------------------------------------
if have_mpl /usr/bin/python3; then
  /usr/bin/python3 scripts/compare_methods.py cases/manchester-halfspace.json \
    --methods multi-hertzian,strips,half-space,auto \
    --reference tests/data/contact/contact_mbench_right_q50_dx0.2.csv -o compare.png --table compare.csv
  test -s compare.csv
fi

# --- docs/tangential.md, "Worked example": creep forces of a yawed wheelset -------------------
./build/mhcontact run cases/manchester-tangential.json -o out/tangential
grep -q ',Fx_kN,Fy_creep_kN,Mz_Nm,F_over_muN,Y_kN,Fz_creep_kN,D_burstow_per_axle,wear_ug_per_m$' <(head -1 out/tangential/cases.csv)

# --- docs/wheelset-dynamics.md, "Running it" (built only when SUNDIALS is found) ---------------
dyn=$(dirname "$bin")/examples/wheelset_dynamics/wheelset_dynamics
if [ -x "$dyn" ]; then
  mkdir -p build/examples/wheelset_dynamics tests/data/profiles
  ln -s "$dyn" build/examples/wheelset_dynamics/wheelset_dynamics
  cp "$src/tests/data/profiles/worn_high_mileage.prw" tests/data/profiles/
  mkdir -p out/dyn
  ./build/examples/wheelset_dynamics/wheelset_dynamics klingel --amplitude-mm 4 --distance 60 --csv out/dyn/klingel.csv --half-cycles out/dyn/klingel_half_cycles.csv
  ./build/examples/wheelset_dynamics/wheelset_dynamics critical --csv out/dyn/critical.csv
  ./build/examples/wheelset_dynamics/wheelset_dynamics worn --wheel tests/data/profiles/worn_high_mileage.prw --distance 30
  test -s out/dyn/klingel_half_cycles.csv && test -s out/dyn/critical.csv
  if have_mpl python3; then
    python3 scripts/plot_wheelset_dynamics.py out/dyn -o docs/img
    test -s docs/img/wheelset_dynamics_klingel.png && test -s docs/img/wheelset_dynamics_critical.png
  fi
else
  echo "readme_examples: $dyn not built (no SUNDIALS): docs/wheelset-dynamics.md's commands not run"
fi

# --- docs/profiles.md, "8. The profile commands" ----------------------------------------------
./build/mhcontact profile info profiles/MBench_S1002_v3.prw
./build/mhcontact profile info profiles/MBench_UIC60_v3.prr --json
./build/mhcontact profile convert profiles/MBench_S1002_v3.prw -o s1002.csv
./build/mhcontact profile generate S1002 -o S1002.csv
cmp S1002.csv profiles/S1002.csv

# --- docs/batch-and-shards.md (the Slurm lines are tested by tests/cli/sharded_scripts.sh, with
# the array task number set by hand) ------------------------------------------------------------
./build/mhcontact run cases/fleet.json -o out/fleet
if command -v parallel >/dev/null && parallel --version 2>/dev/null | grep -q "GNU parallel"; then
  parallel ./build/mhcontact run cases/manchester.json -o out/par.shards/shard{} --shard {}/8 -q ::: 1 2 3 4 5 6 7 8
  ./build/mhcontact merge out/par.shards/shard* -o out/par
  cmp out/par/cases.csv out/manchester/cases.csv
fi
for k in 1 2 3; do ./build/mhcontact run cases/fleet.json -o out/fc.shards/shard$k --shard $k/3 --shard-by cases -q; done
./build/mhcontact merge out/fc.shards/shard* -o out/fc
cmp out/fc/results.json out/fleet/results.json

# --- docs/cluster.md, "A resumable fleet" (the Slurm lines are run by tests/cluster/slurm.sh on a
# private Slurm, the Dask example by python/tests/test_fleet_dask.py) --------------------------------
./build/mhcontact run cases/fleet.json -o out/fleet-resumable --resume
cmp out/fleet-resumable/cases.csv out/fleet/cases.csv

# --- docs/plots.md --------------------------------------------------------------------------
if have_mpl /usr/bin/python3; then
  /usr/bin/python3 scripts/plot_geometry.py out/geo --tY 5
  test -s out/geo/geometry_caf.png && test -s out/geo/geometry_profiles.png
  ./build/mhcontact run cases/manchester-halfspace.json -o out/hs --pressure-grid 2
  /usr/bin/python3 scripts/plot_pressure.py out/hs --case 13
  test -s out/hs/pressure_case_13.png
  /usr/bin/python3 scripts/plot_pressure.py out/fleet --pair 0 --case 23
  /usr/bin/python3 scripts/plot_geometry.py out/fleet --pair 1
  test -s out/fleet/pressure_case_23_pair_0.png && test -s out/fleet/geometry_pair_1_caf.png
  ./build/mhcontact run cases/manchester-rcf.json -o out/traction --pressure-grid 41 --pressure-cases 1
  /usr/bin/python3 scripts/plot_traction.py out/traction --case 1
  test -s out/traction/traction_case_1.png
fi

# --- docs/tables.md, "Making a table": exit 1 (a coarse cell, nodes without an answer); the
# summary the page shows is what the command prints --------------------------------------------
./build/mhcontact table cases/s1002-60e1-table.json -o out/table.csv 2> "$tmp/table.err" || test $? -eq 1
test -s out/table.csv
shown_output docs/tables.md "./build/mhcontact table cases/s1002-60e1-table.json -o out/table.csv" | diff - <(grep '^mhcontact table:' "$tmp/table.err")

# --- docs/tables.md, "Export for MBS codes" and "Shards": the export's summary is the page's; the
# merged shards are byte for byte the table above ---------------------------------------------
./build/mhcontact table-export out/table.csv -o out/export.csv 2> "$tmp/export.err"
shown_output docs/tables.md "./build/mhcontact table-export out/table.csv -o out/export.csv" | diff - "$tmp/export.err"
./build/mhcontact table cases/s1002-60e1-table.json --shard 1/2 -o out/table-part1.json
./build/mhcontact table cases/s1002-60e1-table.json --shard 2/2 -o out/table-part2.json
./build/mhcontact table cases/s1002-60e1-table.json --merge out/table-part1.json out/table-part2.json -o out/table-merged.csv || test $? -eq 1
cmp out/table.csv out/table-merged.csv
# The refinement's passes in shards too: the merge with --next exits 5 until the parts hold every
# point; then the table (exit 1: its coarse cells), byte for byte the table above.
for k in 1 2; do ./build/mhcontact table cases/s1002-60e1-table.json --shard $k/2 -o out/pass0-$k.json; done
pass=0
until ./build/mhcontact table cases/s1002-60e1-table.json --merge out/pass*-*.json --next out/next.json -o out/table-passes.csv; [ $? -ne 5 ]; do
pass=$((pass + 1))
test $pass -le 20  # a merge that never completes fails here, not in an endless loop
for k in 1 2; do ./build/mhcontact table cases/s1002-60e1-table.json --shard $k/2 --points out/next.json -o out/pass$pass-$k.json; done
done
cmp out/table.csv out/table-passes.csv
# --- docs/tables.md, "Roll": the roll tables' summaries are the page's (the S1002 one exit 1: its
# coarse cells) ---------------------------------------------------------------------------------
./build/mhcontact table cases/s1002-60e1-roll-table.json -o out/table-roll.csv 2> "$tmp/roll.err" || test $? -eq 1
shown_output docs/tables.md "./build/mhcontact table cases/s1002-60e1-roll-table.json -o out/table-roll.csv" | diff - <(grep '^mhcontact table:' "$tmp/roll.err")
./build/mhcontact table tests/data/tables/worn-table-roll.json -o out/table-roll-worn.csv 2> "$tmp/roll-worn.err"
shown_output docs/tables.md "./build/mhcontact table tests/data/tables/worn-table-roll.json -o out/table-roll-worn.csv" | diff - <(grep '^mhcontact table:' "$tmp/roll-worn.err")
# --- docs/tables.md, "A wheelset table": the two roll tables above joined, its summary the page's
./build/mhcontact table-wheelset out/table-roll-worn.csv out/table-roll.csv -o out/wheelset-table.csv 2> "$tmp/wheelset-table.err"
shown_output docs/tables.md "./build/mhcontact table-wheelset out/table-roll-worn.csv out/table-roll.csv -o out/wheelset-table.csv" | diff - "$tmp/wheelset-table.err"
# --- docs/tables.md, "Checking a table at random points": the S1002 roll table above against
# direct solves (exit 1: some ok answers beyond tolerance), where python3 has numpy and the
# module is built (CI's Debian python3 has both; the figures of the page come from a run there)
if [ -d "$(dirname "$bin")/python/mhcontact" ] && python3 -c 'import numpy' 2>/dev/null; then
  ln -s "$(dirname "$bin")/python" build/python
  PYTHONPATH=build/python python3 scripts/check_table.py out/table-roll.csv cases/s1002-60e1-roll-table.json --points 300 --seed 2 > "$tmp/check.out" || test $? -eq 1
  grep -q '^ok: direct [0-9]*, table [0-9]*, both [0-9]*' "$tmp/check.out"
  grep -q '^ok answers beyond a tolerance: [0-9]* of [0-9]*$' "$tmp/check.out"
else
  echo "readme_examples: python3 without numpy or the module: scripts/check_table.py not run"
fi

# --- docs/cli.md, "Exit codes": a failing case gives 1, bad input 2, CLI syntax >= 100 --------
set +e
./build/mhcontact run /nonexistent.json -o out/x 2>/dev/null; test $? -eq 2 || exit 1
./build/mhcontact run --no-such-option 2>/dev/null; rc=$?; test $rc -ge 100 || exit 1
./build/mhcontact --version | grep -q "^mhcontact " || exit 1
set -e
set +x

# --- The shipped case files shown in the pages are the files (their "comment" aside) -----------
python3 - "$src" <<'PY'
import json, os, re, sys
src = sys.argv[1]
for page in ["README.md"] + ["docs/" + f for f in sorted(os.listdir(os.path.join(src, "docs"))) if f.endswith(".md")]:
    text = open(os.path.join(src, page), encoding="utf-8").read()
    for m in re.finditer(r"`(cases/[\w.-]+\.json)`:\s*\n\s*\n```json\n(.*?)\n```", text, re.S):
        shown = json.loads(m.group(2))
        actual = json.load(open(os.path.join(src, m.group(1)), encoding="utf-8"))
        shown.pop("comment", None); actual.pop("comment", None)
        if shown != actual:
            sys.exit(f"readme_examples: {page} shows {m.group(1)} otherwise than the file")
PY

# --- Every command of a ```sh block of README.md and docs/*.md is run above ---------------------
# (continuation lines joined, trailing comments dropped; a command counts as run when a line of
# this script is the command, possibly followed by a redirection or a pipe). Not run here:
# bash scripts/test.sh (it is what CI runs, and runs this test), the Slurm lines (see above; the
# contact table's passes on Slurm, docs/cluster.md: tests/cluster/slurm_table.sh runs that loop),
# bash scripts/fuzz.sh (run by scripts/test.sh for 10 s a target; the docs show longer runs),
# the callgrind command of docs/performance.md (a template with CASE.json and OUT), and the
# plastic comparison that regenerates a table of docs/half_space.md (13 s of CPU for the capped
# half-space solves of 33 cases, several times that under the sanitizers; run it by hand when
# that table is updated), and the field trust table of docs/trust.md (every method on 164 cases and
# a 0.1 mm half-space reference: minutes of CPU; tests/cli/trust_selftest.sh and trust_subset.sh
# run the same script on a few cases), and the pip installation of docs/python.md (a fresh virtual
# environment and a build of the module: tests/repo/pip_install.sh runs it).
exempt='^(bash scripts/test\.sh|sbatch |until mhcontact table cases/big-table\.json |python3 -m venv --system-site-packages |venv/bin/pip |venv/bin/python |bash scripts/fuzz\.sh |valgrind |/usr/bin/python3 scripts/compare_methods\.py cases/manchester-plastic\.json |python3 scripts/trust_table\.py )'
commands() {  # the command lines of the ```sh blocks of file $1
  awk '/^```sh/ { b = 1; next } /^```/ { b = 0 } b' "$1" | join_lines
}
join_lines() {  # join "\" continuations, drop comments and leading/trailing blanks
  awk '{ line = line $0 } /\\$/ { sub(/\\$/, "", line); next } { print line; line = "" }' |
    sed -E 's/[[:space:]]+# .*$//; s/^[[:space:]]+//; s/[[:space:]]+$//; s/[[:space:]]+/ /g' | grep -v -e '^#' -e '^$' || true
}
join_lines < "$self" > "$tmp/script_lines"
missing=0
for page in "$src/README.md" "$src"/docs/*.md; do
  while IFS= read -r cmd; do
    [[ $cmd =~ $exempt ]] && continue
    if ! awk -v c="$cmd" '
        substr($0, 1, length(c)) == c {
          rest = substr($0, length(c) + 1)
          if (rest == "" || rest ~ /^ *(\||>|2>|&&|;)/) { found = 1; exit }
        }
        END { exit !found }' "$tmp/script_lines"; then
      echo "readme_examples: $(basename "$page") shows a command this test does not run: $cmd"
      missing=1
    fi
  done < <(commands "$page")
done
test $missing -eq 0
echo "readme_examples: OK"
