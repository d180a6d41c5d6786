// Shards of making a contact table (docs/tables.md "Shards"): the table merged from the shards'
// solves, with the refinement solved at the merge, is byte for byte the one-process table; the
// merge's rules (every shard once, the same case and options) refused with the file and rule.
#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include "core/errors.hpp"
#include "input/case_file.hpp"
#include "jobs/contact_table_make.hpp"
#include "jobs/contact_table_shards.hpp"

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("table shards: the merged table is byte for byte the one-process table", "[tables]") {
  using namespace mh;
  // tests/data/tables/worn-table-q.json: 7 x 2 initial nodes whose one Q interval is refined
  // twice (docs/tables.md), so the merge solves refinement points of its own.
  const CaseFile cf = load_case_file(std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/tables/worn-table-q.json", true);
  TableMakeOptions opt;
  opt.threads = 2;
  opt.quiet = true;
  const std::string dir = "/tmp/mhcontact_test_table_shards_" + std::to_string(::getpid());
  const std::string one = dir + "_one.csv", merged = dir + "_merged.csv";
  std::vector<std::string> parts;
  std::ostringstream out, err;
  CHECK(table_job(cf, opt, one, out, err) == 0);
  for (int k = 1; k <= 3; ++k) {
    parts.push_back(dir + "_part" + std::to_string(k) + ".json");
    CHECK(table_shard_job(cf, opt, std::to_string(k) + "/3", parts.back(), out, err) == 0);
  }
  // Given in any order.
  CHECK(table_job(cf, opt, merged, out, err, {parts[2], parts[0], parts[1]}) == 0);
  const std::string a = slurp(one), b = slurp(merged);
  REQUIRE(!a.empty());
  CHECK(a.find("\"Q_kN_nodes\":[20.0,50.0,80.0,140.0]") != std::string::npos);  // refined at the merge
  CHECK(a == b);

  // The merge's rules.
  CHECK_THROWS_WITH(table_job(cf, opt, merged, out, err, {parts[0], parts[1]}),
                    Catch::Contains("shard 3/3 is missing"));
  CHECK_THROWS_WITH(table_job(cf, opt, merged, out, err, {parts[0], parts[1], parts[1]}),
                    Catch::Contains(parts[1]) && Catch::Contains("shard 2 is given twice"));
  TableMakeOptions nocheck = opt;
  nocheck.check = false;
  nocheck.refine = 0;
  CHECK_THROWS_WITH(table_job(cf, nocheck, merged, out, err, parts),
                    Catch::Contains(parts[0] + ": /check") && Catch::Contains("same case file"));
  CHECK_THROWS_WITH(table_shard_job(cf, opt, "4/3", parts[0], out, err), Catch::Contains("--shard"));
  for (const auto& p : parts) std::remove(p.c_str());
  std::remove(one.c_str());
  std::remove(merged.c_str());
}

TEST_CASE("table shards: the refinement's passes in shards too, byte for byte the one-process table", "[tables]") {
  using namespace mh;
  // worn-table-q.json's Q interval is halved twice: the merge with --next stops at each batch the
  // refinement needs (a round's new nodes with their cells' centres, the edge midpoints of its
  // failing cells), and each batch is solved in 2 shards, until the parts hold every point.
  const CaseFile cf = load_case_file(std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/tables/worn-table-q.json", true);
  TableMakeOptions opt;
  opt.threads = 2;
  opt.quiet = true;
  const std::string dir = "/tmp/mhcontact_test_table_passes_" + std::to_string(::getpid());
  const std::string one = dir + "_one.csv", merged = dir + "_merged.csv";
  std::ostringstream out, err;
  CHECK(table_job(cf, opt, one, out, err) == 0);
  std::vector<std::string> parts, temps;
  for (int k = 1; k <= 3; ++k) {
    parts.push_back(dir + "_p0_" + std::to_string(k) + ".json");
    REQUIRE(table_shard_job(cf, opt, std::to_string(k) + "/3", parts.back(), out, err) == 0);
  }
  int passes = 0, rc = 0;
  std::string first_points;
  for (; passes < 10; ++passes) {
    const std::string next = dir + "_next" + std::to_string(passes + 1) + ".json";
    temps.push_back(next);
    rc = table_job(cf, opt, merged, out, err, parts, next);
    if (rc != kExitMorePoints) break;
    CHECK(!std::ifstream(merged).good());  // no table while points are missing
    if (first_points.empty()) first_points = next;
    for (int k = 1; k <= 2; ++k) {
      parts.push_back(dir + "_p" + std::to_string(passes + 1) + "_" + std::to_string(k) + ".json");
      REQUIRE(table_shard_job(cf, opt, std::to_string(k) + "/2", parts.back(), out, err, next) == 0);
    }
  }
  CHECK(rc == 0);
  CHECK(passes >= 2);  // the refinement took more than one pass of its own
  const std::string a = slurp(one), b = slurp(merged);
  REQUIRE(!a.empty());
  CHECK(a.find("\"Q_kN_nodes\":[20.0,50.0,80.0,140.0]") != std::string::npos);
  CHECK(a == b);

  // A pass's shard missing, a pass's shard given twice, a points file used without its merge.
  std::vector<std::string> lacking(parts.begin(), parts.end() - 1);
  CHECK_THROWS_WITH(table_job(cf, opt, merged, out, err, lacking),
                    Catch::Contains("shard 2/2 of pass " + std::to_string(passes) + " is missing"));
  std::vector<std::string> twice = parts;
  twice.back() = parts[parts.size() - 2];
  CHECK_THROWS_WITH(table_job(cf, opt, merged, out, err, twice), Catch::Contains("shard 1 of pass") && Catch::Contains("given twice"));
  CHECK_THROWS_WITH(table_job(cf, opt, merged, out, err, {}, first_points), Catch::Contains("--next"));
  TableMakeOptions nocheck = opt;
  nocheck.check = false;
  nocheck.refine = 0;
  CHECK_THROWS_WITH(table_shard_job(cf, nocheck, "1/2", dir + "_x.json", out, err, first_points),
                    Catch::Contains(first_points + ": /check"));
  for (const auto& p : parts) std::remove(p.c_str());
  for (const auto& p : temps) std::remove(p.c_str());
  std::remove(one.c_str());
  std::remove(merged.c_str());
}
