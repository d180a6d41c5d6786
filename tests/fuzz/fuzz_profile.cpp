// libFuzzer target: see harness.hpp. Build with scripts/fuzz.sh.
#include "harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // A broken invariant is a finding: trap so libFuzzer keeps the input.
  if (mh::fuzz::profile_one(data, size) != 0) __builtin_trap();
  return 0;
}
