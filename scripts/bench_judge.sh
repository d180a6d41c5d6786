#!/usr/bin/env bash
# The multi-Hertzian sweep with the judge (docs/status.md: the gap-corner test on every row that
# passes the other Hertz tests) against a reference build measured in the same invocation:
# build/mhcontact and build-ref/mhcontact, the latter built from commit REF (default 78406d5, the
# build before the gap-corner test was bounded) in a git worktree build-ref-src. Prints figures,
# never asserts; checks that both builds write the same bytes.
# Usage: scripts/bench_judge.sh [RUNS] [REF]   (part of scripts/bench.sh)
#   RUNS (default 3): runs of each build, alternated, --threads 1, CPU time (user + sys) per run.
#   CALLGRIND=1: also the instructions per case of each build (valgrind, a 5,000-case sweep).
#   REF_BUILD=DIR: a build directory of the reference made already (its DIR/mhcontact), instead.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}; ref=${2:-78406d5}
cmake --build build --target mhcontact -j "$(nproc)" >/dev/null
if [ -z "${REF_BUILD:-}" ]; then
  if [ ! -d build-ref-src ]; then git worktree add --detach build-ref-src "$ref" >/dev/null 2>&1; fi
  git -C build-ref-src checkout -q --detach "$ref"
  cmake -S build-ref-src -B build-ref -DCMAKE_BUILD_TYPE=Release -DMHCONTACT_BUILD_TESTS=OFF >/dev/null
  cmake --build build-ref --target mhcontact -j "$(nproc)" >/dev/null
  REF_BUILD=build-ref
fi
ln -sfn "$(cd "$REF_BUILD" && pwd)" .bench-ref
tmp=$(mktemp -d); trap 'rm -rf "$tmp" .bench-ref' EXIT
# sweep NAME tY_SWEEP Q_SWEEP MATERIAL MODEL: a copy of cases/manchester.json
sweep() {
  sed -e "s|\"sweep\": .*|\"sweep\": {\"tY_mm\": $2, \"Q_kN\": $3}|" -e "s|\"material\": .*|\"material\": $4,|" \
      -e "s|\"model\": .*|\"model\": \"$5\",|" -e "s|\"\\.\\./profiles/|\"$PWD/profiles/|g" cases/manchester.json > "$tmp/$1.json"
}
steel='{"E_GPa": 210, "nu": 0.28}'; capped='{"E_GPa": 210, "nu": 0.28, "p_lim_MPa": 900}'
sweep fine '{"from": -6, "to": 10, "step": 0.001}' '[50]' "$steel" elastic            # 16,001 cases
sweep grid '{"from": -6, "to": 10, "step": 0.1616161616}' '{"from": 10, "to": 150, "step": 0.2805611222}' "$steel" elastic  # 100 x 500
sweep gridp '{"from": -6, "to": 10, "step": 0.1616161616}' '{"from": 10, "to": 150, "step": 0.2805611222}' "$capped" plastic
sweep small '{"from": -6, "to": 10, "step": 0.3265306122}' '{"from": 10, "to": 150, "step": 1.414141414}' "$steel" elastic   # 50 x 100
cpu() {  # $1 = build dir, $2 = sweep: CPU seconds of one run, output in $tmp/out-$1-$2
  rm -rf "$tmp/out-$1-$2"
  /usr/bin/time -f "%U %S" -o "$tmp/time" "./$1/mhcontact" run "$tmp/$2.json" -o "$tmp/out-$1-$2" --format csv --threads 1 -q || true
  awk '{print $1 + $2}' "$tmp/time"
}
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
echo "load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
for s in fine grid gridp; do
  : > "$tmp/r"; : > "$tmp/n"
  for r in $(seq 1 "$runs"); do cpu .bench-ref $s >> "$tmp/r"; cpu build $s >> "$tmp/n"; done
  n=$(($(wc -l < "$tmp/out-build-$s/cases.csv") - 1))
  same=identical
  for f in cases.csv ellipses.csv geometry.csv; do cmp -s "$tmp/out-.bench-ref-$s/$f" "$tmp/out-build-$s/$f" || same="DIFFERENT ($f)"; done
  rm_=$(median < "$tmp/r"); nm=$(median < "$tmp/n")
  awk -v s="$s" -v n="$n" -v a="$rm_" -v b="$nm" -v same="$same" -v ra="$(sort -g "$tmp/r" | tr '\n' ' ')" -v na="$(sort -g "$tmp/n" | tr '\n' ' ')" \
    'BEGIN{printf "%s (%d cases, --threads 1, CPU s, median of runs): reference %.2f (%.1f us/case), this build %.2f (%.1f us/case), ratio %.3f; outputs %s\n  runs: reference %s/ this build %s\n", s, n, a, a / n * 1e6, b, b / n * 1e6, b / a, same, ra, na}'
  echo "$s $rm_ $nm" >> "$tmp/medians"
done
awk '$1 == "grid" {re = $2; ne = $3} $1 == "gridp" {rp = $2; np = $3} END {printf "plastic (p_lim 900 MPa) / elastic, the whole run of the 50,000-case sweep: reference %.2f, this build %.2f\n", rp / re, np / ne}' "$tmp/medians"
echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)"
if [ "${CALLGRIND:-0}" = 1 ] && command -v valgrind >/dev/null; then
  for b in .bench-ref build; do
    valgrind --tool=callgrind --callgrind-out-file="$tmp/cg" "./$b/mhcontact" run "$tmp/small.json" -o "$tmp/cg-out" --format csv --threads 1 -q 2>/dev/null || true
    callgrind_annotate --inclusive=yes "$tmp/cg" 2>/dev/null |
      awk -v b="$b" '/PROGRAM TOTALS/ {gsub(",", "", $1); t = $1}
                     /mh::solve_contact\(/ && !sc {gsub(",", "", $1); sc = $1}
                     /mh::format_case\(/ && !fc {gsub(",", "", $1); fc = $1}
                     /mh::build_pair_geometry\(/ && !bg {gsub(",", "", $1); bg = $1}
                     END {n = 5000; printf "%s, instructions per case (5,000 cases, the whole run): %.0f; solve_contact %.0f, format_case %.0f; geometry build %.0f M once\n", b, (t - bg) / n, sc / n, fc / n, bg / 1e6}'
    rm -rf "$tmp/cg-out"
  done
fi
