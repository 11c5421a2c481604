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
  void flush();
  std::uint64_t lines() const { return lines_; }

 private:
  std::FILE* out_ = nullptr;
  bool owned_ = false;
  std::vector<char> buffer_;
  std::int64_t epoch_offset_s_ = 0;
  std::uint64_t lines_ = 0;
};

}  // namespace sim
