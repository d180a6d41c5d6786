#pragma once
// Output files that are never left half written: the content goes to a temporary file in the
// same directory ("NAME.tmp.PID.XXXXXX") and is renamed onto NAME only by commit(). A file that
// is destroyed without commit() (an exception, an early return) removes its temporary.
// Temporaries of a run killed by a signal are removed by the signal handler installed by the
// CLI (see cli.cpp); a hard kill (SIGKILL) leaves at most a *.tmp.* file, never a complete-
// looking NAME.
#include <fstream>
#include <string>

namespace mh {

class OutputFile {
 public:
  /// Opens a temporary beside `path`. Throws InputError naming the directory if it cannot be written.
  explicit OutputFile(std::string path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  std::ostream& stream() { return out_; }
  const std::string& path() const { return path_; }
  /// Flushes, checks the stream, fsyncs and renames onto the final path. Throws on I/O failure.
  void commit();

 private:
  std::string path_;
  std::string tmp_;
  std::ofstream out_;
  bool committed_ = false;
  int slot_ = -1;
};

/// Remove every temporary still registered (for signal handlers; async-signal-safe: unlink only).
void remove_pending_output_temporaries() noexcept;

/// Make sure a directory exists (creating parents). Throws InputError if it cannot.
void ensure_directory(const std::string& dir);

}  // namespace mh
