#include "output/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <vector>

#include "core/errors.hpp"

namespace mh {
namespace {

// Registry of temporaries, readable from a signal handler: fixed-size array of C strings.
constexpr int kMaxPending = 64;
char g_pending[kMaxPending][4096];
std::atomic<bool> g_used[kMaxPending];
bool g_is_dir[kMaxPending];
std::mutex g_mutex;

}  // namespace

int register_pending(const std::string& path, bool is_dir) {
  std::lock_guard<std::mutex> lock(g_mutex);
  for (int i = 0; i < kMaxPending; ++i) {
    if (!g_used[i].load()) {
      std::snprintf(g_pending[i], sizeof g_pending[i], "%s", path.c_str());
      g_is_dir[i] = is_dir;
      g_used[i].store(true);
      return i;
    }
  }
  return -1;
}

void unregister_pending(int slot) {
  if (slot < 0) return;
  std::lock_guard<std::mutex> lock(g_mutex);
  g_used[slot].store(false);
}

namespace {
char g_interrupt_msg[8192];
std::atomic<std::size_t> g_interrupt_len{0};
}  // namespace

void set_interrupt_message(const std::string& line) {
  g_interrupt_len.store(0);
  const std::size_t n = std::min(line.size(), sizeof g_interrupt_msg);
  std::memcpy(g_interrupt_msg, line.data(), n);
  g_interrupt_len.store(n);
}

void print_interrupt_message() noexcept {
  const std::size_t n = g_interrupt_len.load();
  if (n) {
    const ssize_t r = ::write(2, g_interrupt_msg, n);
    (void)r;
  }
}

void check_written(std::ostream& o, const std::string& where) {
  o.flush();
  if (!o) throw OutputError(where, "output could not be written", "disk full, or the reader closed the pipe?");
}

void remove_pending_output_temporaries() noexcept {
  for (int i = 0; i < kMaxPending; ++i)
    if (g_used[i].load() && !g_is_dir[i]) ::unlink(g_pending[i]);
  for (int i = 0; i < kMaxPending; ++i)
    if (g_used[i].load() && g_is_dir[i]) ::rmdir(g_pending[i]);
}

void ensure_directory(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw OutputError(dir, "output directory cannot be created: " +
                               (ec ? ec.message() : std::string("not a directory")));
}

OutputFile::OutputFile(std::string path) : path_(std::move(path)) {
  std::string templ = path_ + ".tmp.XXXXXX";
  std::vector<char> buf(templ.begin(), templ.end());
  buf.push_back('\0');
  int fd = ::mkstemp(buf.data());
  if (fd < 0)
    throw OutputError(path_, std::string("output file cannot be written: ") + std::strerror(errno));
  // mkstemp creates 0600; an output file gets the usual 0666 less the umask.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  fd_ = fd;
  tmp_.assign(buf.data());
  slot_ = register_pending(tmp_, false);
  // in|out: open the empty temporary without truncating it. (A truncating open of an existing
  // file makes ext4 flush the whole file when it is closed: a serial stall of ~0.1 s per 200 MB.)
  out_.open(tmp_, std::ios::binary | std::ios::in | std::ios::out);
  if (!out_) {
    ::close(fd_);
    ::unlink(tmp_.c_str());
    unregister_pending(slot_);
    throw OutputError(path_, "output file cannot be written");
  }
}

OutputFile::~OutputFile() {
  if (!committed_) {
    out_.close();
    ::unlink(tmp_.c_str());
  }
  if (fd_ >= 0) ::close(fd_);
  unregister_pending(slot_);
}

void OutputFile::start_writeback() {
#ifdef SYNC_FILE_RANGE_WRITE
  constexpr long long kMinBytes = 8LL << 20;
  if (fd_ < 0 || !out_) return;
  out_.flush();
  const std::streamoff end = out_.tellp();
  if (end < 0 || end - written_back_ < kMinBytes) return;
  // Asynchronous: it only queues the pages for writing; errors surface at commit()'s fsync.
  ::sync_file_range(fd_, written_back_, end - written_back_, SYNC_FILE_RANGE_WRITE);
  written_back_ = end;
#endif
}

bool OutputFile::append_copy(int in_fd, long long offset, std::size_t length) {
#if defined(__linux__)
  if (fd_ < 0 || !out_) return false;
  out_.flush();
  const std::streamoff at = out_.tellp();
  if (!out_ || at < 0) return false;
  loff_t in = offset, to = at;
  for (std::size_t left = length; left > 0;) {
    const ssize_t r = ::copy_file_range(in_fd, &in, fd_, &to, left, 0);
    if (r < 0 && left == length && (errno == ENOSYS || errno == EXDEV || errno == EINVAL || errno == EOPNOTSUPP || errno == EBADF))
      return false;
    if (r < 0) throw OutputError(path_, std::string("writing the output file failed: ") + std::strerror(errno));
    if (r == 0) throw OutputError(path_, "copying into it: its source file ended early", "was the source changed while it was read?");
    left -= static_cast<std::size_t>(r);
  }
  out_.seekp(at + static_cast<std::streamoff>(length));
  if (!out_) throw OutputError(path_, "writing the output file failed", "disk full?");
  return true;
#else
  (void)in_fd;
  (void)offset;
  (void)length;
  return false;
#endif
}

void OutputFile::commit() {
  out_.flush();
  if (!out_) throw OutputError(path_, "writing the output file failed", "disk full?");
  out_.close();
  if (out_.fail()) throw OutputError(path_, "writing the output file failed", "disk full?");
  if (fd_ >= 0) {
    const int rc = ::fsync(fd_);
    const int e = errno;
    ::close(fd_);
    fd_ = -1;
    if (rc != 0 && e != EINVAL && e != EROFS)
      throw OutputError(path_, std::string("writing the output file failed: ") + std::strerror(e));
  }
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0)
    throw OutputError(path_, std::string("cannot rename the finished output into place: ") +
                                 std::strerror(errno));
  committed_ = true;
}

}  // namespace mh
