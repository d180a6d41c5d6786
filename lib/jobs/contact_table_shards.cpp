// Shards of making a contact table (contact_table_shards.hpp; docs/tables.md "Shards").
#include "jobs/contact_table_shards.hpp"

#include <algorithm>
#include <fstream>
#include <map>
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

namespace {

/// The fields every shard and points file of one table shares, checked against the case's.
void check_same(const nlohmann::json& j, const std::string& path, const CaseFile& cf, const TableMakeOptions& opt,
                const nlohmann::json& inputs, const nlohmann::json& profiles, const nlohmann::json& program,
                const char* schema, const char* what) {
  auto field = [&](const char* key) -> const nlohmann::json& {
    if (!j.is_object() || !j.contains(key))
      throw InputError(path + ": /" + key, "", std::string("missing: this is not a ") + what);
    return j[key];
  };
  if (field("schema") != schema)
    throw InputError(path + ": /schema", field("schema").dump(), std::string("must be ") + schema,
                     "write it with this mhcontact");
  const std::string other = "the shards of one table come from the same case file, profiles, options and mhcontact";
  if (field("inputs") != inputs) throw InputError(path + ": /inputs", "", "differs from " + cf.path + "'s: " + other);
  if (field("profiles") != profiles) throw InputError(path + ": /profiles", "", "the profiles (checksums) differ: " + other);
  if (field("program") != program) throw InputError(path + ": /program", field("program").dump(), "another mhcontact: " + other);
  if (field("check") != opt.check) throw InputError(path + ": /check", field("check").dump(), "--no-check differs: " + other);
  if (field("check_points") != opt.check_points)
    throw InputError(path + ": /check_points", field("check_points").dump(), "--check-points differs: " + other);
  if (field("validate") != opt.validate)
    throw InputError(path + ": /validate", field("validate").dump(), "--validate differs: " + other);
}

nlohmann::json read_json_file(const std::string& path, const char* what, const char* hint) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", std::string("cannot read the ") + what, hint);
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path, "", std::string("a ") + what + " is one JSON object: " + e.what());
  }
}

/// A pass's points, [[t_Y mm, Q kN, roll mrad], ...], from `j` (a points or shard file), checked.
std::vector<TablePoint> points_from(const nlohmann::json& j, const std::string& where) {
  std::vector<TablePoint> pts;
  if (!j.is_array() || j.empty()) throw InputError(where, "", "must be a non-empty array of [tY_mm, Q_kN, roll_mrad]");
  for (std::size_t p = 0; p < j.size(); ++p) {
    const nlohmann::json& e = j[p];
    if (!e.is_array() || e.size() != 3 || !e[0].is_number() || !e[1].is_number() || !e[2].is_number())
      throw InputError(where + "/" + std::to_string(p), e.dump(), "a point is [tY_mm, Q_kN, roll_mrad]");
    pts.push_back({e[0].get<double>(), e[1].get<double>(), e[2].get<double>()});
  }
  return pts;
}

nlohmann::json points_json(const std::vector<TablePoint>& points) {
  nlohmann::json pp = nlohmann::json::array();
  for (const auto& p : points) pp.push_back({p.tY_mm, p.Q_kN, p.roll_mrad});
  return pp;
}

}  // namespace

int table_shard_job(const CaseFile& cf, const TableMakeOptions& opt, const std::string& shard, const std::string& out_path,
                    std::ostream& out, std::ostream& err, const std::string& points_path) {
  unsigned k = 0, n = 0;
  parse_shard(shard, &k, &n);
  const PairGeometry pg = build_pair_geometry(cf);
  if (!opt.quiet) warn_profiles(pg, err);
  unsigned pass = 0;
  std::vector<TablePoint> all;
  if (points_path.empty()) {
    all = table_first_points(cf, opt);
  } else {
    const nlohmann::json pj = read_json_file(points_path, "points file",
                                             "give the file written by `mhcontact table CASE.json --merge PART... --next FILE`");
    check_same(pj, points_path, cf, opt, inputs_json(cf), profiles_json(pg), program_json(), kContactTablePointsSchema,
               "table points file");
    if (!pj.contains("pass") || !pj["pass"].is_number_unsigned() || pj["pass"].get<unsigned>() < 1)
      throw InputError(points_path + ": /pass", pj.value("pass", nlohmann::json()).dump(), "must be a pass number >= 1");
    pass = pj["pass"].get<unsigned>();
    all = points_from(pj.value("points", nlohmann::json()), points_path + ": /points");
  }
  std::vector<TablePoint> mine;
  for (std::size_t p = k - 1; p < all.size(); p += n) mine.push_back(all[p]);
  Pool pool(std::max(1u, opt.threads ? opt.threads : std::thread::hardware_concurrency()));
  const std::vector<NodeSolve> solves = solve_points(cf, pg, mine, pool);
  nlohmann::json j;
  j["schema"] = kContactTableShardSchema;
  j["program"] = program_json();
  j["shard"] = {k, n};
  j["pass"] = pass;
  j["check"] = opt.check;
  j["check_points"] = opt.check_points;
  j["validate"] = opt.validate;
  j["inputs"] = inputs_json(cf);
  j["profiles"] = profiles_json(pg);
  j["points"] = all.size();
  if (pass > 0) j["pass_points"] = points_json(all);
  nlohmann::json pts = nlohmann::json::array();
  for (std::size_t s = 0; s < solves.size(); ++s)
    pts.push_back({{"tY_mm", mine[s].tY_mm}, {"Q_kN", mine[s].Q_kN}, {"roll_mrad", mine[s].roll_mrad},
                   {"solve", solve_to_json(solves[s])}});
  j["solves"] = pts;
  if (out_path == "-") {
    out << j.dump() << '\n';
  } else {
    OutputFile f(out_path);
    f.stream() << j.dump() << '\n';
    f.commit();
  }
  if (!opt.quiet) {
    err << "mhcontact table: shard " << k << "/" << n << ": " << solves.size() << " of ";
    if (pass == 0) err << "the first round's " << all.size();
    else err << "refinement pass " << pass << "'s " << all.size();
    err << " points solved; merge the shards with `mhcontact table CASE.json --merge PART... -o TABLE`\n";
  }
  return kExitOk;
}

TableSolves read_table_shards(const CaseFile& cf, const PairGeometry& pg, const TableMakeOptions& opt,
                              const std::vector<std::string>& files, unsigned* passes) {
  const nlohmann::json inputs = inputs_json(cf), profiles = profiles_json(pg), program = program_json();
  struct Pass {
    std::vector<TablePoint> all;  // its points
    std::string all_from;                         // the file that listed them (a pass > 0)
    std::vector<std::string> seen;                // by shard index - 1: the file that gave it
    unsigned count = 0;
    std::size_t points = 0;
  };
  std::map<unsigned, Pass> by_pass;
  TableSolves solves;
  for (const std::string& path : files) {
    const nlohmann::json j = read_json_file(path, "shard file",
                                            "give the files written by `mhcontact table CASE.json --shard K/N -o FILE`");
    check_same(j, path, cf, opt, inputs, profiles, program, kContactTableShardSchema, "table shard file");
    if (!j.contains("shard")) throw InputError(path + ": /shard", "", "missing: this is not a table shard file");
    const nlohmann::json& sh = j["shard"];
    if (!sh.is_array() || sh.size() != 2 || !sh[0].is_number_unsigned() || !sh[1].is_number_unsigned())
      throw InputError(path + ": /shard", sh.dump(), "must be [K, N]");
    const unsigned k = sh[0].get<unsigned>(), n = sh[1].get<unsigned>();
    if (k < 1 || k > n) throw InputError(path + ": /shard", sh.dump(), "must be [K, N] with 1 <= K <= N");
    const nlohmann::json pj = j.value("pass", nlohmann::json(0));
    if (!pj.is_number_unsigned()) throw InputError(path + ": /pass", pj.dump(), "must be a pass number (0: the first round)");
    const unsigned pass = pj.get<unsigned>();
    const std::string of_pass = pass == 0 ? std::string() : " of pass " + std::to_string(pass);
    Pass& P = by_pass[pass];
    if (P.count == 0) {
      P.count = n;
      P.seen.assign(n, std::string());
      if (pass == 0) {
        P.all = table_first_points(cf, opt);
      } else {
        P.all = points_from(j.value("pass_points", nlohmann::json()), path + ": /pass_points");
        P.all_from = path;
      }
    }
    if (n != P.count)
      throw InputError(path + ": /shard", sh.dump(), "the shards" + of_pass + " are of " + std::to_string(P.count) + " (" +
                       (P.all_from.empty() ? files.front() : P.all_from) + "): all the shards of one pass, split the same way");
    if (pass > 0 && points_from(j.value("pass_points", nlohmann::json()), path + ": /pass_points") != P.all)
      throw InputError(path + ": /pass_points", "", "differ from " + P.all_from + "'s: the shards of one pass solve one points file");
    if (!P.seen[k - 1].empty())
      throw InputError(path + ": /shard", sh.dump(), "shard " + std::to_string(k) + of_pass + " is given twice (also " +
                       P.seen[k - 1] + ")");
    P.seen[k - 1] = path;
    // Its points: the pass's k-th slice, in order.
    const nlohmann::json& pts = j.contains("solves") ? j["solves"] : nlohmann::json();
    std::size_t s = 0;
    for (std::size_t p = k - 1; p < P.all.size(); p += P.count, ++s) {
      const std::string at = path + ": /solves/" + std::to_string(s);
      if (!pts.is_array() || s >= pts.size())
        throw InputError(path + ": /solves", "", "fewer solves than shard " + std::to_string(k) + "/" + std::to_string(P.count) + "'s points");
      const nlohmann::json& e = pts[s];
      if (!e.is_object() || e.value("tY_mm", nlohmann::json()) != P.all[p].tY_mm || e.value("Q_kN", nlohmann::json()) != P.all[p].Q_kN ||
          e.value("roll_mrad", nlohmann::json()) != P.all[p].roll_mrad)
        throw InputError(at, e.is_object() ? e.value("tY_mm", nlohmann::json()).dump() + ", " + e.value("Q_kN", nlohmann::json()).dump() +
                                                 ", " + e.value("roll_mrad", nlohmann::json()).dump()
                                           : "",
                         "the shard's points must be its slice of the pass's points, in order");
      solves[P.all[p]] = solve_from_json(e.contains("solve") ? e["solve"] : nlohmann::json(), at + "/solve");
    }
    if (s != pts.size()) throw InputError(path + ": /solves", std::to_string(pts.size()), "more solves than the shard's points");
    P.points += s;
  }
  for (const auto& [pass, P] : by_pass) {
    const std::string of_pass = pass == 0 ? std::string() : " of pass " + std::to_string(pass);
    for (unsigned k = 1; k <= P.count; ++k)
      if (P.seen[k - 1].empty())
        throw InputError("--merge", "", "shard " + std::to_string(k) + "/" + std::to_string(P.count) + of_pass + " is missing",
                         "give every shard 1.." + std::to_string(P.count) + " of every pass once");
    if (P.points != P.all.size()) throw InputError("--merge", "", "the shards' points do not tile the pass's points" + of_pass);
  }
  if (!by_pass.count(0))
    throw InputError("--merge", "", "no shard of the first round (pass 0)", "give the shards of `--shard K/N` without --points too");
  if (passes) *passes = by_pass.rbegin()->first + 1;
  return solves;
}

void write_table_points(const CaseFile& cf, const PairGeometry& pg, const TableMakeOptions& opt, unsigned pass,
                        const std::vector<TablePoint>& points, const std::string& path) {
  nlohmann::json j;
  j["schema"] = kContactTablePointsSchema;
  j["program"] = program_json();
  j["pass"] = pass;
  j["check"] = opt.check;
  j["check_points"] = opt.check_points;
  j["validate"] = opt.validate;
  j["inputs"] = inputs_json(cf);
  j["profiles"] = profiles_json(pg);
  j["points"] = points_json(points);
  OutputFile f(path);
  f.stream() << j.dump() << '\n';
  f.commit();
}

}  // namespace mh
