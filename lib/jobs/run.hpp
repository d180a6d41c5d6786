#pragma once
// The jobs behind `mhcontact geometry` and `mhcontact run CASE.json`: build the geometry of the
// case's profile pair once, solve every case (jobs/sweep.hpp), stream the tables to their files
// (never held in memory, never half written: OutputFile), byte-identical whatever the thread count.
#include <iosfwd>
#include <string>

#include "geometry/contact_geometry.hpp"
#include "input/case_file.hpp"
#include "jobs/sweep.hpp"

namespace mh {

/// Read the case's profiles (rail with its inclination) and build their contact geometry.
PairGeometry build_pair_geometry(const CaseFile& cf);

/// The pair's part of the run summary (results.json, run.json): each profile's exact/measured
/// class, the rail's estimated cant [deg] and the pair warnings (cant checks).
nlohmann::json pair_summary_json(const PairGeometry& pg);
/// "mhcontact run: profiles: wheel exact: ...; rail measured: ...; rail cant 1.432 deg (1:40)\n"
std::string pair_summary_line(const PairGeometry& pg);

/// Print each profile's reading warnings on `err`.
void warn_profiles(const PairGeometry& pg, std::ostream& err);

/// `mhcontact geometry`: writes DIR/caf.csv, DIR/geometry.json and DIR/profiles.csv. Returns the exit code.
/// `digits`: significant digits of the numbers in caf.csv and profiles.csv (0 = shortest round-trip).
class RunDirectory;
/// The geometry files of one profile pair into `rd` under `prefix` ("" or "pairs/<k>/"):
/// caf.csv, profiles.csv and geometry.json (potential ellipses, offsets, inputs).
void write_pair_geometry(const CaseFile& cf, const PairGeometry& pg, RunDirectory& rd, const std::string& prefix,
                         const std::string& out_dir);
/// `mhcontact geometry MANIFEST -o DIR`: pairs/<k>/{caf.csv,profiles.csv,geometry.json} for every
/// pair and pairs.csv; an invalid pair is listed with its message (exit 1).
int geometry_batch_job(const nlohmann::json& manifest, const std::string& manifest_path, const std::string& out_dir,
                       std::ostream& err, bool quiet, int digits);
int geometry_job(const CaseFile& cf, const std::string& out_dir, std::ostream& out, std::ostream& err, bool quiet,
                 int digits = 10);

/// `mhcontact run`: returns 0 when every case is ok, 1 when some are not (kExitCasesFailed).
int run_job(const CaseFile& cf, const RunOptions& opt, std::ostream& out, std::ostream& err);

/// The schema names written into results.json and geometry.json.
constexpr const char* kResultsSchema = "mhcontact.results/10";
constexpr const char* kGeometrySchema = "mhcontact.geometry/2";
constexpr const char* kBatchSchema = "mhcontact.batch/10";
/// {"name": "mhcontact", "version": ..., "commit": ...}
nlohmann::json program_json();

}  // namespace mh
