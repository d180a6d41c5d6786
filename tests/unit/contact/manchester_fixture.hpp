#pragma once
// Shared test fixture: the Manchester benchmark pair (S1002 on UIC60 canted 1:40 in its file,
// standard track; tests/data/profiles/README.md) and steel, for the multi-Hertzian tests.
#include <string>

#include "contact/ellipse/hertz.hpp"
#include "geometry/contact_geometry.hpp"
#include "profile/read.hpp"

namespace mh::testing {

/// A profile of tests/data/profiles/, read as `kind` (checks on unless `check` is false).
inline Profile read_test_profile(const std::string& name, ProfileKind kind, bool check = true) {
  ProfileReadOptions o;
  o.kind = kind;
  o.check = check;
  return read_profile(std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/profiles/" + name, o);
}

/// The Manchester pair's contact geometry with default options, built once per test binary.
inline const ContactGeometry& manchester_geometry() {
  static const ContactGeometry G = build_geometry(read_test_profile("MBench_S1002_v3.prw", ProfileKind::Wheel),
                                                  read_test_profile("MBench_UIC60_v3.prr", ProfileKind::Rail),
                                                  TrackSetup{}, GeometryOptions{});
  return G;
}

/// Steel: E = 210 GPa, ν = 0.28.
inline Material steel() {
  Material m;
  m.E = 210e9;
  m.nu = 0.28;
  return m;
}

}  // namespace mh::testing
