#include "sim/file_reader.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace sim {

namespace {

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a plain file";
}

class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }

 private:
  int fd_;
};

}  // namespace

ReadStatus read_input_file(const std::string& path, std::string& text, std::string& reason, std::size_t max_bytes) {
  text.clear();
  // O_NONBLOCK: opening a FIFO without a writer (or a device) must not block; the file type is
  // checked before anything is read.
  const Fd fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC));
  if (fd.get() < 0) {
    if (errno == ENOENT) return ReadStatus::Missing;
    reason = std::string("cannot open: ") + std::strerror(errno);
    return ReadStatus::Failed;
  }
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) {
    reason = std::string("cannot stat: ") + std::strerror(errno);
    return ReadStatus::Failed;
  }
  if (!S_ISREG(st.st_mode)) {
    reason = std::string("not a regular file (") + kind_of(st.st_mode) + ")";
    return ReadStatus::Failed;
  }
  const std::string too_large = "larger than " + std::to_string(max_bytes) + " bytes (the limit for input files)";
  if (static_cast<unsigned long long>(st.st_size) > max_bytes) {
    reason = too_large;
    return ReadStatus::Failed;
  }
  // The size is a hint only (the file may change while read): read until EOF, at most one byte
  // past the limit to tell a file that grew.
  text.resize(static_cast<std::size_t>(st.st_size) + 1);
  std::size_t done = 0;
  for (;;) {
    if (done == text.size()) {
      if (text.size() > max_bytes) {
        text.clear();
        reason = too_large;
        return ReadStatus::Failed;
      }
      text.resize(std::min(max_bytes + 1, text.size() * 2));
    }
    const ssize_t n = ::read(fd.get(), text.data() + done, text.size() - done);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      reason = std::string("cannot read: ") + std::strerror(errno);
      text.clear();
      return ReadStatus::Failed;
    }
    done += static_cast<std::size_t>(n);
  }
  text.resize(done);
  return ReadStatus::Ok;
}

}  // namespace sim
