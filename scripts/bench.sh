#!/usr/bin/env bash
# Benchmarks: prints figures (medians), never asserts. Usage: scripts/bench.sh [CASES_tY] [CASES_Q]
# Default sweep 2000 t_Y x 500 Q = 1,000,000 cases on the Manchester pair, to CSV.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh >/dev/null
ny=${1:-2000}; nq=${2:-500}
./build/mhcontact_bench . 7
# The multi-Hertzian sweep with the judge against the build before the gap-corner bound (CPU time,
# the same bytes checked; docs/performance.md).
bash scripts/bench_judge.sh 3
tmp=$(mktemp -d); trap 'rm -rf "$tmp" .bench-sweep-ref' EXIT
step=$(awk -v n="$ny" 'BEGIN{printf "%.10g", 16/(n-1)}')
qstep=$(awk -v n="$nq" 'BEGIN{printf "%.10g", 140/(n-1)}')
sed -e "s|\"sweep\": .*|\"sweep\": {\"tY_mm\": {\"from\": -6, \"to\": 10, \"step\": $step}, \"Q_kN\": {\"from\": 10, \"to\": 150, \"step\": $qstep}}|" \
    -e "s|\"\\.\\./profiles/|\"$PWD/profiles/|g" cases/manchester.json > "$tmp/big.json"
ncases=$((ny * nq))
# One thread and all cores alternately, 5 runs each (the machine is shared: alternating puts a
# slow spell on both), median wall time and peak RSS [KB] of each.
# fresh: into a new directory; rerun: replacing the previous run's 400 MB set, whose removal at
# the end (~0.1 s of kernel time, serial) is part of the time.
once() {  # $1 = threads, $2 = fresh|rerun, $3 = file to append "wall rss cpu" to, $4 = build dir (default build)
  if [ "$2" = fresh ]; then rm -rf "$tmp/out"; sync; sleep 0.2; fi
  /usr/bin/time -f "%e %M %U %S" -o "$tmp/time" "./${4:-build}/mhcontact" run "$tmp/big.json" -o "$tmp/out" --format csv --threads "$1" -q || true
  awk '{print $1, $2, $3 + $4}' "$tmp/time" >> "$3"
}
median() { sort -g | sed -n 3p; }
echo "load average before the end-to-end runs: $(cut -d' ' -f1-3 /proc/loadavg)"
for mode in fresh rerun; do
  : > "$tmp/t1"; : > "$tmp/tn"
  for r in 1 2 3 4 5; do once 1 $mode "$tmp/t1"; once 0 $mode "$tmp/tn"; done
  t1=$(cut -d' ' -f1 "$tmp/t1" | median); m1=$(cut -d' ' -f2 "$tmp/t1" | median); c1=$(cut -d' ' -f3 "$tmp/t1" | median)
  tn=$(cut -d' ' -f1 "$tmp/tn" | median); mn=$(cut -d' ' -f2 "$tmp/tn" | median); cn=$(cut -d' ' -f3 "$tmp/tn" | median)
  echo "end-to-end run, $ncases cases to CSV, median of 5, $mode output directory:"
  awk -v t="$t1" -v m="$m1" -v c="$c1" -v n="$ncases" 'BEGIN{printf "  --threads 1:      %.2f s wall, %.0f cases/s, peak RSS %.0f MB, CPU %.2f s (user + sys)\n", t, n/t, m/1024, c}'
  awk -v t="$tn" -v m="$mn" -v cp="$cn" -v n="$ncases" -v c="$(nproc)" 'BEGIN{printf "  all %d cores:     %.2f s wall, %.0f cases/s, peak RSS %.0f MB, CPU %.2f s (user + sys)\n", c, t, n/t, m/1024, cp}'
  awk -v a="$t1" -v b="$tn" 'BEGIN{printf "  speed-up:         %.2f\n", a/b}'
  echo "  all runs [s], one thread: $(cut -d' ' -f1 "$tmp/t1" | sort -g | tr '\n' ' ')"
  echo "  all runs [s], all cores:  $(cut -d' ' -f1 "$tmp/tn" | sort -g | tr '\n' ' ')"
done
# What the machine's cores give, the ceiling of the speed-up above: as many one-thread runs at
# once as there are cores (each into its own new directory), against one alone, alternated,
# 3 rounds; their throughput relative to one run alone (the cores' count on an ideal machine).
nc=$(nproc); : > "$tmp/alone"; : > "$tmp/many"
for r in 1 2 3; do
  once 1 fresh "$tmp/alone"
  for k in $(seq 1 "$nc"); do rm -rf "$tmp/out$k"; done; sync; sleep 0.2
  s=$(date +%s.%N)
  for k in $(seq 1 "$nc"); do ./build/mhcontact run "$tmp/big.json" -o "$tmp/out$k" --format csv --threads 1 -q & done
  wait
  echo "$(date +%s.%N) - $s" | bc -l >> "$tmp/many"
  for k in $(seq 1 "$nc"); do rm -rf "$tmp/out$k"; done
done
ta=$(cut -d' ' -f1 "$tmp/alone" | sort -g | sed -n 2p); tm=$(sort -g "$tmp/many" | sed -n 2p)
awk -v a="$ta" -v m="$tm" -v c="$nc" 'BEGIN{printf "%d independent one-thread runs at once: %.2f s wall against %.2f s for one alone (medians of 3): throughput %.2f times one run (the ceiling of the speed-up)\n", c, m, a, c * a / m}'
# REF_BUILD=DIR (a build directory of another commit, e.g. bench_judge.sh's build-ref): the same
# sweep by its mhcontact, alternated with this build's, one thread, 3 runs each, CPU time medians
# and their ratio (the machine is shared: CPU time, not wall time, compares two builds).
if [ -n "${REF_BUILD:-}" ]; then
  ln -sfn "$(cd "$REF_BUILD" && pwd)" .bench-sweep-ref
  : > "$tmp/r1"; : > "$tmp/b1"
  for r in 1 2 3; do once 1 fresh "$tmp/r1" .bench-sweep-ref; once 1 fresh "$tmp/b1"; done
  rm -f .bench-sweep-ref
  rc=$(cut -d' ' -f3 "$tmp/r1" | sort -g | sed -n 2p); bc=$(cut -d' ' -f3 "$tmp/b1" | sort -g | sed -n 2p)
  awk -v a="$rc" -v b="$bc" -v r="$REF_BUILD" 'BEGIN{printf "  --threads 1 against %s (median of 3 CPU times): reference %.2f s, this build %.2f s, ratio %.3f\n", r, a, b, b / a}'
fi
ls -la "$tmp/out" | awk 'NR>1{print "  " $5 " bytes  " $9}'
# The grid methods (half-space, strips) on the CONTACT benchmark sweep (median and worst per case).
./build/mhcontact_bench_grid . 3
# The grid methods with a reused workspace against a new one per call (docs/performance.md).
./build/mhcontact_bench_grid . 5 workspace
# The half-space method against the FFTW build, alternated (skipped without libfftw3-dev).
bash scripts/bench_fft.sh 3
# The exact half-space tangential solve on CONTACT's Hertzian patch, and CONTACT's own time on the
# same deck when a CONTACT binary is given (CONTACT_BIN=…/contact_linux64; its tangential and
# normal solvers' CPU time from its performance timers, six cases). The normal solve on that grid
# (the bench's last line) against CONTACT's, alternated three times: the ratio of CPU times per
# solve, each run's and the median (docs/performance.md, "One convolution a CG step").
./build/mhcontact_bench_tangential_half_space . 5
if [ -x "${CONTACT_BIN:-}" ]; then
  ctmp=$(mktemp -d); cp tests/data/contact_tangential/hstang/hertz44.inp "$ctmp/"
  ratios=()
  for _ in 1 2 3; do
    ours=$(./build/mhcontact_bench_tangential_half_space . 5 | sed -n 's/^normal solve.*CPU \([0-9.]*\) ms per solve.*/\1/p')
    (cd "$ctmp" && OMP_NUM_THREADS=1 "$CONTACT_BIN" 2 hertz44 > /dev/null 2>&1 || true)
    theirs=$(awk -F'|' '/^\|Norm: ConjGrd/ {print $4}' "$ctmp/hertz44.out")
    ratios+=("$(echo "$theirs * 1000 / 6 / $ours" | bc -l)")
  done
  grep -E "^\|(Total|Tang: StedyGS|Norm: ConjGrd)" "$ctmp/hertz44.out" | sed 's/^/  CONTACT /'
  printf '  normal solve, CONTACT CPU / mhcontact CPU per solve: %.1f %.1f %.1f, median %.1f\n' "${ratios[@]}" \
    "$(printf '%s\n' "${ratios[@]}" | sort -g | sed -n 2p)"
  # The same in instructions (callgrind; repeatable where CPU times are not): CONTACT's normcg over
  # its six solves, ours solve_normal_load inclusive over the bench's ten (about a minute).
  if command -v valgrind >/dev/null && command -v callgrind_annotate >/dev/null; then
    (cd "$ctmp" && OMP_NUM_THREADS=1 valgrind --tool=callgrind --callgrind-out-file=cg.contact \
       --toggle-collect='__m_solvpn_MOD_normcg' "$CONTACT_BIN" 2 hertz44 > /dev/null 2>&1 || true)
    valgrind --tool=callgrind --callgrind-out-file="$ctmp/cg.ours" ./build/mhcontact_bench_tangential_half_space . 1 \
      > /dev/null 2>&1
    theirs=$(callgrind_annotate "$ctmp/cg.contact" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}')
    ours=$(callgrind_annotate --inclusive=yes "$ctmp/cg.ours" 2>/dev/null |
      awk '/solve_normal_load\(mh::InfluenceGrid const&, double const\*, double, double, double\*, mh::NormalCGOptions const&\) / {gsub(",", "", $1); print $1; exit}')
    awk -v t="$theirs" -v o="$ours" 'BEGIN{printf "  normal solve, instructions per solve: CONTACT %.1f M, mhcontact %.1f M, ratio %.1f\n", t / 6e6, o / 10e6, (t / 6) / (o / 10)}'
  fi
  rm -rf "$ctmp"
fi
# The wheelset: one pair, and a fleet of 1000 wheels with its CPU time per wheel by stage.
./build/mhcontact_bench_wheelset 1000
# The tangential problem: FASTSIM per ellipse and a whole multi-Hertzian case with creep forces.
./build/mhcontact_bench_tangential .
# The wheelset fleet of measured files through the command (CPU per wheel, 10,000 on 2 cores).
bash scripts/bench_fleet.sh 1000 5
