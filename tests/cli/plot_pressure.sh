#!/usr/bin/env bash
# README example: plastic Manchester run with a pressure grid, then the elastic-versus-plastic
# pressure plot of one case, headless. Then the 2-D pressure maps of the grid methods (half-space
# with --pressure-grid, strips with --strips) with the multi-Hertzian ellipses of the same case
# file outlined, and the clear errors on bad input.
set -euo pipefail
bin=$1; src=$2
py=/usr/bin/python3; [ -x "$py" ] || py=python3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$bin" run "$src/cases/manchester-plastic.json" -o "$tmp/mp" --pressure-grid 21 -q
test -s "$tmp/mp/pressure.csv"
test -s "$tmp/mp/profiles.csv"
MPLBACKEND=Agg "$py" "$src/scripts/plot_pressure.py" "$tmp/mp" --case 23 -o "$tmp/p23.png"
head -c 8 "$tmp/p23.png" | od -An -c | grep -q 'P   N   G'
# A case without contact rows is a clear error, not an empty plot.
if "$py" "$src/scripts/plot_pressure.py" "$tmp/mp" --case 9999 2>"$tmp/err"; then exit 1; fi
grep -q "no loaded ellipse" "$tmp/err"

# Grid methods: t_Y = 3 mm (tread/gauge corner) and 8 mm (flange), by three methods.
sed -e "s|\"\\.\\./profiles/|\"$src/profiles/|g" -e 's|"tY_mm": {"from": -6, "to": 10, "step": 0.5}|"tY_mm": [3, 8]|' \
    "$src/cases/manchester-plastic.json" > "$tmp/mh.json"
sed -e 's|"model": "plastic",|"model": "plastic", "method": "half-space",|' "$tmp/mh.json" > "$tmp/hs.json"
sed -e 's|"model": "plastic",|"model": "plastic", "method": "strips",|' "$tmp/mh.json" > "$tmp/st.json"
grep -q '"method": "half-space"' "$tmp/hs.json"
"$bin" run "$tmp/mh.json" -o "$tmp/mh" -q
"$bin" run "$tmp/hs.json" -o "$tmp/hs" --pressure-grid 2 -q
"$bin" run "$tmp/st.json" -o "$tmp/st" --strips -q || test $? -eq 1  # strips: t_Y = 8 mm plastic may not settle (docs/strips.md)
for k in 0 1; do
  MPLBACKEND=Agg "$py" "$src/scripts/plot_pressure.py" "$tmp/hs" --case $k --ellipses "$tmp/mh" -o "$tmp/hs$k.png"
  head -c 8 "$tmp/hs$k.png" | od -An -c | grep -q 'P   N   G'
done
MPLBACKEND=Agg "$py" "$src/scripts/plot_pressure.py" "$tmp/st" --case 0 --ellipses "$tmp/mh" -o "$tmp/st0.png"
head -c 8 "$tmp/st0.png" | od -An -c | grep -q 'P   N   G'
MPLBACKEND=Agg "$py" "$src/scripts/plot_pressure.py" "$tmp/hs" --case 0 -o "$tmp/hs_alone.png"  # no ellipses: map only
head -c 8 "$tmp/hs_alone.png" | od -An -c | grep -q 'P   N   G'
# Bad input fails with a message that says what to do, and writes no PNG.
fails() {  # fails EXPECTED_TEXT ARGS...: the script must exit non-zero and say EXPECTED_TEXT
  local want=$1; shift
  if MPLBACKEND=Agg "$py" "$src/scripts/plot_pressure.py" "$@" 2>"$tmp/err"; then echo "should fail: $*"; exit 1; fi
  grep -q "$want" "$tmp/err" || { echo "expected '$want', got:"; cat "$tmp/err"; exit 1; }
}
"$bin" run "$tmp/hs.json" -o "$tmp/hs_nogrid" -q
fails "run the half-space method with --pressure-grid" "$tmp/hs_nogrid" --case 0 -o "$tmp/x.png"
fails "no contact patch" "$tmp/hs" --case 7 -o "$tmp/x.png"
fails "not t_Y = 3 mm" "$tmp/hs" --case 0 --ellipses "$tmp/mp" -o "$tmp/x.png"   # case 0 of mp is t_Y = -6 mm
fails "no such file\|No such file" "$tmp/hs" --case 0 --ellipses "$tmp/nowhere" -o "$tmp/x.png"
fails "is not a directory" "$tmp/nowhere" --case 0
fails "for half-space and strip runs" "$tmp/mh" --case 0 --ellipses "$tmp/mh" -o "$tmp/x.png"
test ! -e "$tmp/x.png"
echo "plot_pressure: OK"
