#!/usr/bin/env bash
# README quick start, command 2 (and what CI runs): install what is missing, build and run the
# whole test suite twice: in the Release build (build/), then under AddressSanitizer and
# UndefinedBehaviorSanitizer (build-sanitize/, any report fails the test that triggered it; all
# but three long runs);
# then every libFuzzer target for a few seconds (build-fuzz/, clang 14).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
(cd build && ctest --output-on-failure -j "$(nproc)")
# -O1 -g1 (line tables, enough for the reports' stack traces): per source file 40-60 % of the
# compile time of -O2 -g under the sanitizers, the tests about 13 % slower (docs/development.md).
MHCONTACT_BUILD_DIR=build-sanitize bash scripts/build.sh -DMHCONTACT_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Not under the sanitizers: the wheelset example's three long runs (Klingel free and held, the worn
# pair: 10^4–10^5 steps of the contact adapter and CVODE that its short tests already take under
# the sanitizers; about 7 minutes of CPU there). They run in the Release build above.
(cd build-sanitize && ctest --output-on-failure -j "$(nproc)" -E '^dynamics\.(Klingel|worn pair):')
# A short fuzz run of every target (10 s each; the long runs are `bash scripts/fuzz.sh 600`).
bash scripts/fuzz.sh 10
