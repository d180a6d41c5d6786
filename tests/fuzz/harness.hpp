#pragma once
// Fuzz harnesses, shared by the libFuzzer targets (tests/fuzz/fuzz_*.cpp, built with
// -DMHCONTACT_FUZZ=ON and clang) and by the Catch2 test that replays the seed corpus and every
// kept regression input in the normal test suite (tests/unit/input/test_fuzz_regressions.cpp).
//
// The contract under test: any input either parses or throws mh::InputError. Anything else (a
// crash, a sanitizer report, another exception type, a hang) is a finding.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include "input/case_file.hpp"
#include "output/csv_table.hpp"
#include "core/errors.hpp"
#include "geometry/contact_geometry.hpp"
#include "input/manifest.hpp"
#include "profile/curve.hpp"
#include "profile/read.hpp"
#include "contact/multi_hertz.hpp"

namespace mh::fuzz {

/// A scratch file holding the input (the readers take paths, as users give them).
inline std::string scratch(const std::string& ext, const uint8_t* data, size_t size) {
  static const std::string dir = [] {
    const char* shm = "/dev/shm";
    return std::string(::access(shm, W_OK) == 0 ? shm : "/tmp");
  }();
  const std::string path = dir + "/mhcontact_fuzz_" + std::to_string(::getpid()) + "." + ext;
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

/// Profile readers: the first byte picks the extension (and so the format and kind); the rest is
/// the file. A profile that reads is also smoothed and, paired with itself as wheel and rail,
/// must not crash the geometry.
inline int profile_one(const uint8_t* data, size_t size) {
  static const char* ext[] = {"prr", "prw", "ban", "whl", "txt", "csv", "dat", "wheel", "rail", "whe", "rai", "xyz"};
  if (size < 1) return 0;
  const std::string path = scratch(ext[data[0] % 12], data + 1, size - 1);
  try {
    ProfileReadOptions o;
    const Profile p = read_profile(path, o);
    ProfileCurve c(p);
    (void)c.kappa(0.0);
  } catch (const InputError&) {
  }
  std::remove(path.c_str());
  return 0;
}

/// Case files and manifests (JSON): parse and validate only (profiles are not read).
inline int casefile_one(const uint8_t* data, size_t size) {
  const std::string path = scratch("json", data, size);
  try {
    const nlohmann::json j = read_json_file(path);
    if (is_manifest(j)) {
      const Manifest m = parse_manifest(j, path);
      for (std::size_t k = 0; k < m.pairs.size() && k < 4; ++k) {
        try {
          (void)pair_case(m, k);
        } catch (const InputError&) {
        }
      }
    } else {
      const CaseFile cf = parse_case_json(j, path, false);
      for (std::uint64_t i = 0; i < cf.case_count() && i < 4; ++i) (void)cf.case_at(i);
      (void)cf.resolved_json().dump();
    }
  } catch (const InputError&) {
  }
  std::remove(path.c_str());
  return 0;
}

/// The strict CSV reader of `mhcontact diff`.
inline int csv_one(const uint8_t* data, size_t size) {
  try {
    (void)parse_csv(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.csv");
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace mh::fuzz
