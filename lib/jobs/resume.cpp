#include "jobs/resume.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "jobs/batch.hpp"
#include "jobs/shards.hpp"

namespace fs = std::filesystem;

namespace mh {

std::string resume_parts_dir(const std::string& out_dir) {
  std::string d = out_dir;
  while (d.size() > 1 && d.back() == '/') d.pop_back();
  return d + ".parts";
}

namespace {

// Whether `dir` holds the complete shard K/N of this run: its shard.json (written last, and the
// directory renamed into place only then) describes the same slice, inputs and output options.
bool part_complete(const std::string& dir, unsigned k, unsigned n, const nlohmann::json& inputs, const RunOptions& opt) {
  std::ifstream in(dir + "/shard.json", std::ios::binary);
  if (!in) return false;
  std::stringstream ss;
  ss << in.rdbuf();
  const nlohmann::json j = nlohmann::json::parse(ss.str(), nullptr, false);
  if (j.is_discarded() || !j.is_object()) return false;
  return j.value("schema", "") == "mhcontact.shard/1" && j.value("index", 0u) == k && j.value("count", 0u) == n &&
         j.value("csv", !opt.csv) == opt.csv && j.value("json", !opt.json) == opt.json &&
         j.value("pressure", opt.pressure_grid == 0) == (opt.pressure_grid > 0) && j.value("digits", -1) == opt.digits &&
         j.contains("inputs") && j["inputs"] == inputs;
}

}  // namespace

int resumable_batch_job(const Manifest& m, const RunOptions& opt, std::ostream& out, std::ostream& err) {
  if (opt.out_dir == "-") throw InputError("-o", "-", "--resume writes an output directory", "give a directory");
  if (opt.shard_count > 1)
    throw InputError("--resume", "--shard " + std::to_string(opt.shard_index) + "/" + std::to_string(opt.shard_count),
                     "a resumable run is the whole fleet", "resume each shard by re-running the missing ones, or drop --shard");
  if (opt.fail_on_warning || !opt.fail_on.empty())
    throw InputError("--resume", "--fail-on", "is not available with --resume",
                     "run without --resume, or check the warnings in the merged cases.csv");
  const auto n = static_cast<unsigned>(m.pairs.size());
  if (n < 2) return batch_job(m, opt, out, err);  // one pair: nothing to resume between pairs
  const auto t0 = std::chrono::steady_clock::now();
  const std::string parts = resume_parts_dir(opt.out_dir);
  // What batch_job records as the shard's inputs (jobs/batch.cpp): a part of another run is
  // recomputed, not merged.
  const nlohmann::json inputs = {{"manifest", m.path}, {"common", m.common}, {"pairs", m.pairs.size()}};
  std::vector<std::string> dirs;
  std::vector<unsigned> todo;
  for (unsigned k = 1; k <= n; ++k) {
    dirs.push_back(parts + "/pair" + std::to_string(k));
    if (!part_complete(dirs.back(), k, n, inputs, opt)) todo.push_back(k);
  }
  if (!opt.quiet && todo.size() < n)
    err << "mhcontact run: resuming: " << (n - todo.size()) << " of " << n << " pairs already complete in " << parts
        << ", " << todo.size() << " to run\n";
  const std::uint64_t per_pair = pair_case(m, 0).case_count();
  RunOptions part = opt;
  part.quiet = true;  // one summary for the run, not one per pair
  part.progress = false;
  part.shard_count = n;
  part.shard_by_cases = false;  // a part is a pair
  part.shard_sizes = ShardSizes::Equal;
  std::uint64_t done = 0;
  const std::uint64_t total = per_pair * todo.size();
  for (unsigned k : todo) {
    part.shard_index = k;
    part.out_dir = dirs[k - 1];
    std::ostringstream sink;
    batch_job(m, part, sink, err);  // exit 1 (cases not ok) is the merge's to report
    done += per_pair;
    if (opt.progress && !opt.quiet)
      err << "\r" << progress_line(done, total, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count())
          << std::flush;
  }
  if (opt.progress && !opt.quiet && !todo.empty()) err << "\n";
  return merge_job(dirs, opt.out_dir, err, opt.quiet);
}

}  // namespace mh
