#!/usr/bin/env bash
# Every Catch2 test name can be run by CTest under its own name: catch_discover_tests registers
# each TEST_CASE as a CTest test, and CTest splits a name at ';' (the list separator), so a test
# named "a; b" becomes two tests that match nothing and fail. Names on one line or continued
# over two are checked. Usage: test_names.sh SOURCE_DIR
set -euo pipefail
src=${1:?usage: test_names.sh SOURCE_DIR}
bad=$(grep -rn --include='*.cpp' -E 'TEST_CASE\("[^"]*;' "$src/tests" || true)
if [[ -n "$bad" ]]; then
  echo "test names with ';' (CTest splits them into tests that match nothing): rename them" >&2
  echo "$bad" >&2
  exit 1
fi
echo "test names: none with ';'"
