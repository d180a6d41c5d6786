#pragma once
// Fuzz harnesses, shared by the libFuzzer targets (tests/fuzz/fuzz_*.cpp, built with
// -DMHCONTACT_FUZZ=ON and clang) and by the Catch2 test that replays the seed corpus and every
// kept regression input in the normal test suite (tests/unit/input/test_fuzz_regressions.cpp).
//
// The contract under test: any input either parses or throws mh::InputError. Anything else (a
// crash, a sanitizer report, another exception type, a hang) is a finding. The harnesses also
// assert the invariants they exist for and return kBroken (non-zero) when one fails:
//  - exit class: a refused input is an InputError (exit 2) with a non-empty, printable message
//    naming where; any other exception type is a finding (it would exit 3);
//  - no output on error: the scratch input is removed and nothing else is left behind;
//  - finite numbers: what parses has finite values (profile points, case loads and positions,
//    every number of the resolved inputs), and case loads lie in the plausible ranges.
// The libFuzzer targets trap on a non-zero return; the replay test requires 0.
#include <unistd.h>

#include <cmath>
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
#include "contact/multi_hertz/multi_hertz.hpp"
#include "core/plausible.hpp"

namespace mh::fuzz {

/// Returned when an invariant fails (0: the input was handled as the contract says).
constexpr int kBroken = 1;

/// A refused input's message: non-empty, naming where, no raw control bytes but tab and newline.
inline bool good_error(const InputError& e) {
  const std::string m = e.what();
  if (m.empty() || e.where().empty() || e.rule().empty()) return false;
  for (char ch : m) {
    const auto c = static_cast<unsigned char>(ch);
    if ((c < 0x20 && c != '\t' && c != '\n') || c == 0x7f) return false;
  }
  return true;
}

/// Every number in a JSON document is finite (NaN would be written as null, so no null either).
inline bool all_finite(const nlohmann::json& j) {
  if (j.is_null()) return false;
  if (j.is_number_float()) return std::isfinite(j.get<double>());
  if (j.is_structured())
    for (const auto& e : j)
      if (!all_finite(e)) return false;
  return true;
}

/// The scratch file is gone after the input is handled (nothing left behind).
inline bool removed(const std::string& path) { return ::access(path.c_str(), F_OK) != 0; }

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
  int rc = 0;
  try {
    ProfileReadOptions o;
    const Profile p = read_profile(path, o);
    if (p.y.size() != p.z.size() || p.y.empty()) rc = kBroken;
    for (std::size_t i = 0; i < p.y.size(); ++i)
      if (!std::isfinite(p.y[i]) || !std::isfinite(p.z[i])) rc = kBroken;
    ProfileCurve c(p);
    (void)c.kappa(0.0);
  } catch (const InputError& e) {
    if (!good_error(e)) rc = kBroken;
  }
  std::remove(path.c_str());
  if (!removed(path)) rc = kBroken;
  return rc;
}

/// Case files and manifests (JSON): parse and validate only (profiles are not read).
inline int casefile_one(const uint8_t* data, size_t size) {
  const std::string path = scratch("json", data, size);
  int rc = 0;
  auto check_cases = [&rc](const CaseFile& cf) {
    const std::uint64_t n = cf.case_count();
    for (std::uint64_t i = 0; i < n && i < 4; ++i) {
      const CasePoint p = cf.case_at(i);
      if (!plausible::inside(plausible::kTY_mm, p.tY_mm) || !plausible::inside(plausible::kQ_kN, p.Q_kN)) rc = kBroken;
      if (!std::isfinite(p.tY) || !(p.Q > 0) || !std::isfinite(p.Q)) rc = kBroken;
    }
    if (n > 4) {
      const CasePoint p = cf.case_at(n - 1);
      if (!plausible::inside(plausible::kTY_mm, p.tY_mm) || !plausible::inside(plausible::kQ_kN, p.Q_kN)) rc = kBroken;
    }
    if (!all_finite(cf.resolved_json())) rc = kBroken;
  };
  try {
    const nlohmann::json j = read_json_file(path);
    if (is_manifest(j)) {
      const Manifest m = parse_manifest(j, path);
      for (std::size_t k = 0; k < m.pairs.size() && k < 4; ++k) {
        try {
          check_cases(pair_case(m, k));
        } catch (const InputError& e) {
          if (!good_error(e)) rc = kBroken;
        }
      }
    } else {
      const CaseFile cf = parse_case_json(j, path, false);
      check_cases(cf);
      (void)cf.resolved_json().dump();
    }
  } catch (const InputError& e) {
    if (!good_error(e)) rc = kBroken;
  }
  std::remove(path.c_str());
  if (!removed(path)) rc = kBroken;
  return rc;
}

/// The strict CSV reader of `mhcontact diff`.
inline int csv_one(const uint8_t* data, size_t size) {
  try {
    const CsvTable t = parse_csv(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.csv");
    for (const auto& row : t.rows)
      if (row.size() != t.header.size()) return kBroken;  // every record has one cell per column
    if (t.row_line.size() != t.rows.size()) return kBroken;
  } catch (const InputError& e) {
    if (!good_error(e)) return kBroken;
  }
  return 0;
}

}  // namespace mh::fuzz
