#include "output/run_dir.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/errors.hpp"
#include "output/output_file.hpp"

namespace fs = std::filesystem;

namespace mh {

bool is_mhcontact_output_name(const std::string& name) {
  static const char* const kNames[] = {"cases.csv", "ellipses.csv", "results.json", "pressure.csv", "profiles.csv",
                                       "pairs.csv", "shard.json", "run.json", "caf.csv", "geometry.json",
                                       "geometry.csv", "patches.csv", "pair_profiles.csv", "pair_caf.csv",
                                       "pair_ellipses.csv", "wheelset.csv", "conicity.csv", "summary.json",
                                       "fleet.csv", "wheelset_delta_r.png", "wheelset_conicity.png", "wheelset_fleet.png"};
  for (const char* n : kNames)
    if (name == n) return true;
  if (name.find(".tmp.") != std::string::npos) return true;  // an OutputFile temporary left by a hard kill
  // Plots that scripts/plot_*.py write into the directory by default: derived from the run they
  // sit beside, so they go with it when a new run replaces the set.
  auto ends = [&](const char* suf) { const std::string x(suf); return name.size() >= x.size() && name.compare(name.size() - x.size(), x.size(), x) == 0; };
  return name.rfind("pressure_case_", 0) == 0 && ends(".png");
}

namespace {

// The files listed in DIR/run.json, if any.
std::vector<std::string> listed_files(const fs::path& dir) {
  std::vector<std::string> v;
  std::ifstream in(dir / "run.json");
  if (!in) return v;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    for (const auto& f : j.at("files")) v.push_back(f.get<std::string>());
  } catch (const std::exception&) {
    v.clear();
  }
  return v;
}

}  // namespace

RunDirectory::RunDirectory(std::string dir) : dir_(std::move(dir)) {
  if (dir_.empty()) throw InputError("-o", "\"\"", "an output directory is required");
  std::error_code ec;
  fs::path abs = fs::absolute(dir_, ec).lexically_normal();
  if (!abs.has_filename()) abs = abs.parent_path();  // "out/" -> "out"
  if (ec || !abs.has_filename() || abs == abs.root_path())
    throw InputError("-o", dir_, "is not a directory a run can own", "give a new directory, e.g. -o out");
  abs_ = abs.string();
  const fs::file_status st = fs::symlink_status(abs, ec);
  if (fs::exists(st)) {
    if (!fs::is_directory(st))
      throw OutputError(dir_, "output directory cannot be created: it exists and is not a directory");
    // The set of a run replaces the directory as a whole: it must hold nothing else.
    const std::vector<std::string> listed = listed_files(abs);
    for (const auto& e : fs::directory_iterator(abs, ec)) {
      const std::string name = e.path().filename().string();
      const bool ours = (e.is_regular_file() &&
                         (is_mhcontact_output_name(name) || std::find(listed.begin(), listed.end(), name) != listed.end())) ||
                        (e.is_directory() && name == "pairs");  // a batch's per-pair files (pairs/<k>/)
      if (!ours)
        throw InputError(dir_, name, "the output directory holds a file that no mhcontact run wrote; a run replaces its output directory as a whole",
                         "give a new or empty directory");
    }
  }
  const fs::path parent = abs.parent_path();
  fs::create_directories(parent, ec);
  if (ec || !fs::is_directory(parent))
    throw OutputError(dir_, "output directory cannot be created: " + (ec ? ec.message() : std::string("its parent is not a directory")));
  std::string templ = (parent / ("." + abs.filename().string() + ".mhcontact-XXXXXX")).string();
  std::vector<char> buf(templ.begin(), templ.end());
  buf.push_back('\0');
  if (!::mkdtemp(buf.data()))
    throw OutputError(dir_, std::string("output directory cannot be created: ") + std::strerror(errno));
  tmp_.assign(buf.data());
  ::chmod(tmp_.c_str(), 0777 & ~[] { const mode_t m = ::umask(0); ::umask(m); return m; }());
  slots_.push_back(register_pending(tmp_, true));
  set_interrupt_message(fs::exists(abs)
      ? "\nmhcontact: interrupted: " + dir_ + " was left as it was (the previous complete run); nothing of this run was kept\n"
      : "\nmhcontact: interrupted: nothing was kept (" + dir_ + " was not created)\n");
}

RunDirectory::~RunDirectory() {
  set_interrupt_message("");
  if (!finished_) remove_tmp();
  for (int s : slots_) unregister_pending(s);
}

void RunDirectory::remove_tmp() noexcept {
  if (tmp_.empty()) return;
  std::error_code ec;
  fs::remove_all(tmp_, ec);
}

std::string RunDirectory::path(const std::string& name) {
  if (std::find(files_.begin(), files_.end(), name) == files_.end()) {
    files_.push_back(name);
    slots_.push_back(register_pending(tmp_ + "/" + name, false));
    const fs::path parent = fs::path(name).parent_path();  // pairs/<k>/...: per-pair files of a batch
    if (!parent.empty()) {
      std::error_code ec;
      fs::create_directories(fs::path(tmp_) / parent, ec);
      if (ec) throw OutputError(dir_, "cannot create " + parent.string() + ": " + ec.message());
    }
  }
  return tmp_ + "/" + name;
}

void RunDirectory::finish(const std::string& command, const nlohmann::json& program, const nlohmann::json& extra) {
  std::vector<std::string> present;
  for (const auto& f : files_)
    if (fs::exists(tmp_ + "/" + f)) present.push_back(f);
  present.push_back("run.json");
  std::sort(present.begin(), present.end());
  {
    nlohmann::json j = {{"schema", kRunManifestSchema}, {"command", command}, {"program", program}, {"files", present}};
    for (auto it = extra.begin(); it != extra.end(); ++it) j[it.key()] = it.value();
    OutputFile f(path("run.json"));
    f.stream() << j.dump(2) << "\n";
    f.commit();
  }
  // Make the directory entries durable before the swap.
  if (int fd = ::open(tmp_.c_str(), O_RDONLY | O_DIRECTORY); fd >= 0) { ::fsync(fd); ::close(fd); }
  std::error_code ec;
  if (!fs::exists(abs_, ec)) {
    if (std::rename(tmp_.c_str(), abs_.c_str()) != 0)
      throw OutputError(dir_, std::string("cannot move the finished outputs into place: ") + std::strerror(errno));
    tmp_.clear();
  } else {
#ifdef RENAME_EXCHANGE
    // Atomic: readers see the old set or the new set, never a mix or nothing.
    if (::renameat2(AT_FDCWD, tmp_.c_str(), AT_FDCWD, abs_.c_str(), RENAME_EXCHANGE) != 0)
#endif
    {
      // No atomic exchange here: move the old set aside, the new one in, then drop the old.
      const std::string old = tmp_ + ".old";
      if (std::rename(abs_.c_str(), old.c_str()) != 0)
        throw OutputError(dir_, std::string("cannot replace the previous outputs: ") + std::strerror(errno));
      if (std::rename(tmp_.c_str(), abs_.c_str()) != 0) {
        const int e = errno;
        std::rename(old.c_str(), abs_.c_str());
        throw OutputError(dir_, std::string("cannot move the finished outputs into place: ") + std::strerror(e));
      }
      tmp_ = old;
    }
    // tmp_ now holds the previous set.
  }
  finished_ = true;
  for (int s : slots_) unregister_pending(s);
  slots_.clear();
  remove_tmp();
}

}  // namespace mh
