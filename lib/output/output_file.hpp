#pragma once
// Output files that are never left half written: the content goes to a temporary file in the
// same directory ("NAME.tmp.PID.XXXXXX") and is renamed onto NAME only by commit(). A file that
// is destroyed without commit() (an exception, an early return) removes its temporary.
// Temporaries of a run killed by a signal are removed by the signal handler installed by the
// CLI (see cli.cpp); a hard kill (SIGKILL) leaves at most a *.tmp.* file, never a complete-
// looking NAME.
#include <cstddef>
#include <fstream>
#include <stdexcept>
#include <string>

namespace mh {

/// Output that could not be written: a full disk, a closed pipe, /dev/full, a failed rename, a
/// directory that cannot be created. Exit code 4 (kExitOutput). Message as InputError's:
/// "WHERE: RULE (FIX)".
class OutputError : public std::runtime_error {
 public:
  OutputError(const std::string& where, const std::string& rule, const std::string& hint = {})
      : std::runtime_error(where + ": " + rule + (hint.empty() ? std::string() : " (" + hint + ")")) {}
};

/// Throw OutputError naming `where` if the stream has failed (after flushing it).
void check_written(std::ostream& o, const std::string& where);

class OutputFile {
 public:
  /// Opens a temporary beside `path`. Throws OutputError naming the file if it cannot be written.
  explicit OutputFile(std::string path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  std::ostream& stream() { return out_; }
  const std::string& path() const { return path_; }
  /// Flushes, checks the stream, fsyncs and renames onto the final path. Throws on I/O failure.
  void commit();
  /// Start writing what has been written so far to the disk, without waiting for it, once at
  /// least 8 MB have accumulated since the last call (Linux sync_file_range; elsewhere nothing).
  /// A long sweep calls it after each chunk, so that commit()'s fsync finds little left to do
  /// instead of flushing hundreds of MB at the end while every other core waits.
  void start_writeback();
  /// Append `length` bytes of the open file `in_fd`, from byte `offset`, by a copy inside the
  /// kernel (Linux copy_file_range: the bytes do not pass through this process, and a file
  /// system that shares blocks may share them). Returns false, having written nothing, where the
  /// system cannot (another system, an old kernel, another file system): the caller then writes
  /// the bytes through stream(). Throws OutputError on a failed write or a source that ends early.
  bool append_copy(int in_fd, long long offset, std::size_t length);

 private:
  std::string path_;
  std::string tmp_;
  std::ofstream out_;
  bool committed_ = false;
  int slot_ = -1;
  int fd_ = -1;                  ///< the temporary, kept open for start_writeback() and the fsync
  long long written_back_ = 0;   ///< bytes handed to start_writeback()
};

/// Register a path for removal by remove_pending_output_temporaries() (a file: unlinked; a
/// directory: removed after the files, when empty). Returns its slot (-1: registry full).
int register_pending(const std::string& path, bool is_dir);
void unregister_pending(int slot);

/// The line a signal handler prints after removing the temporaries (what was kept); empty: none.
void set_interrupt_message(const std::string& line);
/// Write that line to standard error (async-signal-safe).
void print_interrupt_message() noexcept;

/// Remove every temporary still registered (for signal handlers; async-signal-safe: unlink only).
void remove_pending_output_temporaries() noexcept;

/// Make sure a directory exists (creating parents). Throws OutputError if it cannot.
void ensure_directory(const std::string& dir);

}  // namespace mh
