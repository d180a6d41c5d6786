#pragma once
// One run per output directory. The files of a run are written into a sibling temporary
// directory (".NAME.mhcontact-XXXXXX" beside NAME) and, when the run completes, that directory
// replaces NAME as a whole (an atomic exchange where the file system offers one), so that NAME
// always holds the complete set of files of one run: never files of two runs side by side,
// never a half-written set. DIR/run.json lists the files that belong to the run.
// An interrupted or failed run removes its temporary directory and leaves NAME as it was (the
// previous complete set, or nothing).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace mh {

/// Schema name of DIR/run.json.
constexpr const char* kRunManifestSchema = "mhcontact.run/1";

class RunDirectory {
 public:
  /// Checks that `dir` can be replaced (missing, empty, or holding only files mhcontact writes:
  /// InputError otherwise, naming a foreign file), creates its parent and the temporary sibling
  /// (OutputError if it cannot). Nothing is created when it throws.
  explicit RunDirectory(std::string dir);
  ~RunDirectory();
  RunDirectory(const RunDirectory&) = delete;
  RunDirectory& operator=(const RunDirectory&) = delete;

  /// The path, in the temporary directory, of the run's file `name`, which is recorded as one
  /// of the run's files.
  std::string path(const std::string& name);
  /// The final directory as given.
  const std::string& dir() const { return dir_; }
  /// Writes run.json ({"schema", "command", "program", "files": [...], plus the members of
  /// `extra`}) and puts the set in place of `dir`. Throws OutputError if it cannot.
  void finish(const std::string& command, const nlohmann::json& program, const nlohmann::json& extra = nlohmann::json::object());

 private:
  std::string dir_, abs_, tmp_;
  std::vector<std::string> files_;
  std::vector<int> slots_;
  bool finished_ = false;
  void remove_tmp() noexcept;
};

/// Names of the files an mhcontact run may leave in its output directory.
bool is_mhcontact_output_name(const std::string& name);

}  // namespace mh
