#!/usr/bin/env bash
# Every command example of README.md, run as written (in a scratch copy of the repository's
# cases/, profiles/, scripts/ and tests/ref/, with build/mhcontact pointing at the binary under test).
set -euo pipefail
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/build" "$tmp/tests"
cp -r "$src/cases" "$src/profiles" "$src/scripts" "$tmp/"
cp -r "$src/tests/ref" "$tmp/tests/"
ln -s "$bin" "$tmp/build/mhcontact"
cd "$tmp"
py=/usr/bin/python3; [ -x "$py" ] || py=python3
export MPLBACKEND=Agg
set -x
# Commands
./build/mhcontact run cases/manchester.json -o out/manchester
./build/mhcontact run cases/manchester-plastic.json -o out/mp --pressure-grid 21
./build/mhcontact geometry cases/manchester.json -o out/geo
# The half-space method
./build/mhcontact run cases/manchester-halfspace.json -o out/manchester-halfspace
./build/mhcontact run cases/manchester-halfspace.json -o out/hs-flange --pressure-grid 2 --pressure-cases 13-14
test "$(cut -d, -f1 out/hs-flange/pressure.csv | tail -n +2 | sort -u | tr '\n' ' ')" = "13 14 "
test "$(wc -l < out/manchester-halfspace/patches.csv)" -eq 18
./build/mhcontact run cases/manchester-strips.json -o out/manchester-strips --strips
test -s out/manchester-strips/strips.csv
if "$py" -c 'import matplotlib' 2>/dev/null; then
  "$py" scripts/compare_methods.py cases/manchester-halfspace.json -o out/compare.png
  test -s out/compare.png
fi
# Profiles
./build/mhcontact profile info profiles/MBench_S1002_v3.prw
./build/mhcontact profile info profiles/MBench_UIC60_v3.prr --json
./build/mhcontact profile convert profiles/MBench_S1002_v3.prw -o s1002.csv
./build/mhcontact profile generate S1002 -o S1002.csv
./build/mhcontact profile generate 60E1 --inclination 1:40 -o 60E1_1-40.csv
cmp S1002.csv profiles/S1002.csv
cmp 60E1_1-40.csv profiles/60E1_1-40.csv
# hertz
./build/mhcontact hertz --R-wyy 460 --R-rxx 300 --N 100 --E 210 --nu 0.3 | grep -q "^a = 7.16"
./build/mhcontact hertz --R-wyy 460 --R-rxx 300 --N 100 --E 210 --nu 0.3 --p-lim 800 --json | grep -q '"a_mm": 7.748'
./build/mhcontact hertz --A 0.001 --B 0.002 --N 10 --E 210 --nu 0.28 --json
# diff
./build/mhcontact run cases/manchester.json -o out/manchester --format csv -q
./build/mhcontact diff tests/ref/manchester/cases.csv out/manchester/cases.csv --rtol 1e-7 --atol 1e-9
./build/mhcontact diff tests/ref/manchester/ellipses.csv out/manchester/ellipses.csv --column-tol p0_MPa=0.5
# Fleets and shards
./build/mhcontact run cases/fleet.json -o out/fleet
bash scripts/run_sharded.sh cases/manchester.json out/study 8 2
cmp out/study/cases.csv out/manchester/cases.csv
if command -v parallel >/dev/null && parallel --version 2>/dev/null | grep -q "GNU parallel"; then
  parallel ./build/mhcontact run cases/manchester.json -o out/par.shards/shard{} --shard {}/8 -q ::: 1 2 3 4 5 6 7 8
  ./build/mhcontact merge out/par.shards/shard* -o out/par
fi
# Plots
"$py" scripts/plot_geometry.py out/geo --tY 5
"$py" scripts/plot_pressure.py out/mp --case 23
test -s out/geo/geometry_caf.png && test -s out/geo/geometry_profiles.png && test -s out/mp/pressure_case_23.png
./build/mhcontact run cases/manchester-halfspace.json -o out/hs --pressure-grid 2
"$py" scripts/plot_pressure.py out/hs --case 13
test -s out/hs/pressure_case_13.png
# Exit codes: a failing case gives 1, bad input 2, CLI syntax >= 100
set +e
./build/mhcontact run /nonexistent.json -o out/x 2>/dev/null; test $? -eq 2 || exit 1
./build/mhcontact run --no-such-option 2>/dev/null; rc=$?; test $rc -ge 100 || exit 1
./build/mhcontact --version | grep -q "^mhcontact " || exit 1
set -e
echo "readme_examples: OK"
