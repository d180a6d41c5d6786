#pragma once
// The physics keys of a case file beside its geometry (docs/case-file.md, docs/tangential.md,
// docs/outputs.md "RCF columns"): "friction", "kinematics" | "creepages", "fastsim" (the
// tangential problem) and "rcf" (the RCF indicators, damage and wear functions, subsurface
// stresses). A batch manifest takes the same keys, as defaults and per pair (input/manifest.hpp),
// read here through the same rules.
//
// Internal to the case-file reader: namespace detail.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "input/case_file.hpp"
#include "input/json_fields.hpp"

namespace mh {
namespace detail {

/// The keys read here: those a manifest pair may give (input/manifest.hpp).
inline const std::vector<std::string>& tangential_rcf_keys() {
  static const std::vector<std::string> k = {"friction", "kinematics", "creepages", "fastsim", "rcf"};
  return k;
}

/// "friction", "kinematics" | "creepages", "fastsim" of the case-file object `j` into
/// cf.tangential; reads the track already parsed (cf.track: r0, l). One rule per option, each
/// error at its JSON path.
void parse_tangential(const Ctx& c, const nlohmann::json& j, CaseFile& cf);

/// "rcf" of the case-file object `j` into cf.rcf; reads the material already parsed (its yield
/// stress) and whether `j` gives friction (the contacts' own |F|/N, or a given f).
void parse_rcf(const Ctx& c, const nlohmann::json& j, CaseFile& cf);

}  // namespace detail
}  // namespace mh
