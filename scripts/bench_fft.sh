#!/usr/bin/env bash
# The half-space method of the default build (PocketFFT) against the FFTW build as the reference
# measured in the same invocation: build/mhcontact_bench_grid and build-fftw/mhcontact_bench_grid
# with "half-space" (the CONTACT sweep, elastic, best of 3 per case; the plastic sweep, one run
# per case; CPU time), alternated RUNS times (default 3). Prints figures, never asserts.
# Usage: scripts/bench_fft.sh [RUNS]   (part of scripts/bench.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
cmake --build build --target mhcontact_bench_grid -j "$(nproc)" >/dev/null
# The half-space method against the FFTW build as the reference of this run (build-fftw/,
# -DMHCONTACT_FFTW=ON, GPL: only for this comparison), when libfftw3-dev is installed: the two
# binaries alternated RUNS times, the medians per case of each run and their ratios.
if pkg-config --exists fftw3; then
  cmake -S . -B build-fftw -DCMAKE_BUILD_TYPE=Release -DMHCONTACT_FFTW=ON -DMHCONTACT_BUILD_TESTS=OFF >/dev/null
  cmake --build build-fftw --target mhcontact_bench_grid -j "$(nproc)" >/dev/null
  hs() {  # $1 = build dir: "elastic_ms plastic_ms", the medians per case of one run
    "./$1/mhcontact_bench_grid" . 3 half-space |
      awk '/^half-space: median/ {e = $3} /^half-space plastic: median/ {p = $4} END {print e, p}'
  }
  echo "half-space, median per case [ms] elastic / plastic, the default build against FFTW (alternated):"
  for r in $(seq 1 "$runs"); do
    read -r e p <<< "$(hs build)"
    read -r ef pf <<< "$(hs build-fftw)"
    awk -v e="$e" -v p="$p" -v ef="$ef" -v pf="$pf" -v r="$r" \
      'BEGIN{printf "  run %d: default %.1f / %.0f, FFTW %.1f / %.0f, ratio default/FFTW %.2f / %.2f\n", r, e, p, ef, pf, e/ef, p/pf}'
  done
else
  echo "half-space against FFTW: skipped (install libfftw3-dev for the reference build)"
fi
