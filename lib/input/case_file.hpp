#pragma once
// The case file (JSON): profiles, track, geometry grid, material, model and the sweep of cases.
// Every error names the file, the JSON path, the value and the rule; unknown keys are errors.
// Field reference: docs/case-file.md.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/contact_geometry.hpp"
#include "profile/profile.hpp"
#include "profile/read.hpp"
#include "contact/options.hpp"
#include "contact/rcf/shakedown.hpp"

namespace mh {

/// Where a profile comes from: a file (with reading options) or a standard definition.
struct ProfileSource {
  std::string file;          ///< resolved path (relative paths are relative to the case file)
  /// The path as the case file or manifest gives it (a glob's matches relative to the manifest,
  /// as the pattern was): what outputs name, so that they do not depend on where the files live.
  std::string given;
  std::string standard;      ///< e.g. "S1002", "60E1", "54E1" (then `file` is empty)
  double step = 0.1e-3;      ///< [m] node spacing of a generated standard profile (default 0.1 mm)
  ProfileReadOptions read;
  std::string json_path;     ///< e.g. "/wheel/profile", for messages
  std::string case_file;     ///< the case file that named it, for messages
  /// How outputs name the profile: `given`, or "standard:NAME".
  std::string label() const { return standard.empty() ? given : "standard:" + standard; }
};

enum class Model { Elastic, Plastic };
const char* to_string(Model m);

struct CasePoint {
  double tY = 0;     ///< [m]
  double Q = 0;      ///< [N]
  double tY_mm = 0;  ///< the value as given (written back verbatim in the tables)
  double Q_kN = 0;   ///< the value as given
};

/// One axis of a sweep, as given: an explicit list, or a range whose values are computed when
/// asked (never stored: memory does not grow with the sweep). A range whose from and step have at
/// most 15 decimals is generated in scaled integers, value i = (F + i·S) / 10^d with F = from·10^d,
/// S = step·10^d: the value is the double nearest to the decimal the user meant, so it prints as
/// that decimal ({"from": 0, "to": 1, "step": 0.3} gives 0, 0.3, 0.6, 0.9, never
/// 0.8999999999999999). Otherwise from + i·step.
struct SweepAxis {
  std::vector<double> list;   ///< explicit values, or empty for a range
  double from = 0, step = 0;  ///< range
  std::uint64_t n = 0;        ///< number of values
  long long F = 0, S = 0;     ///< scaled range (when scale > 0): from = F / scale, step = S / scale
  double scale = 0;           ///< 10^d, or 0 when the range is not scaled
  std::uint64_t size() const { return n; }
  double at(std::uint64_t i) const {
    if (!list.empty()) return list[i];
    if (scale > 0) return static_cast<double>(F + S * static_cast<long long>(i)) / scale;
    return from + step * static_cast<double>(i);
  }
  double min() const;
  double max() const;
};

/// Largest number of cases a run accepts (refused up front with the count).
constexpr std::uint64_t kMaxCases = 1000000000ULL;

struct CaseFile {
  std::string path;
  ProfileSource wheel, rail;
  Inclination inclination = Inclination::AsIs;
  TrackSetup track;
  GeometryOptions geometry;
  Material material;
  Model model = Model::Elastic;
  Method method = Method::MultiHertzian;  ///< "method" (default multi-hertzian)
  MultiHertzOptions solver;                   ///< "solver": the multi-Hertzian iteration
  HalfSpaceOptions half_space;            ///< "half_space": grid and tolerances of the half-space method
  StripMethodOptions strips;              ///< "strips": strip width and tolerances of the strip method
  RcfOptions rcf;                         ///< "rcf": traction coefficient and shear yield of the RCF columns (docs/outputs.md)
  /// The options of the case's method, for solve_contact().
  /// "friction", "kinematics" | "creepages": the tangential problem (docs/tangential.md); off
  /// (tangential.mu NaN) when friction is not given.
  TangentialOptions tangential;
  MethodOptions method_options() const { return {method, solver, half_space, strips, tangential}; }
  /// Either a cartesian sweep (t_Y outer, Q inner: case i has tY[i / nQ], Q[i % nQ]) ...
  SweepAxis sweep_tY_mm, sweep_Q_kN;  ///< as given, in mm and kN
  /// "sweep"/"roll_mrad": the wheel's roll δ against the rail [mrad], an axis of contact tables
  /// only (docs/tables.md "Roll"); empty (size 0) when not given. `run` and `batch` refuse it
  /// (refuse_table_axes).
  SweepAxis sweep_roll_mrad;
  /// ... or an explicit list.
  std::vector<CasePoint> cases;
  bool has_cases = false;  ///< a sweep or a case list was given

  std::uint64_t case_count() const;
  CasePoint case_at(std::uint64_t i) const;
  /// Throws InputError at /sweep/roll_mrad when it is given: the jobs that solve a case list
  /// (`run`, `batch`) solve the wheel upright.
  void refuse_table_axes() const;
  /// The inputs as resolved (defaults filled in, units at the edges), for results.json.
  nlohmann::json resolved_json() const;
};

/// Parse and validate. `need_cases`: `run` needs a sweep; `geometry` does not.
CaseFile load_case_file(const std::string& path, bool need_cases);
/// The same from parsed JSON; `path` names the file in messages and anchors relative paths.
/// `origins`: for an object assembled from several places (a manifest pair's case), the JSON path
/// prefix of a top-level key that came from elsewhere ("friction" -> "/pairs/3"), for the errors.
CaseFile parse_case_json(const nlohmann::json& j, const std::string& path, bool need_cases,
                         const std::map<std::string, std::string>& origins = {});
/// Read a JSON file; a syntax error names file:line:column. Throws InputError.
nlohmann::json read_json_file(const std::string& path);

/// Read or generate a profile of the given kind; rails get the case's inclination applied here,
/// once. Throws InputError.
Profile load_profile(const ProfileSource& src, ProfileKind kind, Inclination incl = Inclination::AsIs);

}  // namespace mh
