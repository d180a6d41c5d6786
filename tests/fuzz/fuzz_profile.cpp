// libFuzzer target: see harness.hpp. Build with scripts/fuzz.sh.
#include "harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return mh::fuzz::profile_one(data, size); }
