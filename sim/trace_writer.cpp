#include "sim/trace_writer.h"

#include <cerrno>
#include <cstring>

namespace sim {

namespace {
constexpr std::size_t kStreamBuffer = 1 << 16;
}

TraceWriter::TraceWriter(const std::string& path, std::string& error) {
  out_ = std::fopen(path.c_str(), "w");
  if (!out_) {
    error = "cannot write trace '" + path + "': " + std::strerror(errno);
    return;
  }
  owned_ = true;
  buffer_.resize(kStreamBuffer);
  std::setvbuf(out_, buffer_.data(), _IOFBF, buffer_.size());
}

TraceWriter::TraceWriter(std::FILE* stream) : out_(stream) {}

TraceWriter::~TraceWriter() {
  if (!out_) return;
  std::fflush(out_);
  if (owned_) std::fclose(out_);
}

void TraceWriter::on_bus_frame(std::string_view wire_name, const CanFrame& frame, Time now) {
  if (!out_) return;
  const std::int64_t us = now.time_since_epoch().count();
  const std::int64_t sec = epoch_offset_s_ + us / 1000000;
  const std::int64_t usec = us % 1000000;
  char text[kCandumpMax];
  format_candump(frame, text);
  std::fprintf(out_, "(%010lld.%06lld) %.*s %s\n", static_cast<long long>(sec), static_cast<long long>(usec),
               static_cast<int>(wire_name.size()), wire_name.data(), text);
  ++lines_;
}

void TraceWriter::flush() {
  if (out_) std::fflush(out_);
}

}  // namespace sim
