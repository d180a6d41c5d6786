#!/usr/bin/env bash
# Re-creates the field-like test profiles of this folder from the standard profiles
# that mhcontact generates, with awk/printf only. Usage: bash make.sh <mhcontact binary>
# Each file shows the features of a measured file seen in the field (README.md in this folder);
# the points are S1002 (wheels) and 60E1 (rails), so that the tests know the true surface.
set -euo pipefail
MH=$1
cd "$(dirname "$0")"
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
"$MH" profile generate S1002 --step 0.1 -o "$T/w.csv" >/dev/null
"$MH" profile generate 60E1 --step 0.1 -o "$T/r.csv" >/dev/null
"$MH" profile generate 60E1 --step 0.1 --inclination 1:40 -o "$T/r40.csv" >/dev/null

# 1. Old-style MiniProf wheel (#MINIWHEELPROF) measured from the flange back (X = y + 70,
#    Y = -z, 0.01 mm), with a 0.6 mm loop at the flange tip (the scan goes 0.6 mm back into the
#    flange and comes forward again: two points inserted before the tip) and ten points of the
#    rim face at the field-side end.
{
  printf '#MINIWHEELPROF\nfield wheel L1, loop at the flange tip\nMINIPROF 2004 12 3\nStock.......: 0815\nWheel ID....: L1\n'
  printf '32.50 28.00 10.80  (Sd/Sh/qR)\n\n'
  awk -F, 'NR>1 {
    printf "%.2f %.2f\n", $1 + 70, -$2
    if (!done && $1 >= -55.25) {                      # just before the tip (y = -55)
      printf "%.2f %.2f\n", $1 + 70 - 0.60, -$2 - 0.05
      printf "%.2f %.2f\n", $1 + 70 + 0.10, -$2 - 0.15
      done = 1
    }
    last = $1 + 70; lastz = -$2 }
    END { for (k = 1; k <= 10; k++) printf "%.2f %.2f\n", last, lastz - 0.5 * k }' "$T/w.csv"
} > old_wheel_loop.whl

# 2. The same wheel scanned from the flange tip on: its origin is still the flange back (X = y + 70)
#    but the flange back is not in the file, so no rule can find the taping line; placed by the
#    gauge rule it stands with its flange tip on the rail crown (refused by the placement check).
{
  printf '#MINIWHEELPROF\nfield wheel L2, scan starts at the flange tip\nMINIPROF 2004 12 3\nWheel ID....: L2\n'
  printf '32.50 28.00 10.80  (Sd/Sh/qR)\n\n'
  awk -F, 'NR>1 && $1 >= -55 {printf "%.2f %.2f\n", $1 + 70, -$2}' "$T/w.csv"
} > tip_start_wheel.whl

# 3. Key=Value MiniProf wheel whose header stores the wheel measures (Sd=, Sh=, qR=), X from the
#    flange back, comma-separated rows.
{
  printf 'Filename=WHEEL_R3.whl\nProgramName=MiniProf\nProgramVer=4.1\nMPTypeNo=1\nSd=32.50\nSh=28.00\nqR=10.80\n'
  printf 'XYPoints=%d\nColumnDef=X,Y\n\n' "$(awk 'NR>1' "$T/w.csv" | wc -l)"
  awk -F, 'NR>1 {printf "%.3f,%.3f\n", $1 + 70, -$2}' "$T/w.csv"
} > kv_wheel_measures.whl

# 4. Key=Value MiniProf rail (60E1 laid at 1:40, the head down to 30 mm) with five columns
#    (ColumnDef=X,Y,A,C,K: X to the gauge side, Y depth, then angle, curvature and a code) and
#    stray drawing-element keys left empty by a CAD export (MPDC=, MPDN=) in its header.
awk -F, 'NR>1 && $2 > -30' "$T/r40.csv" > "$T/head.csv"
{
  printf 'Filename=RAIL_K7.ban\nProgramName=MiniProf\nMPTypeNo=299\nMPDC=\nMPDN=\nXYPoints=%d\nXOffset=0.0000\nYOffset=0.0000\nColumnDef=X,Y,A,C,K\n\n' "$(wc -l < "$T/head.csv")"
  awk -F, '{printf "%.4f,%.4f,0.000,0.000,0\n", -$1, -$2}' "$T/head.csv"
} > kv_rail_stray_mpd.ban

# 5. MiniProf multi-profile file (.mpt): three profiles, each an [ProfileNInfo] section (name,
#    drawing elements) and, for the measured one, its [ProfileNPoints] XY rows. The first is
#    not the rail head (a base line under the foot); the second is the measured head (60E1 at
#    1:40, MiniProf rail axes); the third the drawing of a new head (arcs and lines).
{
  printf '[Profile1Info]\nName=Base line\nMPDC=1\nMPD1=L -75.000000 172.000000 75.000000 172.000000\n'
  printf '[Profile2Info]\nName=Head measured\nColumnDef=X,Y\nXYPoints=%d\nMPDC=2\n' "$(wc -l < "$T/head.csv")"
  printf 'MPD1=L -36.000000 14.000000 0.000000 0.000000\nMPD2=L 0.000000 0.000000 36.000000 14.000000\n'
  printf '[Profile3Info]\nName=Head new (drawing)\nMPDC=5\n'
  printf 'MPD1=L -33.000000 20.000000 -33.000000 12.000000\nMPD2=A -33.000000 12.000000 -20.000000 -1.000000 -20.000000 12.000000\n'
  printf 'MPD3=A -20.000000 -1.000000 20.000000 -1.000000 0.000000 298.333333\nMPD4=A 20.000000 -1.000000 33.000000 12.000000 20.000000 12.000000\n'
  printf 'MPD5=L 33.000000 12.000000 33.000000 20.000000\n'
  printf '[Profile2Points]\n'
  awk -F, '{printf "%.4f,%.4f\n", -$1, -$2}' "$T/head.csv"
} > multi_profile.mpt

# 6. A wheel without a flange (the S1002 tread from 20 mm inside the taping line on: a test
#    wheel, a roller), a plain y z table: placed by the gauge rule with a warning.
awk -F, 'NR>1 && $1 >= -20 {printf "%.4f %.4f\n", $1, $2}' "$T/w.csv" > flat_wheel.txt

# 7. A worn rail laid at 1:40 whose cant estimate is not confident: 60E1 at 1:40 with the gauge
#    side of the crown worn down by 3 mm (y/35)^2 above 16 mm depth (3 mm at the gauge corner).
{
  printf 'y_mm,z_mm\n'
  awk -F, 'NR>1 {y = $1; z = $2; if (y < 0 && z > -16) z -= 3 * (y / 35)^2; printf "%.3f,%.3f\n", y, z}' "$T/r40.csv"
} > worn_rail_1-40.csv
