#!/usr/bin/env bash
# The CMake package as a user consumes it: `cmake --install` into a fresh prefix, then the
# examples copied OUTSIDE the source tree find it (find_package(mhcontact)), build and run:
# examples/c_stepping (C99), and examples/python_stepping.py against the installed Python module
# when the build has one. Usage: package.sh SOURCE_DIR BUILD_DIR [PYTHON]
set -euo pipefail
src=$1; build=$2; python=${3:-python3}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/p" >/dev/null
for f in include/mhcontact.h lib/cmake/mhcontact/mhcontactConfig.cmake share/doc/mhcontact/examples/c_stepping/c_stepping.c; do
  [ -e "$tmp/p/$f" ] || { echo "package: $f missing"; exit 1; }
done
# The library exports the C interface only.
lib=$(ls "$tmp"/p/lib/libmhcontact.so.* | head -1)
if nm -D --defined-only "$lib" | awk '{print $3}' | grep -v '^mhc_' | grep -q .; then
  echo "package: $lib exports more than mhc_*:"; nm -D --defined-only "$lib" | grep -v ' mhc_' | head; exit 1
fi
cp -r "$tmp/p/share/doc/mhcontact/examples/c_stepping" "$tmp/c_stepping"
cmake -S "$tmp/c_stepping" -B "$tmp/c_build" -DCMAKE_PREFIX_PATH="$tmp/p" >/dev/null
cmake --build "$tmp/c_build" >/dev/null
"$tmp/c_build/c_stepping" > "$tmp/c.out"
grep -q '^t_s,tY_mm,status' "$tmp/c.out" || { echo "package: c_stepping printed no table"; cat "$tmp/c.out"; exit 1; }
# 21 steps, every one solved: 20 ok and the last (t_Y = 1 mm, two interacting ellipses) outside
# the multi-Hertzian method's validity.
[ "$(grep -cE ',(ok|outside_validity),' "$tmp/c.out")" = 21 ] || { echo "package: c_stepping: expected 21 solved rows"; cat "$tmp/c.out"; exit 1; }
grep -q '^approach .*Fz 50.000 kN' "$tmp/c.out" || { echo "package: c_stepping: approach round trip"; cat "$tmp/c.out"; exit 1; }
grep -q '^roll refused' "$tmp/c.out" || { echo "package: c_stepping: roll not refused"; exit 1; }
# docs/c-api.md "Worked example" prints this run's output (issue 38: every printed output in the
# docs comes from a run a test checks): each shown line but "..." is a line of it.
awk '/^    \/tmp\/cs\/c_stepping$/ { on = 1; next } on && /^    / { sub(/^    /, ""); print; next } on && NF { exit }' \
  "$src/docs/c-api.md" | grep -vx '\.\.\.' | grep -v '^$' > "$tmp/shown.txt"
[ "$(wc -l < "$tmp/shown.txt")" -ge 8 ] || { echo "package: docs/c-api.md's example output not found"; exit 1; }
while IFS= read -r line; do
  grep -qxF -- "$line" "$tmp/c.out" || { echo "package: docs/c-api.md shows a line c_stepping does not print: $line"; cat "$tmp/c.out"; exit 1; }
done < "$tmp/shown.txt"
"$tmp/c_build/c_stepping" "$src/cases/manchester.json" > "$tmp/m.out"
"$tmp/c_build/c_stepping" /nonexistent.json 2> "$tmp/err" && { echo "package: a missing case file must fail"; exit 1; }
grep -q 'c_stepping: /nonexistent.json: input: ' "$tmp/err" || { echo "package: error message"; cat "$tmp/err"; exit 1; }
# The wheelset call: examples/c_wheelset, a second consumer of the installed package; its rows at
# y = 0 with yaw +2 mrad (t 0.0) and -2 mrad (t 0.5) must be each other's mirror image (equal
# contact angles; the left wheel's load of one the right wheel's of the other: the yaw's lateral
# creep forces shift load between the wheels through the vertical equilibrium), and
# docs/c-api.md "The wheelset call" prints this run's output (each shown line but "..." is a
# line of it).
cp -r "$tmp/p/share/doc/mhcontact/examples/c_wheelset" "$tmp/c_wheelset"
cmake -S "$tmp/c_wheelset" -B "$tmp/w_build" -DCMAKE_PREFIX_PATH="$tmp/p" >/dev/null
cmake --build "$tmp/w_build" >/dev/null
"$tmp/w_build/c_wheelset" > "$tmp/w.out"
[ "$(grep -cE '^[0-9.]+,-?[0-9.]+,-?[0-9.]+,(ok|outside_validity),' "$tmp/w.out")" = 11 ] || { echo "package: c_wheelset: expected 11 solved rows"; cat "$tmp/w.out"; exit 1; }
awk -F, '$1 == "0.0" { g0 = $10 == $12; l = $11; r = $13 } $1 == "0.5" { ok = g0 && $10 == $12 && $11 == r && $13 == l } END { exit !ok }' "$tmp/w.out" || { echo "package: c_wheelset: y = 0 with yaw +-2 mrad not mirror images"; cat "$tmp/w.out"; exit 1; }
grep -q '^dFz/dZ -' "$tmp/w.out" || { echo "package: c_wheelset: no derivatives"; cat "$tmp/w.out"; exit 1; }
awk '/^    \/tmp\/cw\/c_wheelset$/ { on = 1; next } on && /^    / { sub(/^    /, ""); print; next } on && NF { exit }' \
  "$src/docs/c-api.md" | grep -vx '\.\.\.' | grep -v '^$' > "$tmp/shown_w.txt"
[ "$(wc -l < "$tmp/shown_w.txt")" -ge 6 ] || { echo "package: docs/c-api.md's wheelset output not found"; exit 1; }
while IFS= read -r line; do
  grep -qxF -- "$line" "$tmp/w.out" || { echo "package: docs/c-api.md shows a line c_wheelset does not print: $line"; cat "$tmp/w.out"; exit 1; }
done < "$tmp/shown_w.txt"
# The pressure and traction grid of one case: examples/c_grids, a third consumer; in slip the
# traction is mu p within 0.3 % (FASTSIM's bound against the grid's pressure, docs/tangential.md)
# and the print's rounding, and docs/c-api.md "Pressure and traction
# grids" prints this run's output (each shown line but "..." is a line of it).
cp -r "$tmp/p/share/doc/mhcontact/examples/c_grids" "$tmp/c_grids"
cmake -S "$tmp/c_grids" -B "$tmp/g_build" -DCMAKE_PREFIX_PATH="$tmp/p" >/dev/null
cmake --build "$tmp/g_build" >/dev/null
"$tmp/g_build/c_grids" > "$tmp/g.out"
grep -q '^ellipse,x_mm,y_mm,p_MPa,px_MPa,py_MPa,slip$' "$tmp/g.out" || { echo "package: c_grids printed no grid"; cat "$tmp/g.out"; exit 1; }
awk -F, '$7 == "1" { n++; d = sqrt($5 * $5 + $6 * $6) - 0.3 * $4; t = 0.003 * 0.3 * $4 + 0.1; if (d < -t || d > t) bad++ } END { exit !(n >= 3 && !bad) }' "$tmp/g.out" \
  || { echo "package: c_grids: a slipping point's traction is not mu p"; cat "$tmp/g.out"; exit 1; }
grep -q '^too small: out->capacity = ' "$tmp/g.out" || { echo "package: c_grids: a too small array not refused"; cat "$tmp/g.out"; exit 1; }
awk '/^    \/tmp\/cg\/c_grids$/ { on = 1; next } on && /^    / { sub(/^    /, ""); print; next } on && NF { exit }' \
  "$src/docs/c-api.md" | grep -vx '\.\.\.' | grep -v '^$' > "$tmp/shown_g.txt"
[ "$(wc -l < "$tmp/shown_g.txt")" -ge 6 ] || { echo "package: docs/c-api.md's grid output not found"; exit 1; }
while IFS= read -r line; do
  grep -qxF -- "$line" "$tmp/g.out" || { echo "package: docs/c-api.md shows a line c_grids does not print: $line"; cat "$tmp/g.out"; exit 1; }
done < "$tmp/shown_g.txt"
# The Python module, installed under the prefix, and the Python example.
py=$(find "$tmp/p" -path '*/mhcontact/__init__.py' 2>/dev/null | head -1)
if [ -n "$py" ]; then
  cp "$tmp/p/share/doc/mhcontact/examples/python_stepping.py" "$tmp/"
  (cd "$tmp" && PYTHONPATH="$(dirname "$(dirname "$py")")" MPLBACKEND=Agg "$python" python_stepping.py --plot "$tmp/steps.png" > "$tmp/py.out")
  grep -q '^t_s,tY_mm,status' "$tmp/py.out" || { echo "package: python_stepping printed no table"; cat "$tmp/py.out"; exit 1; }
  # The same numbers as the C example, step for step.
  diff <(grep -E ',(ok|outside_validity),' "$tmp/c.out" | cut -d, -f1-6) <(grep -E ',(ok|outside_validity),' "$tmp/py.out" | cut -d, -f1-6) \
    || { echo "package: C and Python examples differ"; exit 1; }
  echo "package: OK (C and Python)"
else
  echo "package: OK (C; no Python module in this build)"
fi
