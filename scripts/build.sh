#!/usr/bin/env bash
# Configure (once) and build mhcontact in Release into build/ (incremental: a second run with
# nothing changed rebuilds nothing). Usage: scripts/build.sh [extra cmake -D options]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
builddir=${MHCONTACT_BUILD_DIR:-build}
if [ ! -f "$builddir/CMakeCache.txt" ] || [ $# -gt 0 ]; then
  cmake -S . -B "$builddir" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
fi
cmake --build "$builddir" -j "$(nproc)"
