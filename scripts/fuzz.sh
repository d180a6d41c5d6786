#!/usr/bin/env bash
# Run every libFuzzer target for SECONDS each (default 60) with clang 14, AddressSanitizer and
# UndefinedBehaviorSanitizer. Seeds: tests/fuzz/corpus/TARGET; the working corpus grows in
# build-fuzz/corpus/TARGET. A crashing or hanging input is written to
# tests/fuzz/regressions/TARGET/ (keep it: the normal test suite replays it) and the script exits 1.
#   scripts/fuzz.sh [SECONDS] [TARGET...]      targets: profile casefile csv
set -euo pipefail
cd "$(dirname "$0")/.."
secs=${1:-60}; shift || true
targets=("$@"); [ ${#targets[@]} -gt 0 ] || targets=(profile casefile csv)
bash scripts/deps.sh
if ! dpkg-query -W -f='${Status}' clang-14 2>/dev/null | grep -q "install ok installed" ||
   ! dpkg-query -W -f='${Status}' libclang-rt-14-dev 2>/dev/null | grep -q "install ok installed"; then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq clang-14 libclang-rt-14-dev >/dev/null
fi
if [ ! -f build-fuzz/CMakeCache.txt ]; then
  CXX=clang++-14 CC=clang-14 cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMHCONTACT_FUZZ=ON -DMHCONTACT_BUILD_TESTS=OFF >/dev/null
fi
cmake --build build-fuzz -j "$(nproc)" --target $(printf 'fuzz_%s ' "${targets[@]}")
status=0
for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/corpus/$t" "tests/fuzz/regressions/$t"
  echo "fuzz_$t: ${secs} s"
  if ! ./build-fuzz/fuzz_$t "build-fuzz/corpus/$t" "tests/fuzz/corpus/$t" -max_total_time="$secs" -timeout=10 \
        -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 -artifact_prefix="tests/fuzz/regressions/$t/" \
        > "build-fuzz/fuzz_$t.log" 2>&1; then
    echo "fuzz_$t: FINDING, see build-fuzz/fuzz_$t.log and tests/fuzz/regressions/$t/" >&2
    tail -40 "build-fuzz/fuzz_$t.log" >&2
    status=1
  fi
  grep -E "stat::number_of_executed_runs|stat::peak_rss_mb" "build-fuzz/fuzz_$t.log" | sed "s/^/  /"
done
exit $status
