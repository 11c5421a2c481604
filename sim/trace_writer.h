// Writes every frame of the buses it taps in can-utils' `candump -L` log format, replayable with
// canplayer: `(0000000001.000250) vcan0 601#4018100100000000`.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "sim/bus.h"

namespace sim {

class TraceWriter final : public FrameTap {
 public:
  /// Opens `path` for writing; on failure `error` is set and is_open() is false.
  TraceWriter(const std::string& path, std::string& error);
  /// Writes to an already open stream (not owned), e.g. stdout.
  explicit TraceWriter(std::FILE* stream);
  ~TraceWriter() override;
  TraceWriter(const TraceWriter&) = delete;
  TraceWriter& operator=(const TraceWriter&) = delete;

  bool is_open() const { return out_ != nullptr; }
  /// Seconds added to simulation time in the log (0 in virtual time for byte-identical traces;
  /// the wall-clock start in real time).
  void set_epoch_offset(std::int64_t seconds) { epoch_offset_s_ = seconds; }
  void on_bus_frame(std::string_view wire_name, const CanFrame& frame, Time now) override;
  /// Pushes the buffered lines to the file; false if this or an earlier write failed.
  bool flush();
  /// Flushes and closes (an owned file); returns the first write error as "cannot write trace
  /// 'PATH': reason", empty if every line reached the file. Later lines are dropped after an error.
  std::string close();
  /// The first write error (see close()), empty while every write succeeded.
  const std::string& error() const { return error_; }
  std::uint64_t lines() const { return lines_; }

 private:
  void fail(int err);

  std::FILE* out_ = nullptr;
  bool owned_ = false;
  std::string path_;
  std::string error_;
  std::vector<char> buffer_;
  std::int64_t epoch_offset_s_ = 0;
  std::uint64_t lines_ = 0;
};

}  // namespace sim
