// Shards of making a contact table (contact_table_shards.hpp; docs/tables.md "Shards").
#include "jobs/contact_table_shards.hpp"

#include <algorithm>
#include <fstream>
#include <ostream>
#include <sstream>
#include <thread>

#include "core/errors.hpp"
#include "core/units.hpp"
#include "jobs/run.hpp"
#include "jobs/shards.hpp"
#include "output/output_file.hpp"
#include "output/pair_tables.hpp"

namespace mh {

int table_shard_job(const CaseFile& cf, const TableMakeOptions& opt, const std::string& shard, const std::string& out_path,
                    std::ostream& out, std::ostream& err) {
  unsigned k = 0, n = 0;
  parse_shard(shard, &k, &n);
  const PairGeometry pg = build_pair_geometry(cf);
  if (!opt.quiet) warn_profiles(pg, err);
  const std::vector<std::pair<double, double>> all = table_first_points(cf, opt);
  std::vector<std::pair<double, double>> mine_mm, mine_si;
  for (std::size_t p = k - 1; p < all.size(); p += n) {
    mine_mm.push_back(all[p]);
    mine_si.emplace_back(all[p].first * units::mm, all[p].second * 1e3);
  }
  Pool pool(std::max(1u, opt.threads ? opt.threads : std::thread::hardware_concurrency()));
  const std::vector<NodeSolve> solves = solve_points(cf, pg, mine_si, pool);
  nlohmann::json j;
  j["schema"] = kContactTableShardSchema;
  j["program"] = program_json();
  j["shard"] = {k, n};
  j["check"] = opt.check;
  j["inputs"] = inputs_json(cf);
  j["profiles"] = profiles_json(pg);
  j["points"] = all.size();
  nlohmann::json pts = nlohmann::json::array();
  for (std::size_t s = 0; s < solves.size(); ++s)
    pts.push_back({{"tY_mm", mine_mm[s].first}, {"Q_kN", mine_mm[s].second}, {"solve", solve_to_json(solves[s])}});
  j["solves"] = pts;
  if (out_path == "-") {
    out << j.dump() << '\n';
  } else {
    OutputFile f(out_path);
    f.stream() << j.dump() << '\n';
    f.commit();
  }
  if (!opt.quiet)
    err << "mhcontact table: shard " << k << "/" << n << ": " << solves.size() << " of the first round's " << all.size()
        << " points solved; merge the shards with `mhcontact table CASE.json --merge PART... -o TABLE`\n";
  return kExitOk;
}

TableSolves read_table_shards(const CaseFile& cf, const PairGeometry& pg, const TableMakeOptions& opt,
                              const std::vector<std::string>& files) {
  const std::vector<std::pair<double, double>> all = table_first_points(cf, opt);
  const nlohmann::json inputs = inputs_json(cf), profiles = profiles_json(pg), program = program_json();
  TableSolves solves;
  std::vector<std::string> seen;  // by shard index - 1: the file that gave it
  unsigned count = 0;
  std::size_t points = 0;
  for (const std::string& path : files) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "", "cannot read the shard file", "give the files written by `mhcontact table CASE.json --shard K/N -o FILE`");
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
      throw InputError(path, "", std::string("a shard file is one JSON object: ") + e.what());
    }
    auto field = [&](const char* key) -> const nlohmann::json& {
      if (!j.is_object() || !j.contains(key)) throw InputError(path + ": /" + key, "", "missing: this is not a table shard file");
      return j[key];
    };
    if (field("schema") != kContactTableShardSchema)
      throw InputError(path + ": /schema", field("schema").dump(), std::string("must be ") + kContactTableShardSchema,
                       "write the shards with this mhcontact");
    const std::string other = "the shards of one table come from the same case file, profiles, options and mhcontact";
    if (field("inputs") != inputs) throw InputError(path + ": /inputs", "", "differs from " + cf.path + "'s: " + other);
    if (field("profiles") != profiles) throw InputError(path + ": /profiles", "", "the profiles (checksums) differ: " + other);
    if (field("program") != program) throw InputError(path + ": /program", field("program").dump(), "another mhcontact: " + other);
    if (field("check") != opt.check) throw InputError(path + ": /check", field("check").dump(), "--no-check differs: " + other);
    const nlohmann::json& sh = field("shard");
    if (!sh.is_array() || sh.size() != 2 || !sh[0].is_number_unsigned() || !sh[1].is_number_unsigned())
      throw InputError(path + ": /shard", sh.dump(), "must be [K, N]");
    const unsigned k = sh[0].get<unsigned>(), n = sh[1].get<unsigned>();
    if (k < 1 || k > n) throw InputError(path + ": /shard", sh.dump(), "must be [K, N] with 1 <= K <= N");
    if (count == 0) {
      count = n;
      seen.assign(n, std::string());
    }
    if (n != count)
      throw InputError(path + ": /shard", sh.dump(), "the shards are of " + std::to_string(count) + " (" + files.front() +
                       "): all the shards of one table, split the same way");
    if (!seen[k - 1].empty())
      throw InputError(path + ": /shard", sh.dump(), "shard " + std::to_string(k) + " is given twice (also " + seen[k - 1] + ")");
    seen[k - 1] = path;
    // Its points: the first round's k-th slice, in order.
    const nlohmann::json& pts = field("solves");
    std::size_t s = 0;
    for (std::size_t p = k - 1; p < all.size(); p += count, ++s) {
      const std::string at = path + ": /solves/" + std::to_string(s);
      if (!pts.is_array() || s >= pts.size())
        throw InputError(path + ": /solves", "", "fewer solves than shard " + std::to_string(k) + "/" + std::to_string(count) + "'s points");
      const nlohmann::json& e = pts[s];
      if (!e.is_object() || e.value("tY_mm", nlohmann::json()) != all[p].first || e.value("Q_kN", nlohmann::json()) != all[p].second)
        throw InputError(at, e.is_object() ? e.value("tY_mm", nlohmann::json()).dump() + ", " + e.value("Q_kN", nlohmann::json()).dump() : "",
                         "the shard's points must be its slice of the first round's points, in order");
      solves[all[p]] = solve_from_json(e.contains("solve") ? e["solve"] : nlohmann::json(), at + "/solve");
    }
    if (s != pts.size()) throw InputError(path + ": /solves", std::to_string(pts.size()), "more solves than the shard's points");
    points += s;
  }
  for (unsigned k = 1; k <= count; ++k)
    if (seen[k - 1].empty())
      throw InputError("--merge", "", "shard " + std::to_string(k) + "/" + std::to_string(count) + " is missing",
                       "give every shard 1.." + std::to_string(count) + " of the table once");
  if (points != all.size()) throw InputError("--merge", "", "the shards' points do not tile the first round's");
  return solves;
}

}  // namespace mh
