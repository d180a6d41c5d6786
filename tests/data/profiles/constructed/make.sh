#!/usr/bin/env bash
# Re-creates the constructed test profiles of this folder from the standard profiles
# that mhcontact generates, with awk/printf only. Usage: bash make.sh <mhcontact binary>
# Every file shows one feature of real measured files (README.md in this folder); the points are
# S1002 (wheels) and 60E1 (rails) at 0.5 mm spacing, so that the tests know the true surface.
set -euo pipefail
MH=$1
cd "$(dirname "$0")"
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
"$MH" profile generate S1002 --step 0.5 -o "$T/w.csv" >/dev/null
"$MH" profile generate 60E1 --step 0.5 -o "$T/r.csv" >/dev/null

# 1. MiniProf old wheel style: #MINIWHEELPROF, name, MINIPROF <year>, dotted fields, quoted
#    measures with the legend on the next line, empty line, X Y rows (X from the flange back,
#    Y = increase of radius: X = y + 70, Y = -z).
{
  printf '#MINIWHEELPROF\nS1002 constructed\nMINIPROF 2004\nStock.......: 4711\nAxle Number.: 2\nWheel ID....: R\n'
  printf '"32.50 28.00 10.80"\n(Sd/Sh/qR)\n\n'
  awk -F, 'NR>1 {printf "%.3f %.3f\n", $1 + 70, -$2}' "$T/w.csv"
} > old_style_wheel.whl

# 2. MiniProf drawing elements (CAD export through MiniProf for Windows): a flat-topped rail head
#    of line segments and arcs in MiniProf rail axes (X to the gauge side, Y down):
#    crown arc R 300 from X=-20 to X=20, R 13 corners down to vertical-ish flanks.
#    Arc: A X1 Y1 X2 Y2 Xc Yc.
cat > elements_rail.ban <<'EOT'
[Profile1Info]
Name=constructed head of arcs and lines
MPDC=5
MPD1=L -33.000000 20.000000 -33.000000 12.000000
MPD2=A -33.000000 12.000000 -20.000000 -1.000000 -20.000000 12.000000
MPD3=A -20.000000 -1.000000 20.000000 -1.000000 0.000000 298.333333
MPD4=A 20.000000 -1.000000 33.000000 12.000000 20.000000 12.000000
MPD5=L 33.000000 12.000000 33.000000 20.000000
EOT
# the same with elements 4 and 5 moved 0.5 mm down: element 4 does not join element 3 (a gap
# of 0.5 mm, joined by a straight piece with a warning)
sed 's/^MPD4=.*/MPD4=A 20.000000 -0.500000 33.000000 12.500000 20.000000 12.500000/; s/^MPD5=.*/MPD5=L 33.000000 12.500000 33.000000 20.000000/' \
  elements_rail.ban > elements_gap.ban

# 3. Folds: 60E1 with a 0.2 mm step back on the gauge face 8 mm below the top (3 points, marked
#    "dent" as some files do), a loop (the scan goes 0.3 mm back and crosses itself) at 3 mm
#    below the top, and a duplicated point.
awk -F, 'NR>1 {n++; y[n]=$1; z[n]=$2} END {
  for (k = 1; k <= n; k++) {
    printf "%.4f %.4f\n", y[k], z[k]
    if (k > 1 && z[k-1] < -8 && z[k] >= -8 && y[k] < 0) {       # fold: three points back
      printf "%.4f %.4f # dent\n", y[k] - 0.20, z[k] + 0.02
      printf "%.4f %.4f # dent\n", y[k] - 0.15, z[k] + 0.05
      printf "%.4f %.4f # dent\n", y[k] - 0.05, z[k] + 0.08
    }
    if (k > 1 && z[k-1] < -3 && z[k] >= -3 && y[k] < 0) {       # loop: back 0.3 mm, below, forward
      printf "%.4f %.4f\n", y[k] - 0.30, z[k] - 0.10
      printf "%.4f %.4f\n", y[k] + 0.10, z[k] - 0.30
    }
    if (k == 100) printf "%.4f %.4f\n", y[k], z[k]               # duplicate
  }}' "$T/r.csv" > folded_rail.txt
# the same rail with a 3 mm loop (larger than the 1 mm limit): rejected
awk -F, 'NR>1 {printf "%.4f %.4f\n", $1, $2; if (NR == 150) printf "%.4f %.4f\n%.4f %.4f\n", $1 - 3, $2 - 0.5, $1 + 0.3, $2 - 1}' \
  "$T/r.csv" > big_loop_rail.txt

# a scan that folds back 0.45 mm after every second point over the whole head: refused
awk -F, 'NR>1 {printf "%.4f %.4f\n", $1, $2; if (NR % 2 == 0) printf "%.4f %.4f\n", $1 - 0.45, $2 - 0.02}' \
  "$T/r.csv" > zigzag_rail.txt

# 4. Spreadsheets: UTF-8 BOM + CRLF + ';' separator + decimal commas (European Excel), and tabs
#    with decimal commas.
{
  printf '\xEF\xBB\xBFy_mm;z_mm\r\n'
  awk -F, 'NR>1 {y=sprintf("%.4f", $1); z=sprintf("%.4f", $2); gsub(/\./, ",", y); gsub(/\./, ",", z); printf "%s;%s\r\n", y, z}' "$T/r.csv"
} > excel_semicolon.csv
awk -F, 'NR>1 {y=sprintf("%.4f", $1); z=sprintf("%.4f", $2); gsub(/\./, ",", y); gsub(/\./, ",", z); printf "%s\t%s\n", y, z}' \
  "$T/r.csv" > tabs_decimal_comma.txt
# UTF-16LE with BOM, gzip, and a binary file with NUL bytes (refused with the encoding named)
printf '\xFF\xFEy\x00_\x00m\x00m\x00\n\x00' > utf16.csv
printf '1 2\n3 4\n' | gzip -n > table.csv.gz && mv table.csv.gz gzip.csv
printf 'y z\n1.0 2.0\n\x00\x01\x02 binary\n' > nul_bytes.txt

# 5. A thick flange (docs/profiles.md "Placement check"): S1002 whose flange and flange root are
#    moved 3.9 mm towards the field side, Sd 32.5 -> 36.4 mm (a worn wheel's flange, above
#    EN 15313's 33 mm), the flange back kept at -70 mm and the tread from -10 mm on unchanged. The
#    shift is D w(y) for the points on the field side of the flange tip, w = 1 up to y = -30 mm,
#    falling as (1 + cos)/2 to 0 at -10 mm; the tip widens by D (the file's straight piece there).
#    Correctly placed, its contact at t_Y = 0 on 60E1 at 1:40 is on the flange root (17 deg).
"$MH" profile generate S1002 --step 0.2 -o "$T/w2.csv" >/dev/null
awk -F, -v D=3.9 'NR > 1 { y[NR] = $1; z[NR] = $2; if (NR == 2 || $2 < z[it]) it = NR; n = NR }
  END {
    pi = atan2(0, -1); print "y_mm,z_mm"
    for (i = 2; i <= n; i++) {
      w = 0; if (i > it) { w = 1; if (y[i] > -30) w = (y[i] >= -10) ? 0 : 0.5 * (1 + cos(pi * (y[i] + 30) / 20)) }
      printf "%.4f,%.4f\n", y[i] + D * w, z[i]
    }
  }' "$T/w2.csv" > thick_flange_wheel.csv
