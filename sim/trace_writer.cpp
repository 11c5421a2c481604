#include "sim/trace_writer.h"

#include <cerrno>
#include <cstring>

namespace sim {

namespace {
constexpr std::size_t kStreamBuffer = 1 << 16;
}

TraceWriter::TraceWriter(const std::string& path, std::string& error) : path_(path) {
  out_ = std::fopen(path.c_str(), "w");
  if (!out_) {
    error = "cannot write trace '" + path + "': " + std::strerror(errno);
    return;
  }
  owned_ = true;
  buffer_.resize(kStreamBuffer);
  std::setvbuf(out_, buffer_.data(), _IOFBF, buffer_.size());
}

TraceWriter::TraceWriter(std::FILE* stream) : out_(stream), path_("-") {}

TraceWriter::~TraceWriter() { close(); }

void TraceWriter::fail(int err) {
  if (error_.empty()) error_ = "cannot write trace '" + path_ + "': " + std::strerror(err != 0 ? err : EIO);
}

void TraceWriter::on_bus_frame(std::string_view wire_name, const CanFrame& frame, Time now) {
  if (!out_ || !error_.empty()) return;
  const std::int64_t us = now.time_since_epoch().count();
  const std::int64_t sec = epoch_offset_s_ + us / 1000000;
  const std::int64_t usec = us % 1000000;
  char text[kCandumpMax];
  format_candump(frame, text);
  // The stream's fixed buffer goes to the file when full; a failed write (disk full, EIO) shows
  // here as a negative return, and the lines after it are dropped rather than lost silently.
  errno = 0;
  if (std::fprintf(out_, "(%010lld.%06lld) %.*s %s\n", static_cast<long long>(sec), static_cast<long long>(usec),
                   static_cast<int>(wire_name.size()), wire_name.data(), text) < 0) {
    fail(errno);
    return;
  }
  ++lines_;
}

bool TraceWriter::flush() {
  if (!out_) return error_.empty();
  errno = 0;
  if (std::fflush(out_) != 0 || std::ferror(out_)) fail(errno);
  return error_.empty();
}

std::string TraceWriter::close() {
  if (!out_) return error_;
  flush();
  if (owned_) {
    errno = 0;
    if (std::fclose(out_) != 0) fail(errno);
  }
  out_ = nullptr;
  return error_;
}

}  // namespace sim
